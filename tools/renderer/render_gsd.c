/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "render_gsd.h"

#define GSD_MAGIC 0x65DF65DF65DF65DFull
#define HEADER_BYTES 256
#define ENTRY_BYTES 32
#define NAME_BLOCK 64 /* the name list is counted in blocks of 64 bytes */

/* The chunks the renderer reads, by their HOOMD names. */
enum { BOX, N, POSITION, DIAMETER, VELOCITY, TIME, WANTED };
static const char *const wanted[WANTED] = {"configuration/box",  "particles/N",
                                           "particles/position", "particles/diameter",
                                           "particles/velocity", "log/disksim/time"};

/* The GSD element types (gsd_type: 1 to 4 unsigned integers of 1 to 8
 * bytes, 5 to 8 signed ones, 9 float, 10 double, 11 a character) and
 * their sizes; 0: not a type. */
enum { GSD_INT8 = 5, GSD_INT64 = 8, GSD_FLOAT = 9, GSD_DOUBLE = 10 };
static uint64_t type_bytes(uint8_t type)
{
    static const uint8_t bytes[] = {0, 1, 2, 4, 8, 1, 2, 4, 8, 4, 8, 1};
    return type < sizeof bytes ? bytes[type] : 0;
}

int rg_is_gsd(const char *path)
{
    const size_t n = strlen(path);
    return n > 4 && strcasecmp(path + n - 4, ".gsd") == 0;
}

typedef struct scan {
    FILE *f;
    uint64_t size;  /* the file's bytes */
    int id[WANTED]; /* each wanted chunk's id in the name list; -1: absent */
    char why[300];
} scan;

static uint64_t le(const uint8_t *p, int bytes)
{
    uint64_t v = 0;
    for (int k = 0; k < bytes; ++k)
        v |= (uint64_t)p[k] << (8 * k);
    return v;
}

/* len bytes at byte at: 0 if they are not all there. */
static int get_at(FILE *f, uint64_t at, void *buf, size_t len)
{
    return at <= (uint64_t)LONG_MAX && fseek(f, (long)at, SEEK_SET) == 0 &&
           fread(buf, 1, len, f) == len;
}

/* The bytes of a chunk: 0 when rows x cols x its type's size overflow or
 * reach past size from its location. */
static uint64_t chunk_bytes(const rg_chunk *c, uint64_t size)
{
    const uint64_t each = type_bytes(c->type);
    if (!each || c->location > size || (c->cols && c->rows > UINT64_MAX / c->cols / each))
        return 0;
    const uint64_t bytes = c->rows * c->cols * each;
    return bytes <= size - c->location ? bytes : 0;
}

/* The header, then the ids of the wanted names in the name list. */
static int names(scan *s, uint64_t *index_at, uint64_t *index_cap)
{
    uint8_t h[HEADER_BYTES];
    if (s->size < HEADER_BYTES || !get_at(s->f, 0, h, sizeof h)) {
        snprintf(s->why, sizeof s->why, "%llu bytes, shorter than a GSD header (256): truncated",
                 (unsigned long long)s->size);
        return -1;
    }
    const uint32_t version = (uint32_t)le(h + 44, 4);
    if (le(h, 8) != GSD_MAGIC)
        snprintf(s->why, sizeof s->why,
                 "not a GSD file: it does not begin with the GSD magic number");
    else if (version >> 16 != 2)
        snprintf(s->why, sizeof s->why, "GSD file layer %u.%u: this reader reads 2.x",
                 version >> 16, version & 0xffffu);
    else if (memcmp(h + 112, "hoomd", 6) != 0)
        snprintf(s->why, sizeof s->why, "its schema is '%.63s', not hoomd", (const char *)h + 112);
    if (s->why[0])
        return -1;
    *index_at = le(h + 8, 8);
    *index_cap = le(h + 16, 8);
    const uint64_t at = le(h + 24, 8), blocks = le(h + 32, 8);
    if (at > s->size || blocks > (s->size - at) / NAME_BLOCK || *index_at > s->size ||
        *index_cap > (s->size - *index_at) / ENTRY_BYTES) {
        snprintf(s->why, sizeof s->why,
                 "its header places the name list or the index past its end (%llu bytes): "
                 "truncated",
                 (unsigned long long)s->size);
        return -1;
    }
    char *list = malloc(blocks * NAME_BLOCK + 1);
    if (!list || !get_at(s->f, at, list, blocks * NAME_BLOCK)) {
        snprintf(s->why, sizeof s->why, list ? "cannot read its name list" : "out of memory");
        free(list);
        return -1;
    }
    list[blocks * NAME_BLOCK] = '\0';
    /* NUL-ended names one after another, an empty one ending the list. */
    int id = 0;
    for (const char *p = list; p < list + blocks * NAME_BLOCK && *p; p += strlen(p) + 1, ++id)
        for (int w = 0; w < WANTED; ++w)
            if (strcmp(p, wanted[w]) == 0)
                s->id[w] = id;
    free(list);
    return 0;
}

