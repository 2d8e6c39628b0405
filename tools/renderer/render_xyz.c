/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "render_xyz.h"

#define MAX_DISKS 100000000 /* 10^8 disks a frame: far past what a frame of disks holds */

int rx_is_xyz(const char *path)
{
    const size_t n = strlen(path);
    return (n > 4 && strcasecmp(path + n - 4, ".xyz") == 0) ||
           (n > 7 && strcasecmp(path + n - 7, ".extxyz") == 0);
}

/* The next key=value of a comment line from *p: key and value copied
 * (a quoted value without its quotes, its escapes kept as written). 1 if
 * there was one, 0 at the end. */
static int next_pair(const char **p, char *key, size_t kcap, char *value, size_t vcap)
{
    const char *s = *p + strspn(*p, " \t\r\n");
    if (!*s)
        return 0;
    size_t k = 0, v = 0;
    while (*s && *s != '=' && !isspace((unsigned char)*s)) {
        if (k + 1 < kcap)
            key[k++] = *s;
        ++s;
    }
    key[k] = '\0';
    if (*s == '=') {
        ++s;
        const char close = *s == '"' ? '"' : *s == '{' ? '}' : '\0';
        s += close != '\0';
        for (; *s && (close ? *s != close : !isspace((unsigned char)*s)); ++s) {
            if (close == '"' && *s == '\\' && s[1])
                ++s;
            if (v + 1 < vcap)
                value[v++] = *s;
        }
        s += close && *s == close;
    }
    value[v] = '\0';
    *p = s;
    return 1;
}

/* Properties=name:type:n:... into the columns the renderer draws. */
static int properties(const char *text, rx_frame *fr, char *why, size_t cap)
{
    char copy[1024];
    snprintf(copy, sizeof copy, "%s", text);
    int column = 0;
    char *save = NULL;
    for (char *name = strtok_r(copy, ":", &save); name; name = strtok_r(NULL, ":", &save)) {
        const char *type = strtok_r(NULL, ":", &save), *n = strtok_r(NULL, ":", &save);
        char *end = NULL;
        const long cols = n ? strtol(n, &end, 10) : 0;
        if (!type || !n || *end || cols < 1 || cols > 1000 || strlen(type) != 1 ||
            !strchr("SRIL", type[0])) {
            snprintf(why, cap, "Properties=%s is not name:type:count triples", text);
            return -1;
        }
        const int real = type[0] == 'R';
        if (!strcasecmp(name, "pos") && real && (cols == 2 || cols == 3))
            fr->pos = column;
        else if (!strcasecmp(name, "radius") && real && cols == 1)
            fr->radius = column;
        else if ((!strcasecmp(name, "velo") || !strcasecmp(name, "vel") ||
                  !strcasecmp(name, "velocities")) &&
                 real && (cols == 2 || cols == 3))
            fr->velocity = column;
        column += (int)cols;
    }
    fr->columns = column;
    if (fr->pos < 0 || fr->radius < 0) {
        snprintf(why, cap, "no %s column in Properties=%s", fr->pos < 0 ? "pos" : "radius", text);
        return -1;
    }
    return 0;
}

/* Lattice="ax ay az bx by bz cx cy cz": a box only when a lies along x
 * and b along y. */
static int lattice(const char *text, rx_frame *fr, char *why, size_t cap)
{
    double v[9];
    const char *p = text;
    for (int k = 0; k < 9; ++k) {
        char *end;
        errno = 0;
        v[k] = strtod(p, &end);
        if (end == p || errno || !isfinite(v[k])) {
            snprintf(why, cap, "Lattice=\"%s\" is not 9 numbers", text);
            return -1;
        }
        p = end;
    }
    if (v[1] != 0.0 || v[3] != 0.0 || !(v[0] > 0.0) || !(v[4] > 0.0)) {
        snprintf(why, cap,
                 "Lattice=\"%s\": only a cell whose first two vectors lie along x and y is drawn",
                 text);
        return -1;
    }
    fr->box_x = v[0];
    fr->box_y = v[4];
    return 0;
}

static int is_true(const char *word)
{
    return !strcasecmp(word, "T") || !strcasecmp(word, "true") || !strcmp(word, "1");
}

