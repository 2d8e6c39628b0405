/* SPDX-License-Identifier: MIT */
/* The disks' columns (see disk_arrays.h): each operation over every row
 * of DS_DISK_COLUMNS. */
#include <stdlib.h>
#include <string.h>

#include "core/disk_arrays.h"

/* Column `name` of n + 1 elements: the new value, the sentinel at n. */
#define ALLOC_COLUMN(d, name, fresh, sentinel)                                                    \
    do {                                                                                          \
        if (!((d)->name = malloc(((d)->n + 1) * sizeof *(d)->name)))                              \
            return DS_ERR_NOMEM;                                                                  \
        for (size_t k = 0; k < (d)->n; ++k)                                                       \
            (d)->name[k] = fresh;                                                                 \
        (d)->name[(d)->n] = sentinel;                                                             \
    } while (0)

/* The columns every simulation has, and those of `like` if given. */
static ds_status alloc_columns(ds_disks *d, size_t n, const ds_disks *like)
{
    memset(d, 0, sizeof *d);
    d->n = n;
#define ALLOC_IF(name, type, every, fresh, sentinel, codec)                                       \
    if ((every) || (like && like->name))                                                          \
        ALLOC_COLUMN(d, name, (type)(fresh), (type)(sentinel));
    DS_DISK_COLUMNS(ALLOC_IF)
#undef ALLOC_IF
    return DS_OK;
}

ds_status ds_disks_alloc(ds_disks *d, size_t n)
{
    ds_status st = alloc_columns(d, n, NULL);
    if (st == DS_OK && !(d->slot = malloc((n + 1) * sizeof *d->slot)))
        st = DS_ERR_NOMEM;
    if (st != DS_OK) {
        ds_disks_free(d);
        return st;
    }
    for (size_t k = 0; k < n; ++k)
        d->id[k] = d->slot[k] = (uint32_t)k;
    d->slot[n] = UINT32_MAX;
    return DS_OK;
}

ds_status ds_disks_alloc_like(ds_disks *d, const ds_disks *like)
{
    const ds_status st = alloc_columns(d, like->n, like);
    if (st != DS_OK)
        ds_disks_free(d);
    return st;
}

ds_status ds_disks_clone(ds_disks *d, const ds_disks *src)
{
    ds_status st = alloc_columns(d, src->n, src);
    if (st == DS_OK && !(d->slot = malloc((src->n + 1) * sizeof *d->slot)))
        st = DS_ERR_NOMEM;
    if (st != DS_OK) {
        ds_disks_free(d);
        return st;
    }
#define CLONE(name, type, every, fresh, sentinel, codec)                                          \
    if (src->name)                                                                                \
        memcpy(d->name, src->name, (src->n + 1) * sizeof *d->name);
    DS_DISK_COLUMNS(CLONE)
#undef CLONE
    memcpy(d->slot, src->slot, (src->n + 1) * sizeof *d->slot);
    return DS_OK;
}

ds_status ds_disks_clone_ordered(ds_disks *d, const ds_disks *src)
{
    ds_status st = alloc_columns(d, src->n, src);
    if (st == DS_OK && !(d->slot = malloc((src->n + 1) * sizeof *d->slot)))
        st = DS_ERR_NOMEM;
    if (st != DS_OK) {
        ds_disks_free(d);
        return st;
    }
    for (size_t i = 0; i < src->n; ++i)
        ds_disks_copy(d, i, src, src->slot[i]);
    for (size_t i = 0; i <= src->n; ++i)
        d->slot[i] = i < src->n ? (uint32_t)i : UINT32_MAX;
    return DS_OK;
}

ds_status ds_disks_add(ds_disks *d, ds_column c)
{
    switch (c) {
#define ADD_CASE(name, type, every, fresh, sentinel, codec)                                       \
    case DS_COLUMN_##name:                                                                        \
        if (!d->name)                                                                             \
            ALLOC_COLUMN(d, name, (type)(fresh), (type)(sentinel));                               \
        return DS_OK;
        DS_DISK_COLUMNS(ADD_CASE)
#undef ADD_CASE
    case DS_COLUMN_COUNT:
        break;
    }
    return DS_ERR_ARG;
}

