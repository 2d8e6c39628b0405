/* SPDX-License-Identifier: MIT */
/* Overlapping disks, found through the neighbour pairs (see overlap.h). */
#include "core/overlap.h"
#include "core/pairs.h"

typedef struct first_overlap {
    const double *r; /* radii, or NULL for one radius */
    double radius, keep;
    size_t a, b;
} first_overlap;

static int is_overlap(void *ctx, size_t j, size_t k, double dx, double dy, double r2)
{
    first_overlap *f = ctx;
    (void)dx;
    (void)dy;
    const double limit = (f->r ? f->r[j] + f->r[k] : 2.0 * f->radius) * f->keep;
    if (!(r2 < limit * limit))
        return 0;
    f->a = j;
    f->b = k;
    return 1;
}

ds_status ds_find_overlap(const ds_world *w, const double *x, const double *y, const double *r,
                          size_t *a, size_t *b)
{
    first_overlap f = {r, w->radius, 1.0 - DS_CONTACT_TOLERANCE, 0, 0};
    ds_pairs p;
    if (ds_pairs_begin(&p, &w->box, w->n, x, y, 2.0 * w->radius_max, 4 * w->n + 16, 1) != DS_OK)
        return DS_ERR_NOMEM;
    const int found = ds_pairs_each(&p, 0, is_overlap, &f);
    ds_pairs_end(&p);
    if (!found)
        return DS_OK;
    *a = f.a;
    *b = f.b;
    return DS_ERR_OVERLAP;
}
