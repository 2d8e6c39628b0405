/* SPDX-License-Identifier: MIT */
/* The disks of a simulation: reading them (one, every one, their radii,
 * masses, images and unwrapped centres, in generation order) and setting
 * them (one, every one at once, every velocity scaled), each new disk
 * checked as ds_check_disk says; the checkpoint's loader checks its disks
 * the same way. */
#include <math.h>
#include <stdlib.h>

#include "core/box.h"
#include "core/overlap.h"
#include "sim/sim.h"

/* The refusal of a NULL argument. */
static ds_status refuse_null(ds_error *err, const char *field)
{
    return ds_refuse(err, DS_ERR_ARG, field, NAN, NAN, "%s: NULL", field);
}

ds_disk ds_sim_get_disk(const ds_sim *sim, size_t i)
{
    ds_disk d = {0.0, 0.0, 0.0, 0.0};
    if (!sim || i >= sim->world.n)
        return d;
    const ds_disks *a = &sim->disks;
    const size_t k = a->slot[i];
    d.x = a->x[k];
    d.y = a->y[k];
    d.vx = a->vx[k];
    d.vy = a->vy[k];
    return d;
}

ds_status ds_sim_get_disks(const ds_sim *sim, ds_disk *out, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !out)
        return refuse_null(err, sim ? "out" : "sim");
    /* Read the arrays front to back and scatter by id: one scattered write
     * per disk, where gathering through slot[] would read four arrays at
     * scattered places. */
    const ds_disks *a = &sim->disks;
    for (size_t k = 0; k < a->n; ++k) {
        ds_disk *d = &out[a->id[k]];
        d->x = a->x[k];
        d->y = a->y[k];
        d->vx = a->vx[k];
        d->vy = a->vy[k];
    }
    return DS_OK;
}

ds_status ds_sim_get_radii(const ds_sim *sim, double *radii, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !radii)
        return refuse_null(err, sim ? "radii" : "sim");
    const ds_disks *a = &sim->disks;
    for (size_t k = 0; k < a->n; ++k)
        radii[a->id[k]] = a->r ? a->r[k] : sim->world.radius;
    return DS_OK;
}

ds_status ds_sim_get_masses(const ds_sim *sim, double *masses, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !masses)
        return refuse_null(err, sim ? "masses" : "sim");
    const ds_disks *a = &sim->disks;
    for (size_t k = 0; k < a->n; ++k)
        masses[a->id[k]] = a->m ? a->m[k] : 1.0;
    return DS_OK;
}

ds_status ds_sim_get_images(const ds_sim *sim, int32_t *image, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !image)
        return refuse_null(err, sim ? "image" : "sim");
    const ds_disks *a = &sim->disks;
    for (size_t k = 0; k < a->n; ++k) {
        image[2 * (size_t)a->id[k]] = a->ix ? a->ix[k] : 0;
        image[2 * (size_t)a->id[k] + 1] = a->iy ? a->iy[k] : 0;
    }
    return DS_OK;
}

ds_status ds_sim_get_unwrapped(const ds_sim *sim, double *xy, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !xy)
        return refuse_null(err, sim ? "xy" : "sim");
    const ds_disks *a = &sim->disks;
    const double box_x = sim->world.box.side[0], box_y = sim->world.box.side[1];
    /* A sheared box's image above stands offset along x (protocols.h). */
    const double offset = sim->world.box.offset;
    for (size_t k = 0; k < a->n; ++k) {
        const size_t i = a->id[k];
        xy[2 * i] = a->ix ? a->x[k] + (double)a->ix[k] * box_x + (double)a->iy[k] * offset : a->x[k];
        xy[2 * i + 1] = a->iy ? a->y[k] + (double)a->iy[k] * box_y : a->y[k];
    }
    return DS_OK;
}

