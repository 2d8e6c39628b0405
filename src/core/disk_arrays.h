/* SPDX-License-Identifier: MIT */
/* The disks' state, structure of arrays: the one owner of the per-disk
 * data and of every operation that moves or permutes it.
 *
 * Slot k of every array is one disk. The broad phases keep the slots in
 * the order their sweeps read (x order for DS_BROADPHASE_SAP, strip then x for
 * DS_BROADPHASE_STRIPS, cell order for the event-driven integrator), so a disk's
 * slot changes and id[k] says which disk (its generation index) slot k
 * holds; slot[i] is the inverse, rebuilt after the slots move. Every
 * array has one element past n: DS_BROADPHASE_SAP keeps x[n] = +infinity there as a
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
    /* A mixture's radii and masses (ds_disks_add_mixture); NULL when every
     * disk has the world's radius (r) or mass 1 (m): then the hot loops
     * take the one radius, and the arrays cost nothing. */
    double *r, *m;
    /* A periodic box's image counters: how many times each disk has
     * crossed the box along x and along y (+1 out at the far edge, -1 out
     * at 0), so that its unwrapped centre is x + ix box (ds_disks_add_images);
     * NULL with walls. They wrap past 2^31 crossings. */
    int32_t *ix, *iy;
    uint32_t *id;   /* the generation index of the disk in each slot */
    uint32_t *slot; /* the slot of disk i: the inverse of id */
} ds_disks;

/* One disk with everything that moves with it between slots. */
typedef struct ds_disk_record {
    double x, y, vx, vy, r, m;
    int32_t ix, iy;
    uint32_t id;
} ds_disk_record;

/* Memory per disk: the arrays that move (a spare set, see
 * ds_disks_alloc_spare) and the slot index; a mixture's radius and mass. */
#define DS_DISKS_MOVING_BYTES (4 * sizeof(double) + sizeof(uint32_t))
#define DS_DISKS_BYTES_PER_DISK (DS_DISKS_MOVING_BYTES + sizeof(uint32_t))
#define DS_DISKS_MIXTURE_BYTES (2 * sizeof(double))
#define DS_DISKS_IMAGE_BYTES (2 * sizeof(int32_t))

/* Arrays for n disks (+ 1: the sentinel slot n, x = y = +infinity), the
 * slots in generation order (id[k] = k, slot[i] = i), positions and
 * velocities zero. DS_ERR_NOMEM leaves nothing allocated. */
ds_status ds_disks_alloc(ds_disks *d, size_t n);
/* The radius and mass arrays of a mixture (radii, masses: either NULL
 * for none), sentinel slot included. */
ds_status ds_disks_add_mixture(ds_disks *d, int radii, int masses);
/* The image counters of a periodic box, zero, sentinel slot included. */
ds_status ds_disks_add_images(ds_disks *d);
/* A second set of the moving arrays of `like` (no slot[]), for a broad
 * phase that rebuilds the order into it and swaps (DS_BROADPHASE_STRIPS). */
ds_status ds_disks_alloc_spare(ds_disks *d, const ds_disks *like);
void ds_disks_free(ds_disks *d); /* NULL pointers are allowed */

/* Exchanges the moving arrays of a and b (not slot[]). */
void ds_disks_swap(ds_disks *a, ds_disks *b);

/* Moves the disks so that new slot k holds what slot order[k] held
 * (order a permutation of 0..n-1); slot[] is rebuilt. */
ds_status ds_disks_permute(ds_disks *d, const uint32_t *order);

/* slot[] from id[], after the slots moved. */
void ds_disks_rebuild_slots(ds_disks *d);

/* The kinetic tensor sum m v_a v_b over the disks: k[0] xx, k[1] yy,
 * k[2] xy (m = 1 without a mixture's masses). */
void ds_disks_kinetic_tensor(const ds_disks *d, double k[3]);

/* A mixture's arrays move with the disk; whether they exist does not
 * change during a run, so the branches on it are always predicted. */
static inline ds_disk_record ds_disks_load(const ds_disks *d, size_t k)
{
    ds_disk_record r;
    r.x = d->x[k];
    r.y = d->y[k];
    r.vx = d->vx[k];
    r.vy = d->vy[k];
    r.r = d->r ? d->r[k] : 0.0;
    r.m = d->m ? d->m[k] : 1.0;
    r.ix = d->ix ? d->ix[k] : 0;
    r.iy = d->iy ? d->iy[k] : 0;
    r.id = d->id[k];
    return r;
}

static inline void ds_disks_store(ds_disks *d, size_t k, ds_disk_record r)
{
    d->x[k] = r.x;
    d->y[k] = r.y;
    d->vx[k] = r.vx;
    d->vy[k] = r.vy;
    if (d->r)
        d->r[k] = r.r;
    if (d->m)
        d->m[k] = r.m;
    if (d->ix) {
        d->ix[k] = r.ix;
        d->iy[k] = r.iy;
    }
    d->id[k] = r.id;
}

/* Slot `from` of src into slot `to` of dst (the same set or another, with
 * the same arrays). */
static inline void ds_disks_copy(ds_disks *dst, size_t to, const ds_disks *src, size_t from)
{
    dst->x[to] = src->x[from];
    dst->y[to] = src->y[from];
    dst->vx[to] = src->vx[from];
    dst->vy[to] = src->vy[from];
    if (src->r)
        dst->r[to] = src->r[from];
    if (src->m)
        dst->m[to] = src->m[from];
    if (src->ix) {
        dst->ix[to] = src->ix[from];
        dst->iy[to] = src->iy[from];
    }
    dst->id[to] = src->id[from];
}

/* ds_disks_copy for arrays known to hold no mixture's and no image
 * counters (r, m and ix NULL):
 * for a loop that has asked once. */
static inline void ds_disks_copy_motion(ds_disks *dst, size_t to, const ds_disks *src,
                                        size_t from)
{
    dst->x[to] = src->x[from];
    dst->y[to] = src->y[from];
    dst->vx[to] = src->vx[from];
    dst->vy[to] = src->vy[from];
    dst->id[to] = src->id[from];
}

#endif
