/* SPDX-License-Identifier: MIT */
/* DS_INTEGRATOR_EVENT_DRIVEN: exact dynamics of hard disks.
 *
 * Between events every disk flies in a straight line, so the state is
 * advanced from event to event instead of by a fixed step: a pair
 * collides at the exact time its centres are 2R apart, a disk turns at the
 * exact time its centre is R from a wall. The design follows the modern
 * event-driven codes (Rapaport's book; Isobe 1999; Bannerman et al. 2011
 * and 2014 for DynamO; Smallenburg 2022 for the single-event calendar):
 *
 * - Delayed states. Each disk keeps its position at the time t of its own
 *   last event. An event touches only its own disks; everyone else stays
 *   where they were and is brought to a common time when looked at.
 * - One scheduled event per disk: the earliest of its wall turn, its next
 *   cell crossing, and its collisions with the disks of the 3 x 3 cells
 *   around it (cells.c). The calendar (event_queue.c) finds the earliest
 *   disk's event.
 * - Stale events are dropped cheaply. A disk counts its velocity changes;
 *   an event remembers its partner's count when it was predicted. If the
 *   partner has changed since, the event is stale: the disk is simply
 *   predicted again at that time. A pair's collision is not even scheduled
 *   if the partner has an earlier event of its own, because the partner is
 *   predicted again at that event and finds the pair then.
 * - Cells at least 2R wide, crossing a cell edge being an event: two disks
 *   in contact are always in neighbouring cells. In a periodic box the
 *   cells wrap, each neighbouring cell carrying the shift of the image it
 *   stands for, and a crossing of the box edge wraps the position.
 * - Numerical stability (Bannerman, Lue et al. 2014): a pair that rounding
 *   has left a hair inside contact collides at once if it is approaching
 *   and is ignored while it separates, so time never runs backwards and
 *   no pair sticks; a wall turn snaps the centre to exactly R from the wall.
 *
 * The integrator's clock starts at an epoch (a step boundary) that moves
 * forward now and then, so the times it adds and subtracts stay small and
 * keep their digits however long the run. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/box.h"
#include "core/collide.h"
#include "core/large_alloc.h"
#include "event/event.h"
#include "event/event_state.h"

/* Predicts disk i and files its event; the calendar writes the time into
 * the disk's record (its `next`), where it keeps it. */
static void schedule(ds_events *e, uint32_t i) { ds_eq_set(e->queue, i, ds_ed_predict(e, i)); }

/* ------------------------------------------------------------------ */
/* Events                                                               */
/* ------------------------------------------------------------------ */

static void collide(ds_sim *sim, ds_events *e, uint32_t i, uint32_t j, double t)
{
    ds_tally *tally = &sim->tally;
    ds_tally_flight_to(tally, t);
    if (e->law.rate > 0.0) {
        ds_ed_collide_growing(sim, e, i, j, t);
        return;
    }
    ed_disk *a = &e->disk[i], *b = &e->disk[j];
    ds_ed_advance(a, t);
    ds_ed_advance(b, t);
    double rx = b->x - a->x, ry = b->y - a->y;
    double dvx = b->vx - a->vx;
    const double dvy = b->vy - a->vy;
    ds_ed_nearest(e, t, &rx, &ry, &dvx);
    const double approach = rx * dvx + ry * dvy;
    int across = 0; /* a sheared box's, for its stress tally (sheared.c) */
    double before[3] = {0.0}, v0[4] = {0.0};
    if (e->lees_edwards)
        ds_ed_sheared_before(tally, a, b, ry, &across, before, v0);
    /* Rounding can leave a predicted pair a hair from approaching; then
     * there is nothing to exchange, and both are simply predicted again.
     * Restitution below 1 goes by the TC model (core/collide.h); the
     * relative motion is the same in the falling frame as in the box. */
    if (approach < 0.0 && e->inelastic)
        ds_collide_with(
            rx, ry, approach, e->mass != NULL, e->mass ? e->mass[i] : 1.0,
            e->mass ? e->mass[j] : 1.0,
            ds_tc_restitution(e->restitution, e->contact_time, t, &e->last_hit[i], &e->last_hit[j]),
            &a->vx, &a->vy, &b->vx, &b->vy, tally);
    else if (approach < 0.0 && e->mass)
        ds_collide_masses(rx, ry, approach, e->mass[i], e->mass[j], &a->vx, &a->vy, &b->vx, &b->vy,
                          tally);
    else if (approach < 0.0)
        ds_collide(rx, ry, approach, &a->vx, &a->vy, &b->vx, &b->vy, tally);
    if (e->lees_edwards)
        ds_ed_sheared_collision(tally, e, i, j, across, before, v0);
    ++a->changes;
    ++b->changes;
    schedule(e, i);
    schedule(e, j);
}

