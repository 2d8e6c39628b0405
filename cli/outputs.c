/* SPDX-License-Identifier: MIT */
/* The paths of the outputs: the --out directory made, and the --stats and
 * --trajectory paths refused at once when they cannot become a file. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"

void make_dirs(const char *path)
{
    char buf[4096];
    size_t len = strlen(path);
    if (len >= sizeof buf)
        die(EXIT_USAGE, "--out path is too long");
    memcpy(buf, path, len + 1);
    for (size_t k = 1; k <= len; ++k) {
        if (buf[k] != '/' && buf[k] != '\0')
            continue;
        char saved = buf[k];
        buf[k] = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            die(EXIT_RUN, "cannot create directory '%s': %s", buf, strerror(errno));
        buf[k] = saved;
    }
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode))
        die(EXIT_RUN, "'%s' is not a directory", path);
}

/* Splits the path of --stats or --trajectory into directory and base name,
 * refusing at once (before any simulation time is spent) a path that
 * cannot become a file. */
const char *output_split(const char *option, const char *path, char *dir, size_t dir_cap)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    if (!slash)
        snprintf(dir, dir_cap, ".");
    else if (slash == path)
        snprintf(dir, dir_cap, "/");
    else
        snprintf(dir, dir_cap, "%.*s", (int)(slash - path), path);
    struct stat st;
    if (!*base || (stat(path, &st) == 0 && S_ISDIR(st.st_mode)))
        die(EXIT_USAGE, "%s needs a file name, got directory '%s'", option, path);
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
        die(EXIT_RUN, "cannot write %s %s: '%s' is not a directory", option, path, dir);
    return base;
}
