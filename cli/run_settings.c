/* SPDX-License-Identifier: MIT */
/* The run's settings in its checkpoints, so that --restart goes on with
 * the run it continues: the frame spacing, the frames still to write, the
 * frame format, where the frames and the outputs go, the checkpoints and
 * --measure-after. They are the library's metadata text
 * (ds_sim_set_metadata), one "key value" line each after a first line
 * naming the format; a value's backslashes and newlines are escaped (\\,
 * \n), so any path survives. A restart takes every setting its command
 * line did not give from there, and refuses one that contradicts the run
 * (another frame spacing, or velocities the frames so far do not have). A
 * checkpoint without them (written by the library for another program, or
 * by disksim 2.x) restarts with the command's defaults, as 2.x did. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define FIRST_LINE "disks run settings 1"

typedef struct settings {
    int present;
    uint64_t steps_per_frame;
    long last_frame;
    int velocities;
    char *out, *stats, *trajectory, *gsd, *checkpoint; /* NULL: none */
    long checkpoint_every;
    double measure_after;
} settings;

/* The text grows here; a path is at most PATH_CAP bytes, escaped twice. */
typedef struct text {
    char buf[8 * PATH_CAP + 512];
    size_t len;
} text;

static void put_line(text *t, const char *key, const char *value)
{
    size_t room = sizeof t->buf - t->len;
    int n = snprintf(t->buf + t->len, room, "%s ", key);
    t->len += (size_t)n;
    for (const char *c = value; *c && t->len + 3 < sizeof t->buf; ++c) {
        if (*c == '\\' || *c == '\n') {
            t->buf[t->len++] = '\\';
            t->buf[t->len++] = *c == '\n' ? 'n' : '\\';
        } else {
            t->buf[t->len++] = *c;
        }
    }
    t->buf[t->len++] = '\n';
    t->buf[t->len] = '\0';
}

void record_run_settings(ds_sim *sim, const options *o, long last)
{
    static text t; /* 34 kB: not on the stack */
    char number[64];
    t.len = (size_t)snprintf(t.buf, sizeof t.buf, "%s\n", FIRST_LINE);
    snprintf(number, sizeof number, "%llu", (unsigned long long)o->steps_per_frame);
    put_line(&t, "steps_per_frame", number);
    snprintf(number, sizeof number, "%ld", last);
    put_line(&t, "last_frame", number);
    put_line(&t, "velocities", o->velocities ? "1" : "0");
    put_line(&t, "out", o->out_dir);
    if (o->stats_path)
        put_line(&t, "stats", o->stats_path);
    if (o->trajectory_path)
        put_line(&t, "trajectory", o->trajectory_path);
    if (o->gsd_path)
        put_line(&t, "gsd", o->gsd_path);
    if (o->checkpoint_path) {
        put_line(&t, "checkpoint", o->checkpoint_path);
        snprintf(number, sizeof number, "%ld", o->checkpoint_every);
        put_line(&t, "checkpoint_every", number);
    }
    if (o->measure_after > 0.0) {
        snprintf(number, sizeof number, "%.17g", o->measure_after);
        put_line(&t, "measure_after", number);
    }
    ds_error err;
    if (ds_sim_set_metadata(sim, t.buf, &err) != DS_OK)
        die(EXIT_RUN, "cannot record the run's settings: %s", err.message);
}

/* A line's value, unescaped, into a new string. */
static char *value_of(const char *v, size_t len)
{
    char *out = malloc(len + 1);
    if (!out)
        die(EXIT_RUN, "out of memory for the run's settings");
    size_t n = 0;
    for (size_t k = 0; k < len; ++k)
        out[n++] = v[k] == '\\' && k + 1 < len ? (v[++k] == 'n' ? '\n' : v[k]) : v[k];
    out[n] = '\0';
    return out;
}

/* Reads what record_run_settings wrote; a key it does not know is
 * skipped (a later command's), a number that is not one refused. */
/* The settings read: their paths are the run's options until the command
 * ends, then freed (the leak checkers see every allocation go). */
static settings kept;

static void forget_settings(void)
{
    free(kept.out);
    free(kept.stats);
    free(kept.trajectory);
    free(kept.gsd);
    free(kept.checkpoint);
}

