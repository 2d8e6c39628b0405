/* SPDX-License-Identifier: MIT */
/* DS_INTEGRATOR_TIME_STEP: the seed's fixed time step. Each step moves every disk by
 * v dt and turns those past a wall, or wraps them in a periodic box
 * (free_flight.c), then the broad phase (broad_phase.c) finds the
 * overlapping pairs and the approaching ones exchange their normal
 * velocities. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/box.h"
#include "core/collide.h"
#include "timestep/broad_phase.h"
#include "timestep/timestep.h"

/* What the pair callbacks change: the tally, and in a periodic box the
 * sides for the nearest image; the disk-disk restitution (1: elastic). */
typedef struct pair_context {
    ds_tally *tally;
    const ds_box *box;
    double restitution;
} pair_context;

/* The response to a pair whose separation from a to b is (dx, dy). A
 * mixture's broad phase prunes with the largest diameter: the pair's own
 * contact distance is tested here. */
static inline void resolve(ds_disks *d, size_t a, size_t b, double dx, double dy,
                           const pair_context *c)
{
    if (d->r) {
        const double sigma = d->r[a] + d->r[b];
        if (!(dx * dx + dy * dy < sigma * sigma))
            return;
    }
    const double approach = (d->vx[b] - d->vx[a]) * dx + (d->vy[b] - d->vy[a]) * dy;
    /* Only an approaching pair collides. An overlapping pair that already
     * separates was resolved on an earlier step; swapping again would turn
     * it back towards each other and the disks would stick together.
     * approach < 0 needs dx, dy != 0. */
    if (!(approach < 0.0))
        return;
    /* Restitution applies to every collision: a step resolves a pair at
     * most once, so the time step cannot collapse (no TC model here). */
    ds_collide_with(dx, dy, approach, d->m != NULL, d->m ? d->m[a] : 1.0, d->m ? d->m[b] : 1.0,
                    c->restitution, &d->vx[a], &d->vy[a], &d->vx[b], &d->vy[b], c->tally);
}

static void resolve_pair(ds_disks *d, size_t a, size_t b, void *ctx)
{
    const pair_context *c = ctx;
    resolve(d, a, b, d->x[b] - d->x[a], d->y[b] - d->y[a], c);
}

static void resolve_pair_periodic(ds_disks *d, size_t a, size_t b, void *ctx)
{
    const pair_context *c = ctx;
    double dx = d->x[b] - d->x[a], dy = d->y[b] - d->y[a];
    ds_box_nearest(c->box, &dx, &dy);
    resolve(d, a, b, dx, dy, c);
}

/* The time step's time is the simulation's: steps dt. */
static double now_of(const ds_sim *sim) { return (double)sim->steps * sim->world.dt; }

/* The protocols at the end of a step: each of their moments that fell in
 * it, at its end, the only time the step knows (a heat bath's
 * collisions, in the order of their times), then their step's end (a
 * barostat's move may build the state again). */
static ds_status protocols_after_step(ds_sim *sim, ds_error *err)
{
    const double now = now_of(sim);
    while (ds_protocols_due(&sim->protocols, now, now))
        ds_protocols_fire(sim, now, now);
    return sim->protocols.stepping ? ds_protocols_step_end(sim, err) : DS_OK;
}

static ds_status run(ds_sim *sim, uint64_t steps, ds_error *err)
{
    ds_status st = DS_OK; /* a step needs no memory; a protocol's step's end may */
    ds_bp *bp = sim->state;
    const ds_world *w = &sim->world;
    const ds_pair_fn on_pair = ds_box_any_periodic(&w->box) ? resolve_pair_periodic : resolve_pair;
    pair_context ctx = {&sim->tally, &w->box, w->rules.restitution};
    const int falls = ds_rules_fall(&w->rules);
    for (uint64_t s = 0; s < steps && st == DS_OK; ++s) {
        /* A field first (v += g dt, then the flight at the new velocity:
         * semi-implicit Euler), then the step's flight at the velocities
         * its start then has. */
        if (falls)
            ds_fall(&sim->disks, w, &sim->tally);
        ds_tally_flight(&sim->tally, w->dt);
        ds_move(&sim->disks, w, &sim->tally);
        ds_timer_start(&sim->collision_timer);
        sim->tally.pairs_tested += ds_bp_find_pairs(bp, &sim->disks, on_pair, &ctx);
        ds_timer_stop(&sim->collision_timer);
        ++sim->steps;
        if (sim->protocols.stepping || sim->protocols.next < INFINITY) {
            st = protocols_after_step(sim, err);
            bp = sim->state; /* a new box has a new broad phase */
        }
    }
    ds_disks_rebuild_slots(&sim->disks);
    return st;
}

/* The time step has the sweeps and brute force. */
static int fits(ds_broadphase bp)
{
    return bp == DS_BROADPHASE_SAP || bp == DS_BROADPHASE_STRIPS || bp == DS_BROADPHASE_BRUTE;
}

static ds_broadphase choose(const ds_world *w)
{
    /* Plain SAP tests ~ n 2R / box candidates per disk (those within 2R in
     * x, anywhere in y); strips test a constant few but pay for disks
     * changing strip. Measured (N = 1000, 2000, 4000, candidates per disk
     * 4 to 11, best of 5): SAP is 3.6x faster at 4 (the seed case) and
     * 1.1-1.2x faster at 8 at N <= 2000; they break even between 8 and 9;
     * strips are 1.15-1.35x faster at 10. */
    const double per_disk = (double)w->n * 2.0 * w->radius / w->box.side[0];
    return per_disk > 8.5 ? DS_BROADPHASE_STRIPS : DS_BROADPHASE_SAP;
}

