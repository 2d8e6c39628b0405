/* SPDX-License-Identifier: MIT */
/* Growth: the Lubachevsky-Stillinger compression (Lubachevsky and
 * Stillinger 1990, J. Stat. Phys. 60, 561), in a periodic box. Every
 * radius grows in proportion to itself, r_i(t) = base_i (1 + rate (t -
 * from)), so ratios stay and a pair's contact distance is linear in time;
 * pair times solve a quadratic with the growing distance
 * (event_predict.c), and a collision reflects the pair's normal velocity
 * in the frame of their surfaces, which recede at a = s0 rate from each
 * other: u' = 2 a - u. That adds energy, taken out by scaling every
 * velocity back to the kinetic energy growth started with at the end of
 * each window of 2 n collisions. (Once a frame is not enough: near
 * jamming a cluster's collisions heat it a thousandfold within a frame,
 * and the collision rate with it.)
 *
 * The growth stops when the area fraction reaches its target (at the
 * exact time, found in advance) or when the reduced pressure passes a
 * threshold, watched over windows of 2 n collisions as the run goes: near
 * jamming the collision rate diverges within a time shorter than a step,
 * and a check only at a step's end would never come. Stopping, like any
 * change of course of everyone, takes every disk to that instant and
 * predicts it again (ds_ed_restart_at). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/boundary.h"
#include "core/collide.h"
#include "event/event_state.h"

#define GROWTH_SLOWS_AT_Z 10000.0

/* The growth factor at integrator time t. */
static double factor_at(const ds_growth *g, double t) { return 1.0 + g->rate * (t - g->from); }

void ds_ed_restart_at(ds_events *e, size_t n, double t, double speed)
{
    ds_growth *g = &e->growth;
    const double f = g->base ? factor_at(g, t) : 1.0;
    double covered = 0.0;
    for (size_t k = 0; k < n; ++k) {
        ed_disk *d = &e->disk[k];
        ds_ed_advance(d, t);
        if (g->base) {
            g->base[k] *= f;
            covered += g->base[k] * g->base[k];
        }
        ++d->changes; /* every prediction is stale */
        d->next = INFINITY;
    }
    g->from = t;
    g->scale *= f;
    g->rate = speed / g->scale;
    /* The target's time from the area fraction of now, which grows as the
     * square of the factor: a restart never moves it. */
    if (g->rate > 0.0 && g->until_eta > 0.0) {
        const double eta = 0.5 * DS_TWO_PI * covered / (e->box_x * e->box_y);
        g->stop_time = t + (sqrt(g->until_eta / eta) - 1.0) / g->rate;
    }
    ds_ed_schedule_all(e, n);
    ds_eq_build(e->queue, t);
}

void ds_ed_growth_go_on(ds_events *e, size_t n, double t)
{
    ds_ed_restart_at(e, n, t, e->growth.rate * e->growth.scale);
}

/* The kinetic energy of the records and the internal part's degrees of
 * freedom: a periodic box conserves the momentum, so the centre of mass's
 * energy is not the temperature's. */
static void measure(ds_events *e, size_t n, ds_growth *g)
{
    double k = 0.0, px = 0.0, py = 0.0, mass = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const ed_disk *d = &e->disk[i];
        const double m = e->mass ? e->mass[i] : 1.0;
        k += m * (d->vx * d->vx + d->vy * d->vy);
        px += m * d->vx;
        py += m * d->vy;
        mass += m;
    }
    g->kinetic = 0.5 * k;
    g->momentum_energy = (px * px + py * py) / (2.0 * mass);
}

