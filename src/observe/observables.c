/* SPDX-License-Identifier: MIT */
/* The observables of a simulation: kinetic energy and momentum from the
 * disks, wall pressure and virial pressure from what the integrators
 * tallied since the last reset. */
#include "core/core.h"
#include "observe/observe.h"

double ds_kinetic_energy(const ds_sim *sim)
{
    if (!sim)
        return 0.0;
    const ds_disks *d = &sim->disks;
    double e = 0.0;
    for (size_t k = 0; k < d->n; ++k)
        e += d->vx[k] * d->vx[k] + d->vy[k] * d->vy[k];
    return 0.5 * e;
}

void ds_momentum(const ds_sim *sim, double *px, double *py)
{
    double sx = 0.0, sy = 0.0;
    for (size_t k = 0; sim && k < sim->disks.n; ++k) {
        sx += sim->disks.vx[k];
        sy += sim->disks.vy[k];
    }
    if (px)
        *px = sx;
    if (py)
        *py = sy;
}

uint64_t ds_wall_count(const ds_sim *sim) { return sim ? sim->tally.wall_count : 0; }
double ds_wall_impulse(const ds_sim *sim) { return sim ? sim->tally.wall_impulse : 0.0; }

/* Simulated time since the last reset. */
static double elapsed(const ds_sim *sim)
{
    return (double)(sim->steps - sim->observables_since_step) * sim->world.dt;
}

double ds_pressure(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    const ds_world *w = &sim->world;
    if (w->boundary == DS_PERIODIC) /* no wall to push on */
        return ds_virial_pressure(sim);
    const double perimeter = 2.0 * (w->box - 2.0 * w->radius) + 2.0 * (w->box_y - 2.0 * w->radius);
    return sim->tally.wall_impulse / (elapsed(sim) * perimeter);
}

/* The area the centres reach: with walls they stay R from each wall. */
static double centre_area(const ds_world *w)
{
    if (w->boundary == DS_PERIODIC)
        return w->box * w->box_y;
    return (w->box - 2.0 * w->radius) * (w->box_y - 2.0 * w->radius);
}

double ds_virial_pressure(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    return (ds_kinetic_energy(sim) + sim->tally.virial / (2.0 * elapsed(sim))) /
           centre_area(&sim->world);
}

void ds_reset_observables(ds_sim *sim)
{
    if (!sim)
        return;
    sim->tally.wall_count = 0;
    sim->tally.wall_impulse = 0.0;
    sim->tally.virial = 0.0;
    sim->observables_since_step = sim->steps;
}
