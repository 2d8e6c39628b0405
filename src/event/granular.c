/* SPDX-License-Identifier: MIT */
/* The event-driven integrator's granular parts: the rules taken from the
 * simulation (restitution, the TC model's contact time and each disk's
 * time of last collision, a field and its falling frame), wall turns that
 * take energy or hold a disk against a field, and a drive's kicks. The
 * collision of two disks with restitution is core/collide.h's, called
 * from event_driven.c; flights in a field are falling.c's. */
#include <math.h>

#include "core/collide.h"
#include "core/protocol.h"
#include "event/event_state.h"

static double now_of(const ds_sim *sim, const ds_events *e)
{
    return (double)sim->steps * sim->world.dt - e->epoch;
}

ds_status ds_ed_take_rules(ds_sim *sim, const ds_rules *rules)
{
    ds_events *e = sim->state;
    const size_t n = sim->world.n;
    /* The memory first, so that without it nothing has changed. A new
     * column holds -infinity: no disk has collided yet. */
    if (ds_rules_inelastic(rules) && !sim->disks.last_hit &&
        ds_disks_add(&sim->disks, DS_COLUMN_last_hit) != DS_OK)
        return DS_ERR_NOMEM;
    const ds_rules *old = &sim->world.rules;
    const int new_field = rules->field[0] != old->field[0] || rules->field[1] != old->field[1];
    if (!new_field) {
        ds_ed_adopt_rules(e, rules, sim->disks.last_hit);
        return DS_OK;
    }
    /* A new field changes every flight: the clock's origin moved to now
     * (which leaves the records in the box: the new frame starts there),
     * and every disk predicted again. */
    const double now = now_of(sim, e);
    ds_ed_rebase(e, n, now);
    ds_protocols_rebased(sim, now);
    ds_ed_adopt_rules(e, rules, sim->disks.last_hit);
    e->rebase_time = ds_ed_rebase_time(&sim->world, rules);
    for (size_t k = 0; k < n; ++k) {
        ++e->disk[k].changes;
        e->disk[k].next = INFINITY;
    }
    ds_ed_schedule_all(e, n);
    ds_eq_build(e->queue, 0.0);
    return DS_OK;
}

/* A wall turn in general: the disk's side of the box, the TC model, the
 * field's floor, the tallies and the way back into the frame, in that
 * order (the disk taken to t, not predicted again: the caller's). */
void ds_ed_turn_granular(ds_sim *sim, ds_events *e, uint32_t i, double t, int axis)
{
    ds_tally *tally = &sim->tally;
    ed_disk *d = &e->disk[i];
    ds_ed_advance(d, t);
    ds_tally_flight_to(tally, t);
    const double r = e->radius ? e->radius[i] : e->one_radius;
    const double m = e->mass ? e->mass[i] : 1.0;
    const double side = e->box.side[axis], g = e->field[axis];
    double x, y, vx, vy;
    ds_ed_lab_at(e, d, t, &x, &y, &vx, &vy);
    const double u = axis ? y : x, v = axis ? vy : vx;
    /* Which wall: the one the centre is at (with a field a disk may meet
     * a wall at the top of an arc, its velocity no guide). */
    const int low = u < 0.5 * side;
    const double restitution = e->inelastic
                                   ? ds_tc_restitution(e->wall_restitution, e->contact_time, t,
                                                       &e->last_hit[i], &e->last_hit[i])
                                   : 1.0;
    /* Away from the wall at e |v_n|; a field that presses the disk on
     * this wall sends it off no slower than g_n t_c / 2, a flight of the
     * contact time: hard disks cannot rest on a floor, and one that
     * bounced ever lower (its turns elastic within t_c of each other)
     * would meet it ever more often, without end. */
    double away = restitution * fabs(v);
    const double press = low ? -g : g;
    if (press > 0.0)
        away = fmax(away, 0.5 * press * e->contact_time);
    const double after = low ? away : -away;
    ds_tally_wall_bounce(tally, m, vx, vy, axis, after);
    const double impulse = m * fabs(after - v);
    tally->wall_impulse += impulse;
    if (e->radius || e->mass)
        tally->wall_reach += impulse / ds_box_wall_reached(&e->box, r);
    ++tally->wall_count;
    /* Back into the frame, the centre on the wall line to the bit of its
     * box coordinate (rounding must not let it creep). */
    const double h = e->falls ? 0.5 * t * t : 0.0, wall = low ? r : side - r;
    double *pu = axis ? &d->y : &d->x, *pv = axis ? &d->vy : &d->vx;
    *pu = e->falls ? wall - g * h : wall;
    *pv = e->falls ? after - g * t : after;
    ++d->changes;
}

void ds_ed_kick(ds_sim *sim, const double *dv)
{
    ds_events *e = sim->state;
    ds_tally *tally = &sim->tally;
    const size_t n = sim->world.n;
    const double now = now_of(sim, e);
    ds_tally_flight_to(tally, now);
    for (size_t k = 0; k < n; ++k) {
        ed_disk *d = &e->disk[k];
        ds_ed_advance(d, now);
        double x, y, vx, vy;
        ds_ed_lab_at(e, d, now, &x, &y, &vx, &vy);
        const double m = e->mass ? e->mass[k] : 1.0, ux = dv[2 * k], uy = dv[2 * k + 1];
        tally->injected += m * (vx * ux + vy * uy + 0.5 * (ux * ux + uy * uy));
        tally->kinetic[0] += m * ux * (2.0 * vx + ux);
        tally->kinetic[1] += m * uy * (2.0 * vy + uy);
        tally->kinetic[2] += m * (vx * uy + ux * vy + ux * uy);
        tally->momentum[0] += m * ux;
        tally->momentum[1] += m * uy;
        d->vx += ux;
        d->vy += uy;
        ++d->changes; /* every prediction is stale */
        d->next = INFINITY;
    }
    ds_ed_schedule_all(e, n);
    ds_eq_build(e->queue, now);
}
