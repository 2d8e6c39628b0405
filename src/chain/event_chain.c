/* SPDX-License-Identifier: MIT */
/* DS_INTEGRATOR_EVENT_CHAIN: event-chain Monte Carlo (Bernard, Krauth and
 * Wilson 2009), straight chains along +x and +y in turn (chain_move.c).
 *
 * What the integrator contract asks, and what it means here:
 * - Time. A step of dt carries n speed dt of chain displacement in all,
 *   the distance n disks at the request's speed fly in dt: molecular
 *   dynamics and the chains then do about as many events per step, and
 *   ds_sim_get_time counts steps as for the other integrators. A chain
 *   that a step's end interrupts goes on in the next step.
 * - Velocities. The chains never touch them: frames show the velocities
 *   the disks were given (placement, ds_sim_set_disk), and they stand for
 *   the temperature, kT = K / N (no momentum is conserved, so every
 *   component is a degree of freedom).
 * - Pressure. Z from the liftings, 1 + (sum of the separations along the
 *   chain at its liftings) / (the chains' displacement), since the last
 *   reset (Michel, Kapfer and Krauth 2014; docs/physics.md derives it with
 *   walls), and P A = Z N kT.
 * - Protocols see a step's end: their moments inside a step act at its
 *   end (no protocol needs more today; growth refuses, having no
 *   growing radii here). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "chain/chain.h"
#include "chain/chain_state.h"
#include "core/collide.h"

static ds_status create(ds_sim *sim, ds_error *err)
{
    ds_status st = ds_ch_alloc(sim);
    ds_chain *c = sim->state;
    if (st == DS_OK)
        st = ds_ch_grid_make(c, &sim->world, &sim->disks);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)sim->world.n, NAN,
                         "n = %zu disks: no memory for the event-chain integrator", sim->world.n);
    /* Its own stream, apart from placement's; a state made again later in
     * a run (ds_sim_set_disks) draws another. */
    ds_rng_seed(&c->rng, sim->world.seed ^ 0x5EC7C4A1u ^ (sim->steps * 0x9E3779B97F4A7C15u));
    c->chain.axis = 1; /* the first chain is along x */
    ds_ch_new_chain(c);
    return DS_OK;
}

static ds_status run(ds_sim *sim, uint64_t steps, ds_error *err)
{
    ds_chain *c = sim->state;
    ds_status st = DS_OK;
    c->kt = ds_ch_kt(&sim->disks);
    ds_timer_start(&sim->collision_timer);
    for (uint64_t s = 0; s < steps && st == DS_OK; ++s) {
        ds_ch_step(sim, c);
        ++sim->steps;
        /* The velocities never change: the kinetic tensor's integral is
         * the tensor times the time. */
        ds_tally_flight(&sim->tally, sim->world.dt);
        const double now = (double)sim->steps * sim->world.dt;
        while (ds_protocols_due(&sim->protocols, now, now))
            ds_protocols_fire(sim, now, now);
        if (sim->protocols.stepping) {
            st = ds_protocols_step_end(sim, err); /* names the protocol and the step */
            c = sim->state;
            c->kt = ds_ch_kt(&sim->disks);
        }
    }
    ds_timer_stop(&sim->collision_timer);
    return st;
}

/* Whether a disk of radius r at (x, y) is closer to disk k than contact
 * allows (DS_CONTACT_TOLERANCE), through the nearest image. */
static int too_close(const ds_sim *sim, size_t k, double x, double y, double r)
{
    const ds_disks *d = &sim->disks;
    double dx = d->x[k] - x, dy = d->y[k] - y;
    ds_box_nearest(&sim->world.box, &dx, &dy);
    const double sigma = (d->r ? d->r[k] : sim->world.radius) + r;
    const double keep = sigma * (1.0 - DS_CONTACT_TOLERANCE);
    return dx * dx + dy * dy < keep * keep;
}

/* Any disk but self closer to (x, y) than contact allows: the disks of
 * the 3 x 3 cells around, or every disk for brute force (or a grid of a
 * few cells). */
static int overlaps(const ds_sim *sim, const ds_chain *c, size_t self, double x, double y, double r)
{
    const ch_grid *g = &c->grid;
    if (g->count[0] < 3 || g->count[1] < 3) {
        for (size_t k = 0; k < c->n; ++k)
            if (k != self && too_close(sim, k, x, y, r))
                return 1;
        return 0;
    }
    uint32_t column, row;
    ds_ch_cell_of(g, x, y, &column, &row);
    for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) {
            double sx, sy;
            const long cx = ds_box_cell_along(&c->box, 0, (long)column + ox, g->count[0], &sx);
            const long cy = ds_box_cell_along(&c->box, 1, (long)row + oy, g->count[1], &sy);
            if (cx < 0 || cy < 0)
                continue;
            const size_t cell = (size_t)cy * g->count[0] + (size_t)cx;
            for (int s = 0; s < CH_SLOTS; ++s) {
                const uint32_t k = g->who[cell * CH_SLOTS + (size_t)s];
                if (k != CH_NONE && k != self && too_close(sim, k, x, y, r))
                    return 1;
            }
            for (uint32_t m = g->more[cell]; m != CH_NONE; m = c->disk[m].next)
                if (m != self && too_close(sim, m, x, y, r))
                    return 1;
        }
    return 0;
}

