/* SPDX-License-Identifier: MIT */
/* Growing radii, the dynamics the growth protocol (protocols/growth.c)
 * drives: every radius grows in proportion to itself, r_i(t) = base_i (1
 * + rate (t - from)), so ratios stay and a pair's contact distance is
 * linear in time; pair times solve a quadratic with the growing distance
 * (event_predict.c), and a collision reflects the pair's normal velocity
 * in the frame of their surfaces, which recede at a = s0 rate from each
 * other: u' = 2 a - u, which adds energy (the protocol takes it out).
 * Every change of course of everyone (a new rate, a heat bath's scaling)
 * takes every disk to that instant and predicts it again
 * (ds_ed_restart_at), and the cells are built again, wider, when the
 * contacts of the next step would not fit them (the widen service). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/box.h"
#include "core/collide.h"
#include "core/protocol.h"
#include "event/event_state.h"

void ds_ed_restart_at(ds_events *e, size_t n, double t, double speed)
{
    ds_ed_law *g = &e->law;
    const double f = g->base ? ds_ed_factor(g, t) : 1.0;
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
    /* The area fraction of now, which grows as the square of the factor. */
    if (g->base)
        g->eta = 0.5 * DS_TWO_PI * covered / (e->box.side[0] * e->box.side[1]);
    ds_ed_schedule_all(e, n);
    ds_eq_build(e->queue, t);
}

void ds_ed_growth_go_on(ds_events *e, size_t n, double t)
{
    ds_ed_restart_at(e, n, t, e->law.rate * e->law.scale);
}

void ds_ed_collide_growing(ds_sim *sim, ds_events *e, uint32_t i, uint32_t j, double t)
{
    ed_disk *a = &e->disk[i], *b = &e->disk[j];
    ds_ed_advance(a, t);
    ds_ed_advance(b, t);
    double rx = b->x - a->x, ry = b->y - a->y;
    ds_box_nearest(&e->box, &rx, &ry);
    const double dvx = b->vx - a->vx, dvy = b->vy - a->vy;
    const double s0 = e->law.base[i] + e->law.base[j];
    /* Closing speed in the frame of the receding surfaces, times |r|. */
    const double approach = rx * dvx + ry * dvy - s0 * e->law.rate * sqrt(rx * rx + ry * ry);
    if (approach < 0.0) {
        const double ma = e->mass ? e->mass[i] : 1.0, mb = e->mass ? e->mass[j] : 1.0;
        const double before =
            ma * (a->vx * a->vx + a->vy * a->vy) + mb * (b->vx * b->vx + b->vy * b->vy);
        ds_collide_masses(rx, ry, approach, ma, mb, &a->vx, &a->vy, &b->vx, &b->vy, &sim->tally);
        if (sim->protocols.watching) {
            ds_collision c;
            c.a = i;
            c.b = j;
            c.t = t;
            c.energy = 0.5 * (ma * (a->vx * a->vx + a->vy * a->vy) +
                              mb * (b->vx * b->vx + b->vy * b->vy) - before);
            ds_protocols_collided(sim, &c);
        }
    }
    ++a->changes;
    ++b->changes;
    ds_eq_set(e->queue, i, ds_ed_predict(e, i));
    ds_eq_set(e->queue, j, ds_ed_predict(e, j));
}

void ds_ed_show_radii(ds_sim *sim, const ds_events *e, double t)
{
    const ds_ed_law *g = &e->law;
    if (!g->base)
        return;
    const double f = ds_ed_factor(g, t);
    for (size_t k = 0; k < sim->disks.n; ++k)
        sim->disks.r[k] = g->base[k] * f;
    ds_world_take_radii(&sim->world, &sim->disks);
}

/* A growth's start at t from the radii of t (the law's, if one goes on,
 * else the disks'): the memory first, so that without it nothing has
 * changed, then the radii of t as the law's base at scale 1. */
static ds_status start_law(ds_sim *sim, ds_events *e, double t, double speed)
{
    const size_t n = sim->world.n;
    double *base = e->law.base ? NULL : malloc(n * sizeof *base);
    if (!e->law.base && !base)
        return DS_ERR_NOMEM;
    if (!sim->disks.r) { /* one kind of disk has no array of radii until it grows */
        if (ds_disks_add(&sim->disks, DS_COLUMN_r) != DS_OK) {
            free(base);
            return DS_ERR_NOMEM;
        }
        for (size_t k = 0; k <= n; ++k)
            sim->disks.r[k] = k < n ? sim->world.radius : 0.0;
        ds_world_take_radii(&sim->world, &sim->disks); /* now a sum over the array */
    }
    if (e->law.rate > 0.0) /* the radii of now, from a growth going on */
        ds_ed_growth_go_on(e, n, t);
    ds_ed_show_radii(sim, e, t);
    if (!e->law.base)
        e->law.base = base;
    memcpy(e->law.base, sim->disks.r, n * sizeof *e->law.base);
    e->radius = e->law.base;
    e->law.from = t;
    e->law.scale = 1.0;
    e->law.rate = 0.0; /* restart_at: the radii are those of t already */
    ds_ed_restart_at(e, n, t, speed);
    return DS_OK;
}

