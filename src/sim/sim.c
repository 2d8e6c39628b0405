/* SPDX-License-Identifier: MIT */
/* The simulation: the public API of creation, stepping and the disks,
 * dispatching to the integrator through its table (core.h). It never
 * asks which integrator it has. */
#include <math.h>
#include <stdlib.h>

#include "sim/sim.h"
#include "init/init.h"

ds_status ds_create(const ds_params *params, ds_sim **out)
{
    if (!out)
        return DS_ERR_ARG;
    *out = NULL;
    ds_status st = ds_check_params(params, NULL);
    if (st != DS_OK)
        return st;
    ds_sim *sim = calloc(1, sizeof *sim);
    if (!sim)
        return DS_ERR_NOMEM;
    sim->world = ds_world_of(params);
    sim->integrator = ds_integrator_ops_of(sim->world.integrator);
    if (sim->world.broadphase == DS_AUTO)
        sim->world.broadphase = sim->integrator->choose(&sim->world);
    st = ds_disks_alloc(&sim->disks, sim->world.n);
    if (st == DS_OK)
        st = ds_place(&sim->disks, &sim->world);
    if (st == DS_OK)
        st = sim->integrator->create(sim);
    if (st != DS_OK) {
        ds_destroy(sim);
        return st;
    }
    ds_disks_rebuild_slots(&sim->disks);
    ds_timer_reset(&sim->collision_timer);
    *out = sim;
    return DS_OK;
}

void ds_destroy(ds_sim *sim)
{
    if (!sim)
        return;
    if (sim->integrator)
        sim->integrator->destroy(sim);
    ds_disks_free(&sim->disks);
    free(sim);
}

void ds_run(ds_sim *sim, uint64_t steps)
{
    if (!sim || steps == 0)
        return;
    sim->integrator->run(sim, steps);
}

void ds_step(ds_sim *sim) { ds_run(sim, 1); }

size_t ds_count(const ds_sim *sim) { return sim ? sim->world.n : 0; }
double ds_radius(const ds_sim *sim) { return sim ? sim->world.radius : 0.0; }
double ds_box(const ds_sim *sim) { return sim ? sim->world.box : 0.0; }
double ds_box_y(const ds_sim *sim) { return sim ? sim->world.box_y : 0.0; }
double ds_dt(const ds_sim *sim) { return sim ? sim->world.dt : 0.0; }
/* steps * dt rather than a running sum, so time carries no rounding drift. */
double ds_time(const ds_sim *sim) { return sim ? (double)sim->steps * sim->world.dt : 0.0; }
uint64_t ds_steps(const ds_sim *sim) { return sim ? sim->steps : 0; }
ds_boundary ds_boundary_used(const ds_sim *sim) { return sim ? sim->world.boundary : DS_WALLS; }
ds_broadphase ds_broadphase_used(const ds_sim *sim) { return sim ? sim->world.broadphase : DS_SAP; }
ds_integrator ds_integrator_used(const ds_sim *sim)
{
    return sim ? sim->world.integrator : DS_TIME_STEP;
}

ds_disk ds_get(const ds_sim *sim, size_t i)
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

ds_status ds_get_all(const ds_sim *sim, ds_disk *out)
{
    if (!sim || !out)
        return DS_ERR_ARG;
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

ds_status ds_set(ds_sim *sim, size_t i, ds_disk d)
{
    if (!sim || i >= sim->world.n || ds_check_disk(&sim->world, i, d, NULL) != DS_OK)
        return DS_ERR_ARG;
    return sim->integrator->set(sim, sim->disks.slot[i], d);
}

double ds_collision_seconds(const ds_sim *sim)
{
    return sim ? ds_timer_seconds(&sim->collision_timer) : 0.0;
}
uint64_t ds_collision_count(const ds_sim *sim) { return sim ? sim->tally.collisions : 0; }
uint64_t ds_pairs_tested(const ds_sim *sim) { return sim ? sim->tally.pairs_tested : 0; }