/* One more frame of WANTED empty chunks at the end of *chunks. */
static int add_frame(rg_chunk **chunks, size_t *count, size_t *cap)
{
    if (*count == *cap) {
        const size_t ncap = *cap ? 2 * *cap : 64;
        rg_chunk *grown = realloc(*chunks, ncap * WANTED * sizeof *grown);
        if (!grown)
            return -1;
        *chunks = grown;
        *cap = ncap;
    }
    memset(*chunks + *count * WANTED, 0, WANTED * sizeof **chunks);
    ++*count;
    return 0;
}

/* Every index entry up to the first unused one (location 0), each of
 * the wanted chunks kept in its frame's slot in chunks (WANTED a frame). */
static int read_index(scan *s, uint64_t at, uint64_t cap, rg_chunk **chunks, size_t *count)
{
    size_t frames_cap = 0;
    *count = 0;
    uint8_t e[ENTRY_BYTES];
    for (uint64_t k = 0; k < cap; ++k) {
        if (!get_at(s->f, at + k * ENTRY_BYTES, e, sizeof e)) {
            snprintf(s->why, sizeof s->why, "cannot read its index");
            return -1;
        }
        const rg_chunk c = {le(e + 16, 8), le(e + 8, 8), (uint32_t)le(e + 24, 4), e[30]};
        const uint64_t frame = le(e, 8);
        const int id = (int)le(e + 28, 2);
        if (c.location == 0)
            break;
        if (frame + 1 < *count || frame > *count) {
            snprintf(s->why, sizeof s->why, "index entry %llu is of frame %llu after frame %zu",
                     (unsigned long long)k, (unsigned long long)frame, *count ? *count - 1 : 0);
            return -1;
        }
        if (!type_bytes(c.type) || (!chunk_bytes(&c, s->size) && c.rows * c.cols != 0)) {
            if (type_bytes(c.type))
                snprintf(s->why, sizeof s->why,
                         "frame %llu: index entry %llu reaches past the end of the file (%llu "
                         "bytes): truncated",
                         (unsigned long long)frame, (unsigned long long)k,
                         (unsigned long long)s->size);
            else
                snprintf(s->why, sizeof s->why, "index entry %llu has type %u, not one of GSD's",
                         (unsigned long long)k, c.type);
            return -1;
        }
        if (frame == *count && add_frame(chunks, count, &frames_cap) != 0) {
            snprintf(s->why, sizeof s->why, "out of memory for its index");
            return -1;
        }
        for (int w = 0; w < WANTED; ++w)
            if (id == s->id[w])
                (*chunks)[frame * WANTED + (uint64_t)w] = c;
    }
    if (*count == 0)
        snprintf(s->why, sizeof s->why, "no frame");
    return *count ? 0 : -1;
}

/* Element k of a chunk's bytes b as a double: GSD's integers, float and
 * double, little-endian. */
static double element(const uint8_t *b, uint8_t type, uint64_t k)
{
    const int each = (int)type_bytes(type);
    const uint64_t u = le(b + k * (uint64_t)each, each);
    if (type == GSD_FLOAT) {
        const uint32_t bits = (uint32_t)u;
        float f;
        memcpy(&f, &bits, sizeof f);
        return f;
    }
    if (type == GSD_DOUBLE) {
        double d;
        memcpy(&d, &u, sizeof d);
        return d;
    }
    const int is_signed = type >= GSD_INT8 && type <= GSD_INT64;
    if (is_signed && each < 8 && (u >> (8 * each - 1)) != 0)
        return (double)(int64_t)(u | ~((UINT64_C(1) << (8 * each)) - 1)); /* negative */
    return is_signed ? (double)(int64_t)u : (double)u;
}