/* pbc="T T F": periodic along x and y, along x only, or walls. */
static int pbc(const char *text, rx_frame *fr, char *why, size_t cap)
{
    char a[8] = "", b[8] = "";
    if (sscanf(text, "%7s %7s", a, b) != 2) {
        snprintf(why, cap, "pbc=\"%s\" is not three T or F", text);
        return -1;
    }
    const int x = is_true(a), y = is_true(b);
    if (!x && y) {
        snprintf(why, cap, "pbc=\"%s\": a box periodic along y only is not drawn", text);
        return -1;
    }
    fr->boundary = x && y ? DS_BOUNDARY_PERIODIC : x ? DS_BOUNDARY_CHANNEL : DS_BOUNDARY_WALLS;
    return 0;
}

static int comment_line(const char *line, rx_frame *fr, char *why, size_t cap)
{
    char key[64], value[1024];
    int have_properties = 0, have_pbc = 0;
    for (const char *p = line; next_pair(&p, key, sizeof key, value, sizeof value);) {
        int rc = 0;
        if (!strcasecmp(key, "Properties")) {
            rc = properties(value, fr, why, cap);
            have_properties = 1;
        } else if (!strcasecmp(key, "Lattice")) {
            rc = lattice(value, fr, why, cap);
        } else if (!strcasecmp(key, "pbc")) {
            rc = pbc(value, fr, why, cap);
            have_pbc = 1;
        } else if (!strcasecmp(key, "Time")) {
            char *end;
            fr->time = strtod(value, &end);
            if (end == value || *end || !isfinite(fr->time)) {
                snprintf(why, cap, "Time=%s is not a number", value);
                rc = -1;
            }
        }
        if (rc)
            return -1;
    }
    /* ASE's defaults: species and positions; a cell without pbc= periodic. */
    if (!have_properties && properties("species:S:1:pos:R:3", fr, why, cap))
        return -1;
    if (!have_pbc && fr->box_x > 0.0)
        fr->boundary = DS_BOUNDARY_PERIODIC;
    return 0;
}

/* The count line: a whole number, spaces around it allowed. */
static int count_line(const char *line, size_t *count)
{
    char *end;
    errno = 0;
    const char *s = line + strspn(line, " \t");
    const long long n = isdigit((unsigned char)*s) ? strtoll(s, &end, 10) : -1;
    if (n < 0 || errno || end[strspn(end, " \t\r\n")] != '\0' || n > MAX_DISKS)
        return -1;
    *count = (size_t)n;
    return 0;
}

static int grow(rx_frame **frames, size_t count, size_t *cap)
{
    if (count < *cap)
        return 0;
    size_t ncap = *cap ? 2 * *cap : 64;
    rx_frame *grown = realloc(*frames, ncap * sizeof *grown);
    if (!grown)
        return -1;
    *frames = grown;
    *cap = ncap;
    return 0;
}

/* Long: one pass over the file, a frame at a time: its count line, its
 * comment line and its disks' lines, each failure named by its line. */
