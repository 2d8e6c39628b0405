/* SPDX-License-Identifier: MIT */
/* Order: the bond-orientational order parameter psi6, per disk and for the
 * whole system.
 *
 * psi6_j = (1/n_j) sum_k exp(6 i theta_jk) over the n_j disks k whose
 * centres are closer than a cutoff to j's, theta_jk the angle of the bond
 * j -> k from the x axis. Six neighbours at multiples of 60 degrees give 1
 * times the lattice's phase, a liquid's bonds point anywhere and average
 * out. Neighbours are found in a cell grid of cells at least a cutoff wide,
 * so each disk looks only at the 3 x 3 cells around its own: O(N). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/boundary.h"
#include "core/grid.h"
#include "observe/observe.h"

/* Closer centres are the first shell of neighbours: the first peak of
 * g(r) of the dense liquid has fallen below 1 by 1.4 diameters, and its
 * first minimum (1.55 d at area fraction 0.70) and a crystal's second
 * shell (sqrt 3 spacings) lie beyond. */
#define PSI6_CUTOFF_DIAMETERS 1.4

/* A dilute system would want more cells than disks (a tiny cutoff in a huge
 * box); beyond a few cells per disk, larger cells cost only a few more
 * distance tests, far less than clearing and scanning empty cells. */
#define CELLS_PER_DISK 4
#define MIN_CELL_CAP 64

/* exp(6 i theta) of the bond (dx, dy) of squared length r2 > 0, added to
 * (*re, *im): (u / |u|)^6 for u = dx + i dy, three complex products and
 * no trigonometry. */
static void add_bond(double dx, double dy, double r2, double *re, double *im)
{
    const double inv = 1.0 / sqrt(r2);
    const double ur = dx * inv, ui = dy * inv;
    const double u2r = ur * ur - ui * ui, u2i = 2.0 * ur * ui;
    const double u3r = u2r * ur - u2i * ui, u3i = u2r * ui + u2i * ur;
    *re += u3r * u3r - u3i * u3i;
    *im += 2.0 * u3r * u3i;
}

ds_status ds_local_psi6(size_t n, const double *x, const double *y, double box_x, double box_y,
                        ds_boundary boundary, double cutoff, double *re, double *im)
{
    /* No disks: nothing to read or write, whatever the pointers. */
    if (n > 0 && (!x || !y || !re || !im))
        return DS_ERR_ARG;
    if (!(box_x > 0.0) || !isfinite(box_x) || !(box_y > 0.0) || !isfinite(box_y) ||
        !(cutoff > 0.0) || !isfinite(cutoff))
        return DS_ERR_ARG;
    if (boundary != DS_WALLS && boundary != DS_PERIODIC)
        return DS_ERR_ARG;
    const int periodic = boundary == DS_PERIODIC;
    /* Beyond half the box a second image could be as close as the first. */
    if (periodic && !(cutoff < 0.5 * fmin(box_x, box_y)))
        return DS_ERR_ARG;
    for (size_t j = 0; j < n; ++j)
        if (!isfinite(x[j]) || !isfinite(y[j]))
            return DS_ERR_ARG;
    if (n == 0)
        return DS_OK;
    if (n > SIZE_MAX / sizeof(size_t) / CELLS_PER_DISK - 1 || n > SIZE_MAX / (2 * sizeof(double)))
        return DS_ERR_NOMEM;

    /* In a periodic box the centres may come from anywhere: wrapped into
     * the box first, two of them are less than a box apart, as the
     * nearest image needs (boundary.h). */
    double *wrapped = NULL;
    if (periodic) {
        if (!(wrapped = malloc(2 * n * sizeof *wrapped)))
            return DS_ERR_NOMEM;
        for (size_t j = 0; j < n; ++j) {
            wrapped[j] = ds_wrap_any(x[j], box_x);
            wrapped[n + j] = ds_wrap_any(y[j], box_y);
        }
        x = wrapped;
        y = wrapped + n;
    }
    ds_grid g;
    const size_t cap = n * CELLS_PER_DISK < MIN_CELL_CAP ? MIN_CELL_CAP : n * CELLS_PER_DISK;
    ds_grid_init(&g, box_x, box_y, cutoff, cap, periodic);
    ds_grid_bins bins;
    ds_status st = ds_grid_bin(&g, n, x, y, &bins);
    if (st != DS_OK) {
        free(wrapped);
        return st;
    }
    const double cut2 = cutoff * cutoff;
    for (size_t j = 0; j < n; ++j) {
        size_t around[9];
        const int cells = ds_grid_neighbours(&g, bins.cell[j] % g.nx, bins.cell[j] / g.nx, around);
        double sum_re = 0.0, sum_im = 0.0;
        size_t bonds = 0;
        for (int c = 0; c < cells; ++c)
            for (size_t s = bins.start[around[c]]; s < bins.start[around[c] + 1]; ++s) {
                const size_t k = bins.order[s];
                double dx = x[k] - x[j], dy = y[k] - y[j];
                if (periodic) {
                    dx = ds_nearest(dx, box_x);
                    dy = ds_nearest(dy, box_y);
                }
                const double r2 = dx * dx + dy * dy;
                /* A coincident centre has no bond direction. */
                if (k == j || !(r2 < cut2) || r2 == 0.0)
                    continue;
                add_bond(dx, dy, r2, &sum_re, &sum_im);
                ++bonds;
            }
        re[j] = bonds ? sum_re / (double)bonds : 0.0;
        im[j] = bonds ? sum_im / (double)bonds : 0.0;
    }
    ds_grid_bins_free(&bins);
    free(wrapped);
    return DS_OK;
}

double ds_psi6(const ds_sim *sim)
{
    if (!sim)
        return NAN;
    const ds_world *w = &sim->world;
    const size_t n = w->n;
    double *re = malloc(n * sizeof *re), *im = malloc(n * sizeof *im);
    double result = NAN;
    /* The arrays hold the disks in slot order, which the mean ignores. */
    if (re && im &&
        ds_local_psi6(n, sim->disks.x, sim->disks.y, w->box, w->box_y, w->boundary,
                      PSI6_CUTOFF_DIAMETERS * 2.0 * w->radius, re, im) == DS_OK) {
        double sum_re = 0.0, sum_im = 0.0;
        for (size_t j = 0; j < n; ++j) {
            sum_re += re[j];
            sum_im += im[j];
        }
        result = hypot(sum_re, sum_im) / (double)n;
    }
    free(re);
    free(im);
    return result;
}
