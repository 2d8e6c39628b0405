/* SPDX-License-Identifier: MIT */
/* frames.json: the run's description beside its frame files. The frames
 * keep the seed's text, which says nothing of the box, the boundary or
 * the time; this file says it, for tools/render, tools/gr and any script
 * (docs/cli.md, "Frame files"). It is flat JSON, one key a line, so that
 * every language reads it with its standard library and grep finds a key:
 *
 *   {
 *     "disksim_frames": 1,
 *     "n": 400,
 *     ...
 *   }
 *
 * It is written like a frame (whole, then renamed) right after the first
 * frame a run writes, and again when growth jams, whose last frame is not
 * at a whole number of frame spacings. The frames of a run are its
 * frames.json's: a directory whose frames.json describes another run
 * holds that run's frames (outputs.c). */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"

#define NAME "frames.json"
#define TEXT_CAP 4096 /* the keys below, and two kind names of at most 16 bytes escaped */
#define READ_CAP 65536

typedef struct text {
    char *buf;
    size_t len;
} text;

static void add(text *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void add(text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(t->buf + t->len, TEXT_CAP - t->len, fmt, ap);
    va_end(ap);
    if (n > 0)
        t->len = t->len + (size_t)n < TEXT_CAP ? t->len + (size_t)n : TEXT_CAP - 1;
}

/* The shortest of %.15g, %.16g and %.17g that reads back as v: 0.001,
 * not 0.0010000000000000000208. */
static void add_number(text *t, double v)
{
    char s[32];
    for (int digits = 15; digits <= 17; ++digits) {
        snprintf(s, sizeof s, "%.*g", digits, v);
        if (strtod(s, NULL) == v)
            break;
    }
    add(t, "%s", s);
}

/* A JSON string: quotes, backslashes and control bytes escaped. */
static void add_string(text *t, const char *s)
{
    add(t, "\"");
    for (const unsigned char *c = (const unsigned char *)s; *c; ++c) {
        if (*c == '"' || *c == '\\')
            add(t, "\\%c", *c);
        else if (*c < 0x20)
            add(t, "\\u%04x", *c);
        else
            add(t, "%c", *c);
    }
    add(t, "\"");
}

char *frames_json_text(const ds_sim *sim, const options *o, long jammed_frame)
{
    text t = {malloc(TEXT_CAP), 0};
    if (!t.buf)
        die(EXIT_RUN, "out of memory for %s", NAME);
    add(&t, "{\n  \"disksim_frames\": 1,\n  \"n\": %zu,\n  \"radius\": ", ds_sim_get_count(sim));
    add_number(&t, ds_sim_get_radius(sim));
    add(&t, ",\n  \"box\": [");
    add_number(&t, ds_sim_get_box_width(sim));
    add(&t, ", ");
    add_number(&t, ds_sim_get_box_height(sim));
    add(&t, "],\n  \"boundary\": \"%s\",\n  \"dt\": ", ds_boundary_name(ds_sim_get_boundary(sim)));
    add_number(&t, ds_sim_get_dt(sim));
    add(&t, ",\n  \"steps_per_frame\": %llu,\n  \"integrator\": \"%s\",\n  \"velocities\": %s",
        (unsigned long long)o->steps_per_frame, ds_integrator_name(ds_sim_get_integrator(sim)),
        o->velocities ? "true" : "false");
    const size_t kinds = ds_sim_get_kind_count(sim);
    if (kinds > 1) {
        add(&t, ",\n  \"kinds\": [");
        for (size_t k = 0; k < kinds; ++k) {
            add(&t, k ? ", " : "");
            add_string(&t, ds_sim_get_kind_name(sim, k));
        }
        add(&t, "]");
    }
    /* A barostat moves the box: the box above is the one at the frame
     * this file was written with, and the frames' own are in
     * --trajectory and --gsd. */
    if (ds_sim_get_barostat_pressure(sim) > 0.0) {
        add(&t, ",\n  \"pressure\": ");
        add_number(&t, ds_sim_get_barostat_pressure(sim));
    }
    /* A sheared box's images above move at shear_rate box_y along x
     * (the frames keep each disk inside the box; --trajectory and --gsd
     * record the images' offset frame by frame). */
    if (ds_sim_get_shear(sim) != 0.0) {
        add(&t, ",\n  \"shear_rate\": ");
        add_number(&t, ds_sim_get_shear(sim));
    }
    if (jammed_frame >= 0) {
        add(&t, ",\n  \"jammed_frame\": %ld,\n  \"jammed_time\": ", jammed_frame);
        add_number(&t, ds_sim_get_time(sim));
    }
    add(&t, "\n}\n");
    return t.buf;
}

void frames_json_write(const options *o, const char *json)
{
    const char *why = "";
    if (write_file_atomic(o->out_dir, NAME, json, strlen(json), 0, &why) != 0)
        die(EXIT_RUN, "cannot write %s/%s: %s", o->out_dir, NAME, why);
}

/* The line of key in a text of lines `  "key": value,`, its value's
 * length in *len (without the comma); NULL if absent. */
static const char *value_of(const char *json, const char *key, size_t *len)
{
    const size_t klen = strlen(key);
    for (const char *line = json; line && *line; line = strchr(line, '\n'), line += !!line) {
        const char *p = line + strspn(line, " \t");
        if (*p != '"' || strncmp(p + 1, key, klen) != 0 || strncmp(p + 1 + klen, "\":", 2) != 0)
            continue;
        p += klen + 3;
        p += strspn(p, " \t");
        size_t n = strcspn(p, "\r\n");
        while (n > 0 && (p[n - 1] == ',' || p[n - 1] == ' '))
            --n;
        *len = n;
        return p;
    }
    return NULL;
}

/* The keys that say which run the frames are from: all but the jam's,
 * which a restart from before the jam does not know yet. */
static const char *const run_keys[] = {
    "n", "radius", "box", "boundary", "dt", "steps_per_frame", "integrator", "velocities", "kinds"};

int frames_json_compare(const char *dir, const char *json, char *why, size_t cap)
{
    char path[PATH_CAP];
    path_printf(path, sizeof path, "%s/%s", dir, NAME);
    struct stat st;
    if (lstat(path, &st) != 0)
        return 0;
    FILE *f = S_ISREG(st.st_mode) ? fopen(path, "rb") : NULL;
    char *old = malloc(READ_CAP);
    size_t got = f && old ? fread(old, 1, READ_CAP - 1, f) : 0;
    if (f)
        fclose(f);
    if (!old)
        die(EXIT_RUN, "out of memory for %s", path);
    old[got] = '\0';
    size_t len = 0, mine_len = 0;
    int result = 0;
    const char *v = value_of(old, "disksim_frames", &len);
    if (!v || len != 1 || *v != '1') {
        snprintf(why, cap, "is not a disksim run's description");
        result = 2;
    }
    /* A run whose barostat moves the box is the same run at another box
     * (a restart's is the checkpoint's). */
    const int box_moves = value_of(json, "pressure", &mine_len) != NULL;
    for (size_t k = 0; !result && k < sizeof run_keys / sizeof run_keys[0]; ++k) {
        if (box_moves && strcmp(run_keys[k], "box") == 0)
            continue;
        const char *theirs = value_of(old, run_keys[k], &len);
        const char *mine = value_of(json, run_keys[k], &mine_len);
        if ((theirs || mine) &&
            !(theirs && mine && len == mine_len && !memcmp(theirs, mine, len))) {
            snprintf(why, cap, "has %s %.*s, this run's %.*s", run_keys[k], theirs ? (int)len : 4,
                     theirs ? theirs : "none", mine ? (int)mine_len : 4, mine ? mine : "none");
            result = 1;
        }
    }
    free(old);
    return result;
}
