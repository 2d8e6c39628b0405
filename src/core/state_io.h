/* SPDX-License-Identifier: MIT */
/* The bytes of a saved state (sim/state.c writes the frame of the file,
 * each integrator its own part): little-endian integers and IEEE doubles
 * by their bits, whatever the machine, so a file moves between machines
 * and a value reads back to the bit. A writer counts when it has no
 * buffer (the size of a state, before writing it); a reader never reads
 * past its end, and once out of bytes keeps failing, so a caller checks
 * once at the end. Not installed. */
#ifndef DS_STATE_IO_H
#define DS_STATE_IO_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "disk_sim.h"

typedef struct ds_state_writer {
    uint8_t *buf; /* NULL: only count */
    size_t len;   /* bytes written (or counted) so far */
} ds_state_writer;

static inline void ds_put_u64(ds_state_writer *w, uint64_t v)
{
    if (w->buf)
        for (int k = 0; k < 8; ++k)
            w->buf[w->len + (size_t)k] = (uint8_t)(v >> (8 * k));
    w->len += 8;
}

static inline void ds_put_u32(ds_state_writer *w, uint32_t v)
{
    if (w->buf)
        for (int k = 0; k < 4; ++k)
            w->buf[w->len + (size_t)k] = (uint8_t)(v >> (8 * k));
    w->len += 4;
}

static inline void ds_put_i32(ds_state_writer *w, int32_t v) { ds_put_u32(w, (uint32_t)v); }

static inline void ds_put_f64(ds_state_writer *w, double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    ds_put_u64(w, bits);
}

typedef struct ds_reader {
    const uint8_t *at, *end;
    int failed; /* ran out of bytes */
} ds_reader;

static inline const uint8_t *ds_take(ds_reader *r, size_t bytes)
{
    if (r->failed || (size_t)(r->end - r->at) < bytes) {
        r->failed = 1;
        return NULL;
    }
    const uint8_t *p = r->at;
    r->at += bytes;
    return p;
}

static inline uint64_t ds_get_u64(ds_reader *r)
{
    const uint8_t *p = ds_take(r, 8);
    uint64_t v = 0;
    for (int k = 0; p && k < 8; ++k)
        v |= (uint64_t)p[k] << (8 * k);
    return v;
}

static inline uint32_t ds_get_u32(ds_reader *r)
{
    const uint8_t *p = ds_take(r, 4);
    uint32_t v = 0;
    for (int k = 0; p && k < 4; ++k)
        v |= (uint32_t)p[k] << (8 * k);
    return v;
}

/* Any 32 bits are a count (image counts wrap past 2^31). */
static inline int32_t ds_get_i32(ds_reader *r) { return (int32_t)ds_get_u32(r); }

static inline double ds_get_f64(ds_reader *r)
{
    const uint64_t bits = ds_get_u64(r);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* A broad phase as saved states number it: 2.x's numbers (0 SAP, 1
 * brute force, 2 strips, 3 auto, 4 cells), which the format keeps
 * whatever the order of the public enumeration. */
static inline uint32_t ds_broadphase_code(ds_broadphase bp)
{
    switch (bp) {
    case DS_BROADPHASE_SAP:
        return 0;
    case DS_BROADPHASE_BRUTE:
        return 1;
    case DS_BROADPHASE_STRIPS:
        return 2;
    case DS_BROADPHASE_AUTO:
        return 3;
    case DS_BROADPHASE_CELLS:
        return 4;
    case DS_BROADPHASE_COUNT:
        break;
    }
    return UINT32_MAX;
}

/* The broad phase saved as code, or DS_BROADPHASE_COUNT for none. */
static inline ds_broadphase ds_broadphase_of_code(uint32_t code)
{
    for (int bp = 0; bp < DS_BROADPHASE_COUNT; ++bp)
        if (ds_broadphase_code((ds_broadphase)bp) == code)
            return (ds_broadphase)bp;
    return DS_BROADPHASE_COUNT;
}

/* Bytes left to read. */
static inline size_t ds_left(const ds_reader *r)
{
    return r->failed ? 0 : (size_t)(r->end - r->at);
}

#endif