/* Every record taken to t and its velocity scaled, with the stress
 * tally's kinetic tensor and its integral to t at the velocities before. */
static void scale_records(ds_sim *sim, ds_events *e, double factor, double t)
{
    ds_tally_flight_to(&sim->tally, t);
    for (int c = 0; c < 3; ++c)
        sim->tally.kinetic[c] *= factor * factor;
    for (size_t k = 0; k < sim->world.n; ++k) {
        ds_ed_advance(&e->disk[k], t);
        e->disk[k].vx *= factor;
        e->disk[k].vy *= factor;
    }
}

ds_status ds_ed_grow(ds_sim *sim, double t, double factor, double speed, int fresh)
{
    ds_events *e = sim->state;
    if (fresh)
        return start_law(sim, e, t, speed);
    if (factor != 1.0)
        scale_records(sim, e, factor, t);
    ds_ed_restart_at(e, sim->world.n, t, speed);
    if (speed == 0.0)
        ds_ed_show_radii(sim, e, t);
    return DS_OK;
}

void ds_ed_growth_law(const ds_sim *sim, ds_growth_law *law)
{
    const ds_events *e = sim->state;
    law->rate = e->law.rate;
    law->scale = e->law.scale;
    law->from = e->law.from;
    law->eta = e->law.eta;
}

/* The disks of state e at integrator time now, in fresh's own arrays
 * (fresh a copy of the simulation whose state e is, without its state or
 * arrays), and a state of fresh's own for them, its cells for radii 5%
 * larger than now: a new state every 5% of growth, not every step. */
static ds_status build_again(const ds_sim *sim, ds_events *e, ds_sim *fresh, double now)
{
    const size_t n = sim->world.n;
    ds_disks *d = &fresh->disks;
    ds_status st = ds_disks_alloc_like(d, &sim->disks);
    if (st == DS_OK && !(d->slot = malloc((n + 1) * sizeof *d->slot)))
        st = DS_ERR_NOMEM;
    if (st != DS_OK)
        return st;
    memcpy(d->id, sim->disks.id, n * sizeof *d->id);
    if (d->m)
        memcpy(d->m, sim->disks.m, n * sizeof *d->m);
    if (d->kind)
        memcpy(d->kind, sim->disks.kind, n * sizeof *d->kind);
    d->slot[n] = UINT32_MAX;
    ds_disks_rebuild_slots(d);
    ds_ed_show_at(d, e, now); /* with the image counts */
    ds_ed_show_radii(fresh, e, now);
    const double radius_max = fresh->world.radius_max;
    fresh->world.radius_max *= 1.05;
    st = ds_ed_create(fresh);
    fresh->world.radius_max = radius_max;
    return st;
}

/* The cells must be wider than every contact distance up to until; when
 * growth passes that, a new state is built from the disks of now, with
 * wider cells, and swapped in once it stands, the law going on in it from
 * its new origin (the present). Without memory for it nothing changes. */
ds_status ds_ed_widen(ds_sim *sim, double until, int *rebuilt)
{
    ds_events *e = sim->state;
    const ds_ed_law *g = &e->law;
    const size_t n = sim->world.n;
    *rebuilt = 0;
    double largest = 0.0;
    for (size_t k = 0; k < n; ++k)
        largest = fmax(largest, g->base[k]);
    const double widest = 2.0 * largest * ds_ed_factor(g, until);
    if (widest < fmin(e->cells.wx, e->cells.wy) * (1.0 - 1e-9))
        return DS_OK;
    const double now = (double)sim->steps * sim->world.dt - e->epoch;
    const double f = ds_ed_factor(g, now);
    for (size_t k = 0; k < n; ++k)
        ds_ed_advance(&e->disk[k], now);
    ds_sim fresh = *sim;
    fresh.state = NULL;
    memset(&fresh.disks, 0, sizeof fresh.disks);
    ds_status st = build_again(sim, e, &fresh, now);
    ds_events *fe = fresh.state;
    if (st == DS_OK && !(fe->law.base = malloc(n * sizeof *fe->law.base)))
        st = DS_ERR_NOMEM;
    if (st != DS_OK) {
        ds_ed_destroy(&fresh);
        ds_disks_free(&fresh.disks);
        return st;
    }
    memcpy(fe->law.base, fresh.disks.r, n * sizeof *fe->law.base);
    fe->radius = fe->law.base;
    fe->law.from = 0.0;
    fe->law.scale = g->scale * f;
    fe->law.rate = 0.0;
    ds_ed_restart_at(fe, n, 0.0, g->rate * g->scale);
    ds_ed_destroy(sim);
    ds_disks_free(&sim->disks);
    *sim = fresh;
    *rebuilt = 1;
    return DS_OK;
}