/* A small chunk's count elements (at most 8) into v. */
static int small(scan *s, const rg_chunk *c, double *v, uint64_t count)
{
    uint8_t b[64];
    if (!get_at(s->f, c->location, b, (size_t)(count * type_bytes(c->type))))
        return -1;
    for (uint64_t k = 0; k < count; ++k)
        v[k] = element(b, c->type, k);
    return 0;
}

static int is_real(uint8_t type) { return type == GSD_FLOAT || type == GSD_DOUBLE; }

/* A per-disk chunk: count rows of cols reals, or absent. */
static int fits(scan *s, size_t i, const rg_chunk *c, int w, size_t count, uint32_t cols)
{
    if (!c->location || (c->rows == count && c->cols == cols && is_real(c->type)))
        return 0;
    if (c->rows != count)
        snprintf(s->why, sizeof s->why, "frame %zu: %s has %llu rows, but particles/N is %zu", i,
                 wanted[w], (unsigned long long)c->rows, count);
    else
        snprintf(s->why, sizeof s->why,
                 "frame %zu: %s is %llu x %u of GSD type %u: want N x %u floats", i, wanted[w],
                 (unsigned long long)c->rows, c->cols, c->type, cols);
    return -1;
}

/* The sides of configuration/box (HOOMD's default a unit box), refused
 * unless upright with positive sides. */
static int box_of(scan *s, size_t i, const rg_chunk *c, rg_frame *fr)
{
    double box[6] = {1, 1, 1, 0, 0, 0};
    if (c->location && (c->rows * c->cols != 6 || !is_real(c->type) || small(s, c, box, 6))) {
        snprintf(s->why, sizeof s->why, "frame %zu: configuration/box is not 6 reals", i);
        return -1;
    }
    if (!(box[0] > 0.0 && box[0] < INFINITY && box[1] > 0.0 && box[1] < INFINITY) ||
        box[3] != 0.0) {
        snprintf(s->why, sizeof s->why,
                 "frame %zu: configuration/box Lx = %g, Ly = %g, xy = %g: only an upright box "
                 "with positive sides is drawn",
                 i, box[0], box[1], box[3]);
        return -1;
    }
    fr->box_x = box[0];
    fr->box_y = box[1];
    return 0;
}

/* Frame i from its own chunks, the ones it leaves out taken from frame
 * 0's (all but the time, which is each frame's own). */
static int frame_of(scan *s, const rg_chunk *all, size_t i, rg_frame *fr)
{
    rg_chunk c[WANTED];
    for (int w = 0; w < WANTED; ++w)
        c[w] = all[i * WANTED + (size_t)w].location || w == TIME ? all[i * WANTED + (size_t)w]
                                                                 : all[w];
    double n = 0.0, time = NAN; /* the schema's N without a chunk is 0 */
    if (c[N].location && (c[N].rows * c[N].cols != 1 || is_real(c[N].type) ||
                          small(s, &c[N], &n, 1) || !(n >= 0.0 && n <= 1e9))) {
        snprintf(s->why, sizeof s->why, "frame %zu: particles/N is not one count", i);
        return -1;
    }
    if (c[TIME].location && (c[TIME].rows * c[TIME].cols != 1 || !is_real(c[TIME].type) ||
                             small(s, &c[TIME], &time, 1))) {
        snprintf(s->why, sizeof s->why, "frame %zu: log/disksim/time is not one real", i);
        return -1;
    }
    fr->count = (size_t)n;
    fr->time = isfinite(time) ? time : NAN;
    fr->position = c[POSITION];
    fr->diameter = c[DIAMETER];
    fr->velocity = c[VELOCITY];
    if (!c[POSITION].location && fr->count > 0) {
        snprintf(s->why, sizeof s->why, "frame %zu: no particles/position chunk%s", i,
                 i ? ", nor in frame 0" : "");
        return -1;
    }
    if (box_of(s, i, &c[BOX], fr) || fits(s, i, &c[POSITION], POSITION, fr->count, 3) ||
        fits(s, i, &c[DIAMETER], DIAMETER, fr->count, 1) ||
        fits(s, i, &c[VELOCITY], VELOCITY, fr->count, 3))
        return -1;
    return 0;
}