void ds_ed_collide_growing(ds_tally *tally, ds_events *e, uint32_t i, uint32_t j, double t)
{
    ed_disk *a = &e->disk[i], *b = &e->disk[j];
    ds_ed_advance(a, t);
    ds_ed_advance(b, t);
    const double rx = ds_nearest(b->x - a->x, e->box_x), ry = ds_nearest(b->y - a->y, e->box_y);
    const double dvx = b->vx - a->vx, dvy = b->vy - a->vy;
    const double s0 = e->growth.base[i] + e->growth.base[j];
    /* Closing speed in the frame of the receding surfaces, times |r|. */
    const double approach = rx * dvx + ry * dvy - s0 * e->growth.rate * sqrt(rx * rx + ry * ry);
    if (approach < 0.0) {
        const double ma = e->mass ? e->mass[i] : 1.0, mb = e->mass ? e->mass[j] : 1.0;
        const double before =
            ma * (a->vx * a->vx + a->vy * a->vy) + mb * (b->vx * b->vx + b->vy * b->vy);
        ds_collide_masses(rx, ry, approach, ma, mb, &a->vx, &a->vy, &b->vx, &b->vy, tally);
        e->growth.kinetic += 0.5 * (ma * (a->vx * a->vx + a->vy * a->vy) +
                                    mb * (b->vx * b->vx + b->vy * b->vy) - before);
        ++e->growth.window;
    }
    ++a->changes;
    ++b->changes;
    ds_eq_set(e->queue, i, ds_ed_predict(e, i));
    ds_eq_set(e->queue, j, ds_ed_predict(e, j));
}

/* Z over the window that ends at t: 1 + the window's virial over 2 t N kT,
 * N kT = N K_int / (N - 1). */
static double window_z(const ds_sim *sim, const ds_growth *g, double t)
{
    const double n = (double)sim->world.n;
    const double nkt = n * (g->kinetic - g->momentum_energy) / (n > 1.0 ? n - 1.0 : 1.0);
    const double span = t - g->window_start;
    return span > 0.0 && nkt > 0.0
               ? 1.0 + (sim->tally.virial - g->window_virial) / (2.0 * span * nkt)
               : 1.0;
}

/* The heat growth added, out: every velocity scaled at once back to the
 * kinetic energy growth started with (which keeps a zero momentum zero);
 * the caller predicts every disk again. */
static void heat_out(ds_tally *tally, ds_events *e, size_t n, ds_growth *g, double t)
{
    const double factor = g->kinetic > 0.0 ? sqrt(g->kinetic_target / g->kinetic) : 1.0;
    /* The kinetic tensor's integral to t, at the velocities before. */
    ds_tally_flight_to(tally, t);
    for (int c = 0; c < 3; ++c)
        tally->kinetic[c] *= factor * factor;
    for (size_t k = 0; k < n; ++k) {
        ds_ed_advance(&e->disk[k], t);
        e->disk[k].vx *= factor;
        e->disk[k].vy *= factor;
    }
    g->kinetic *= factor * factor;
    g->momentum_energy *= factor * factor;
}

int ds_ed_growth_before(ds_sim *sim, ds_events *e, double t, double end)
{
    ds_growth *g = &e->growth;
    const size_t n = sim->world.n;
    /* The target area fraction, at its own time, whether an event comes
     * before it in this step or not: the step that holds it (its end
     * included) ends with the radii of the target. */
    if (g->stop_time <= t && g->stop_time <= end) {
        g->stopped = 1;
        heat_out(&sim->tally, e, n, g, g->stop_time);
        ds_ed_restart_at(e, n, g->stop_time, 0.0);
        return 1;
    }
    /* Z is watched before events, not at a step's end. */
    if (t < end && g->window >= 2 * n) {
        const double z = window_z(sim, g, t);
        g->last_z = z;
        const int jammed = z >= g->until_z;
        g->stopped = jammed ? 2 : 0;
        /* Slower as the pressure rises, rate ~ 1 / Z past Z = 10^4: a
         * compression at a fixed rate outruns the disks' rearranging near
         * jamming, and the pressure it measures is its own push, not the
         * packing's (at a fixed rate 0.01, Z passed 10^6 with most gaps
         * between neighbours near 1e-4 of a diameter, a packing at Z ~
         * 10^4). Slowing past 10^4 leaves the contacts 1e-6 to 1e-4 apart
         * at Z = 10^6, 4.00 per disk with the rattlers out, in 108 s at
         * 1024 disks from 0.476 at rate 0.01 (docs/physics.md). Donev,
         * Torquato and Stillinger 2005 slow down likewise. */
        const double rate = z > GROWTH_SLOWS_AT_Z ? g->asked * GROWTH_SLOWS_AT_Z / z : g->asked;
        heat_out(&sim->tally, e, n, g, t);
        g->window = 0;
        g->window_start = t;
        g->window_virial = sim->tally.virial;
        ds_ed_restart_at(e, n, t, jammed ? 0.0 : rate);
        return 1;
    }
    return 0;
}

