/* SPDX-License-Identifier: MIT */
/* The box rescaled: its sides times sx and sy and every centre with them,
 * at the present step boundary (a barostat's move, protocols/barostat.c,
 * through the integrators' resize service). The box is the world's, and
 * the integrators' states are built for it (cells, broad phases, clocks),
 * so a new box is a new state: built beside the old one as
 * ds_sim_set_disks builds one (a copy of the disk columns, scaled, and
 * the integrator's own state made for them through its table), and
 * swapped in only once it stands, so that a move refused, or without
 * memory, changes nothing. */
#include <math.h>

#include "core/core.h"
#include "core/pairs.h"

/* ds_params' bound on a side (sim/params.c). */
#define SIDE_MOST 1e9

typedef struct new_overlap {
    const double *r; /* radii by slot, or NULL for one radius */
    double radius, keep, sx, sy;
} new_overlap;

/* A pair closer than contact in the scaled box that was not before:
 * (dx, dy) joins them in the scaled box, (dx / sx, dy / sy) before (the
 * same image: every side is more than two diameters). The time step's
 * disks may overlap a little at a step's end (it sees each collision
 * after it happens): those pairs are left to it, as they were. */
static int is_new_overlap(void *ctx, size_t j, size_t k, double dx, double dy, double r2)
{
    const new_overlap *o = ctx;
    const double contact = (o->r ? o->r[j] + o->r[k] : 2.0 * o->radius) * o->keep;
    const double c2 = contact * contact, bx = dx / o->sx, by = dy / o->sy;
    return r2 < c2 && !(bx * bx + by * by < c2);
}

static ds_status check_new_overlaps(const ds_sim *fresh, double sx, double sy)
{
    const ds_world *w = &fresh->world;
    const ds_disks *d = &fresh->disks;
    new_overlap o = {d->r, w->radius, 1.0 - DS_CONTACT_TOLERANCE, sx, sy};
    ds_pairs p;
    if (ds_pairs_begin(&p, &w->box, w->n, d->x, d->y, 2.0 * w->radius_max, 4 * w->n + 16, 1) !=
        DS_OK)
        return DS_ERR_NOMEM;
    const int found = ds_pairs_each(&p, 0, is_new_overlap, &o);
    ds_pairs_end(&p);
    return found ? DS_ERR_OVERLAP : DS_OK;
}

ds_status ds_rescale_box(ds_sim *sim, double sx, double sy)
{
    const ds_box *b = &sim->world.box;
    const double wx = b->side[0] * sx, wy = b->side[1] * sy, r = sim->world.radius_max;
    if (!ds_box_periodic(b, 0) || !ds_box_periodic(b, 1) || !(r < 0.25 * wx && r < 0.25 * wy) ||
        !(wx <= SIDE_MOST && wy <= SIDE_MOST))
        return DS_ERR_ARG;
    ds_sim fresh = *sim;
    fresh.state = NULL;
    ds_status st = ds_disks_clone(&fresh.disks, &sim->disks);
    if (st != DS_OK)
        return st;
    fresh.world.box.side[0] = wx;
    fresh.world.box.side[1] = wy;
    /* Every centre scaled, wrapped back into the box where rounding took
     * it to the far side itself (a wrap an image count records). */
    ds_disks *d = &fresh.disks;
    for (size_t k = 0; k < d->n; ++k) {
        double x = d->x[k] * sx, y = d->y[k] * sy;
        ds_box_wrap(&fresh.world.box, &x, &y, &d->ix[k], &d->iy[k]);
        d->x[k] = x;
        d->y[k] = y;
    }
    ds_disks_rebuild_slots(d); /* the time step's are stale inside its run */
    st = check_new_overlaps(&fresh, sx, sy);
    if (st == DS_OK)
        st = fresh.integrator->create(&fresh, NULL);
    if (st != DS_OK) {
        fresh.integrator->destroy(&fresh);
        ds_disks_free(&fresh.disks);
        return st;
    }
    ds_disks_rebuild_slots(&fresh.disks);
    sim->integrator->destroy(sim);
    ds_disks_free(&sim->disks);
    *sim = fresh;
    return DS_OK;
}