static void turn_at_wall(ds_sim *sim, ds_events *e, uint32_t i, double t, int axis_y)
{
    if (e->inelastic || e->falls) { /* restitution, the TC model, the field's floor */
        ds_ed_turn_granular(sim, e, i, t, axis_y);
        schedule(e, i);
        return;
    }
    ds_tally *tally = &sim->tally;
    ed_disk *d = &e->disk[i];
    ds_ed_advance(d, t);
    ds_tally_flight_to(tally, t);
    ds_tally_wall_turn(tally, e->mass ? e->mass[i] : 1.0, d->vx, d->vy);
    double *u = axis_y ? &d->y : &d->x, *v = axis_y ? &d->vy : &d->vx;
    /* Snap to the wall line (a mixture's disk: its own): rounding must not
     * let it creep. */
    const double r = e->radius ? e->radius[i] : e->one_radius;
    *u = *v < 0.0 ? r : e->box.side[axis_y] - r;
    if (e->radius || e->mass) {
        const double m = e->mass ? e->mass[i] : 1.0;
        tally->wall_impulse += 2.0 * m * fabs(*v);
        tally->wall_reach += 2.0 * m * fabs(*v) / ds_box_wall_reached(&e->box, r);
    } else {
        tally->wall_impulse += 2.0 * fabs(*v);
    }
    ++tally->wall_count;
    *v = -*v;
    ++d->changes;
    schedule(e, i);
}

static void cross_cell(ds_sim *sim, ds_events *e, uint32_t i, double t, int axis_y)
{
    ed_disk *d = &e->disk[i];
    ds_cells *cells = &e->cells;
    ds_ed_advance(d, t);
    ds_cells_remove(cells, ds_cells_index(cells, d->column, d->row), i);
    uint16_t *c = axis_y ? &d->row : &d->column;
    const uint32_t count = axis_y ? cells->ny : cells->nx;
    double *u = axis_y ? &d->y : &d->x;
    const double box = e->box.side[axis_y];
    /* A periodic box's crossing counts in the disk's images. */
    int32_t *image = e->image ? &e->image[2 * (size_t)i + (axis_y ? 1 : 0)] : NULL;
    if (ds_ed_leaves_up(e, d, axis_y)) {
        if (++*c == count) { /* periodic: out at the far edge, in at 0 */
            *c = 0;
            *u -= box;
            if (image) /* none with walls, where only a forged state crosses */
                *image = (int32_t)((uint32_t)*image + 1u);
            if (axis_y && e->lees_edwards)
                ds_ed_cross_sheared(sim, e, i, t, 1);
        }
    } else if (*c == 0) {
        *c = (uint16_t)(count - 1);
        *u += box;
        if (image)
            *image = (int32_t)((uint32_t)*image - 1u);
        if (axis_y && e->lees_edwards)
            ds_ed_cross_sheared(sim, e, i, t, 0);
    } else {
        --*c;
    }
    ds_cells_add(cells, ds_cells_index(cells, d->column, d->row), i);
    /* The trajectory is unchanged: events predicted against this disk stay
     * valid, so its change count stays. */
    schedule(e, i);
}

static void handle_event(ds_sim *sim, ds_events *e, uint32_t i, double t)
{
    ed_disk *d = &e->disk[i];
    const uint32_t partner = d->partner;
    switch (partner) {
    case EV_WALL_X:
    case EV_WALL_Y:
        turn_at_wall(sim, e, i, t, partner == EV_WALL_Y);
        return;
    case EV_CELL_X:
    case EV_CELL_Y:
        cross_cell(sim, e, i, t, partner == EV_CELL_Y);
        return;
    default:
        if (ds_fetch_note_current(d->partner_changes, e->disk[partner].changes)) {
            collide(sim, e, i, partner, t);
        } else {
            ds_ed_advance(d, t); /* stale: the partner has changed course */
            schedule(e, i);
        }
    }
}