ds_status ds_disks_add_mixture(ds_disks *d, int radii, int masses)
{
    if (radii && ds_disks_add(d, DS_COLUMN_r) != DS_OK)
        return DS_ERR_NOMEM;
    return masses ? ds_disks_add(d, DS_COLUMN_m) : DS_OK;
}

ds_status ds_disks_add_images(ds_disks *d)
{
    if (ds_disks_add(d, DS_COLUMN_ix) != DS_OK)
        return DS_ERR_NOMEM;
    return ds_disks_add(d, DS_COLUMN_iy);
}

uint32_t ds_disks_columns(const ds_disks *d)
{
    uint32_t bits = 0;
#define HAS_BIT(name, type, every, fresh, sentinel, codec)                                        \
    if (d->name)                                                                                  \
        bits |= 1u << DS_COLUMN_##name;
    DS_DISK_COLUMNS(HAS_BIT)
#undef HAS_BIT
    return bits;
}

int ds_disks_has(const ds_disks *d, ds_column c)
{
    return c < DS_COLUMN_COUNT && (ds_disks_columns(d) >> c & 1u);
}

void ds_disks_free(ds_disks *d)
{
#define FREE(name, type, every, fresh, sentinel, codec)                                           \
    free(d->name);                                                                                \
    d->name = NULL;
    DS_DISK_COLUMNS(FREE)
#undef FREE
    free(d->slot);
    d->slot = NULL;
}

void ds_disks_swap(ds_disks *a, ds_disks *b)
{
#define SWAP(name, type, every, fresh, sentinel, codec)                                           \
    {                                                                                             \
        type *t = a->name;                                                                        \
        a->name = b->name;                                                                        \
        b->name = t;                                                                              \
    }
    DS_DISK_COLUMNS(SWAP)
#undef SWAP
}

ds_status ds_disks_permute(ds_disks *d, const uint32_t *order)
{
    ds_disks old;
    if (ds_disks_alloc_like(&old, d) != DS_OK)
        return DS_ERR_NOMEM;
    ds_disks_swap(d, &old);
    for (size_t k = 0; k < d->n; ++k)
        ds_disks_copy(d, k, &old, order[k]);
    ds_disks_free(&old);
    ds_disks_rebuild_slots(d);
    return DS_OK;
}

void ds_disks_rebuild_slots(ds_disks *d)
{
    for (size_t k = 0; k < d->n; ++k)
        d->slot[d->id[k]] = (uint32_t)k;
}

void ds_disks_save(const ds_disks *d, ds_state_writer *w)
{
    for (size_t k = 0; k < d->n; ++k) {
#define SAVE(name, type, every, fresh, sentinel, codec)                                           \
    if ((every) || d->name)                                                                       \
        ds_put_##codec(w, d->name[k]);
        DS_DISK_COLUMNS(SAVE)
#undef SAVE
    }
}

int ds_disks_load_all(ds_disks *d, ds_reader *r)
{
    for (size_t k = 0; k < d->n && !r->failed; ++k) {
#define LOAD(name, type, every, fresh, sentinel, codec)                                           \
    if ((every) || d->name)                                                                       \
        d->name[k] = ds_get_##codec(r);
        DS_DISK_COLUMNS(LOAD)
#undef LOAD
    }
    return !r->failed;
}

void ds_disks_kinetic_tensor(const ds_disks *d, double k[3])
{
    double xx = 0.0, yy = 0.0, xy = 0.0;
    for (size_t i = 0; i < d->n; ++i) {
        const double m = d->m ? d->m[i] : 1.0, vx = d->vx[i], vy = d->vy[i];
        xx += m * vx * vx;
        yy += m * vy * vy;
        xy += m * vx * vy;
    }
    k[0] = xx;
    k[1] = yy;
    k[2] = xy;
}

void ds_disks_momentum(const ds_disks *d, double p[2], double *mass)
{
    double px = 0.0, py = 0.0, total = 0.0;
    for (size_t i = 0; i < d->n; ++i) {
        const double m = d->m ? d->m[i] : 1.0;
        px += m * d->vx[i];
        py += m * d->vy[i];
        total += m;
    }
    p[0] = px;
    p[1] = py;
    *mass = total;
}
