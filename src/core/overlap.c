/* SPDX-License-Identifier: MIT */
/* Overlapping disks, found through the cell grid (see overlap.h). */
#include "core/overlap.h"
#include "core/boundary.h"
#include "core/grid.h"

ds_status ds_find_overlap(const ds_world *w, const double *x, const double *y, const double *r,
                          size_t *a, size_t *b)
{
    const size_t n = w->n;
    const int periodic = w->boundary == DS_BOUNDARY_PERIODIC;
    const double keep = 1.0 - DS_CONTACT_TOLERANCE;
    ds_grid g;
    ds_grid_init(&g, w->box, w->box_y, 2.0 * w->radius_max, 4 * n + 16, periodic);
    ds_grid_bins bins;
    if (ds_grid_bin(&g, n, x, y, &bins) != DS_OK)
        return DS_ERR_NOMEM;
    ds_status st = DS_OK;
    for (size_t j = 0; j < n && st == DS_OK; ++j) {
        size_t around[9];
        const int count = ds_grid_neighbours(&g, bins.cell[j] % g.nx, bins.cell[j] / g.nx, around);
        for (int c = 0; c < count && st == DS_OK; ++c)
            for (size_t s = bins.start[around[c]]; s < bins.start[around[c] + 1]; ++s) {
                const size_t k = bins.order[s];
                double dx = x[k] - x[j], dy = y[k] - y[j];
                if (periodic) {
                    dx = ds_nearest(dx, w->box);
                    dy = ds_nearest(dy, w->box_y);
                }
                const double limit = (r ? r[j] + r[k] : 2.0 * w->radius) * keep;
                if (k > j && dx * dx + dy * dy < limit * limit) {
                    *a = j;
                    *b = k;
                    st = DS_ERR_OVERLAP;
                    break;
                }
            }
    }
    ds_grid_bins_free(&bins);
    return st;
}