/* ------------------------------------------------------------------ */
/* Showing the disks, moving the epoch                                  */
/* ------------------------------------------------------------------ */

static ds_status run(ds_sim *sim, uint64_t steps, ds_error *err)
{
    ds_events *e = sim->state;
    ds_status st = DS_OK;
    ds_timer_start(&sim->collision_timer);
    double target = (double)sim->steps * sim->world.dt - e->epoch;
    sim->tally.stress_clock = target;
    /* Falling disks change the kinetic tensor between events too. */
    sim->tally.falling = e->falls;
    sim->tally.field[0] = e->field[0];
    sim->tally.field[1] = e->field[1];
    ds_ed_start_shear_tally(sim, e);
    for (uint64_t s = 0; s < steps && st == DS_OK; ++s) {
        /* From the step count, not a running sum: no drift. */
        target = (double)(sim->steps + 1) * sim->world.dt - e->epoch;
        for (;;) {
            const uint32_t i = ds_eq_first(e->queue);
            const double t = e->disk[i].next;
            /* A protocol's moment first (growth's target, its window's
             * end), before this event or before the step's end if no
             * event comes first. */
            if (ds_protocols_due(&sim->protocols, t, target)) {
                ds_protocols_fire(sim, t, target);
                continue;
            }
            if (!(t < target))
                break;
            if (e->fetching)
                ds_fetch_ahead(e);
            handle_event(sim, e, i, t);
        }
        ++sim->steps;
        ds_tally_flight_to(&sim->tally, target);
        if (target >= e->rebase_time) {
            ds_ed_rebase(e, sim->world.n, target);
            ds_protocols_rebased(sim, target);
            target = 0.0;
            sim->tally.stress_clock = 0.0;
        }
        /* The protocols' step's end (growth's wider cells, a barostat's
         * new box may build the state again: it then starts at the
         * present time, 0; without memory for that the run stops). */
        if (sim->protocols.stepping) {
            sim->tally.pairs_tested += e->tested;
            e->tested = 0;
            st = ds_protocols_step_end(sim, err);
            e = sim->state;
            target = (double)sim->steps * sim->world.dt - e->epoch;
            sim->tally.stress_clock = target; /* a state made again has its own clock */
        }
    }
    ds_timer_stop(&sim->collision_timer);
    sim->tally.pairs_tested += e->tested;
    e->tested = 0;
    ds_ed_show_at(&sim->disks, e, target);
    ds_ed_show_radii(sim, e, target);
    ds_ed_show_shear(sim, e, target);
    return st;
}

/* ------------------------------------------------------------------ */
/* ds_sim_set_disk, the services                                                 */
/* ------------------------------------------------------------------ */

/* Whether disk k (record p) at time now is closer to (x, y) than the
 * contact distance with disk self allows (DS_CONTACT_TOLERANCE). */
static int too_close(const ds_events *e, uint32_t k, uint32_t self, double now, double x, double y)
{
    const ed_disk *p = &e->disk[k];
    const double lag = now - p->t;
    const double rx = p->x + p->vx * lag - x, ry = p->y + p->vy * lag - y;
    const double keep = 1.0 - DS_CONTACT_TOLERANCE;
    const double sigma = e->radius ? e->radius[k] + e->radius[self] : 0.0;
    const double limit = (e->radius ? sigma * sigma : e->sigma2) * keep * keep;
    return rx * rx + ry * ry < limit;
}

/* Whether a disk of cell other than `self` overlaps a disk self at (x, y)
 * at time now. */
static int cell_overlaps(const ds_events *e, uint32_t cell, uint32_t self, double now, double x,
                         double y)
{
    const ds_cells *cells = &e->cells;
    const uint32_t *slot = ds_cells_slots(cells, cell);
    for (int j = 0; j < DS_CELL_SLOTS; ++j)
        if (slot[j] != cells->empty && slot[j] != self && too_close(e, slot[j], self, now, x, y))
            return 1;
    if (slot[DS_CELL_SLOTS - 1] != cells->empty)
        for (uint32_t m = ds_cells_overflow(cells, cell); m != cells->empty; m = cells->next[m])
            if (m != self && too_close(e, m, self, now, x, y))
                return 1;
    return 0;
}

