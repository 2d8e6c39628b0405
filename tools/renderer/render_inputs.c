/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_inputs.h"

/* A directory's frames.json, or an extended XYZ file and its frames. */
struct ri_source {
    char *path;    /* the directory, or the XYZ file */
    int has_run;   /* frames.json was there and read */
    fj_run run;    /* ... and says this */
    rx_frame *xyz; /* an XYZ file's frames */
    size_t xyz_count;
    rg_frame *gsd; /* a GSD file's frames */
    size_t gsd_count;
    int warned; /* a contradiction with the options has been said */
};

static char *copy(const char *s)
{
    const size_t n = strlen(s) + 1;
    char *c = malloc(n);
    if (c)
        memcpy(c, s, n);
    return c;
}

static int out_of_memory(void)
{
    fprintf(stderr, "render: out of memory\n");
    return -1;
}

/* A new source at the end of the list's; its index, or -1. */
static long add_source(ri_list *l, const char *path)
{
    if (l->nsources == l->source_cap) {
        size_t cap = l->source_cap ? 2 * l->source_cap : 8;
        ri_source *grown = realloc(l->sources, cap * sizeof *grown);
        if (!grown)
            return -1;
        l->sources = grown;
        l->source_cap = cap;
    }
    ri_source *s = &l->sources[l->nsources];
    memset(s, 0, sizeof *s);
    if (!(s->path = copy(path)))
        return -1;
    return (long)l->nsources++;
}

/* The source of the frame files in dir: its frames.json, read once. */
static long dir_source(ri_list *l, const char *dir)
{
    for (size_t k = 0; k < l->nsources; ++k)
        if (!l->sources[k].xyz && !l->sources[k].gsd && strcmp(l->sources[k].path, dir) == 0)
            return (long)k;
    const long k = add_source(l, dir);
    if (k < 0) {
        out_of_memory();
        return -1;
    }
    char why[512];
    const int got = fj_read(dir, &l->sources[k].run, why, sizeof why);
    if (got < 0) {
        fprintf(stderr, "render: %s\n", why);
        return -1;
    }
    l->sources[k].has_run = got;
    return k;
}

static ri_frame *add_frame(ri_list *l, const char *path, size_t source)
{
    if (l->count == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        ri_frame *grown = realloc(l->frames, cap * sizeof *grown);
        if (!grown)
            return NULL;
        l->frames = grown;
        l->cap = cap;
    }
    ri_frame *f = &l->frames[l->count];
    memset(f, 0, sizeof *f);
    if (!(f->path = copy(path)))
        return NULL;
    f->source = source;
    f->number = -1;
    f->time = NAN;
    ++l->count;
    return f;
}

/* The options' box where given, else the file's, else 1000 x 1000; the
 * options' boundary, else the file's, else `otherwise`; a contradiction
 * said once per source. what names the file. */
static void place(ri_frame *f, ri_source *s, const ri_box *given, double file_x, double file_y,
                  int file_boundary, ds_boundary otherwise, const char *what)
{
    const int box_given = given->box > 0.0 || given->box_y > 0.0;
    const double gx = given->box > 0.0 ? given->box : 1000.0;
    const double gy = given->box_y > 0.0 ? given->box_y : gx;
    const int have_box = file_x > 0.0 && file_y > 0.0;
    f->box_x = box_given ? gx : have_box ? file_x : 1000.0;
    f->box_y = box_given ? gy : have_box ? file_y : 1000.0;
    f->boundary = (ds_boundary)(given->boundary >= 0 ? given->boundary
                                : file_boundary >= 0 ? file_boundary
                                                     : (int)otherwise);
    if (s->warned)
        return;
    if (box_given && have_box && (gx != file_x || gy != file_y)) {
        fprintf(stderr,
                "render: warning: %s gives the box %g x %g; drawn %g x %g as the options say\n",
                what, file_x, file_y, gx, gy);
        s->warned = 1;
    }
    if (given->boundary >= 0 && file_boundary >= 0 && given->boundary != file_boundary) {
        fprintf(stderr, "render: warning: %s gives the boundary %s; drawn %s as the options say\n",
                what, ds_boundary_name((ds_boundary)file_boundary),
                ds_boundary_name((ds_boundary)given->boundary));
        s->warned = 1;
    }
}

/* k of frame_k.txt (any number of digits), else -1. */
static long frame_number(const char *base)
{
    const size_t n = strlen(base);
    if (n < 11 || strncmp(base, "frame_", 6) != 0 || strcmp(base + n - 4, ".txt") != 0 ||
        strspn(base + 6, "0123456789") != n - 10 || n - 10 > 9)
        return -1;
    return strtol(base + 6, NULL, 10);
}

