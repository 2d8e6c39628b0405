/* SPDX-License-Identifier: MIT */
/* Lees-Edwards boundaries in the event-driven integrator (a sheared
 * periodic box, protocols/shear.c): the images above and below stand
 * offset + shift_speed t along x (event_state.h). What that changes:
 * - the boundary rows' stencils reach the four columns across the top
 *   or bottom that the images stand over (event_predict.c), valid until
 *   the offset passes the next cell edge, the shear protocol's moment
 *   (ds_ed_shear, the table's service);
 * - a disk crossing the top or bottom takes the image's shift and speed
 *   (ds_ed_cross_sheared);
 * - the pressure tensor's kinetic xy part is the peculiar velocities'
 *   (ds_ed_start_shear_tally, ds_ed_sheared_collision, core/collide.h's
 *   ds_tally_shear_flight), and the temperature and the isokinetic
 *   scaling take them (ds_ed_scale_peculiar, ds_ed_streaming). */
#include <math.h>

#include "core/collide.h"
#include "event/event_state.h"

static void schedule(ds_events *e, uint32_t i) { ds_eq_set(e->queue, i, ds_ed_predict(e, i)); }

/* Disk d (record i), wrapped at t across the top (up) or bottom of a
 * sheared box: it enters as the image it was, the image's shift along x
 * and its speed taken off (up) or added, and its x image count takes the
 * offset's whole widths so that its unwrapped centre, x + ix width + iy
 * offset, goes on continuously (ds_sim_get_shear_offset). Its velocity
 * changes (the kinetic tensor and the shear's moment with it) but not
 * its motion relative to anyone: what was predicted against it stays. */
void ds_ed_cross_sheared(ds_sim *sim, ds_events *e, uint32_t i, double t, int up)
{
    ed_disk *d = &e->disk[i];
    ds_tally *tally = &sim->tally;
    double turns;
    const double shift = ds_ed_shift(e, t, &turns), sign = up ? 1.0 : -1.0;
    const double m = e->mass ? e->mass[i] : 1.0, speed = e->box.shift_speed;
    ds_tally_flight_to(tally, t);
    ds_tally_velocity(tally, m, d->vx, d->vy, d->vx - sign * speed, d->vy);
    tally->momentum[0] -= m * sign * speed;
    tally->shear_moment -= sign * m * d->vy * e->box.side[1];
    d->vx -= sign * speed;
    int32_t *ix = &e->image[2 * (size_t)i];
    const uint32_t w = ds_turns_u32(turns);
    *ix = (int32_t)(up ? (uint32_t)*ix - w : (uint32_t)*ix + w);
    /* A shift moves the disk along x into another column; none (the
     * images standing at 0) leaves it in its own, to the bit. */
    if (shift != 0.0) {
        d->x = ds_wrap_counting(d->x - sign * shift, e->box.side[0], ix);
        d->column = (uint16_t)ds_cells_column(&e->cells, d->x);
    }
}

/* A sheared box's rate and moment sum m (y - H/2) vy for the stress
 * tally (core.h), from the disks as the arrays show them at the run's
 * start; 0 without shear. */
void ds_ed_start_shear_tally(ds_sim *sim, const ds_events *e)
{
    ds_tally *t = &sim->tally;
    t->shear_rate = e->lees_edwards ? e->box.shift_speed / e->box.side[1] : 0.0;
    t->shear_moment = 0.0;
    if (t->shear_rate == 0.0)
        return;
    const ds_disks *d = &sim->disks;
    const double middle = 0.5 * e->box.side[1];
    for (size_t k = 0; k < d->n; ++k)
        t->shear_moment += (d->m ? d->m[k] : 1.0) * (d->y[k] - middle) * d->vy[k];
}

/* A collision of records i and j in a sheared box, their velocities
 * changed, before[] the kinetic tensor and v0[] their velocities (a's,
 * b's) before it: the shear's moment sum m (y - H/2) vy takes a's change
 * of momentum along y, b's the opposite, at the two centres in the box;
 * and a pair across the top or bottom meets as images moving apart along
 * x, whose lab energy is not kept, so the kinetic tensor's change is
 * taken from the velocities themselves (the rules assume it kept). */
void ds_ed_sheared_collision(ds_tally *tally, const ds_events *e, uint32_t i, uint32_t j,
                             int across, const double before[3], const double v0[4])
{
    const ed_disk *a = &e->disk[i], *b = &e->disk[j];
    const double ma = e->mass ? e->mass[i] : 1.0, mb = e->mass ? e->mass[j] : 1.0;
    if (tally->shear_rate != 0.0)
        tally->shear_moment += ma * (a->vy - v0[1]) * (a->y - b->y);
    if (!across)
        return;
    tally->kinetic[0] =
        before[0] + ma * (a->vx * a->vx - v0[0] * v0[0]) + mb * (b->vx * b->vx - v0[2] * v0[2]);
    tally->kinetic[1] =
        before[1] + ma * (a->vy * a->vy - v0[1] * v0[1]) + mb * (b->vy * b->vy - v0[3] * v0[3]);
    tally->kinetic[2] =
        before[2] + ma * (a->vx * a->vy - v0[0] * v0[1]) + mb * (b->vx * b->vy - v0[2] * v0[3]);
}

