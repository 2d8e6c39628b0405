/* SPDX-License-Identifier: MIT */
/* The paths a run names, checked before any work (docs/cli.md, "Nothing
 * lost, nothing mixed"): no two files the same, no output over a frame,
 * every output in a directory that exists or that --out will make; the
 * --out directory made; and the frames an earlier run left there. */
/* realpath() is X/Open. */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

/* The absolute path a name means, symbolic links resolved as far as the
 * name exists; the rest, which a run will create, is added as written
 * ("." and ".." resolved). Two names of one file give the same string. */
static void canonical(const char *path, char *out, size_t cap)
{
    char resolved[PATH_CAP * 2];
    if (strlen(path) < PATH_CAP && realpath(path, resolved)) {
        path_printf(out, cap, "%s", resolved);
        return;
    }
    char copy[PATH_CAP];
    snprintf(copy, sizeof copy, "%s", path);
    size_t len = strlen(copy);
    while (len > 1 && copy[len - 1] == '/')
        copy[--len] = '\0';
    char dir[PATH_CAP], parent[PATH_CAP];
    const char *base;
    split_path(copy, dir, sizeof dir, &base);
    if (strcmp(dir, copy) == 0 || !*base) { /* "/" or a name realpath could not reach */
        snprintf(out, cap, "%s", copy);
        return;
    }
    canonical(dir, parent, sizeof parent);
    if (strcmp(base, ".") == 0) {
        snprintf(out, cap, "%s", parent);
    } else if (strcmp(base, "..") == 0) {
        char *slash = strrchr(parent, '/');
        if (slash && slash != parent)
            *slash = '\0';
        else
            snprintf(parent, sizeof parent, "/");
        snprintf(out, cap, "%s", parent);
    } else {
        path_printf(out, cap, "%s%s%s", parent, strcmp(parent, "/") == 0 ? "" : "/", base);
    }
}