void ds_ed_show_radii(ds_sim *sim, const ds_events *e, double t)
{
    const ds_growth *g = &e->growth;
    if (!g->base)
        return;
    const double f = factor_at(g, t);
    for (size_t k = 0; k < sim->disks.n; ++k)
        sim->disks.r[k] = g->base[k] * f;
    ds_world_take_radii(&sim->world, &sim->disks);
}

/* Installs growth at integrator time now in a state without it (the
 * disks' radii in sim->disks.r, the records at their times): asked is
 * relative to the radii at the ask, scale of now over those, speed the
 * one to go on at (asked, or less once Z slowed it). Only the array of
 * the radii it grows from can fail, if the state has none yet: then
 * nothing has changed. */
static ds_status install(ds_sim *sim, ds_events *e, double now, double asked, double scale,
                         double speed, double until_eta, double until_z)
{
    const size_t n = sim->world.n;
    ds_growth *g = &e->growth;
    if (!g->base && !(g->base = malloc(n * sizeof *g->base)))
        return DS_ERR_NOMEM;
    memcpy(g->base, sim->disks.r, n * sizeof *g->base);
    e->radius = g->base;
    g->from = now;
    g->asked = asked;
    g->scale = scale;
    g->rate = 0.0; /* restart_at: the radii are those of now already */
    g->stop_time = INFINITY;
    g->until_eta = until_eta;
    g->until_z = until_z;
    g->stopped = 0;
    g->last_z = 0.0;
    measure(e, n, g);
    g->kinetic_target = g->kinetic;
    g->window = 0;
    g->window_start = now;
    g->window_virial = sim->tally.virial;
    ds_ed_restart_at(e, n, now, speed);
    return DS_OK;
}

/* The disks of state e at integrator time now, in fresh's own arrays
 * (fresh a copy of the simulation whose state e is, without its state or
 * arrays), and a state of fresh's own for them, its cells for radii 5%
 * larger than now: a new state every 5% of growth, not every step. */
static ds_status build_again(const ds_sim *sim, ds_events *e, ds_sim *fresh, double now)
{
    const size_t n = sim->world.n;
    ds_disks *d = &fresh->disks;
    ds_status st = ds_disks_alloc(d, n);
    if (st == DS_OK)
        st = ds_disks_add_mixture(d, 1, sim->disks.m != NULL);
    if (st == DS_OK && sim->disks.ix)
        st = ds_disks_add_images(d);
    if (st != DS_OK)
        return st;
    memcpy(d->id, sim->disks.id, n * sizeof *d->id);
    if (d->m)
        memcpy(d->m, sim->disks.m, n * sizeof *d->m);
    ds_disks_rebuild_slots(d);
    ds_ed_show_at(d, e, now); /* with the image counts */
    ds_ed_show_radii(fresh, e, now);
    const double radius_max = fresh->world.radius_max;
    fresh->world.radius_max *= 1.05;
    st = ds_ed_create(fresh);
    fresh->world.radius_max = radius_max;
    return st;
}

/* The cells must be wider than every contact distance of the next step;
 * when growth passes that, a new state is built from the disks at this
 * step's end, with wider cells, and swapped in once it stands, the growth
 * going on in it. Without memory for it the state stays as it was and the
 * growth stops now, its heat out, since its cells cannot hold the next
 * step's contacts: DS_ERR_NOMEM, and ds_sim_get_growth_state says
 * DS_GROWTH_NONE (the run stops there with that status). */
