/* SPDX-License-Identifier: MIT */
/* The simulation: the public API of creation, stepping and the disks,
 * dispatching to the integrator through its table (core.h). It never
 * asks which integrator it has. */
#include <math.h>
#include <stdlib.h>

#include "sim/sim.h"
#include "init/init.h"
#include "protocols/protocols.h"

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

ds_status ds_create_mixture(const ds_params *params, const ds_mixture *mixture, ds_sim **out)
{
    if (!out)
        return DS_ERR_ARG;
    *out = NULL;
    ds_world w;
    ds_status st = ds_world_of_request(params, mixture, &w);
    if (st != DS_OK)
        return st;
    ds_sim *sim = calloc(1, sizeof *sim);
    if (!sim)
        return DS_ERR_NOMEM;
    ds_protocols_refresh(&sim->protocols);
    sim->world = w;
    sim->integrator = ds_integrator_ops_of(sim->world.integrator);
    st = ds_disks_alloc(&sim->disks, sim->world.n);
    if (st == DS_OK && mixture)
        st = fill_mixture(&sim->disks, mixture, w.radius);
    /* The radii and the area covered as every later part computes them
     * from the arrays (a checkpoint's load, growth): the same bits. */
    if (st == DS_OK)
        ds_world_take_radii(&sim->world, &sim->disks);
    if (sim->world.broadphase == DS_AUTO)
        sim->world.broadphase = sim->integrator->choose(&sim->world);
    if (st == DS_OK && w.boundary == DS_PERIODIC)
        st = ds_disks_add_images(&sim->disks);
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

ds_status ds_create(const ds_params *params, ds_sim **out)
{
    return ds_create_mixture(params, NULL, out);
}

void ds_destroy(ds_sim *sim)
{
    if (!sim)
        return;
    ds_protocols_destroy_all(&sim->protocols);
    if (sim->integrator)
        sim->integrator->destroy(sim);
    ds_disks_free(&sim->disks);
    free(sim);
}

void ds_run(ds_sim *sim, uint64_t steps)
{
    if (!sim || steps == 0)
        return;
    /* The kinetic tensor the run changes collision by collision
     * (collide.h), from the disks as they are now: whatever set them
     * since the last run is in it. */
    ds_disks_kinetic_tensor(&sim->disks, sim->tally.kinetic);
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

ds_status ds_get_images(const ds_sim *sim, int32_t *image)
{
    if (!sim || !image)
        return DS_ERR_ARG;
    const ds_disks *a = &sim->disks;
    for (size_t k = 0; k < a->n; ++k) {
        image[2 * (size_t)a->id[k]] = a->ix ? a->ix[k] : 0;
        image[2 * (size_t)a->id[k] + 1] = a->iy ? a->iy[k] : 0;
    }
    return DS_OK;
}

ds_status ds_get_unwrapped(const ds_sim *sim, double *xy)
{
    if (!sim || !xy)
        return DS_ERR_ARG;
    const ds_disks *a = &sim->disks;
    const double box_x = sim->world.box, box_y = sim->world.box_y;
    for (size_t k = 0; k < a->n; ++k) {
        const size_t i = a->id[k];
        xy[2 * i] = a->ix ? a->x[k] + (double)a->ix[k] * box_x : a->x[k];
        xy[2 * i + 1] = a->iy ? a->y[k] + (double)a->iy[k] * box_y : a->y[k];
    }
    return DS_OK;
}

ds_status ds_set(ds_sim *sim, size_t i, ds_disk d)
{
    if (!sim || i >= sim->world.n ||
        ds_check_disk(&sim->world, i, ds_radius_of(sim, i), 0.0, d, NULL) != DS_OK)
        return DS_ERR_ARG;
    const ds_status st = sim->integrator->set(sim, sim->disks.slot[i], d);
    if (st == DS_OK)
        ds_protocols_disks_set(sim, 0);
    return st;
}

double ds_radius_of(const ds_sim *sim, size_t i)
{
    if (!sim || i >= sim->world.n)
        return 0.0;
    return sim->disks.r ? sim->disks.r[sim->disks.slot[i]] : sim->world.radius;
}

double ds_mass_of(const ds_sim *sim, size_t i)
{
    if (!sim || i >= sim->world.n)
        return 0.0;
    return sim->disks.m ? sim->disks.m[sim->disks.slot[i]] : 1.0;
}

ds_status ds_get_radii(const ds_sim *sim, double *radii, double *masses)
{
    if (!sim)
        return DS_ERR_ARG;
    const ds_disks *a = &sim->disks;
    for (size_t k = 0; k < a->n; ++k) {
        if (radii)
            radii[a->id[k]] = a->r ? a->r[k] : sim->world.radius;
        if (masses)
            masses[a->id[k]] = a->m ? a->m[k] : 1.0;
    }
    return DS_OK;
}

double ds_radius_max(const ds_sim *sim) { return sim ? sim->world.radius_max : 0.0; }

double ds_area_fraction(const ds_sim *sim)
{
    return sim ? sim->world.covered / (sim->world.box * sim->world.box_y) : 0.0;
}

ds_status ds_set_growth(ds_sim *sim, double rate, double until_eta, double until_z)
{
    if (!sim || !sim->integrator->grow || sim->world.boundary != DS_PERIODIC ||
        !(rate >= 0.0) || !isfinite(rate) ||
        !(until_eta >= 0.0 && until_eta < 1.0) ||
        (until_eta > 0.0 && until_eta <= ds_area_fraction(sim)) ||
        !(until_z == 0.0 || (until_z > 1.0 && until_z <= 1e9)))
        return DS_ERR_ARG;
    /* The compression must be slow beside the motion: the surfaces of the
     * largest pair recede at 2 r_max rate, at most 10 rms speeds (past
     * 1000, 20 disks made no step in 20 s: every collision sends a pair
     * off at twice the surfaces' speed, and the growth outruns them). */
    double mass = 0.0;
    for (size_t i = 0; i < sim->disks.n; ++i)
        mass += sim->disks.m ? sim->disks.m[i] : 1.0;
    const double rms = mass > 0.0 ? sqrt(2.0 * ds_kinetic_energy(sim) / mass) : 0.0;
    if (rate > 0.0 && !(2.0 * ds_radius_max(sim) * rate <= 10.0 * rms))
        return DS_ERR_ARG;
    return ds_growth_start(sim, rate, until_eta, until_z == 0.0 ? DS_JAMMED_Z : until_z);
}

ds_growth_state ds_growth_state_of(const ds_sim *sim)
{
    double z = 0.0;
    return sim ? (ds_growth_state)ds_growth_state_get(sim, &z) : DS_GROWTH_NONE;
}

double ds_growth_z(const ds_sim *sim)
{
    double z = 0.0;
    if (sim)
        (void)ds_growth_state_get(sim, &z);
    return z;
}

ds_status ds_scale_velocities(ds_sim *sim, double factor)
{
    if (!sim || !(factor > 0.0) || !isfinite(factor))
        return DS_ERR_ARG;
    /* No faster than ds_set takes: an infinite velocity would never let an
     * event-driven step end. */
    double fastest = 0.0;
    for (size_t i = 0; i < sim->disks.n; ++i)
        fastest = fmax(fastest, fmax(fabs(sim->disks.vx[i]), fabs(sim->disks.vy[i])));
    if (!(fastest * factor <= DS_VELOCITY_MAX))
        return DS_ERR_ARG;
    const ds_status st = sim->integrator->scale_velocities(sim, factor);
    if (st == DS_OK)
        ds_protocols_scaled(sim, factor);
    return st;
}

double ds_collision_seconds(const ds_sim *sim)
{
    return sim ? ds_timer_seconds(&sim->collision_timer) : 0.0;
}
uint64_t ds_collision_count(const ds_sim *sim) { return sim ? sim->tally.collisions : 0; }
uint64_t ds_pairs_tested(const ds_sim *sim) { return sim ? sim->tally.pairs_tested : 0; }