int frame_number(const char *base)
{
    if (strlen(base) != strlen("frame_0000.txt") || strncmp(base, "frame_", 6) != 0 ||
        strcmp(base + 10, ".txt") != 0)
        return -1;
    int k = 0;
    for (int i = 6; i < 10; ++i) {
        if (base[i] < '0' || base[i] > '9')
            return -1;
        k = 10 * k + (base[i] - '0');
    }
    return k;
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* Refuses an --out that cannot become a directory, as mkdir would, before
 * anything is made. */
static void check_out_dir(const char *path)
{
    char buf[PATH_CAP];
    size_t len = strlen(path);
    if (len >= sizeof buf)
        die(EXIT_USAGE, "--out path is too long");
    memcpy(buf, path, len + 1);
    for (size_t k = 1; k <= len; ++k) {
        if (buf[k] != '/' && buf[k] != '\0')
            continue;
        char saved = buf[k];
        buf[k] = '\0';
        struct stat st;
        int exists = stat(buf, &st) == 0;
        buf[k] = saved;
        if (!exists)
            return; /* this part and the rest are made */
        if (S_ISDIR(st.st_mode))
            continue;
        if (k == len || strspn(path + k, "/") == len - k)
            die(EXIT_RUN, "'%s' is not a directory", path);
        size_t next = k + 1;
        while (next < len && buf[next] != '/')
            ++next;
        die(EXIT_RUN, "cannot create directory '%.*s': %s", (int)next, path, strerror(ENOTDIR));
    }
}

typedef struct named {
    const char *option;
    const char *path;
    int output; /* written by the run; else read (--restart, --from) */
    char canon[PATH_CAP];
} named;

/* Outputs whose directory is missing are fine if --out makes it: the
 * directory is --out or one of the parents it creates. */
static void check_output_dir(const named *f, const char *out_canon)
{
    char dir[PATH_CAP], dir_canon[PATH_CAP];
    const char *base;
    split_path(f->path, dir, sizeof dir, &base);
    struct stat st;
    if (stat(dir, &st) == 0) {
        if (!S_ISDIR(st.st_mode))
            die(EXIT_RUN, "cannot write %s %s: '%s' is not a directory", f->option, f->path, dir);
        return;
    }
    canonical(dir, dir_canon, sizeof dir_canon);
    size_t l = strlen(dir_canon);
    if (strcmp(dir_canon, out_canon) == 0 ||
        (strncmp(out_canon, dir_canon, l) == 0 && out_canon[l] == '/'))
        return;
    die(EXIT_RUN, "cannot write %s %s: '%s' is not a directory", f->option, f->path, dir);
}

void check_paths(const options *o)
{
    check_out_dir(o->out_dir);
    char out_canon[PATH_CAP];
    canonical(o->out_dir, out_canon, sizeof out_canon);
    named files[] = {{"--stats", o->stats_path, 1, ""},
                     {"--trajectory", o->trajectory_path, 1, ""},
                     {"--checkpoint", o->checkpoint_path, 1, ""},
                     {"--restart", o->restart_path, 0, ""},
                     {"--from", o->from_path, 0, ""}};
    const size_t count = sizeof files / sizeof files[0];
    for (size_t i = 0; i < count; ++i) {
        named *f = &files[i];
        if (!f->path)
            continue;
        if (f->output && is_dir(f->path))
            die(EXIT_USAGE, "%s needs a file name, got directory '%s'", f->option, f->path);
        canonical(f->path, f->canon, sizeof f->canon);
        if (strcmp(f->canon, out_canon) == 0)
            die(EXIT_USAGE, "%s %s is the --out directory: give it a file name", f->option,
                f->path);
        char dir[PATH_CAP];
        const char *base;
        split_path(f->canon, dir, sizeof dir, &base);
        if (strcmp(*dir ? dir : "/", out_canon) == 0 && frame_number(base) >= 0) {
            if (f->output)
                die(EXIT_USAGE,
                    "%s %s would replace a frame file in the --out directory '%s': choose "
                    "another name",
                    f->option, f->path, o->out_dir);
            die(EXIT_USAGE,
                "%s %s is a frame file in the --out directory '%s', which this run writes: "
                "copy it elsewhere first",
                f->option, f->path, o->out_dir);
        }
    }
    /* Two names of one file: the later write would replace the earlier, or
     * an output its own input. --restart and --checkpoint may be the same
     * file (the checkpoint is read first and replaced atomically), and
     * /dev/null takes anything. */
    for (size_t i = 0; i < count; ++i)
        for (size_t j = i + 1; j < count; ++j) {
            const named *a = &files[i], *b = &files[j];
            if (!a->path || !b->path || strcmp(a->canon, b->canon) != 0 ||
                strcmp(a->canon, "/dev/null") == 0)
                continue;
            if (strcmp(a->option, "--checkpoint") == 0 && strcmp(b->option, "--restart") == 0)
                continue;
            die(EXIT_USAGE, "%s and %s both name %s: give each its own file", a->option, b->option,
                b->path);
        }
    for (size_t i = 0; i < count; ++i)
        if (files[i].path && files[i].output)
            check_output_dir(&files[i], out_canon);
}

void make_out_dir(const char *path)
{
    char buf[PATH_CAP];
    size_t len = strlen(path);
    if (len >= sizeof buf)
        die(EXIT_USAGE, "--out path is too long");
    memcpy(buf, path, len + 1);
    for (size_t k = 1; k <= len; ++k) {
        if (buf[k] != '/' && buf[k] != '\0')
            continue;
        char saved = buf[k];
        buf[k] = '\0';
        if (mkdir(buf, 0777) == 0)
            note_created_dir(buf);
        else if (errno != EEXIST)
            die(EXIT_RUN, "cannot create directory '%s': %s", buf, strerror(errno));
        buf[k] = saved;
    }
    if (!is_dir(path))
        die(EXIT_RUN, "'%s' is not a directory", path);
}

/* Frame files numbered after last: another run's (a run writes frames
 * 0 .. last, a restart its checkpoint's frame + 1 .. last after the
 * frames before, which are its own). */
static long other_frames(const char *dir, long last, long *lo, long *hi, int remove)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0; /* not there yet: made by this run */
    long count = 0;
    *lo = MAX_FRAMES;
    *hi = -1;
    struct dirent *e;
    while ((e = readdir(d))) {
        int k = frame_number(e->d_name);
        if (k < 0 || k <= last)
            continue;
        char path[PATH_CAP];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat st;
        if (lstat(path, &st) != 0 || S_ISDIR(st.st_mode))
            continue;
        if (remove && unlink(path) != 0)
            die(EXIT_RUN, "cannot remove %s (--overwrite): %s", path, strerror(errno));
        ++count;
        *lo = k < *lo ? k : *lo;
        *hi = k > *hi ? k : *hi;
    }
    closedir(d);
    return count;
}

void check_other_runs(const options *o, long last)
{
    long lo = 0, hi = 0;
    long count = other_frames(o->out_dir, last, &lo, &hi, 0);
    if (count == 0 || o->overwrite)
        return;
    char where[PATH_CAP];
    const char *dir = o->out_dir;
    if (strcmp(dir, ".") == 0)
        snprintf(where, sizeof where, "the current directory");
    else
        path_printf(where, sizeof where, "%s%s", dir, dir[strlen(dir) - 1] == '/' ? "" : "/");
    if (count == 1)
        die(EXIT_RUN, "%s holds frame_%04ld.txt from another run; remove it or pass --overwrite",
            where, lo);
    if (count == 2)
        die(EXIT_RUN,
            "%s holds frame_%04ld.txt and frame_%04ld.txt from another run; remove them or pass "
            "--overwrite",
            where, lo, hi);
    if (count == hi - lo + 1)
        die(EXIT_RUN,
            "%s holds frame_%04ld.txt ... frame_%04ld.txt from another run; remove them or pass "
            "--overwrite",
            where, lo, hi);
    die(EXIT_RUN,
        "%s holds %ld frame files from another run, frame_%04ld.txt ... frame_%04ld.txt; remove "
        "them or pass --overwrite",
        where, count, lo, hi);
}

void remove_other_runs(const options *o, long last)
{
    long lo = 0, hi = 0;
    if (o->overwrite)
        (void)other_frames(o->out_dir, last, &lo, &hi, 1);
}