static ds_status check_values(const ds_world *w, size_t i, double radius, double past, ds_disk d,
                              ds_error *err)
{
    if (!isfinite(d.x) || !isfinite(d.y) || !isfinite(d.vx) || !isfinite(d.vy))
        return ds_refuse(err, DS_ERR_ARG, "disk", NAN, NAN,
                         "disk %zu has a value that is not a finite number", i);
    if (fabs(d.vx) > DS_VELOCITY_MAX || fabs(d.vy) > DS_VELOCITY_MAX)
        return ds_refuse(err, DS_ERR_ARG, "disk", fmax(fabs(d.vx), fabs(d.vy)), DS_VELOCITY_MAX,
                         "disk %zu moves at (%g, %g): a velocity component beyond 1e12", i, d.vx,
                         d.vy);
    /* Along walls the centre stays R from each (past that by past); a
     * periodic side takes any point of [0, side), as frames show them. */
    const ds_box *b = &w->box;
    if (ds_box_holds(b, d.x, d.y, radius, past))
        return DS_OK;
    if (ds_box_periodic(b, 0) && ds_box_periodic(b, 1))
        return ds_refuse(err, DS_ERR_ARG, "disk", NAN, NAN,
                         "disk %zu at (%g, %g) is outside the periodic box [0, %g) x [0, %g)", i,
                         d.x, d.y, b->side[0], b->side[1]);
    double lo_x, hi_x, lo_y, hi_y;
    ds_box_reach(b, 0, radius, &lo_x, &hi_x);
    ds_box_reach(b, 1, radius, &lo_y, &hi_y);
    if (!ds_box_periodic(b, 0) && !ds_box_periodic(b, 1))
        return ds_refuse(err, DS_ERR_ARG, "disk", NAN, NAN,
                         "disk %zu at (%g, %g) is outside [%g, %g] x [%g, %g], where the "
                         "centre of a disk of radius %g stays between the walls",
                         i, d.x, d.y, lo_x - past, hi_x + past, lo_y - past, hi_y + past, radius);
    return ds_refuse(err, DS_ERR_ARG, "disk", NAN, NAN,
                     "disk %zu at (%g, %g) is outside the channel [0, %g) x [%g, %g], where the "
                     "centre of a disk of radius %g stays between the walls along y",
                     i, d.x, d.y, b->side[0], lo_y - past, hi_y + past, radius);
}

ds_status ds_check_disk(const ds_world *w, size_t i, double radius, double past, ds_disk d,
                        ds_error *err)
{
    const ds_status st = check_values(w, i, radius, past, d, err);
    if (st != DS_OK)
        ds_error_index(err, i);
    return st;
}

/* Disk i's radius (generation order). */
static double radius_of(const ds_sim *sim, size_t i)
{
    return sim->disks.r ? sim->disks.r[sim->disks.slot[i]] : sim->world.radius;
}

ds_status ds_sim_set_disk(ds_sim *sim, size_t i, ds_disk d, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return refuse_null(err, "sim");
    if (i >= sim->world.n) {
        ds_error_index(err, i);
        return ds_refuse(err, DS_ERR_ARG, "disk", (double)i, (double)sim->world.n,
                         "disk %zu is not one of the %zu disks", i, sim->world.n);
    }
    ds_status st = ds_check_disk(&sim->world, i, radius_of(sim, i), 0.0, d, err);
    if (st != DS_OK)
        return st;
    st = sim->integrator->set(sim, sim->disks.slot[i], d);
    if (st == DS_ERR_OVERLAP)
        return ds_refuse(err, st, "disk", NAN, NAN,
                         "disk %zu at (%g, %g) would overlap another disk", i, d.x, d.y);
    if (st == DS_OK)
        ds_protocols_disks_set(sim, 0);
    return ds_error_done(err, st);
}

/* The first pair closer than contact allows, named; radii in generation
 * order (NULL: one radius). */
static ds_status check_overlaps(const ds_world *w, const ds_disk *disks, const double *radii,
                                ds_error *err)
{
    const size_t n = w->n;
    double *xy = malloc(2 * n * sizeof *xy);
    ds_status st = xy ? DS_OK : DS_ERR_NOMEM;
    size_t j = 0, k = 0;
    for (size_t i = 0; xy && i < n; ++i) {
        xy[i] = disks[i].x;
        xy[n + i] = disks[i].y;
    }
    if (xy)
        st = ds_find_overlap(w, xy, xy + n, radii, &j, &k);
    free(xy);
    if (st == DS_ERR_NOMEM)
        return ds_refuse(err, DS_ERR_NOMEM, "disks", NAN, NAN, "no memory to check %zu disks", n);
    if (st != DS_OK) {
        double dx = disks[k].x - disks[j].x, dy = disks[k].y - disks[j].y;
        ds_box_nearest(&w->box, &dx, &dy);
        const double apart = sqrt(dx * dx + dy * dy);
        const double contact = radii ? radii[j] + radii[k] : 2.0 * w->radius;
        ds_error_index(err, j);
        return ds_refuse(err, DS_ERR_OVERLAP, "disks", apart, contact,
                         "disks %zu and %zu overlap: their centres are %.17g apart, closer "
                         "than their radii's sum, %.17g",
                         j, k, apart, contact);
    }
    return DS_OK;
}