static settings read_settings(const char *meta, const char *path)
{
    settings s;
    memset(&s, 0, sizeof s);
    const size_t first = strlen(FIRST_LINE);
    if (strncmp(meta, FIRST_LINE, first) != 0 || meta[first] != '\n')
        return s;
    s.present = 1;
    for (const char *line = meta + first + 1; *line;) {
        const char *end = strchr(line, '\n');
        const size_t len = end ? (size_t)(end - line) : strlen(line);
        const char *space = memchr(line, ' ', len);
        if (space) {
            const size_t klen = (size_t)(space - line);
            char *v = value_of(space + 1, len - klen - 1);
            char *stop = v;
            errno = 0;
#define KEY(name) (klen == sizeof(name) - 1 && strncmp(line, name, klen) == 0)
            if (KEY("steps_per_frame"))
                s.steps_per_frame = strtoull(v, &stop, 10);
            else if (KEY("last_frame"))
                s.last_frame = strtol(v, &stop, 10);
            else if (KEY("velocities"))
                s.velocities = (int)strtol(v, &stop, 10);
            else if (KEY("checkpoint_every"))
                s.checkpoint_every = strtol(v, &stop, 10);
            else if (KEY("measure_after"))
                s.measure_after = strtod(v, &stop);
            else
                stop = v + strlen(v); /* a path, or a key of a later command */
#undef KEY
            if (*stop != '\0' || stop == v || errno)
                die(EXIT_RUN, "cannot restart from %s: its run settings are damaged (%.*s)", path,
                    (int)klen, line);
            char **path_field = strncmp(line, "out ", 4) == 0           ? &s.out
                                : strncmp(line, "stats ", 6) == 0       ? &s.stats
                                : strncmp(line, "trajectory ", 11) == 0 ? &s.trajectory
                                : strncmp(line, "gsd ", 4) == 0         ? &s.gsd
                                : strncmp(line, "checkpoint ", 11) == 0 ? &s.checkpoint
                                                                        : NULL;
            if (path_field)
                *path_field = v; /* kept for the run */
            else
                free(v);
        }
        line += len + (end != NULL);
    }
    if (s.steps_per_frame < 1 || s.steps_per_frame > 1000000000u || s.last_frame < 0 ||
        s.last_frame > MAX_FRAMES - 1 || !s.out)
        die(EXIT_RUN, "cannot restart from %s: its run settings are damaged", path);
    kept = s;
    atexit(forget_settings);
    return s;
}

/* The frame the checkpoint holds at K steps a frame: a growth that jammed
 * ended its run between frames, in the frame it was making. */
static long frame_of(const ds_sim *sim, uint64_t k)
{
    const uint64_t steps = ds_sim_get_steps(sim);
    return (long)(steps / k + (steps % k != 0));
}

/* Outputs the restart writes where its run did: it goes on with them. */
static void go_on_with(const char **given, int *continues, char *recorded)
{
    if (!*given)
        *given = recorded;
    *continues = recorded && strcmp(*given, recorded) == 0;
}

long resume_run_settings(options *o, const ds_sim *sim)
{
    const char *path = o->restart_path;
    settings s = read_settings(ds_sim_get_metadata(sim), path);
    if (s.present) {
        if (o->steps_given && o->steps_per_frame != s.steps_per_frame)
            die(EXIT_USAGE,
                "--steps-per-frame %llu contradicts the run of %s, which wrote a frame every "
                "%llu steps: give none (the restart goes on with it) or the same",
                (unsigned long long)o->steps_per_frame, path,
                (unsigned long long)s.steps_per_frame);
        if (o->velocities && !s.velocities)
            die(EXIT_USAGE,
                "--velocities contradicts the run of %s, whose frames have no velocities: "
                "give another --out for frames with them",
                path);
        o->steps_per_frame = s.steps_per_frame;
        o->velocities = s.velocities;
        if (!o->out_given)
            o->out_dir = s.out;
        go_on_with(&o->stats_path, &o->stats_continues, s.stats);
        go_on_with(&o->trajectory_path, &o->trajectory_continues, s.trajectory);
        go_on_with(&o->gsd_path, &o->gsd_continues, s.gsd);
        if (!o->checkpoint_path && s.checkpoint) {
            o->checkpoint_path = s.checkpoint;
            if (!o->checkpoint_every)
                o->checkpoint_every = s.checkpoint_every;
        }
        if (!(o->measure_after > 0.0) && s.measure_after > 0.0)
            o->measure_after = s.measure_after;
    }
    if (o->checkpoint_every && !o->checkpoint_path)
        die(EXIT_USAGE, "--checkpoint-every needs --checkpoint FILE");
    const long frame = frame_of(sim, o->steps_per_frame);
    if (s.present && !o->frames_given) {
        if (s.last_frame <= frame)
            die(EXIT_USAGE,
                "the run of %s ended at frame %ld, its last: give --frames F to write F more", path,
                frame);
        o->frames = s.last_frame - frame;
    }
    return restart_frame(o, sim);
}
