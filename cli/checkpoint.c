/* SPDX-License-Identifier: MIT */
/* Checkpoints written so that a crash or a kill never leaves a corrupt one
 * in place of a good one: the whole state formatted in memory, written to
 * a temporary beside FILE, synced to the disk, renamed over FILE, and the
 * directory synced (files.c). A device or a link is written in place. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

void checkpoint_write(const ds_sim *sim, const char *path)
{
    size_t cap = ds_checkpoint_get_size(sim), len = 0;
    char *buf = malloc(cap ? cap : 1);
    if (!buf)
        die(EXIT_RUN, "cannot write --checkpoint %s: out of memory", path);
    ds_error err;
    if (ds_checkpoint_format(sim, buf, cap, &len, &err) != DS_OK)
        die(EXIT_RUN, "cannot write --checkpoint %s: %s", path, err.message);
    const char *why = "";
    int failed;
    if (is_special_file(path)) {
        failed = write_file_in_place(path, buf, len, &why);
    } else {
        char dir[PATH_CAP];
        const char *base;
        split_path(path, dir, sizeof dir, &base);
        failed = write_file_atomic(dir, base, buf, len, 1, &why);
    }
    free(buf);
    if (failed)
        die(EXIT_RUN, "cannot write --checkpoint %s: %s", path, why);
}

void checkpoint_probe(const char *path)
{
    if (is_special_file(path))
        return;
    char dir[PATH_CAP];
    const char *base;
    split_path(path, dir, sizeof dir, &base);
    int err = probe_dir(dir, base);
    if (err)
        die(EXIT_RUN, "cannot write --checkpoint %s: %s", path, strerror(err));
}
