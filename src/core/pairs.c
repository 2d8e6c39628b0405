/* SPDX-License-Identifier: MIT */
/* Neighbour pairs through the cell grid (see pairs.h). */
#include <stdlib.h>

#include "core/pairs.h"

ds_status ds_pairs_begin(ds_pairs *p, const ds_box *box, size_t n, const double *x,
                         const double *y, double range, size_t cap, int inside)
{
    p->box = box;
    p->n = n;
    p->wrapped = NULL;
    p->range2 = range * range;
    if (!inside && ds_box_any_periodic(box) && n > 0) {
        /* Wrapped into the box, two centres are less than a side apart
         * along a periodic axis, as the nearest image needs. */
        if (!(p->wrapped = malloc(2 * n * sizeof *p->wrapped)))
            return DS_ERR_NOMEM;
        for (size_t j = 0; j < n; ++j) {
            double u = x[j], v = y[j];
            ds_box_wrap_any(box, &u, &v);
            p->wrapped[j] = u;
            p->wrapped[n + j] = v;
        }
        x = p->wrapped;
        y = p->wrapped + n;
    }
    p->x = x;
    p->y = y;
    ds_grid_init(&p->grid, box, range, cap);
    if (ds_grid_bin(&p->grid, n, x, y, &p->bins) != DS_OK) {
        free(p->wrapped);
        p->wrapped = NULL;
        return DS_ERR_NOMEM;
    }
    return DS_OK;
}

void ds_pairs_end(ds_pairs *p)
{
    ds_grid_bins_free(&p->bins);
    free(p->wrapped);
    p->wrapped = NULL;
}

int ds_pairs_each(const ds_pairs *p, int both, ds_pair_visit visit, void *ctx)
{
    const ds_grid *g = &p->grid;
    const int nearest = ds_box_any_periodic(p->box);
    for (size_t j = 0; j < p->n; ++j) {
        size_t around[9];
        const size_t cell = p->bins.cell[j];
        const int cells = ds_grid_neighbours(g, cell % g->nx, cell / g->nx, around);
        for (int c = 0; c < cells; ++c)
            for (size_t s = p->bins.start[around[c]]; s < p->bins.start[around[c] + 1]; ++s) {
                const size_t k = p->bins.order[s];
                if (both ? k == j : k <= j)
                    continue;
                double dx = p->x[k] - p->x[j], dy = p->y[k] - p->y[j];
                if (nearest)
                    ds_box_nearest(p->box, &dx, &dy);
                const double r2 = dx * dx + dy * dy;
                if (r2 < p->range2 && visit(ctx, j, k, dx, dy, r2))
                    return 1;
            }
    }
    return 0;
}