static void split(const char *path, char *dir, size_t cap, const char **base)
{
    const char *slash = strrchr(path, '/');
    *base = slash ? slash + 1 : path;
    if (!slash)
        snprintf(dir, cap, ".");
    else
        snprintf(dir, cap, "%.*s", slash == path ? 1 : (int)(slash - path), path);
}

static int add_text_frame(ri_list *l, const char *path, const ri_box *given, long source)
{
    char dir[4200];
    const char *base;
    split(path, dir, sizeof dir, &base);
    if (source < 0 && (source = dir_source(l, dir)) < 0)
        return -1;
    ri_frame *f = add_frame(l, path, (size_t)source);
    if (!f)
        return out_of_memory();
    ri_source *s = &l->sources[source];
    const fj_run *run = &s->run;
    char what[4300];
    snprintf(what, sizeof what, "%s/%s", s->path, FJ_NAME);
    place(f, s, given, s->has_run ? run->box_x : 0.0, s->has_run ? run->box_y : 0.0,
          s->has_run ? run->boundary : -1, DS_BOUNDARY_WALLS, what);
    f->number = frame_number(base);
    if (s->has_run && f->number >= 0)
        f->time = fj_frame_time(run, f->number);
    return 0;
}

static int add_xyz(ri_list *l, const char *path, const ri_box *given)
{
    const long k = add_source(l, path);
    if (k < 0)
        return out_of_memory();
    char why[1400];
    ri_source *s = &l->sources[k];
    if (rx_scan(path, &s->xyz, &s->xyz_count, why, sizeof why) != 0) {
        fprintf(stderr, "render: %s\n", why);
        return -1;
    }
    for (size_t i = 0; i < s->xyz_count; ++i) {
        ri_frame *f = add_frame(l, path, (size_t)k);
        if (!f)
            return out_of_memory();
        s = &l->sources[k];
        const rx_frame *fr = &s->xyz[i];
        f->xyz = fr;
        f->number = (long)i;
        f->time = fr->time;
        place(f, s, given, fr->box_x, fr->box_y, fr->boundary, DS_BOUNDARY_WALLS, path);
    }
    return 0;
}

/* A GSD file's frames, each in its own box. GSD records no boundary:
 * periodic, as HOOMD's boxes are, unless the options say otherwise (and
 * then nothing contradicts them). */
static int add_gsd(ri_list *l, const char *path, const ri_box *given)
{
    const long k = add_source(l, path);
    if (k < 0)
        return out_of_memory();
    char why[1400];
    ri_source *s = &l->sources[k];
    if (rg_scan(path, &s->gsd, &s->gsd_count, why, sizeof why) != 0) {
        fprintf(stderr, "render: %s\n", why);
        return -1;
    }
    for (size_t i = 0; i < s->gsd_count; ++i) {
        ri_frame *f = add_frame(l, path, (size_t)k);
        if (!f)
            return out_of_memory();
        s = &l->sources[k];
        const rg_frame *fr = &s->gsd[i];
        f->gsd = fr;
        f->number = (long)i;
        f->time = fr->time;
        place(f, s, given, fr->box_x, fr->box_y, -1, DS_BOUNDARY_PERIODIC, path);
    }
    return 0;
}

int ri_add_file(ri_list *l, const char *path, const ri_box *given)
{
    return rx_is_xyz(path)   ? add_xyz(l, path, given)
           : rg_is_gsd(path) ? add_gsd(l, path, given)
                             : add_text_frame(l, path, given, -1);
}

