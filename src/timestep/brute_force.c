/* SPDX-License-Identifier: MIT */
/* DS_BROADPHASE_BRUTE: every pair tested, O(N^2), in any slot order. The
 * reference the sweeps are checked against; in a periodic box it takes
 * each pair to its nearest image itself, so it needs no seam pass. */
#include "core/box.h"
#include "timestep/broad_phase.h"

static uint64_t all_pairs(ds_disks *d, double diameter, ds_pair_fn on_pair, void *ctx)
{
    const size_t n = d->n;
    const double *x = d->x, *y = d->y;
    const double d2max = diameter * diameter;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            const double dx = x[j] - x[i], dy = y[j] - y[i];
            if (dx * dx + dy * dy < d2max)
                on_pair(d, i, j, ctx);
        }
    return (uint64_t)n * (n - 1) / 2;
}

static uint64_t all_pairs_periodic(ds_disks *d, double diameter, const ds_box *box,
                                   ds_pair_fn on_pair, void *ctx)
{
    const size_t n = d->n;
    const double *x = d->x, *y = d->y;
    const double d2max = diameter * diameter;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            double dx = x[j] - x[i], dy = y[j] - y[i];
            ds_box_nearest(box, &dx, &dy);
            if (dx * dx + dy * dy < d2max)
                on_pair(d, i, j, ctx);
        }
    return (uint64_t)n * (n - 1) / 2;
}

uint64_t ds_brute_force_find_pairs(const ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx)
{
    return ds_box_any_periodic(&bp->box) ? all_pairs_periodic(d, bp->diameter, &bp->box, on_pair, ctx)
                                         : all_pairs(d, bp->diameter, on_pair, ctx);
}