static ds_status set(ds_sim *sim, size_t k, ds_disk nd)
{
    ds_chain *c = sim->state;
    ds_disks *d = &sim->disks;
    const double r = d->r ? d->r[k] : sim->world.radius;
    if (overlaps(sim, c, k, nd.x, nd.y, r))
        return DS_ERR_OVERLAP;
    ds_ch_remove(c, (uint32_t)k, d);
    d->x[k] = nd.x;
    d->y[k] = nd.y;
    d->vx[k] = nd.vx;
    d->vy[k] = nd.vy;
    uint32_t column, row;
    ds_ch_cell_of(&c->grid, nd.x, nd.y, &column, &row);
    ds_ch_add(c, (uint32_t)k, column, row, nd.x, nd.y, r);
    c->kt = ds_ch_kt(d);
    return DS_OK;
}

static ds_status scale_velocities(ds_sim *sim, double factor)
{
    ds_disks *d = &sim->disks;
    for (size_t k = 0; k < d->n; ++k) {
        d->vx[k] *= factor;
        d->vy[k] *= factor;
    }
    ds_chain *c = sim->state;
    c->kt = ds_ch_kt(d);
    return DS_OK;
}

/* The temperature the velocities stand for (see the top). */
static double temperature(const ds_sim *sim) { return ds_ch_kt(&sim->disks); }

/* Z from the liftings since the last reset: every step carried n speed
 * dt of displacement (docs/physics.md, "Event-chain Monte Carlo"). */
static double compressibility(const ds_sim *sim)
{
    const ds_chain *c = sim->state;
    const double moved = (double)(sim->steps - sim->observables_since_step) * c->per_step;
    return moved > 0.0 ? 1.0 + sim->tally.virial / moved : 0.0;
}

static double now_of(const ds_sim *sim) { return (double)sim->steps * sim->world.dt; }


/* A barostat's move: the box and the centres scaled, the chains' state
 * made anew for them (core/rescale.c); the chain under way ends there,
 * as at any step's end that makes a new state. */
static ds_status resize(ds_sim *sim, double sx, double sy) { return ds_rescale_box(sim, sx, sy); }

/* Restitution and a field act on dynamics, which the chains have not:
 * only the elastic rules without a field (a contact time alone changes
 * nothing). */
static ds_status take_rules(ds_sim *sim, const ds_rules *r)
{
    (void)sim;
    const int dynamic = r->restitution != 1.0 || r->wall_restitution != 1.0 || r->field[0] != 0.0 ||
                        r->field[1] != 0.0;
    return dynamic ? DS_ERR_ARG : DS_OK;
}

/* The cells, or brute force: every disk a candidate. */
static int fits(ds_broadphase bp) { return bp == DS_BROADPHASE_CELLS || bp == DS_BROADPHASE_BRUTE; }

static ds_broadphase choose(const ds_world *w)
{
    (void)w;
    return DS_BROADPHASE_CELLS;
}

/* Disk numbers are 32-bit with CH_NONE above them (ds_params_check
 * keeps n below 2^32 - 1); walls, periodic sides and the channel all
 * work the same way, axis by axis. */
static ds_status check(const ds_world *w, unsigned *warnings, ds_error *err)
{
    (void)w;
    (void)warnings;
    (void)err;
    return DS_OK;
}

static size_t bytes(const ds_world *w)
{
    return sizeof(ds_chain) + w->n * sizeof(ch_disk) + ds_ch_grid_bytes(w);
}

double ds_chain_length(const ds_sim *sim)
{
    const ds_chain *c = sim->state;
    return c->length;
}

void ds_chain_set_length(ds_sim *sim, double length)
{
    ds_chain *c = sim->state;
    c->length = length;
}

const ds_integrator_ops ds_event_chain_ops = {
    .name = "chain",
    /* Disks in contact on every side (a lattice at close packing) would
     * pass every chain round without moving. */
    .min_room = DS_ROOM_TO_MOVE,
    .fits = fits,
    .choose = choose,
    .check = check,
    .bytes = bytes,
    .create = create,
    .destroy = ds_ch_destroy,
    .run = run,
    .set = set,
    .save = ds_ch_save,
    .load = ds_ch_load,
    .scale_velocities = scale_velocities,
    .temperature = temperature,
    .compressibility = compressibility,
    .now = now_of,
    .kinetic = ds_disks_kinetic,
    .resize = resize,
    .take_rules = take_rules,
    /* No set_velocity: velocities are the chains' temperature only, so a
     * heat bath refuses them. No growing radii: growth refuses the chains. */
};
