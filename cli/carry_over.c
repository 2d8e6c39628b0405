/* SPDX-License-Identifier: MIT */
/* What a restarted run keeps of the --stats, --trajectory and --gsd
 * files its run wrote: the rows and frames up to the checkpoint's frame,
 * copied into the new file before the restart's own, so that the file
 * ends up as the uninterrupted run's. Frames written after the checkpoint
 * (a run killed later) are dropped: the restart writes them again. A file
 * that is not what this command writes is refused rather than guessed
 * at. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"

/* The whole of a regular file, or NULL if there is none at path (the run
 * lost it, or never wrote it: nothing to keep). */
static char *read_whole(const char *option, const char *path, size_t *len)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return NULL;
    FILE *f = fopen(path, "rb");
    char *data = malloc((size_t)st.st_size + 1);
    if (!f || !data)
        die(EXIT_RUN, "cannot read %s %s to go on with it: %s", option, path,
            f ? "out of memory" : strerror(errno));
    *len = fread(data, 1, (size_t)st.st_size, f);
    const int failed = ferror(f) || *len != (size_t)st.st_size;
    fclose(f);
    if (failed)
        die(EXIT_RUN, "cannot read %s %s to go on with it: it changed while read", option, path);
    data[*len] = '\0';
    return data;
}

/* The end of the line that starts at p (past its newline), or NULL if
 * the text ends without one (a cut line: not kept). */
static const char *line_end(const char *p, const char *end)
{
    const char *nl = memchr(p, '\n', (size_t)(end - p));
    return nl ? nl + 1 : NULL;
}

int carry_over_stats(output *out, const char *header, long last)
{
    size_t len = 0;
    char *data = read_whole(out->option, out->path, &len);
    if (!data)
        return 0;
    const size_t hlen = strlen(header);
    if (len < hlen || memcmp(data, header, hlen) != 0)
        die(EXIT_RUN,
            "cannot go on with --stats %s: its first line is not this command's header; give "
            "another --stats",
            out->path);
    const char *p = data + hlen, *end = data + len;
    while (p < end) {
        const char *next = line_end(p, end);
        char *stop;
        const long frame = strtol(p, &stop, 10);
        if (!next || stop == p || *stop != ',' || frame > last)
            break;
        p = next;
    }
    output_write(out, data, (size_t)(p - data));
    free(data);
    return 1;
}

int carry_over_trajectory(output *out, const ds_sim *sim, uint64_t steps_per_frame, long last)
{
    size_t len = 0;
    char *data = read_whole(out->option, out->path, &len);
    if (!data)
        return 0;
    const size_t n = ds_sim_get_count(sim);
    const double frame_time = (double)steps_per_frame * ds_sim_get_dt(sim);
    const char *p = data, *end = data + len;
    /* Frame by frame: a count line, a comment line with Time=, n lines. */
    while (p < end) {
        char *stop;
        const unsigned long long count = strtoull(p, &stop, 10);
        const char *comment = line_end(p, end);
        if (stop == p || count != n || !comment)
            break;
        const char *body = line_end(comment, end);
        const char *time = body ? strstr(comment, "Time=") : NULL;
        if (!time || time > body)
            break;
        const double t = strtod(time + 5, NULL);
        if (!(llround(t / frame_time) <= last))
            break;
        const char *q = body;
        for (size_t k = 0; k < n && q; ++k)
            q = line_end(q, end);
        if (!q)
            break;
        p = q;
    }
    if (p == data && len > 0)
        die(EXIT_RUN,
            "cannot go on with --trajectory %s: it does not begin with a frame of this run's %zu "
            "disks up to frame %ld; give another --trajectory",
            out->path, n, last);
    output_write(out, data, (size_t)(p - data));
    free(data);
    return 1;
}

/* The little-endian number (GSD's byte order) in the `bytes` bytes at p. */
static uint64_t le(const unsigned char *p, int bytes)
{
    uint64_t v = 0;
    for (int k = 0; k < bytes; ++k)
        v |= (uint64_t)p[k] << (8 * k);
    return v;
}

/* The id of name in a GSD file's name list (the header's), or -1. */
static long name_id(const unsigned char *b, size_t len, const char *name)
{
    const uint64_t at = le(b + 24, 8), size = 64 * le(b + 32, 8);
    if (at > len || size > len - at)
        return -1;
    long id = 0;
    for (uint64_t p = at; p < at + size && b[p] != 0; ++id) {
        const void *nul = memchr(b + p, 0, (size_t)(at + size - p));
        if (!nul)
            return -1;
        if (strcmp((const char *)b + p, name) == 0)
            return id;
        p = (uint64_t)((const unsigned char *)nul - b) + 1;
    }
    return -1;
}

/* The GSD file: the index's entries from the first frame whose step is
 * past sim's are emptied (location 0 ends the index: their chunks stay,
 * unread), and the file copied whole. */
int carry_over_gsd(output *out, const ds_sim *sim)
{
    size_t len = 0;
    char *data = read_whole(out->option, out->path, &len);
    if (!data)
        return 0;
    unsigned char *b = (unsigned char *)data;
    const uint64_t steps = ds_sim_get_steps(sim), at = len >= 256 ? le(b + 8, 8) : 0,
                   cap = len >= 256 ? le(b + 16, 8) : 0;
    const long step_id = len >= 256 && le(b, 8) == 0x65DF65DF65DF65DFull
                             ? name_id(b, len, "configuration/step")
                             : -1;
    if (step_id < 0 || at > len || cap > (len - at) / 32)
        die(EXIT_RUN,
            "cannot go on with --gsd %s: it is not a GSD file this command wrote; give another "
            "--gsd",
            out->path);
    uint64_t k = 0, cut = UINT64_MAX; /* the frame from which entries go */
    for (; k < cap; ++k) {
        const unsigned char *e = b + at + 32 * k;
        const uint64_t location = le(e + 16, 8), frame = le(e, 8);
        if (location == 0 || frame >= cut)
            break;
        if ((long)le(e + 28, 2) == step_id && location <= len - 8 && le(b + location, 8) > steps)
            cut = frame;
    }
    for (uint64_t j = 0; j < cap; ++j)
        if (le(b + at + 32 * j + 16, 8) != 0 && le(b + at + 32 * j, 8) >= cut)
            memset(b + at + 32 * j, 0, 32);
    output_write(out, data, len);
    free(data);
    return 1;
}
