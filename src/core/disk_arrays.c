/* SPDX-License-Identifier: MIT */
/* The disks' arrays (see disk_arrays.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/disk_arrays.h"

/* The moving arrays of n + 1 slots, the sentinel at n. */
static ds_status alloc_moving(ds_disks *d, size_t n, int radii, int masses, int images)
{
    const size_t cap = n + 1;
    d->n = n;
    d->x = malloc(cap * sizeof *d->x);
    d->y = malloc(cap * sizeof *d->y);
    d->vx = malloc(cap * sizeof *d->vx);
    d->vy = malloc(cap * sizeof *d->vy);
    d->id = malloc(cap * sizeof *d->id);
    if (!d->x || !d->y || !d->vx || !d->vy || !d->id ||
        ds_disks_add_mixture(d, radii, masses) != DS_OK ||
        (images && ds_disks_add_images(d) != DS_OK)) {
        ds_disks_free(d);
        return DS_ERR_NOMEM;
    }
    /* Slot n is the sweep sentinel: never inside any x window. */
    d->x[n] = INFINITY;
    d->y[n] = INFINITY;
    d->vx[n] = d->vy[n] = 0.0;
    d->id[n] = UINT32_MAX;
    return DS_OK;
}

ds_status ds_disks_add_mixture(ds_disks *d, int radii, int masses)
{
    const size_t cap = d->n + 1;
    if (radii && !d->r && !(d->r = calloc(cap, sizeof *d->r)))
        return DS_ERR_NOMEM;
    if (masses && !d->m) {
        if (!(d->m = malloc(cap * sizeof *d->m)))
            return DS_ERR_NOMEM;
        for (size_t k = 0; k < cap; ++k)
            d->m[k] = 1.0;
    }
    return DS_OK;
}

ds_status ds_disks_add_images(ds_disks *d)
{
    const size_t cap = d->n + 1;
    if (!d->ix && !(d->ix = calloc(cap, sizeof *d->ix)))
        return DS_ERR_NOMEM;
    if (!d->iy && !(d->iy = calloc(cap, sizeof *d->iy)))
        return DS_ERR_NOMEM;
    return DS_OK;
}

ds_status ds_disks_alloc(ds_disks *d, size_t n)
{
    memset(d, 0, sizeof *d);
    if (alloc_moving(d, n, 0, 0, 0) != DS_OK)
        return DS_ERR_NOMEM;
    d->slot = malloc((n + 1) * sizeof *d->slot);
    if (!d->slot) {
        ds_disks_free(d);
        return DS_ERR_NOMEM;
    }
    for (size_t k = 0; k < n; ++k) {
        d->x[k] = d->y[k] = d->vx[k] = d->vy[k] = 0.0;
        d->id[k] = d->slot[k] = (uint32_t)k;
    }
    d->slot[n] = UINT32_MAX;
    return DS_OK;
}

ds_status ds_disks_alloc_spare(ds_disks *d, const ds_disks *like)
{
    memset(d, 0, sizeof *d);
    return alloc_moving(d, like->n, like->r != NULL, like->m != NULL, like->ix != NULL);
}

void ds_disks_free(ds_disks *d)
{
    free(d->x);
    free(d->y);
    free(d->vx);
    free(d->vy);
    free(d->r);
    free(d->m);
    free(d->ix);
    free(d->iy);
    free(d->id);
    free(d->slot);
    d->x = d->y = d->vx = d->vy = d->r = d->m = NULL;
    d->ix = d->iy = NULL;
    d->id = d->slot = NULL;
}

static void swap_doubles(double **a, double **b)
{
    double *t = *a;
    *a = *b;
    *b = t;
}

void ds_disks_swap(ds_disks *a, ds_disks *b)
{
    swap_doubles(&a->x, &b->x);
    swap_doubles(&a->y, &b->y);
    swap_doubles(&a->vx, &b->vx);
    swap_doubles(&a->vy, &b->vy);
    swap_doubles(&a->r, &b->r);
    swap_doubles(&a->m, &b->m);
    int32_t *ix = a->ix, *iy = a->iy;
    a->ix = b->ix;
    a->iy = b->iy;
    b->ix = ix;
    b->iy = iy;
    uint32_t *t = a->id;
    a->id = b->id;
    b->id = t;
}

ds_status ds_disks_permute(ds_disks *d, const uint32_t *order)
{
    ds_disks old;
    if (ds_disks_alloc_spare(&old, d) != DS_OK)
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