/* The integrator's present time: the last step boundary. */
static double now_of(const ds_sim *sim)
{
    const ds_events *e = sim->state;
    return (double)sim->steps * sim->world.dt - e->epoch;
}

static ds_status set(ds_sim *sim, size_t k, ds_disk nd)
{
    ds_events *e = sim->state;
    ds_cells *cells = &e->cells;
    const double now = now_of(sim);
    /* Growing: the radii of now, from which the growth goes on. */
    if (e->law.rate > 0.0)
        ds_ed_growth_go_on(e, sim->world.n, now);
    const uint32_t column = ds_cells_column(cells, nd.x), row = ds_cells_row(cells, nd.y);
    /* The disk in the records' frame (falling with a field, event_state.h). */
    ds_disk f = nd;
    if (e->falls) {
        const double h = 0.5 * now * now;
        f.x -= e->field[0] * h;
        f.y -= e->field[1] * h;
        f.vx -= e->field[0] * now;
        f.vy -= e->field[1] * now;
    }
    /* Refuse an overlap before changing anything. */
    ds_ed_stencil_cells st;
    ds_ed_stencil(e, column, row, now, &st);
    for (uint32_t c = 0; c < st.count; ++c)
        if (cell_overlaps(e, st.cell[c], (uint32_t)k, now, f.x - st.sx[c], f.y - st.sy[c]))
            return DS_ERR_OVERLAP;
    ed_disk *d = &e->disk[k];
    ds_cells_remove(cells, ds_cells_index(cells, d->column, d->row), (uint32_t)k);
    d->x = f.x;
    d->y = f.y;
    d->vx = f.vx;
    d->vy = f.vy;
    d->t = now;
    d->column = (uint16_t)column;
    d->row = (uint16_t)row;
    ds_cells_add(cells, ds_cells_index(cells, column, row), (uint32_t)k);
    if (e->image) { /* the disk keeps its images; its new centre is in the box */
        e->image[2 * k] = sim->disks.ix[k];
        e->image[2 * k + 1] = sim->disks.iy[k];
    }
    ++d->changes; /* whatever was predicted against the old disk is stale */
    schedule(e, (uint32_t)k);
    sim->tally.pairs_tested += e->tested;
    e->tested = 0;
    ds_disks *disks = &sim->disks;
    disks->x[k] = nd.x;
    disks->y[k] = nd.y;
    disks->vx[k] = nd.vx;
    disks->vy[k] = nd.vy;
    return DS_OK;
}

/* Every velocity times factor at the present time, the records and the
 * arrays alike; a growth goes on from the radii of now. */
static ds_status scale_velocities(ds_sim *sim, double factor)
{
    ds_events *e = sim->state;
    const size_t n = sim->world.n;
    const double now = now_of(sim);
    if (sim->tally.shear_rate != 0.0) {
        ds_ed_scale_peculiar(sim, e, now, factor);
        ds_ed_growth_go_on(e, n, now);
        return DS_OK;
    }
    for (int c = 0; c < 3; ++c)
        sim->tally.kinetic[c] *= factor * factor;
    for (size_t k = 0; k < n; ++k) {
        ed_disk *d = &e->disk[k];
        ds_ed_advance(d, now);
        if (e->falls) { /* the velocities in the box, not the frame */
            double x, y, vx, vy;
            ds_ed_lab_at(e, d, now, &x, &y, &vx, &vy);
            d->vx = vx * factor - e->field[0] * now;
            d->vy = vy * factor - e->field[1] * now;
            sim->disks.vx[k] = vx * factor;
            sim->disks.vy[k] = vy * factor;
            continue;
        }
        d->vx *= factor;
        d->vy *= factor;
        sim->disks.vx[k] = d->vx;
        sim->disks.vy[k] = d->vy;
    }
    ds_ed_growth_go_on(e, n, now);
    return DS_OK;
}