int rx_scan(const char *path, rx_frame **frames, size_t *count, char *err, size_t errlen)
{
    *frames = NULL;
    *count = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    char *line = NULL, why[1100] = "";
    size_t linecap = 0, cap = 0;
    long number = 0, offset = 0, at = 0; /* at: the line at fault, 0 for the file */
    ssize_t got;
    while (!why[0] && (got = getline(&line, &linecap, f)) >= 0) {
        rx_frame fr = {offset, ++number, 0, 0.0, 0.0, -1, NAN, 0, -1, -1, -1};
        offset += got;
        if (line[strspn(line, " \t\r\n")] == '\0')
            continue; /* blank lines between or after frames */
        at = number;
        if (memchr(line, '\0', (size_t)got) || count_line(line, &fr.count) != 0) {
            snprintf(why, sizeof why, "expected the number of disks of a frame");
            break;
        }
        if ((got = getline(&line, &linecap, f)) < 0) {
            snprintf(why, sizeof why, "the frame ends before its comment line");
            break;
        }
        offset += got;
        at = ++number;
        if (comment_line(line, &fr, why, sizeof why))
            break;
        for (size_t k = 0; !why[0] && k < fr.count; ++k) {
            if ((got = getline(&line, &linecap, f)) < 0) {
                at = fr.line;
                snprintf(why, sizeof why, "the frame is cut: %zu disk%s announced, %zu line%s",
                         fr.count, fr.count == 1 ? "" : "s", k, k == 1 ? "" : "s");
            }
            offset += got;
            ++number;
        }
        if (!why[0] && grow(frames, *count, &cap) != 0) {
            at = 0;
            snprintf(why, sizeof why, "out of memory");
        }
        if (!why[0])
            (*frames)[(*count)++] = fr;
    }
    if (!why[0] && ferror(f)) {
        at = 0;
        snprintf(why, sizeof why, "read error: %s", strerror(errno));
    } else if (!why[0] && *count == 0) {
        at = 0;
        snprintf(why, sizeof why, "no frame");
    }
    free(line);
    fclose(f);
    if (!why[0])
        return 0;
    if (at)
        snprintf(err, errlen, "%s:%ld: %s", path, at, why);
    else
        snprintf(err, errlen, "%s: %s", path, why);
    free(*frames);
    *frames = NULL;
    *count = 0;
    return -1;
}

/* The numbers of one disk's line into d, by the frame's columns. */
static int disk_line(char *line, const rx_frame *fr, ds_frame_disk *d, char *why, size_t cap)
{
    int column = 0;
    char *save = NULL;
    for (char *w = strtok_r(line, " \t\r\n", &save); w; w = strtok_r(NULL, " \t\r\n", &save)) {
        double *into = column == fr->pos                                 ? &d->x
                       : column == fr->pos + 1                           ? &d->y
                       : column == fr->radius                            ? &d->r
                       : column == fr->velocity                          ? &d->vx
                       : column == fr->velocity + 1 && fr->velocity >= 0 ? &d->vy
                                                                         : NULL;
        if (into) {
            char *end;
            errno = 0;
            *into = strtod(w, &end);
            if (end == w || *end || errno || !isfinite(*into)) {
                snprintf(why, cap, "column %d is not a finite number: '%.40s'", column + 1, w);
                return -1;
            }
        }
        ++column;
    }
    if (column != fr->columns) {
        snprintf(why, cap, "expected %d columns (by Properties=), got %d", fr->columns, column);
        return -1;
    }
    if (!(d->r > 0.0)) {
        snprintf(why, cap, "radius must be positive");
        return -1;
    }
    return 0;
}

int rx_read(const char *path, const rx_frame *fr, ds_frame *frame, char *err, size_t errlen)
{
    frame->disks = NULL;
    frame->count = 0;
    frame->columns = 0;
    FILE *f = fopen(path, "rb");
    if (!f || fseek(f, fr->offset, SEEK_SET) != 0) {
        snprintf(err, errlen, "%s: cannot read: %s", path, strerror(errno));
        if (f)
            fclose(f);
        return -1;
    }
    ds_frame_disk *disks = malloc((fr->count ? fr->count : 1) * sizeof *disks);
    char *line = NULL, why[200] = "";
    size_t linecap = 0;
    long number = fr->line - 1;
    int rc = disks ? 0 : -1;
    if (!disks)
        snprintf(why, sizeof why, "out of memory for %zu disks", fr->count);
    /* The count and comment lines, then a line per disk. */
    for (size_t k = 0; rc == 0 && k < fr->count + 2; ++k) {
        ++number;
        if (getline(&line, &linecap, f) < 0) {
            snprintf(why, sizeof why, "the file changed since it was scanned");
            rc = -1;
        } else if (k >= 2) {
            ds_frame_disk *d = &disks[k - 2];
            *d = (ds_frame_disk){0.0, 0.0, 0.0, 0.0, 0.0};
            rc = disk_line(line, fr, d, why, sizeof why);
        }
    }
    free(line);
    fclose(f);
    if (rc != 0) {
        snprintf(err, errlen, "%s:%ld: %s", path, number, why);
        free(disks);
        return -1;
    }
    frame->disks = disks;
    frame->count = fr->count;
    frame->columns = fr->velocity >= 0 ? 5 : 3;
    return 0;
}
