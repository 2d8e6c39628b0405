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

#include "core/pairs.h"
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

/* psi6 of n checked centres in box; with radii (a mixture's), the bond
 * cutoff of a pair is factor times its contact distance, cutoff the
 * largest. */
static ds_status local_psi6(size_t n, const double *x, const double *y, const double *radii,
                            double factor, const ds_box *box, double cutoff, double *re,
                            double *im);

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
    if ((unsigned)boundary >= DS_BOUNDARY_COUNT)
        return ds_refuse(err, DS_ERR_ARG, "boundary", (double)boundary, NAN,
                         "boundary = %d is not a ds_boundary", (int)boundary);
    /* Beyond half a periodic side a second image could be as close as the
     * first. */
    const ds_box box = ds_box_of(boundary, box_x, box_y);
    for (int a = 0; a < 2; ++a)
        if (ds_box_periodic(&box, a) && !(cutoff < 0.5 * box.side[a]))
            return ds_refuse(err, DS_ERR_ARG, "cutoff", cutoff, 0.5 * box.side[a],
                             "cutoff = %g must be below half of each periodic side (%g)", cutoff,
                             0.5 * box.side[a]);
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
    const ds_box box = ds_box_of(boundary, box_x, box_y);
    st = local_psi6(n, x, y, NULL, 0.0, &box, cutoff, re, im);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)n, NAN, "n = %zu centres: no memory for the cells",
                         n);
    return DS_OK;
}

/* The bonds of a pair, added to disk j's sums (each ordered pair comes
 * once: every disk's own sum, in the order of its neighbours' cells). */
typedef struct bonds {
    const double *radii;
    double factor, cut2;
    double *re, *im;
    size_t *count;
} bonds;

static int add_pair(void *ctx, size_t j, size_t k, double dx, double dy, double r2)
{
    bonds *b = ctx;
    const double pair_cut = b->radii ? b->factor * (b->radii[j] + b->radii[k]) : 0.0;
    /* A coincident centre has no bond direction. */
    if (!(r2 < (b->radii ? pair_cut * pair_cut : b->cut2)) || r2 == 0.0)
        return 0;
    add_bond(dx, dy, r2, &b->re[j], &b->im[j]);
    ++b->count[j];
    return 0;
}

static ds_status local_psi6(size_t n, const double *x, const double *y, const double *radii,
                            double factor, const ds_box *box, double cutoff, double *re,
                            double *im)
{
    if (n > SIZE_MAX / sizeof(size_t) / CELLS_PER_DISK - 1 || n > SIZE_MAX / (2 * sizeof(double)))
        return DS_ERR_NOMEM;
    bonds b = {radii, factor, cutoff * cutoff, re, im, calloc(n, sizeof(size_t))};
    if (!b.count)
        return DS_ERR_NOMEM;
    for (size_t j = 0; j < n; ++j)
        re[j] = im[j] = 0.0;
    /* The centres may come from anywhere: ds_pairs wraps them into the
     * box first, so two are less than a side apart, as the nearest image
     * needs. */
    ds_pairs p;
    const size_t cap = n * CELLS_PER_DISK < MIN_CELL_CAP ? MIN_CELL_CAP : n * CELLS_PER_DISK;
    if (ds_pairs_begin(&p, box, n, x, y, cutoff, cap, 0) != DS_OK) {
        free(b.count);
        return DS_ERR_NOMEM;
    }
    ds_pairs_each(&p, 1, add_pair, &b);
    ds_pairs_end(&p);
    for (size_t j = 0; j < n; ++j) {
        re[j] = b.count[j] ? re[j] / (double)b.count[j] : 0.0;
        im[j] = b.count[j] ? im[j] / (double)b.count[j] : 0.0;
    }
    free(b.count);
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
    for (int a = 0; a < 2; ++a)
        if (ds_box_periodic(&w->box, a) && !(cutoff < 0.5 * w->box.side[a])) {
            const char *field = a ? "box_y" : "box";
            return ds_refuse(err, DS_ERR_ARG, field, w->box.side[a], 2.0 * cutoff,
                             "%s = %g: psi6's cutoff, 1.4 diameters (%g), must be below half "
                             "each periodic side",
                             field, w->box.side[a], cutoff);
        }
    double *re = malloc(n * sizeof *re), *im = malloc(n * sizeof *im);
    ds_status st = re && im ? DS_OK : DS_ERR_NOMEM;
    if (st == DS_OK)
        st = local_psi6(n, sim->disks.x, sim->disks.y, sim->disks.r,
                        sim->disks.r ? PSI6_CUTOFF_DIAMETERS : 0.0, &w->box, cutoff, re, im);
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
