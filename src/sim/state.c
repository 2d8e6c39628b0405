/* A simulation's whole state at once: checking a state to start from and
 * setting every disk (ds_set_all). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/boundary.h"
#include "core/grid.h"
#include "sim/sim.h"

ds_status ds_state_refuse(ds_state_error *err, ds_status status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return status;
}

ds_status ds_check_disk(const ds_world *w, size_t i, ds_disk d, ds_state_error *err)
{
    if (!isfinite(d.x) || !isfinite(d.y) || !isfinite(d.vx) || !isfinite(d.vy))
        return ds_state_refuse(err, DS_ERR_ARG, "disk %zu has a value that is not a finite number",
                               i);
    if (fabs(d.vx) > 1e12 || fabs(d.vy) > 1e12)
        return ds_state_refuse(err, DS_ERR_ARG,
                               "disk %zu moves at (%g, %g): a velocity component beyond 1e12", i,
                               d.vx, d.vy);
    /* With walls the centre stays R from each wall; a periodic box takes
     * any point of [0, box) x [0, box_y), as its frames show them. */
    if (w->boundary == DS_PERIODIC) {
        if (!(d.x >= 0.0 && d.x < w->box && d.y >= 0.0 && d.y < w->box_y))
            return ds_state_refuse(err, DS_ERR_ARG,
                                   "disk %zu at (%g, %g) is outside the periodic box [0, %g) x "
                                   "[0, %g)",
                                   i, d.x, d.y, w->box, w->box_y);
    } else if (!(d.x >= w->radius && d.x <= w->box - w->radius && d.y >= w->radius &&
                 d.y <= w->box_y - w->radius)) {
        return ds_state_refuse(err, DS_ERR_ARG,
                               "disk %zu at (%g, %g) is outside [%g, %g] x [%g, %g], where the "
                               "centre of a disk of radius %g stays between the walls",
                               i, d.x, d.y, w->radius, w->box - w->radius, w->radius,
                               w->box_y - w->radius, w->radius);
    }
    return DS_OK;
}

/* The first pair (in the order of the disks) closer than contact allows,
 * through a cell grid: O(n). */
static ds_status check_overlaps(const ds_world *w, const ds_disk *disks, ds_state_error *err)
{
    const size_t n = w->n;
    const int periodic = w->boundary == DS_PERIODIC;
    const double contact = 2.0 * w->radius;
    const double limit = contact * (1.0 - DS_CONTACT_TOLERANCE);
    double *xy = malloc(2 * n * sizeof *xy);
    if (!xy)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to check %zu disks", n);
    for (size_t i = 0; i < n; ++i) {
        xy[i] = disks[i].x;
        xy[n + i] = disks[i].y;
    }
    ds_grid g;
    ds_grid_init(&g, w->box, w->box_y, contact, 4 * n + 16, periodic);
    ds_grid_bins bins;
    ds_status st = ds_grid_bin(&g, n, xy, xy + n, &bins);
    if (st != DS_OK) {
        free(xy);
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to check %zu disks", n);
    }
    for (size_t j = 0; j < n && st == DS_OK; ++j) {
        size_t around[9];
        const int count = ds_grid_neighbours(&g, bins.cell[j] % g.nx, bins.cell[j] / g.nx, around);
        for (int c = 0; c < count && st == DS_OK; ++c)
            for (size_t s = bins.start[around[c]]; s < bins.start[around[c] + 1]; ++s) {
                const size_t k = bins.order[s];
                double dx = xy[k] - xy[j], dy = xy[n + k] - xy[n + j];
                if (periodic) {
                    dx = ds_nearest(dx, w->box);
                    dy = ds_nearest(dy, w->box_y);
                }
                if (k > j && dx * dx + dy * dy < limit * limit) {
                    st = ds_state_refuse(err, DS_ERR_OVERLAP,
                                         "disks %zu and %zu overlap: their centres are %.17g "
                                         "apart, closer than 2R = %.17g",
                                         j, k, sqrt(dx * dx + dy * dy), contact);
                    break;
                }
            }
    }
    ds_grid_bins_free(&bins);
    free(xy);
    return st;
}

ds_status ds_set_all(ds_sim *sim, const ds_disk *disks, ds_state_error *err)
{
    if (err)
        err->message[0] = '\0';
    if (!sim || !disks)
        return ds_state_refuse(err, DS_ERR_ARG, "no simulation or no disks (NULL)");
    const ds_world *w = &sim->world;
    for (size_t i = 0; i < w->n; ++i) {
        const ds_status st = ds_check_disk(w, i, disks[i], err);
        if (st != DS_OK)
            return st;
    }
    ds_status st = check_overlaps(w, disks, err);
    if (st != DS_OK)
        return st;
    /* A fresh simulation from the new state, at the present time; the old
     * one is replaced only once the new one stands, so a failure changes
     * nothing. */
    ds_sim fresh = *sim;
    fresh.state = NULL;
    st = ds_disks_alloc(&fresh.disks, w->n);
    if (st == DS_OK) {
        for (size_t i = 0; i < w->n; ++i) {
            fresh.disks.x[i] = disks[i].x;
            fresh.disks.y[i] = disks[i].y;
            fresh.disks.vx[i] = disks[i].vx;
            fresh.disks.vy[i] = disks[i].vy;
        }
        st = fresh.integrator->create(&fresh);
    }
    if (st != DS_OK) {
        fresh.integrator->destroy(&fresh);
        ds_disks_free(&fresh.disks);
        return ds_state_refuse(err, st, "no memory for the new state of %zu disks", w->n);
    }
    ds_disks_rebuild_slots(&fresh.disks);
    sim->integrator->destroy(sim);
    ds_disks_free(&sim->disks);
    *sim = fresh;
    return DS_OK;
}