/* The kinetic energy, momentum and mass of the records. */
static void kinetic(const ds_sim *sim, ds_kinetic *out)
{
    const ds_events *e = sim->state;
    const double now = now_of(sim);
    double k = 0.0, px = 0.0, py = 0.0, mass = 0.0;
    for (size_t i = 0; i < sim->world.n; ++i) {
        const ed_disk *d = &e->disk[i];
        const double m = e->mass ? e->mass[i] : 1.0;
        double vx = d->vx, vy = d->vy;
        if (e->falls) { /* in the box at now, not the frame */
            vx += e->field[0] * now;
            vy += e->field[1] * now;
        }
        if (e->lees_edwards) /* the peculiar velocity: less the profile's */
            vx -= ds_ed_streaming(e, d->y + d->vy * (now - d->t));
        k += m * (vx * vx + vy * vy);
        px += m * vx;
        py += m * vy;
        mass += m;
    }
    out->k = 0.5 * k;
    out->px = px;
    out->py = py;
    out->mass = mass;
}

/* A heat bath's collision with record k at t: the records before it are
 * at their own times, no later than t; whatever was predicted against
 * the disk is stale. */
static void set_velocity(ds_sim *sim, size_t k, double t, double vx, double vy)
{
    ds_events *e = sim->state;
    ed_disk *d = &e->disk[k];
    /* With a field the records fly in the falling frame: the velocity in
     * the box at t is the record's plus g t, and the new one goes in as
     * the frame's. */
    const double gx = e->falls ? e->field[0] * t : 0.0, gy = e->falls ? e->field[1] * t : 0.0;
    ds_tally_flight_to(&sim->tally, t);
    ds_tally_velocity(&sim->tally, e->mass ? e->mass[k] : 1.0, d->vx + gx, d->vy + gy, vx, vy);
    ds_ed_advance(d, t);
    d->vx = vx - gx;
    d->vy = vy - gy;
    ++d->changes;
    schedule(e, (uint32_t)k);
}

/* The box rescaled at the present step boundary: the disks shown at it
 * into the columns, a state built for the new box from them
 * (ds_rescale_box), whose origin is the present, so every protocol's
 * time moves by the old origin's distance to it. */
static ds_status resize(ds_sim *sim, double sx, double sy)
{
    ds_events *e = sim->state;
    const double now = now_of(sim);
    sim->tally.pairs_tested += e->tested;
    e->tested = 0;
    ds_ed_show_at(&sim->disks, e, now);
    const ds_status st = ds_rescale_box(sim, sx, sy);
    if (st == DS_OK)
        ds_protocols_rebased(sim, now - now_of(sim));
    return st;
}

/* ------------------------------------------------------------------ */
/* The table                                                            */
/* ------------------------------------------------------------------ */

/* The integrator's cell grid, or brute force: one cell for everyone. */
static int fits(ds_broadphase bp) { return bp == DS_BROADPHASE_CELLS || bp == DS_BROADPHASE_BRUTE; }

static ds_broadphase choose(const ds_world *w)
{
    (void)w;
    return DS_BROADPHASE_CELLS;
}

/* Disk numbers share 32 bits with the EV_* kinds, and the calendar's
 * entries keep them in 30. */
static ds_status check(const ds_world *w, unsigned *warnings, ds_error *err)
{
    (void)warnings;
    if (w->n >= ((size_t)1 << 30))
        return ds_refuse(err, DS_ERR_NOMEM, "n", (double)w->n, (double)((size_t)1 << 30),
                         "n = %zu disks: the event-driven integrator takes fewer than 2^30", w->n);
    return DS_OK;
}

static ds_status create(ds_sim *sim, ds_error *err)
{
    const ds_status st = ds_ed_create(sim);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)sim->world.n, NAN,
                         "n = %zu disks: no memory for the event-driven integrator", sim->world.n);
    return DS_OK;
}

const ds_integrator_ops ds_event_driven_ops = {
    .name = "event",
    /* Disks in contact on every side (a lattice at close packing) would
     * collide for ever at one instant. */
    .min_room = DS_ROOM_TO_MOVE,
    .fits = fits,
    .choose = choose,
    .check = check,
    .bytes = ds_ed_bytes,
    .create = create,
    .destroy = ds_ed_destroy,
    .run = run,
    .set = set,
    .save = ds_ed_save,
    .load = ds_ed_load,
    .scale_velocities = scale_velocities,
    .now = now_of,
    .kinetic = kinetic,
    .set_velocity = set_velocity,
    .resize = resize,
    .grow = ds_ed_grow,
    .growth_law = ds_ed_growth_law,
    .widen = ds_ed_widen,
    .kick = ds_ed_kick,
    .take_rules = ds_ed_take_rules,
    .shear = ds_ed_shear,
};