static int name_order(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int ri_add_dir(ri_list *l, const char *dir, const ri_box *given)
{
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "render: %s: cannot open directory: %s\n", dir, strerror(errno));
        return -1;
    }
    char **names = NULL;
    size_t count = 0, cap = 0;
    int failed = 0;
    struct dirent *e;
    errno = 0;
    while (!failed && (e = readdir(d)) != NULL) {
        const size_t n = strlen(e->d_name);
        if (n < 10 || strncmp(e->d_name, "frame_", 6) != 0 ||
            strcmp(e->d_name + n - 4, ".txt") != 0)
            continue;
        if (count == cap) {
            cap = cap ? 2 * cap : 1024;
            char **grown = realloc(names, cap * sizeof *grown);
            failed = !grown;
            names = grown ? grown : names;
        }
        if (!failed && !(names[count] = malloc(strlen(dir) + n + 2)))
            failed = 1;
        if (!failed)
            sprintf(names[count++], "%s/%s", dir, e->d_name);
        errno = 0;
    }
    const int saved = errno;
    closedir(d);
    int rc = -1;
    if (failed)
        out_of_memory();
    else if (saved)
        fprintf(stderr, "render: %s: cannot read directory: %s\n", dir, strerror(saved));
    else if (count == 0)
        fprintf(stderr, "render: %s: no frame_*.txt files\n", dir);
    else
        rc = 0;
    long source = -1;
    if (rc == 0) {
        qsort(names, count, sizeof *names, name_order);
        rc = (source = dir_source(l, dir)) < 0 ? -1 : 0;
    }
    for (size_t k = 0; k < count; ++k) {
        if (rc == 0)
            rc = add_text_frame(l, names[k], given, source);
        free(names[k]);
    }
    free(names);
    return rc;
}

/* frame_0012.txt -> frame_0012.png; run.xyz's (or run.gsd's) frame 12 ->
 * run_0012.png;
 * in out_dir if given, else beside the file. */
static char *png_name(const ri_frame *f, const char *out_dir)
{
    const char *slash = strrchr(f->path, '/');
    const char *base = slash ? slash + 1 : f->path;
    size_t stem = strlen(base);
    const int trajectory = f->xyz || f->gsd;
    const char *suffix = trajectory ? strrchr(base, '.') : NULL;
    if (suffix)
        stem = (size_t)(suffix - base);
    else if (stem > 4 && strcmp(base + stem - 4, ".txt") == 0)
        stem -= 4;
    const size_t dir = out_dir ? strlen(out_dir) + 1 : (size_t)(base - f->path);
    char *s = malloc(dir + stem + 32);
    if (!s)
        return NULL;
    if (out_dir)
        sprintf(s, "%s/", out_dir);
    else
        memcpy(s, f->path, dir);
    memcpy(s + dir, base, stem);
    if (trajectory)
        sprintf(s + dir + stem, "_%04ld.png", f->number);
    else
        memcpy(s + dir + stem, ".png", 5);
    return s;
}

int ri_name_outputs(ri_list *l, const char *out_dir, const char *out_file)
{
    for (size_t i = 0; i < l->count; ++i) {
        ri_frame *f = &l->frames[i];
        if (!(f->output = out_file ? copy(out_file) : png_name(f, out_dir)))
            return -1;
    }
    return 0;
}

int ri_read(const ri_list *l, size_t i, ds_frame *frame, char *err, size_t errlen)
{
    const ri_frame *f = &l->frames[i];
    if (f->xyz)
        return rx_read(f->path, f->xyz, frame, err, errlen);
    if (f->gsd)
        return rg_read(f->path, f->gsd, (size_t)f->number, frame, err, errlen);
    ds_error fe;
    if (ds_frame_read(f->path, frame, &fe) != DS_OK) {
        if (fe.index)
            snprintf(err, errlen, "%s:%zu: %s", f->path, fe.index, fe.message);
        else
            snprintf(err, errlen, "%s: %s", f->path, fe.message);
        return -1;
    }
    /* Frames that are not their frames.json's run would be drawn in
     * another run's box. */
    const ri_source *s = &l->sources[f->source];
    const fj_run *run = &s->run;
    const int velocities = frame->columns == 5;
    if (s->has_run && run->n >= 0 && (long)frame->count != run->n)
        snprintf(err, errlen, "%s: %zu disk%s, but %s/%s says n = %ld: not that run's frame",
                 f->path, frame->count, frame->count == 1 ? "" : "s", s->path, FJ_NAME, run->n);
    else if (s->has_run && run->velocities >= 0 && velocities != run->velocities)
        snprintf(err, errlen,
                 "%s: %s velocities, but %s/%s says \"velocities\": %s: not that run's frame",
                 f->path, velocities ? "has" : "has no", s->path, FJ_NAME,
                 run->velocities ? "true" : "false");
    else
        return 0;
    ds_frame_free(frame);
    return -1;
}

void ri_free(ri_list *l)
{
    for (size_t i = 0; i < l->count; ++i) {
        free(l->frames[i].path);
        free(l->frames[i].output);
    }
    for (size_t k = 0; k < l->nsources; ++k) {
        free(l->sources[k].path);
        free(l->sources[k].xyz);
        free(l->sources[k].gsd);
    }
    free(l->frames);
    free(l->sources);
    memset(l, 0, sizeof *l);
}