/* A simulation like sim but from disks (checked), images 0, its
 * integrator's state built for them; on failure fresh holds nothing. */
static ds_status build_fresh(ds_sim *sim, const ds_disk *disks, ds_sim *fresh, ds_error *err)
{
    const size_t n = sim->world.n;
    *fresh = *sim;
    fresh->state = NULL;
    /* Every column of the disks (radii, masses, kinds) in generation
     * order, the new centres and velocities, images 0 (a new state). */
    ds_status st = ds_disks_clone_ordered(&fresh->disks, &sim->disks);
    if (st == DS_OK) {
        ds_disks *d = &fresh->disks;
        for (size_t i = 0; i < n; ++i) {
            d->x[i] = disks[i].x;
            d->y[i] = disks[i].y;
            d->vx[i] = disks[i].vx;
            d->vy[i] = disks[i].vy;
            if (d->ix)
                d->ix[i] = d->iy[i] = 0;
        }
        st = fresh->integrator->create(fresh, NULL);
    }
    if (st != DS_OK) {
        fresh->integrator->destroy(fresh);
        ds_disks_free(&fresh->disks);
        return ds_refuse(err, st, "disks", NAN, NAN, "no memory for the new state of %zu disks", n);
    }
    ds_disks_rebuild_slots(&fresh->disks);
    return DS_OK;
}

ds_status ds_sim_set_disks(ds_sim *sim, const ds_disk *disks, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !disks)
        return refuse_null(err, sim ? "disks" : "sim");
    const ds_world *w = &sim->world;
    double *radii = NULL;
    if (sim->disks.r) {
        if (!(radii = malloc(w->n * sizeof *radii)))
            return ds_refuse(err, DS_ERR_NOMEM, "disks", NAN, NAN, "no memory to check %zu disks",
                             w->n);
        ds_sim_get_radii(sim, radii, NULL);
    }
    ds_status st = DS_OK;
    for (size_t i = 0; i < w->n && st == DS_OK; ++i)
        st = ds_check_disk(w, i, radii ? radii[i] : w->radius, 0.0, disks[i], err);
    if (st == DS_OK)
        st = check_overlaps(w, disks, radii, err);
    free(radii);
    /* A fresh simulation from the new state, at the present time; the old
     * one is replaced only once the new one stands, so a failure changes
     * nothing. */
    ds_sim fresh;
    if (st == DS_OK)
        st = build_fresh(sim, disks, &fresh, err);
    if (st != DS_OK)
        return st;
    sim->integrator->destroy(sim);
    ds_disks_free(&sim->disks);
    *sim = fresh;
    ds_protocols_disks_set(sim, 1);
    return DS_OK;
}

ds_status ds_sim_scale_velocities(ds_sim *sim, double factor, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return refuse_null(err, "sim");
    if (!(factor > 0.0) || !isfinite(factor))
        return ds_refuse(err, DS_ERR_ARG, "factor", factor, 0.0,
                         "factor = %g must be finite and > 0", factor);
    /* No faster than ds_sim_set_disk takes: an infinite velocity would
     * never let an event-driven step end. */
    double fastest = 0.0;
    for (size_t i = 0; i < sim->disks.n; ++i)
        fastest = fmax(fastest, fmax(fabs(sim->disks.vx[i]), fabs(sim->disks.vy[i])));
    if (!(fastest * factor <= DS_VELOCITY_MAX))
        return ds_refuse(err, DS_ERR_ARG, "factor", factor, DS_VELOCITY_MAX / fastest,
                         "factor = %g would take a velocity component from %g to %g, beyond %g "
                         "(at most %g)",
                         factor, fastest, fastest * factor, DS_VELOCITY_MAX,
                         DS_VELOCITY_MAX / fastest);
    const ds_status st = sim->integrator->scale_velocities(sim, factor);
    if (st == DS_OK)
        ds_protocols_scaled(sim, factor);
    return ds_error_done(err, st);
}