int rg_scan(const char *path, rg_frame **frames, size_t *count, char *err, size_t errlen)
{
    *frames = NULL;
    *count = 0;
    scan s = {fopen(path, "rb"), 0, {-1, -1, -1, -1, -1, -1}, ""};
    if (!s.f) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    const long size = fseek(s.f, 0, SEEK_END) == 0 ? ftell(s.f) : -1;
    uint64_t index_at = 0, index_cap = 0;
    rg_chunk *chunks = NULL;
    size_t n = 0;
    s.size = size > 0 ? (uint64_t)size : 0;
    int rc = size < 0 ? -1 : names(&s, &index_at, &index_cap);
    if (size < 0)
        snprintf(s.why, sizeof s.why, "cannot read: %s", strerror(errno));
    if (rc == 0)
        rc = read_index(&s, index_at, index_cap, &chunks, &n);
    rg_frame *fr = rc == 0 ? calloc(n, sizeof *fr) : NULL;
    if (rc == 0 && !fr) {
        snprintf(s.why, sizeof s.why, "out of memory for %zu frames", n);
        rc = -1;
    }
    for (size_t i = 0; rc == 0 && i < n; ++i)
        rc = frame_of(&s, chunks, i, &fr[i]);
    fclose(s.f);
    free(chunks);
    if (rc != 0) {
        snprintf(err, errlen, "%s: %s", path, s.why);
        free(fr);
        return -1;
    }
    *frames = fr;
    *count = n;
    return 0;
}

/* A chunk's bytes, malloc'd; NULL for none (or on failure, *failed). */
static uint8_t *chunk_data(FILE *f, const rg_chunk *c, size_t count, int *failed)
{
    if (!c->location || count == 0)
        return NULL;
    const size_t bytes = (size_t)(c->rows * c->cols * type_bytes(c->type));
    uint8_t *b = malloc(bytes);
    if (!b || !get_at(f, c->location, b, bytes)) {
        free(b);
        *failed = 1;
        return NULL;
    }
    return b;
}

/* Disk k of the chunks' bytes, its centre moved from HOOMD's box about
 * the origin to disksim's [0, L): in double, as the writer took it off.
 * NULL, or what is wrong with it. */
static const char *disk_of(const rg_frame *fr, const uint8_t *pos, const uint8_t *dia,
                           const uint8_t *vel, size_t k, ds_frame_disk *d)
{
    d->x = element(pos, fr->position.type, 3 * (uint64_t)k) + 0.5 * fr->box_x;
    d->y = element(pos, fr->position.type, 3 * (uint64_t)k + 1) + 0.5 * fr->box_y;
    d->r = dia ? 0.5 * element(dia, fr->diameter.type, k) : 0.5; /* HOOMD's diameter: 1 */
    d->vx = vel ? element(vel, fr->velocity.type, 3 * (uint64_t)k) : 0.0;
    d->vy = vel ? element(vel, fr->velocity.type, 3 * (uint64_t)k + 1) : 0.0;
    if (!(d->r > 0.0 && d->r < INFINITY))
        return "its diameter is not a positive number";
    if (!isfinite(d->x) || !isfinite(d->y) || !isfinite(d->vx) || !isfinite(d->vy))
        return "its position or velocity is not finite";
    return NULL;
}

int rg_read(const char *path, const rg_frame *fr, size_t number, ds_frame *frame, char *err,
            size_t errlen)
{
    frame->disks = NULL;
    frame->count = 0;
    frame->columns = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot read: %s", path, strerror(errno));
        return -1;
    }
    int failed = 0;
    uint8_t *pos = chunk_data(f, &fr->position, fr->count, &failed);
    uint8_t *dia = chunk_data(f, &fr->diameter, fr->count, &failed);
    uint8_t *vel = chunk_data(f, &fr->velocity, fr->count, &failed);
    fclose(f);
    ds_frame_disk *disks = failed ? NULL : malloc((fr->count ? fr->count : 1) * sizeof *disks);
    size_t bad = fr->count;
    const char *why = NULL;
    for (size_t k = 0; disks && k < fr->count && !why; ++k)
        if ((why = disk_of(fr, pos, dia, vel, k, &disks[k])) != NULL)
            bad = k;
    free(pos);
    free(dia);
    free(vel);
    if (!disks || bad < fr->count) {
        if (failed)
            snprintf(err, errlen,
                     "%s: frame %zu: cannot read its chunks: the file changed since it was scanned",
                     path, number);
        else if (!disks)
            snprintf(err, errlen, "%s: frame %zu: out of memory for %zu disks", path, number,
                     fr->count);
        else
            snprintf(err, errlen, "%s: frame %zu: particle %zu: %s", path, number, bad, why);
        free(disks);
        return -1;
    }
    frame->disks = disks;
    frame->count = fr->count;
    frame->columns = fr->velocity.location ? 5 : 3;
    return 0;
}
