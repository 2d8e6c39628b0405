/* SPDX-License-Identifier: MIT */
/* The histogram of pair separations behind g(r) (ds_pair_histogram): every
 * pair closer than the histogram's range, through the neighbour pairs
 * (core/pairs.h): O(n) at a fixed density. */
#include <math.h>
#include <stdlib.h>

#include "core/pairs.h"
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
    if ((unsigned)boundary >= DS_BOUNDARY_COUNT)
        return ds_refuse(err, DS_ERR_ARG, "boundary", (double)boundary, NAN,
                         "boundary = %d is not a ds_boundary", (int)boundary);
    const ds_box box = ds_box_of(boundary, box_x, box_y);
    for (int a = 0; a < 2; ++a)
        if (ds_box_periodic(&box, a) && !(range <= 0.5 * box.side[a]))
            return ds_refuse(err, DS_ERR_ARG, "dr", range, 0.5 * box.side[a],
                             "dr = %g: the range bins dr = %g must be at most half of each "
                             "periodic side (%g)",
                             dr, range, 0.5 * box.side[a]);
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

typedef struct histogram {
    uint64_t *counts;
    double dr;
    size_t bins;
} histogram;

static int count_pair(void *ctx, size_t j, size_t k, double dx, double dy, double r2)
{
    const histogram *h = ctx;
    (void)j;
    (void)k;
    (void)dx;
    (void)dy;
    const size_t b = (size_t)(sqrt(r2) / h->dr);
    ++h->counts[b < h->bins ? b : h->bins - 1]; /* sqrt may round up to the range */
    return 0;
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
    /* ds_pairs wraps centres from anywhere into the box: two are then
     * less than a side apart, as the nearest image needs. */
    histogram h = {counts, dr, bins};
    const ds_box box = ds_box_of(boundary, box_x, box_y);
    const size_t cap = n * CELLS_PER_CENTRE < MIN_CELL_CAP ? MIN_CELL_CAP : n * CELLS_PER_CENTRE;
    ds_pairs p;
    st = ds_pairs_begin(&p, &box, n, x, y, (double)bins * dr, cap, 0);
    if (st == DS_OK) {
        ds_pairs_each(&p, 0, count_pair, &h);
        ds_pairs_end(&p);
    }
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)n, NAN, "n = %zu centres: no memory for the cells",
                         n);
    return st;
}
