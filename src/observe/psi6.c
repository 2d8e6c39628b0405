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

/* psi6 of n checked centres; with radii (a mixture's), the bond cutoff
 * of a pair is factor times its contact distance, cutoff the largest. */
static ds_status local_psi6(size_t n, const double *x, const double *y, const double *radii,
                            double factor, double box_x, double box_y, int periodic, double cutoff,
                            double *re, double *im);

/* A length that must be finite and > 0, refused with its name. */
static ds_status check_length(const char *field, double v, ds_error *err)
{
    if (v > 0.0 && isfinite(v))
        return DS_OK;
    return ds_refuse(err, DS_ERR_ARG, field, v, 0.0, "%s = %g must be finite and > 0", field, v);
}

static ds_status check_arguments(size_t n, const double *x, const double *y, double box_x,
                                 double box_y, ds_boundary boundary, double cutoff,
                                 const double *re, const double *im, ds_error *err)
{
    /* No disks: nothing to read or write, whatever the pointers. */
    if (n > 0 && (!x || !y || !re || !im)) {
        const char *which = !x ? "x" : !y ? "y" : !re ? "re" : "im";
        return ds_refuse(err, DS_ERR_ARG, which, NAN, NAN, "%s: NULL", which);
    }
    ds_status st = check_length("box_x", box_x, err);
    if (st == DS_OK)
        st = check_length("box_y", box_y, err);
    if (st == DS_OK)
        st = check_length("cutoff", cutoff, err);
    if (st != DS_OK)
        return st;
    if (boundary != DS_BOUNDARY_WALLS && boundary != DS_BOUNDARY_PERIODIC)
        return ds_refuse(err, DS_ERR_ARG, "boundary", (double)boundary, NAN,
                         "boundary = %d is not a ds_boundary", (int)boundary);
    /* Beyond half the box a second image could be as close as the first. */
    const double half = 0.5 * fmin(box_x, box_y);
    if (boundary == DS_BOUNDARY_PERIODIC && !(cutoff < half))
        return ds_refuse(err, DS_ERR_ARG, "cutoff", cutoff, half,
                         "cutoff = %g must be below half the shorter side (%g) in a periodic box",
                         cutoff, half);
    for (size_t j = 0; j < n; ++j)
        if (!isfinite(x[j]) || !isfinite(y[j])) {
            ds_error_index(err, j);
            return ds_refuse(err, DS_ERR_ARG, "x", isfinite(x[j]) ? y[j] : x[j], NAN,
                             "x: centre %zu is not finite", j);
        }
    return DS_OK;
}

ds_status ds_psi6_local(size_t n, const double *x, const double *y, double box_x, double box_y,
                        ds_boundary boundary, double cutoff, double *re, double *im, ds_error *err)
{
    ds_error_clear(err);
    ds_status st = check_arguments(n, x, y, box_x, box_y, boundary, cutoff, re, im, err);
    if (st != DS_OK || n == 0)
        return st;
    st = local_psi6(n, x, y, NULL, 0.0, box_x, box_y, boundary == DS_BOUNDARY_PERIODIC, cutoff, re,
                    im);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)n, NAN, "n = %zu centres: no memory for the cells",
                         n);
    return DS_OK;
}

static ds_status local_psi6(size_t n, const double *x, const double *y, const double *radii,
                            double factor, double box_x, double box_y, int periodic, double cutoff,
                            double *re, double *im)
{
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
                const double pair_cut = radii ? factor * (radii[j] + radii[k]) : 0.0;
                /* A coincident centre has no bond direction. */
                if (k == j || !(r2 < (radii ? pair_cut * pair_cut : cut2)) || r2 == 0.0)
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

ds_status ds_sim_get_psi6(const ds_sim *sim, double *psi6, ds_error *err)
{
    ds_error_clear(err);
    if (psi6)
        *psi6 = NAN;
    if (!sim || !psi6)
        return ds_refuse(err, DS_ERR_ARG, sim ? "psi6" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "psi6" : "sim");
    const ds_world *w = &sim->world;
    const size_t n = w->n;
    /* The arrays hold the disks in slot order, which the mean ignores. A
     * mixture's pair is bonded within 1.4 times its own contact distance;
     * its cells are as wide as the largest pair's cutoff. */
    const double cutoff = PSI6_CUTOFF_DIAMETERS * 2.0 * w->radius_max;
    const int periodic = w->boundary == DS_BOUNDARY_PERIODIC;
    if (periodic && !(cutoff < 0.5 * fmin(w->box, w->box_y))) {
        const int y = w->box_y < w->box;
        return ds_refuse(err, DS_ERR_ARG, y ? "box_y" : "box", y ? w->box_y : w->box, 2.0 * cutoff,
                         "%s = %g: psi6's cutoff, 1.4 diameters (%g), must be below half each "
                         "side of a periodic box",
                         y ? "box_y" : "box", y ? w->box_y : w->box, cutoff);
    }
    double *re = malloc(n * sizeof *re), *im = malloc(n * sizeof *im);
    ds_status st = re && im ? DS_OK : DS_ERR_NOMEM;
    if (st == DS_OK)
        st = local_psi6(n, sim->disks.x, sim->disks.y, sim->disks.r,
                        sim->disks.r ? PSI6_CUTOFF_DIAMETERS : 0.0, w->box, w->box_y, periodic,
                        cutoff, re, im);
    if (st == DS_OK) {
        double sum_re = 0.0, sum_im = 0.0;
        for (size_t j = 0; j < n; ++j) {
            sum_re += re[j];
            sum_im += im[j];
        }
        *psi6 = hypot(sum_re, sum_im) / (double)n;
    }
    free(re);
    free(im);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)n, NAN, "n = %zu disks: no memory for psi6", n);
    return DS_OK;
}