/* A sheared box's velocities scaled about the profile (the peculiar
 * velocities times factor) at now, the records and arrays alike, the
 * kinetic tensor and the shear's moment summed afresh. */
void ds_ed_scale_peculiar(ds_sim *sim, ds_events *e, double now, double factor)
{
    ds_tally *t = &sim->tally;
    const double middle = 0.5 * e->box.side[1];
    double xx = 0.0, yy = 0.0, xy = 0.0, moment = 0.0;
    for (size_t k = 0; k < sim->world.n; ++k) {
        ed_disk *d = &e->disk[k];
        ds_ed_advance(d, now);
        const double u = ds_ed_streaming(e, d->y), m = e->mass ? e->mass[k] : 1.0;
        d->vx = u + factor * (d->vx - u);
        d->vy *= factor;
        sim->disks.vx[k] = d->vx; /* the arrays' y is the wrapped record's: same profile */
        sim->disks.vy[k] = d->vy;
        xx += m * d->vx * d->vx;
        yy += m * d->vy * d->vy;
        xy += m * d->vx * d->vy;
        moment += m * (d->y - middle) * d->vy;
    }
    t->kinetic[0] = xx;
    t->kinetic[1] = yy;
    t->kinetic[2] = xy;
    t->shear_moment = moment;
}

/* The disks of row `row` taken to t and predicted again there. */
static void predict_row(ds_events *e, uint32_t row, double t)
{
    const ds_cells *cells = &e->cells;
    for (uint32_t c = 0; c < cells->nx; ++c) {
        const uint32_t cell = ds_cells_index(cells, c, row);
        const uint32_t *slot = ds_cells_slots(cells, cell);
        for (int j = 0; j < DS_CELL_SLOTS && slot[j] != cells->empty; ++j) {
            ds_ed_advance(&e->disk[slot[j]], t);
            schedule(e, slot[j]);
        }
        if (slot[DS_CELL_SLOTS - 1] != cells->empty)
            for (uint32_t k = ds_cells_overflow(cells, cell); k != cells->empty;
                 k = cells->next[k]) {
                ds_ed_advance(&e->disk[k], t);
                schedule(e, k);
            }
    }
}

/* Every disk at t takes the change of the shear's profile, du (y - H/2)
 * along x (a shear set afresh starts from its steady profile rather than
 * from rest, which momentum would take a diffusion time over the height
 * to reach); the kinetic tensor and the shear's moment summed afresh,
 * and everyone predicted again. */
static void add_profile(ds_sim *sim, ds_events *e, double t, double du)
{
    ds_tally *tally = &sim->tally;
    const double middle = 0.5 * e->box.side[1];
    ds_tally_flight_to(tally, t);
    double xx = 0.0, yy = 0.0, xy = 0.0;
    for (size_t k = 0; k < sim->world.n; ++k) {
        ed_disk *d = &e->disk[k];
        ds_ed_advance(d, t);
        const double m = e->mass ? e->mass[k] : 1.0;
        d->vx += du * (d->y - middle);
        xx += m * d->vx * d->vx;
        yy += m * d->vy * d->vy;
        xy += m * d->vx * d->vy;
        ++d->changes; /* every prediction is stale */
        d->next = INFINITY;
    }
    tally->kinetic[0] = xx;
    tally->kinetic[1] = yy;
    tally->kinetic[2] = xy;
    ds_ed_schedule_all(e, sim->world.n);
    ds_eq_build(e->queue, t);
}

/* The table's shear service (core.h). The boundary rows' stencils reach the
 * columns shear_cell along (event_predict.c), valid while the offset
 * stays within that cell width: each time it passes an edge the count
 * moves by one and the two rows are predicted again, which costs 2 nx
 * disks' predictions per cell width of shift (rate H / w of them per
 * unit time). */
double ds_ed_shear(ds_sim *sim, double t, double speed, int moved)
{
    ds_events *e = sim->state;
    /* The stencils change when the count moves, the speed changes, or a
     * box that was not sheared stands shifted; a shear set again as it
     * was, or at rate 0 on a box at rest, leaves every prediction true. */
    const int again = moved || speed != e->box.shift_speed;
    if (moved) {
        e->shear_cell += moved;
    } else {
        if (speed != e->box.shift_speed)
            add_profile(sim, e, t, (speed - e->box.shift_speed) / e->box.side[1]);
        const double o = ds_ed_offset(e, t);
        e->lees_edwards = 1;
        e->box.shift_speed = sim->world.box.shift_speed = speed;
        e->offset = o - speed * t;
        e->shear_cell = (int64_t)floor(o * e->cells.inv_wx);
        sim->world.box.shift = ds_ed_box_at(e, t).shift;
        sim->world.box.offset = o;
        sim->tally.shear_rate = speed / e->box.side[1];
        ds_ed_show_at(&sim->disks, e, t); /* the profile's velocities */
    }
    if (again) {
        predict_row(e, 0, t);
        if (e->cells.ny > 1)
            predict_row(e, e->cells.ny - 1, t);
    }
    sim->tally.pairs_tested += e->tested;
    e->tested = 0;
    double next = INFINITY;
    if (speed > 0.0)
        next = ((double)(e->shear_cell + 1) * e->cells.wx - e->offset) / speed;
    else if (speed < 0.0)
        next = ((double)e->shear_cell * e->cells.wx - e->offset) / speed;
    return next > t ? next : t;
}
