/* SPDX-License-Identifier: MIT */
/* The histogram of pair separations behind g(r) (ds_pair_histogram): every
 * pair closer than the histogram's range found through the cell grid, the
 * cells at least that range wide, so each centre looks at the 3 x 3 cells
 * around its own: O(n) at a fixed density. */
#include <math.h>
#include <stdlib.h>

#include "core/boundary.h"
#include "core/grid.h"
#include "observe/observe.h"

/* Cells at most about four per centre (a huge box with a short range
 * would want far more, mostly empty). */
#define CELLS_PER_CENTRE 4
#define MIN_CELL_CAP 64

/* A length that must be finite and > 0, refused with its name. */
static ds_status check_length(const char *field, double v, ds_error *err)
{
    if (v > 0.0 && isfinite(v))
        return DS_OK;
    return ds_refuse(err, DS_ERR_ARG, field, v, 0.0, "%s = %g must be finite and > 0", field, v);
}

static ds_status check_arguments(size_t n, const double *x, const double *y, double box_x,
                                 double box_y, ds_boundary boundary, double dr, size_t bins,
                                 const uint64_t *counts, ds_error *err)
{
    if (!counts || (n > 0 && (!x || !y))) {
        const char *which = !counts ? "counts" : !x ? "x" : "y";
        return ds_refuse(err, DS_ERR_ARG, which, NAN, NAN, "%s: NULL", which);
    }
    if (bins == 0)
        return ds_refuse(err, DS_ERR_ARG, "bins", 0.0, 1.0, "bins = 0: there must be one");
    ds_status st = check_length("box_x", box_x, err);
    if (st == DS_OK)
        st = check_length("box_y", box_y, err);
    if (st == DS_OK)
        st = check_length("dr", dr, err);
    if (st != DS_OK)
        return st;
    const double range = (double)bins * dr;
    if (!isfinite(range))
        return ds_refuse(err, DS_ERR_ARG, "dr", dr, NAN,
                         "dr = %g: bins dr, the range, must be finite", dr);
    if (boundary != DS_BOUNDARY_WALLS && boundary != DS_BOUNDARY_PERIODIC)
        return ds_refuse(err, DS_ERR_ARG, "boundary", (double)boundary, NAN,
                         "boundary = %d is not a ds_boundary", (int)boundary);
    const double half = 0.5 * fmin(box_x, box_y);
    if (boundary == DS_BOUNDARY_PERIODIC && !(range <= half))
        return ds_refuse(err, DS_ERR_ARG, "dr", range, half,
                         "dr = %g: the range bins dr = %g must be at most half the shorter side "
                         "(%g) in a periodic box",
                         dr, range, half);
    for (size_t j = 0; j < n; ++j)
        if (!isfinite(x[j]) || !isfinite(y[j])) {
            ds_error_index(err, j);
            return ds_refuse(err, DS_ERR_ARG, "x", isfinite(x[j]) ? y[j] : x[j], NAN,
                             "x: centre %zu is not finite", j);
        }
    if (n > SIZE_MAX / sizeof(size_t) / CELLS_PER_CENTRE - 1 || n > SIZE_MAX / (2 * sizeof(double)))
        return ds_refuse(err, DS_ERR_NOMEM, "n", (double)n, NAN,
                         "n = %zu centres cannot be held in memory", n);
    return DS_OK;
}

ds_status ds_pair_histogram(size_t n, const double *x, const double *y, double box_x, double box_y,
                            ds_boundary boundary, double dr, size_t bins, uint64_t *counts,
                            ds_error *err)
{
    ds_error_clear(err);
    ds_status st = check_arguments(n, x, y, box_x, box_y, boundary, dr, bins, counts, err);
    if (st != DS_OK)
        return st;
    for (size_t b = 0; b < bins; ++b)
        counts[b] = 0;
    const int periodic = boundary == DS_BOUNDARY_PERIODIC;
    /* Wrapped into the box, two centres are less than a box apart, as the
     * nearest image needs (boundary.h). */
    double *wrapped = NULL;
    if (periodic && n > 0) {
        if (!(wrapped = malloc(2 * n * sizeof *wrapped)))
            return ds_refuse(err, DS_ERR_NOMEM, "n", (double)n, NAN,
                             "n = %zu centres: no memory to wrap them", n);
        for (size_t j = 0; j < n; ++j) {
            wrapped[j] = ds_wrap_any(x[j], box_x);
            wrapped[n + j] = ds_wrap_any(y[j], box_y);
        }
        x = wrapped;
        y = wrapped + n;
    }
    const double range = (double)bins * dr, range2 = range * range;
    ds_grid g;
    const size_t cap = n * CELLS_PER_CENTRE < MIN_CELL_CAP ? MIN_CELL_CAP : n * CELLS_PER_CENTRE;
    ds_grid_init(&g, box_x, box_y, range, cap, periodic);
    ds_grid_bins cells;
    st = ds_grid_bin(&g, n, x, y, &cells);
    for (size_t j = 0; st == DS_OK && j < n; ++j) {
        size_t around[9];
        const int count =
            ds_grid_neighbours(&g, cells.cell[j] % g.nx, cells.cell[j] / g.nx, around);
        for (int c = 0; c < count; ++c)
            for (size_t s = cells.start[around[c]]; s < cells.start[around[c] + 1]; ++s) {
                const size_t k = cells.order[s];
                if (k <= j)
                    continue;
                double dx = x[k] - x[j], dy = y[k] - y[j];
                if (periodic) {
                    dx = ds_nearest(dx, box_x);
                    dy = ds_nearest(dy, box_y);
                }
                const double r2 = dx * dx + dy * dy;
                if (r2 < range2) {
                    const size_t b = (size_t)(sqrt(r2) / dr);
                    ++counts[b < bins ? b : bins - 1]; /* sqrt may round up to the range */
                }
            }
    }
    if (st == DS_OK)
        ds_grid_bins_free(&cells);
    free(wrapped);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)n, NAN, "n = %zu centres: no memory for the cells",
                         n);
    return st;
}
