/* SPDX-License-Identifier: MIT */
/* The disks' state, structure of arrays, from one table of columns: the
 * one owner of the per-disk data and of every operation that moves or
 * permutes it.
 *
 * Slot k of every column is one disk. The integrators keep the slots in
 * the order their loops read (x order for the sweep, strip then x for the
 * strips, cell order for the event-driven integrator), so a disk's slot
 * changes and id[k] says which disk (its generation index) slot k holds;
 * slot[i] is the inverse, rebuilt after the slots move. Every column has
 * one element past n, the sentinel: x[n] = +infinity ends every sweep
 * window.
 *
 * DS_DISK_COLUMNS is the table: a row per column with its name, C type,
 * whether every simulation has it (1) or only some (0: the pointer is
 * NULL where it is absent, and a hot loop that has asked once takes the
 * plain path), the value a new element starts with, the sentinel's, and
 * how a checkpoint writes it. The struct, the record that moves a disk
 * between slots, allocation, copy, swap, permutation and the checkpoint's
 * disk loop are generated from it: adding a per-disk array is one row
 * here plus whoever fills and reads it. An integrator that keeps records
 * of its own (the event-driven ed_disk) copies from the columns when it is
 * created and back when it shows the disks, and says which. Not
 * installed. */
#ifndef DS_DISK_ARRAYS_H
#define DS_DISK_ARRAYS_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "core/state_io.h"
#include "disk_sim.h"

/*  name  type      every  new         sentinel    codec */
#define DS_DISK_COLUMNS(X)                                                                        \
    X(x, double, 1, 0.0, INFINITY, f64)     /* centre (sentinel: past every sweep window) */     \
    X(y, double, 1, 0.0, INFINITY, f64)                                                          \
    X(vx, double, 1, 0.0, 0.0, f64)         /* velocity */                                       \
    X(vy, double, 1, 0.0, 0.0, f64)                                                              \
    X(id, uint32_t, 1, 0u, UINT32_MAX, u32) /* generation index of the disk in the slot */       \
    X(r, double, 0, 0.0, 0.0, f64)          /* a mixture's radius (else the world's) */          \
    X(m, double, 0, 1.0, 1.0, f64)          /* a mixture's mass (else 1) */                      \
    X(ix, int32_t, 0, 0, 0, i32)            /* periodic images crossed along x */                \
    X(iy, int32_t, 0, 0, 0, i32)            /* ... and along y (both or neither) */              \
    X(kind, uint32_t, 0, 0u, 0u, u32)       /* a mixture's species index */                      \
    X(last_hit, double, 0, -INFINITY, -INFINITY, f64) /* its last collision's time (the TC   */   \
                                                      /* model's, event-driven time)         */

typedef enum ds_column {
#define DS_COLUMN_ENUM(name, type, every, fresh, sentinel, codec) DS_COLUMN_##name,
    DS_DISK_COLUMNS(DS_COLUMN_ENUM)
#undef DS_COLUMN_ENUM
        DS_COLUMN_COUNT
} ds_column;

typedef struct ds_disks {
    size_t n;
#define DS_COLUMN_MEMBER(name, type, every, fresh, sentinel, codec) type *name;
    DS_DISK_COLUMNS(DS_COLUMN_MEMBER)
#undef DS_COLUMN_MEMBER
    uint32_t *slot; /* the slot of disk i: the inverse of id, never saved */
} ds_disks;

/* One disk with everything that moves with it between slots. */
typedef struct ds_disk_record {
#define DS_COLUMN_FIELD(name, type, every, fresh, sentinel, codec) type name;
    DS_DISK_COLUMNS(DS_COLUMN_FIELD)
#undef DS_COLUMN_FIELD
} ds_disk_record;

/* Bytes per disk of the columns every simulation has, of all of them, of
 * the slot index, of a mixture's columns and of the image counts (memory
 * estimates). */
#define DS_COLUMN_SIZE(name, type, every, fresh, sentinel, codec) +sizeof(type)
#define DS_COLUMN_EVERY_SIZE(name, type, every, fresh, sentinel, codec) +(every) * sizeof(type)
#define DS_DISKS_MOVING_BYTES (0 DS_DISK_COLUMNS(DS_COLUMN_EVERY_SIZE))
#define DS_DISKS_ALL_BYTES (0 DS_DISK_COLUMNS(DS_COLUMN_SIZE) + sizeof(uint32_t))
#define DS_DISKS_BYTES_PER_DISK (DS_DISKS_MOVING_BYTES + sizeof(uint32_t))
#define DS_DISKS_MIXTURE_BYTES (sizeof(double) + sizeof(double) + sizeof(uint32_t))
#define DS_DISKS_IMAGE_BYTES (2 * sizeof(int32_t))

/* Columns for n disks (+ 1: the sentinel slot n), the ones every
 * simulation has: the slots in generation order (id[k] = k, slot[i] = i),
 * positions and velocities zero. DS_ERR_NOMEM leaves nothing allocated. */