/* A head-on pair at 3x the initial speed (which the Rayleigh tail exceeds
 * with probability e^-9) can pass through each other between two steps
 * when 2 * speed_max * dt > 4 R (the smallest R of a mixture). */
static ds_status check(const ds_world *w, unsigned *warnings, ds_error *err)
{
    if (2.0 * 3.0 * w->speed * w->dt > 4.0 * w->radius_min) {
        if (warnings)
            *warnings |= DS_WARN_TUNNELING;
        if (err)
            snprintf(err->warning, sizeof err->warning,
                     "radius = %g is small for speeds near %g and dt = %g: a fast pair can pass "
                     "through each other within one step and miss its collision",
                     w->radius_min, w->speed, w->dt);
    }
    return DS_OK;
}

static size_t bytes(const ds_world *w) { return sizeof(ds_bp) + ds_bp_bytes(w); }

static ds_status create(ds_sim *sim, ds_error *err)
{
    ds_bp *bp = calloc(1, sizeof *bp);
    sim->state = bp;
    const ds_status st =
        bp ? ds_bp_create(bp, sim->world.broadphase, &sim->world, &sim->disks) : DS_ERR_NOMEM;
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)sim->world.n, NAN,
                         "n = %zu disks: no memory for the %s broad phase", sim->world.n,
                         ds_broadphase_name(sim->world.broadphase));
    return DS_OK;
}

static void destroy(ds_sim *sim)
{
    ds_bp *bp = sim->state;
    if (!bp)
        return;
    ds_bp_destroy(bp);
    free(bp);
    sim->state = NULL;
}

static ds_status scale_velocities(ds_sim *sim, double factor)
{
    ds_disks *d = &sim->disks;
    for (int c = 0; c < 3; ++c)
        sim->tally.kinetic[c] *= factor * factor;
    for (size_t k = 0; k < d->n; ++k) {
        d->vx[k] *= factor;
        d->vy[k] *= factor;
    }
    return DS_OK;
}

static void save(const ds_sim *sim, ds_state_writer *w) { ds_bp_save(sim->state, w); }

static ds_status load(ds_sim *sim, ds_reader *r, uint32_t version, ds_legacy *legacy,
                      ds_error *err)
{
    (void)version; /* the same part in every version */
    (void)legacy;
    ds_bp *bp = calloc(1, sizeof *bp);
    if (!bp)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the broad phase");
    sim->state = bp;
    return ds_bp_load(bp, &sim->world, &sim->disks, r, err);
}

/* A drive's kicks, at the step boundary: the columns are the disks. */
static void kick(ds_sim *sim, const double *dv)
{
    ds_disks *d = &sim->disks;
    ds_tally *t = &sim->tally;
    for (size_t k = 0; k < d->n; ++k) {
        const double m = d->m ? d->m[k] : 1.0, vx = d->vx[k], vy = d->vy[k];
        const double ux = dv[2 * k], uy = dv[2 * k + 1];
        t->injected += m * (vx * ux + vy * uy + 0.5 * (ux * ux + uy * uy));
        t->kinetic[0] += m * ux * (2.0 * vx + ux);
        t->kinetic[1] += m * uy * (2.0 * vy + uy);
        t->kinetic[2] += m * (vx * uy + ux * vy + ux * uy);
        t->momentum[0] += m * ux;
        t->momentum[1] += m * uy;
        d->vx[k] = vx + ux;
        d->vy[k] = vy + uy;
    }
}

static ds_status set(ds_sim *sim, size_t k, ds_disk d)
{
    /* The time step does not refuse overlaps: its next step resolves them.
     * The broad phase re-sorts on the next step; insertion sort copes with
     * any displacement, just more slowly for a large one. */
    ds_disks *a = &sim->disks;
    a->x[k] = d.x;
    a->y[k] = d.y;
    a->vx[k] = d.vx;
    a->vy[k] = d.vy;
    return DS_OK;
}


/* A heat bath's collision that fell in the step just taken, at its end:
 * whether it fell early or late in the step, the step's flight and its
 * collisions were at the velocity before, as with a redraw at the end. */
static void set_velocity(ds_sim *sim, size_t k, double t, double vx, double vy)
{
    (void)t;
    ds_disks *d = &sim->disks;
    ds_tally_velocity(&sim->tally, d->m ? d->m[k] : 1.0, d->vx[k], d->vy[k], vx, vy);
    d->vx[k] = vx;
    d->vy[k] = vy;
}

/* The columns are the disks at the step boundary: the new box's state is
 * built from them; the time is the simulation's, no origin moves. */
static ds_status resize(ds_sim *sim, double sx, double sy) { return ds_rescale_box(sim, sx, sy); }

const ds_integrator_ops ds_time_step_ops = {
    .name = "step",
    .min_room = 0.0, /* a step is a fixed amount of work, in any room */
    .fits = fits,
    .choose = choose,
    .check = check,
    .bytes = bytes,
    .create = create,
    .destroy = destroy,
    .run = run,
    .set = set,
    .save = save,
    .load = load,
    .scale_velocities = scale_velocities,
    /* The services to protocols it can give: a drive's kicks, a heat bath
     * and a barostat; radii grow only with exact contact times, so growth
     * refuses it. It reads the rules each step (take_rules NULL). */
    .kick = kick,
    .now = now_of,
    .kinetic = ds_disks_kinetic,
    .set_velocity = set_velocity,
    .resize = resize,
};
