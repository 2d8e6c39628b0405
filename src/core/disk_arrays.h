/* SPDX-License-Identifier: MIT */
/* The disks' state, structure of arrays: the one owner of the per-disk
 * data and of every operation that moves or permutes it.
 *
 * Slot k of every array is one disk. The broad phases keep the slots in
 * the order their sweeps read (x order for DS_SAP, strip then x for
 * DS_SAP_STRIPS, cell order for the event-driven integrator), so a disk's
 * slot changes and id[k] says which disk (its generation index) slot k
 * holds; slot[i] is the inverse, rebuilt after the slots move. Every
 * array has one element past n: DS_SAP keeps x[n] = +infinity there as a
 * sweep sentinel.
 *
 * Adding a per-disk array (a radius, a mass, image counters) is one edit
 * here: the field in ds_disks and ds_disk_record, its line in load, store
 * and copy, and its allocation in disk_arrays.c. Every sort, merge and
 * permutation moves disks through these functions, so they all carry it.
 * An integrator that keeps its own records (the event-driven ed_disk)
 * copies from the arrays when it is created and back when it shows the
 * disks (event/event_driven.c says where). Not installed. */
#ifndef DS_DISK_ARRAYS_H
#define DS_DISK_ARRAYS_H

#include <stddef.h>
#include <stdint.h>

#include "disk_sim.h"

typedef struct ds_disks {
    size_t n;
    double *x, *y, *vx, *vy;
    uint32_t *id;   /* the generation index of the disk in each slot */
    uint32_t *slot; /* the slot of disk i: the inverse of id */
} ds_disks;

/* One disk with everything that moves with it between slots. */
typedef struct ds_disk_record {
    double x, y, vx, vy;
    uint32_t id;
} ds_disk_record;

/* Memory per disk: the arrays that move (a spare set, see
 * ds_disks_alloc_spare) and the slot index. */
#define DS_DISKS_MOVING_BYTES (4 * sizeof(double) + sizeof(uint32_t))
#define DS_DISKS_BYTES_PER_DISK (DS_DISKS_MOVING_BYTES + sizeof(uint32_t))

/* Arrays for n disks (+ 1: the sentinel slot n, x = y = +infinity), the
 * slots in generation order (id[k] = k, slot[i] = i), positions and
 * velocities zero. DS_ERR_NOMEM leaves nothing allocated. */
ds_status ds_disks_alloc(ds_disks *d, size_t n);
/* A second set of the moving arrays (no slot[]), for a broad phase that
 * rebuilds the order into it and swaps (DS_SAP_STRIPS). */
ds_status ds_disks_alloc_spare(ds_disks *d, size_t n);
void ds_disks_free(ds_disks *d); /* NULL pointers are allowed */

/* Exchanges the moving arrays of a and b (not slot[]). */
void ds_disks_swap(ds_disks *a, ds_disks *b);

/* Moves the disks so that new slot k holds what slot order[k] held
 * (order a permutation of 0..n-1); slot[] is rebuilt. */
ds_status ds_disks_permute(ds_disks *d, const uint32_t *order);

/* slot[] from id[], after the slots moved. */
void ds_disks_rebuild_slots(ds_disks *d);

static inline ds_disk_record ds_disks_load(const ds_disks *d, size_t k)
{
    ds_disk_record r;
    r.x = d->x[k];
    r.y = d->y[k];
    r.vx = d->vx[k];
    r.vy = d->vy[k];
    r.id = d->id[k];
    return r;
}

static inline void ds_disks_store(ds_disks *d, size_t k, ds_disk_record r)
{
    d->x[k] = r.x;
    d->y[k] = r.y;
    d->vx[k] = r.vx;
    d->vy[k] = r.vy;
    d->id[k] = r.id;
}

/* Slot `from` of src into slot `to` of dst (the same set or another). */
static inline void ds_disks_copy(ds_disks *dst, size_t to, const ds_disks *src, size_t from)
{
    dst->x[to] = src->x[from];
    dst->y[to] = src->y[from];
    dst->vx[to] = src->vx[from];
    dst->vy[to] = src->vy[from];
    dst->id[to] = src->id[from];
}

#endif