ds_status ds_ed_growth_step_end(ds_sim *sim, double target_next)
{
    ds_events *e = sim->state;
    ds_growth *g = &e->growth;
    const size_t n = sim->world.n;
    double largest = 0.0;
    for (size_t k = 0; k < n; ++k)
        largest = fmax(largest, g->base[k]);
    const double widest = 2.0 * largest * factor_at(g, target_next);
    if (widest < fmin(e->cells.wx, e->cells.wy) * (1.0 - 1e-9))
        return DS_OK;
    const double now = (double)sim->steps * sim->world.dt - e->epoch;
    const double f = factor_at(g, now);
    for (size_t k = 0; k < n; ++k)
        ds_ed_advance(&e->disk[k], now);
    ds_sim fresh = *sim;
    fresh.state = NULL;
    memset(&fresh.disks, 0, sizeof fresh.disks);
    ds_status st = build_again(sim, e, &fresh, now);
    if (st == DS_OK)
        st = install(&fresh, fresh.state, 0.0, g->asked, g->scale * f, g->rate * g->scale,
                     g->until_eta, g->until_z);
    if (st != DS_OK) {
        ds_ed_destroy(&fresh);
        ds_disks_free(&fresh.disks);
        heat_out(&sim->tally, e, n, g, now);
        ds_ed_restart_at(e, n, now, 0.0);
        g->stopped = 0;
        return st;
    }
    /* The energy growth started with, not this step's. */
    ((ds_events *)fresh.state)->growth.kinetic_target = g->kinetic_target;
    ds_ed_destroy(sim);
    ds_disks_free(&sim->disks);
    *sim = fresh;
    return DS_OK;
}

int ds_ed_growth_state(const ds_sim *sim, double *z)
{
    const ds_growth *g = &((const ds_events *)sim->state)->growth;
    *z = g->last_z;
    return g->rate > 0.0     ? DS_GROWTH_GROWING
           : g->stopped == 1 ? DS_GROWTH_REACHED_ETA
           : g->stopped == 2 ? DS_GROWTH_JAMMED
                             : DS_GROWTH_NONE;
}

ds_status ds_ed_set_growth(ds_sim *sim, double rate, double until_eta, double until_z)
{
    ds_events *e = sim->state;
    const size_t n = sim->world.n;
    const double now = (double)sim->steps * sim->world.dt - e->epoch;
    if (!e->periodic)
        return DS_ERR_ARG;
    if (rate == 0.0) { /* stop */
        if (e->growth.rate > 0.0)
            ds_ed_restart_at(e, n, now, 0.0);
        ds_ed_show_radii(sim, e, now);
        return DS_OK;
    }
    /* The memory growth needs first, so that without it nothing has
     * changed: the radii it grows from, and an array of the disks' own
     * radii (one kind has none until it grows). */
    double *base = e->growth.base ? NULL : malloc(n * sizeof *base);
    if (!e->growth.base && !base)
        return DS_ERR_NOMEM;
    if (!sim->disks.r) {
        if (ds_disks_add_mixture(&sim->disks, 1, 0) != DS_OK) {
            free(base);
            return DS_ERR_NOMEM;
        }
        for (size_t k = 0; k <= n; ++k)
            sim->disks.r[k] = k < n ? sim->world.radius : 0.0;
        ds_world_take_radii(&sim->world, &sim->disks); /* now a sum over the array */
    }
    /* The radii of now (of a growth going on: base is then its own). */
    if (e->growth.rate > 0.0)
        ds_ed_growth_go_on(e, n, now);
    ds_ed_show_radii(sim, e, now);
    if (!e->growth.base)
        e->growth.base = base;
    return install(sim, e, now, rate, 1.0, rate, until_eta, until_z);
}

ds_status ds_ed_scale_velocities(ds_sim *sim, double factor)
{
    ds_events *e = sim->state;
    const size_t n = sim->world.n;
    const double now = (double)sim->steps * sim->world.dt - e->epoch;
    for (size_t k = 0; k < n; ++k) {
        ds_ed_advance(&e->disk[k], now);
        e->disk[k].vx *= factor;
        e->disk[k].vy *= factor;
        sim->disks.vx[k] = e->disk[k].vx;
        sim->disks.vy[k] = e->disk[k].vy;
    }
    e->growth.kinetic *= factor * factor;
    e->growth.kinetic_target *= factor * factor;
    e->growth.momentum_energy *= factor * factor;
    ds_ed_growth_go_on(e, n, now);
    return DS_OK;
}