ds_status ds_disks_alloc(ds_disks *d, size_t n);
/* Adds optional column c (a no-op where it is there), every element at
 * the table's new value: DS_ERR_NOMEM changes nothing. */
ds_status ds_disks_add(ds_disks *d, ds_column c);
/* The optional columns of a mixture (radii, masses: either 0 for none)
 * and of a periodic box (both image counts): ds_disks_add of each. */
ds_status ds_disks_add_mixture(ds_disks *d, int radii, int masses);
ds_status ds_disks_add_images(ds_disks *d);
/* Whether column c is there. */
int ds_disks_has(const ds_disks *d, ds_column c);
/* A bit per column that is there (bit c for column c). */
uint32_t ds_disks_columns(const ds_disks *d);
/* A second set of the columns `like` has (no slot[]), for a broad phase
 * that rebuilds the order into it and swaps (the strips), or a state
 * built beside the old one (ds_rebuild). */
ds_status ds_disks_alloc_like(ds_disks *d, const ds_disks *like);
/* A whole copy of src (every column and slot[]): the disks of a state to
 * build beside src's. */
ds_status ds_disks_clone(ds_disks *d, const ds_disks *src);
/* The same with the slots in generation order (slot k holds disk k): the
 * columns of a new state, which its integrator sorts as it needs. */
ds_status ds_disks_clone_ordered(ds_disks *d, const ds_disks *src);
void ds_disks_free(ds_disks *d); /* NULL pointers are allowed */

/* Exchanges the columns of a and b (not slot[]). */
void ds_disks_swap(ds_disks *a, ds_disks *b);

/* Moves the disks so that new slot k holds what slot order[k] held
 * (order a permutation of 0..n-1); slot[] is rebuilt. */
ds_status ds_disks_permute(ds_disks *d, const uint32_t *order);

/* slot[] from id[], after the slots moved. */
void ds_disks_rebuild_slots(ds_disks *d);

/* A checkpoint's disks: slot by slot, each column that is there in the
 * table's order, by its codec (ds_disks_columns says which, and load reads
 * into the columns d has). Load returns 0 if the bytes ran out. */
void ds_disks_save(const ds_disks *d, ds_state_writer *w);
int ds_disks_load_all(ds_disks *d, ds_reader *r);

/* The kinetic tensor sum m v_a v_b over the disks: k[0] xx, k[1] yy,
 * k[2] xy (m = 1 without masses). */
void ds_disks_kinetic_tensor(const ds_disks *d, double k[3]);
/* The momentum sum m v and the total mass (m = 1 without masses). */
void ds_disks_momentum(const ds_disks *d, double p[2], double *mass);

/* An optional column's presence does not change during a run, so the
 * branches on it are always predicted. */
static inline ds_disk_record ds_disks_load(const ds_disks *d, size_t k)
{
    ds_disk_record r;
#define DS_COLUMN_LOAD(name, type, every, fresh, sentinel, codec)                                 \
    r.name = (every) || d->name ? d->name[k] : (type)(fresh);
    DS_DISK_COLUMNS(DS_COLUMN_LOAD)
#undef DS_COLUMN_LOAD
    return r;
}

static inline void ds_disks_store(ds_disks *d, size_t k, ds_disk_record r)
{
#define DS_COLUMN_STORE(name, type, every, fresh, sentinel, codec)                                \
    if ((every) || d->name)                                                                       \
        d->name[k] = r.name;
    DS_DISK_COLUMNS(DS_COLUMN_STORE)
#undef DS_COLUMN_STORE
}

/* Slot `from` of src into slot `to` of dst (the same set or another, with
 * the same columns). */
static inline void ds_disks_copy(ds_disks *dst, size_t to, const ds_disks *src, size_t from)
{
#define DS_COLUMN_COPY(name, type, every, fresh, sentinel, codec)                                 \
    if ((every) || src->name)                                                                     \
        dst->name[to] = src->name[from];
    DS_DISK_COLUMNS(DS_COLUMN_COPY)
#undef DS_COLUMN_COPY
}

/* ds_disks_copy for columns known to hold none of the optional ones: for
 * a loop that has asked once (ds_disks_columns). */
static inline void ds_disks_copy_motion(ds_disks *dst, size_t to, const ds_disks *src,
                                        size_t from)
{
#define DS_COLUMN_COPY_EVERY(name, type, every, fresh, sentinel, codec)                           \
    if (every)                                                                                    \
        dst->name[to] = src->name[from];
    DS_DISK_COLUMNS(DS_COLUMN_COPY_EVERY)
#undef DS_COLUMN_COPY_EVERY
}

/* The columns every simulation has, as a bit set: the columns of a plain
 * simulation (ds_disks_columns equal to it: no optional column). */
#define DS_COLUMN_EVERY_BIT(name, type, every, fresh, sentinel, codec)                            \
    | ((every) ? 1u << DS_COLUMN_##name : 0u)
#define DS_DISKS_EVERY_COLUMN (0u DS_DISK_COLUMNS(DS_COLUMN_EVERY_BIT))

#endif
