/* SPDX-License-Identifier: MIT */
/* The simulation: the public API of creating and running it and of what
 * it is, dispatching to the integrator through its table (core.h). It
 * never asks which integrator it has. */
#include <math.h>
#include <stdlib.h>

#include "sim/sim.h"
#include "init/init.h"

/* A mixture's radii and masses into the disk arrays (generation order):
 * an array only where the disks differ from the world's radius or from
 * mass 1, so that a mixture of one kind of radius R and mass 1 is the
 * plain simulation, to the bit. */
static ds_status fill_mixture(ds_disks *d, const ds_mixture *m, double radius)
{
    int radii = 0, masses = 0;
    for (size_t i = 0; i < d->n; ++i) {
        radii |= ds_mixture_radius(m, i) != radius;
        masses |= ds_mixture_mass(m, radius, i) != 1.0;
    }
    if (ds_disks_add_mixture(d, radii, masses) != DS_OK)
        return DS_ERR_NOMEM;
    for (size_t i = 0; i < d->n; ++i) {
        if (d->r)
            d->r[i] = ds_mixture_radius(m, i);
        if (d->m)
            d->m[i] = ds_mixture_mass(m, radius, i);
    }
    return DS_OK;
}

/* The disk arrays of a new simulation, placed; on failure err says why. */
static ds_status make_disks(ds_sim *sim, const ds_mixture *mixture, ds_error *err)
{
    const ds_world *w = &sim->world;
    ds_status st = ds_disks_alloc(&sim->disks, w->n);
    if (st == DS_OK && mixture)
        st = fill_mixture(&sim->disks, mixture, w->radius);
    if (st == DS_OK)
        st = ds_kinds_make(sim, mixture);
    /* The radii and the area covered as every later part computes them
     * from the arrays (a checkpoint's load, growth): the same bits. */
    if (st == DS_OK)
        ds_world_take_radii(&sim->world, &sim->disks);
    if (st == DS_OK && ds_box_any_periodic(&w->box))
        st = ds_disks_add_images(&sim->disks);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)w->n, NAN, "n = %zu disks: no memory for them",
                         w->n);
    st = ds_place(&sim->disks, w);
    if (st == DS_ERR_PLACEMENT)
        return ds_refuse(err, st, "n", (double)w->n, NAN,
                         "n = %zu disks: random placement found no free spot for one in 2 million "
                         "draws (seed %llu; another seed, or fewer or smaller disks)",
                         w->n, (unsigned long long)w->seed);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)w->n, NAN, "n = %zu disks: no memory to place them",
                         w->n);
    return DS_OK;
}

ds_status ds_sim_create(const ds_params *params, const ds_mixture *mixture, ds_sim **out,
                        ds_error *err)
{
    ds_error_clear(err);
    if (!out)
        return ds_refuse(err, DS_ERR_ARG, "out", NAN, NAN, "out: nowhere to put the simulation");
    *out = NULL;
    ds_world w;
    ds_status st = ds_world_of_request(params, mixture, &w, err);
    if (st != DS_OK)
        return st;
    ds_sim *sim = calloc(1, sizeof *sim);
    if (!sim)
        return ds_refuse(err, DS_ERR_NOMEM, "n", (double)w.n, NAN,
                         "n = %zu disks: no memory for the simulation", w.n);
    ds_protocols_refresh(&sim->protocols);
    sim->world = w;
    sim->integrator = ds_integrator_ops_of(w.integrator);
    if (sim->world.broadphase == DS_BROADPHASE_AUTO)
        sim->world.broadphase = sim->integrator->choose(&sim->world);
    st = make_disks(sim, mixture, err);
    if (st == DS_OK)
        st = sim->integrator->create(sim, err);
    if (st != DS_OK) {
        ds_sim_destroy(sim);
        return ds_error_done(err, st);
    }
    ds_disks_rebuild_slots(&sim->disks);
    ds_timer_reset(&sim->collision_timer);
    *out = sim;
    return ds_error_done(err, DS_OK);
}

void ds_sim_destroy(ds_sim *sim)
{
    if (!sim)
        return;
    ds_protocols_destroy_all(&sim->protocols);
    if (sim->integrator)
        sim->integrator->destroy(sim);
    ds_disks_free(&sim->disks);
    free(sim->kind_names);
    free(sim->metadata);
    free(sim);
}

ds_status ds_sim_run(ds_sim *sim, uint64_t steps, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    if (steps == 0)
        return DS_OK;
    /* The kinetic tensor the run changes collision by collision
     * (collide.h), from the disks as they are now: whatever set them
     * since the last run is in it. */
    ds_disks_kinetic_tensor(&sim->disks, sim->tally.kinetic);
    return ds_error_done(err, sim->integrator->run(sim, steps, err));
}

ds_status ds_sim_step(ds_sim *sim, ds_error *err) { return ds_sim_run(sim, 1, err); }

size_t ds_sim_get_count(const ds_sim *sim) { return sim ? sim->world.n : 0; }
double ds_sim_get_radius(const ds_sim *sim) { return sim ? sim->world.radius : 0.0; }
double ds_sim_get_radius_max(const ds_sim *sim) { return sim ? sim->world.radius_max : 0.0; }
double ds_sim_get_box_width(const ds_sim *sim) { return sim ? sim->world.box.side[0] : 0.0; }
double ds_sim_get_box_height(const ds_sim *sim) { return sim ? sim->world.box.side[1] : 0.0; }
double ds_sim_get_area_fraction(const ds_sim *sim)
{
    return sim ? sim->world.covered / (sim->world.box.side[0] * sim->world.box.side[1]) : 0.0;
}
double ds_sim_get_dt(const ds_sim *sim) { return sim ? sim->world.dt : 0.0; }
/* steps * dt rather than a running sum, so time carries no rounding drift
 * (io/xyz.c computes it the same way). */
double ds_sim_get_time(const ds_sim *sim) { return sim ? (double)sim->steps * sim->world.dt : 0.0; }
uint64_t ds_sim_get_steps(const ds_sim *sim) { return sim ? sim->steps : 0; }
uint64_t ds_sim_get_seed(const ds_sim *sim) { return sim ? sim->world.seed : 0; }
ds_integrator ds_sim_get_integrator(const ds_sim *sim)
{
    return sim ? sim->world.integrator : DS_INTEGRATOR_TIME_STEP;
}
ds_boundary ds_sim_get_boundary(const ds_sim *sim)
{
    return sim ? sim->world.boundary : DS_BOUNDARY_WALLS;
}
ds_placement ds_sim_get_placement(const ds_sim *sim)
{
    return sim ? sim->world.placement : DS_PLACEMENT_RANDOM;
}
ds_broadphase ds_sim_get_broadphase(const ds_sim *sim)
{
    return sim ? sim->world.broadphase : DS_BROADPHASE_AUTO;
}

double ds_sim_get_collision_seconds(const ds_sim *sim)
{
    return sim ? ds_timer_seconds(&sim->collision_timer) : 0.0;
}
uint64_t ds_sim_get_collision_count(const ds_sim *sim) { return sim ? sim->tally.collisions : 0; }
uint64_t ds_sim_get_pairs_tested(const ds_sim *sim) { return sim ? sim->tally.pairs_tested : 0; }
