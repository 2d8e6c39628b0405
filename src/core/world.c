/* SPDX-License-Identifier: MIT */
/* What the world says about the disks' sizes, computed one way from the
 * disk arrays (core.h). */
#include <math.h>

#include "core/core.h"

void ds_world_take_radii(ds_world *w, const ds_disks *d)
{
    if (!d->r) {
        w->radius_min = w->radius_max = w->radius;
        w->covered = ds_covered_by((double)d->n, w->radius);
        return;
    }
    /* Generation order, not the slots': those are in the broad phase's
     * order (by x, by cell), and a sum in it differed in its last bits
     * from the sum at creation once the slots had moved. */
    double lo = INFINITY, hi = 0.0, covered = 0.0;
    for (size_t i = 0; i < d->n; ++i) {
        const double r = d->r[d->slot[i]];
        lo = fmin(lo, r);
        hi = fmax(hi, r);
        covered += ds_covered_by(1.0, r);
    }
    w->radius_min = lo;
    w->radius_max = hi;
    w->covered = covered;
}
