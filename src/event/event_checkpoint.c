/* SPDX-License-Identifier: MIT */
/* A checkpoint of the event-driven integrator: what its next event
 * depends on, to the bit. The records (positions at their own times,
 * velocities, scheduled times and partners, change counts), the cells'
 * slots and overflow lists in their order (the order candidates are
 * tested in, which settles a tie between two equal pair times), and the
 * clock's epoch. The calendar is built again from the records' times: it
 * gives its events in the order of their times, ties by disk number,
 * whatever its history (event_queue.h), so that is the order the run
 * would have taken. What fetching ahead holds only brings memory in, and
 * starts empty. */
#include <math.h>
#include <stdlib.h>

#include "core/box.h"
#include "core/overlap.h"
#include "event/event_state.h"

void ds_ed_save(const ds_sim *sim, ds_state_writer *w)
{
    const ds_events *e = sim->state;
    const size_t n = sim->world.n, cells = (size_t)e->cells.nx * e->cells.ny;
    ds_put_f64(w, e->epoch);
    ds_put_f64(w, e->rebase_time);
    ds_put_u64(w, e->tested);
    ds_put_u32(w, e->cells.nx);
    ds_put_u32(w, e->cells.ny);
    for (size_t k = 0; k < n; ++k) {
        const ed_disk *d = &e->disk[k];
        ds_put_f64(w, d->x);
        ds_put_f64(w, d->y);
        ds_put_f64(w, d->vx);
        ds_put_f64(w, d->vy);
        ds_put_f64(w, d->t);
        ds_put_f64(w, d->next);
        ds_put_u32(w, (uint32_t)d->column | (uint32_t)d->row << 16);
        ds_put_u32(w, d->changes);
        ds_put_u32(w, d->partner);
        ds_put_u32(w, d->partner_changes);
    }
    for (size_t s = 0; s < cells * DS_CELL_SLOTS; ++s)
        ds_put_u32(w, e->cells.slot[s]);
    for (size_t c = 0; c < cells; ++c)
        ds_put_u32(w, e->cells.more[c]);
    for (size_t k = 0; k < n; ++k)
        ds_put_u32(w, e->cells.next[k]);
    /* Growing radii: their law and the radii they grow from (the growth
     * protocol's part is its own, core/protocol.h). */
    const ds_ed_law *g = &e->law;
    ds_put_u32(w, g->base ? 1u : 0u);
    if (g->base) {
        ds_put_f64(w, g->rate);
        ds_put_f64(w, g->scale);
        ds_put_f64(w, g->from);
        ds_put_f64(w, g->eta);
        for (size_t k = 0; k < n; ++k)
            ds_put_f64(w, g->base[k]);
    }
    /* A sheared box (since format version 5): the images' offset at the
     * clock's origin, their speed and the stencils' cell count. */
    ds_put_u32(w, (uint32_t)e->lees_edwards);
    ds_put_f64(w, e->offset);
    ds_put_f64(w, e->box.shift_speed);
    ds_put_u64(w, (uint64_t)e->shear_cell);
}

/* A sheared box's part (format version 5 on; before, none): it must be a
 * periodic box's, its numbers finite, its cell count that of its offset
 * at the present within one (the count lags the offset by at most the
 * edge it is passing). */
static ds_status read_shear(ds_sim *sim, ds_events *e, double now, ds_reader *r, uint32_t version,
                            ds_error *err)
{
    if (version < 5)
        return DS_OK;
    const uint32_t on = ds_get_u32(r);
    const double offset = ds_get_f64(r), speed = ds_get_f64(r);
    const int64_t cell = (int64_t)ds_get_u64(r);
    if (r->failed || on > 1u)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its shear's part is not one");
    if (!on)
        return DS_OK;
    e->lees_edwards = 1;
    e->offset = offset;
    e->box.shift_speed = speed;
    const double o = ds_ed_offset(e, now), at = floor(o * e->cells.inv_wx);
    if (!ds_box_periodic(&e->box, 0) || !ds_box_periodic(&e->box, 1) || !isfinite(o) ||
        !(fabs(speed) <= DS_VELOCITY_MAX) || !(fabs((double)cell - at) <= 1.0))
        return ds_state_refuse(err, DS_ERR_FORMAT, "its shear does not fit its box");
    e->shear_cell = cell;
    sim->world.box.shift_speed = speed;
    sim->world.box.shift = ds_ed_box_at(e, now).shift;
    sim->world.box.offset = o;
    return DS_OK;
}

/* Format versions 1 and 2 kept the growth protocol's fields between the
 * law's (as their ds_growth struct had them): the protocol's part goes to
 * legacy, for the checkpoint's loader to hand over. */
static void read_law_2x(ds_ed_law *g, ds_reader *r, ds_legacy *legacy)
{
    ds_growth_record *p = &legacy->growth;
    legacy->has_growth = 1;
    g->rate = ds_get_f64(r);
    p->asked = ds_get_f64(r);
    g->scale = ds_get_f64(r);
    g->from = ds_get_f64(r);
    p->stop_time = ds_get_f64(r);
    p->until_eta = ds_get_f64(r);
    p->until_z = ds_get_f64(r);
    p->kinetic = ds_get_f64(r);
    p->kinetic_target = ds_get_f64(r);
    p->momentum_energy = ds_get_f64(r);
    p->window = ds_get_u64(r);
    p->window_start = ds_get_f64(r);
    p->window_virial = ds_get_f64(r);
    p->stopped = (int)ds_get_u32(r);
    p->last_z = ds_get_f64(r);
    p->growing = g->rate > 0.0;
    if (p->stopped < 0 || p->stopped > 2)
        r->failed = 1;
}

static ds_status read_growth(ds_sim *sim, ds_events *e, double now, ds_reader *r, uint32_t version,
                             ds_legacy *legacy, ds_error *err)
{
    const size_t n = sim->world.n;
    const uint32_t has = ds_get_u32(r);
    if (r->failed || has > 1u)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the growth's part is not one");
    if (!has)
        return DS_OK;
    ds_ed_law *g = &e->law;
    if (!sim->disks.r || !ds_box_periodic(&e->box, 0) || !ds_box_periodic(&e->box, 1))
        return ds_state_refuse(err, DS_ERR_FORMAT, "growth without radii or walls around it");
    if (version < 3) {
        read_law_2x(g, r, legacy);
    } else {
        g->rate = ds_get_f64(r);
        g->scale = ds_get_f64(r);
        g->from = ds_get_f64(r);
        g->eta = ds_get_f64(r);
    }
    if (r->failed || !(g->rate >= 0.0 && g->rate < 1e300) ||
        !(g->scale >= 1.0 && g->scale < 1e300) || !(g->from <= now) || !isfinite(g->from) ||
        !(g->eta >= 0.0 && g->eta < 1.0) || !(1.0 + g->rate * (now - g->from) > 0.0))
        return ds_state_refuse(err, DS_ERR_FORMAT, "the growth's clock or targets are not a run's");
    if (!(g->base = malloc(n * sizeof *g->base)))
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the growth of %zu disks", n);
    e->radius = g->base;
    double covered = 0.0;
    for (size_t k = 0; k < n; ++k) {
        g->base[k] = ds_get_f64(r);
        covered += g->base[k] * g->base[k];
        /* The radius shown is the base grown to now, to the bit. */
        if (r->failed || !(g->base[k] > 0.0) ||
            g->base[k] * (1.0 + g->rate * (now - g->from)) != sim->disks.r[k])
            return ds_state_refuse(err, DS_ERR_FORMAT, "disk %zu's growing radius is not its own",
                                   k);
    }
    /* 2.x kept no area fraction: the one its restart computed from the
     * same radii, to the bit. */
    if (version < 3)
        g->eta = 0.5 * DS_TWO_PI * covered / (e->box.side[0] * e->box.side[1]);
    return DS_OK;
}

static int is_event_kind(uint32_t partner)
{
    return partner == EV_WALL_X || partner == EV_WALL_Y || partner == EV_CELL_X ||
           partner == EV_CELL_Y || partner == EV_NONE;
}

static ds_status read_records(ds_events *e, size_t n, double now, ds_reader *r, ds_error *err)
{
    for (size_t k = 0; k < n; ++k) {
        ed_disk *d = &e->disk[k];
        d->x = ds_get_f64(r);
        d->y = ds_get_f64(r);
        d->vx = ds_get_f64(r);
        d->vy = ds_get_f64(r);
        d->t = ds_get_f64(r);
        d->next = ds_get_f64(r);
        const uint32_t cell = ds_get_u32(r);
        d->column = (uint16_t)(cell & 0xffffu);
        d->row = (uint16_t)(cell >> 16);
        d->changes = ds_get_u32(r);
        d->partner = ds_get_u32(r);
        d->partner_changes = ds_get_u32(r);
        if (r->failed)
            return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside disk %zu's record", k);
        /* Every scheduled time is at or after now (events before it were
         * handled), or never. */
        if (!isfinite(d->x) || !isfinite(d->y) || !isfinite(d->vx) || !isfinite(d->vy) ||
            !isfinite(d->t) || !(d->next >= now))
            return ds_state_refuse(err, DS_ERR_FORMAT, "disk %zu's record has a bad number", k);
        /* "Nothing ahead, ever" only at +infinity: handle_event takes any
         * other kind it meets for a disk or a wall or a cell edge. */
        if (d->column >= e->cells.nx || d->row >= e->cells.ny ||
            !(d->partner < n || is_event_kind(d->partner)) ||
            (d->partner == EV_NONE) != (d->next == INFINITY))
            return ds_state_refuse(err, DS_ERR_FORMAT,
                                   "disk %zu's record names a cell or partner out of range", k);
    }
    return DS_OK;
}

/* Reads the cells and checks they hold every disk once, in the cell its
 * record names, packed from the first slot, with an overflow list only
 * behind four taken slots: what predicting and fetching rely on. */
static ds_status read_cells(ds_events *e, size_t n, ds_reader *r, ds_error *err)
{
    ds_cells *c = &e->cells;
    const size_t cells = (size_t)c->nx * c->ny;
    const uint32_t empty = c->empty;
    for (size_t s = 0; s < cells * DS_CELL_SLOTS; ++s)
        c->slot[s] = ds_get_u32(r);
    for (size_t k = 0; k < cells; ++k)
        c->more[k] = ds_get_u32(r);
    for (size_t k = 0; k < n; ++k)
        c->next[k] = ds_get_u32(r);
    if (r->failed)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside the cells");
    unsigned char *seen = calloc(n ? n : 1, 1);
    if (!seen)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to check the cells");
    ds_status st = DS_OK;
    size_t found = 0;
    for (size_t cell = 0; cell < cells && st == DS_OK; ++cell) {
        const uint32_t *slot = ds_cells_slots(c, (uint32_t)cell);
        for (int j = 0; j < DS_CELL_SLOTS && st == DS_OK; ++j) {
            const uint32_t k = slot[j];
            if (k == empty) {
                if (j + 1 < DS_CELL_SLOTS && slot[j + 1] != empty)
                    st = DS_ERR_FORMAT; /* not packed */
                continue;
            }
            if (k > empty || seen[k] ||
                ds_cells_index(c, e->disk[k].column, e->disk[k].row) != cell) {
                st = DS_ERR_FORMAT;
            } else {
                seen[k] = 1;
                ++found;
            }
        }
        if (st == DS_OK && c->more[cell] != empty && slot[DS_CELL_SLOTS - 1] == empty)
            st = DS_ERR_FORMAT; /* a list behind a free slot */
        for (uint32_t k = c->more[cell]; st == DS_OK && k != empty; k = c->next[k]) {
            /* seen[] stops a list that loops: no disk is in two places. */
            if (k > empty || seen[k] ||
                ds_cells_index(c, e->disk[k].column, e->disk[k].row) != cell) {
                st = DS_ERR_FORMAT;
                break; /* before next[k] is read */
            }
            seen[k] = 1;
            ++found;
        }
    }
    free(seen);
    if (st == DS_OK && found != n)
        st = DS_ERR_FORMAT;
    return st == DS_OK ? DS_OK
                       : ds_state_refuse(err, st,
                                         "the cells do not hold each disk once, where its "
                                         "record says");
}

/* The records against the disk arrays, which were shown from them when
 * the state was saved: each record, flown from its time to now, is its
 * slot's disk to the bit (whose values sim/state.c checked as ds_sim_set_disk
 * checks a disk: finite, no faster than it allows, in the box); it lies
 * in the cell it names (up to rounding); and no two disks overlap. A
 * state that passes is one the integrator could have reached, so a run
 * from it is a run (a forged record far from its cell would have it
 * cross cells at one instant for ever). */
static ds_status check_records(const ds_sim *sim, ds_events *e, double now, ds_error *err)
{
    const ds_disks *a = &sim->disks;
    const ds_cells *c = &e->cells;
    const double slack = 1e-9 * fmax(e->box.side[0], e->box.side[1]);
    const ds_box box = ds_ed_box_at(e, now);
    double turns = 0.0;
    if (e->lees_edwards)
        (void)ds_ed_shift(e, now, &turns);
    for (size_t k = 0; k < a->n; ++k) {
        const ed_disk *d = &e->disk[k];
        double x, y, vx, vy;
        ds_ed_lab_at(e, d, now, &x, &y, &vx, &vy);
        if (e->image) {
            /* The records' image counts: the arrays' less the wrap of
             * showing (ds_ed_show_at). */
            double u[4];
            int32_t image[2] = {0, 0};
            ds_ed_show_disk(e, k, now, &box, turns, u, image);
            x = u[0];
            y = u[1];
            vx = u[2];
            vy = u[3];
            e->image[2 * k] = (int32_t)((uint32_t)a->ix[k] - (uint32_t)image[0]);
            e->image[2 * k + 1] = (int32_t)((uint32_t)a->iy[k] - (uint32_t)image[1]);
        }
        /* Where the record's centre is in the box at its own time. */
        const double cx = ds_ed_lab_coordinate(e, d, 0), cy = ds_ed_lab_coordinate(e, d, 1);
        const int in_cell = cx >= (double)d->column * c->wx - slack &&
                            cx <= (double)(d->column + 1u) * c->wx + slack &&
                            cy >= (double)d->row * c->wy - slack &&
                            cy <= (double)(d->row + 1u) * c->wy + slack;
        /* A time of last collision is a past time, or none. */
        const int last_ok = !e->last_hit || e->last_hit[k] <= now;
        if (!(d->t >= 0.0 && d->t <= now) || !in_cell || !last_ok || x != a->x[k] || y != a->y[k] ||
            vx != a->vx[k] || vy != a->vy[k])
            return ds_state_refuse(err, DS_ERR_FORMAT,
                                   "disk %zu's record is not the disk of its slot", k);
    }
    size_t i = 0, j = 0;
    const ds_status st = ds_find_overlap(&sim->world, a->x, a->y, a->r, &i, &j);
    if (st == DS_ERR_OVERLAP)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the disks of slots %zu and %zu overlap", i, j);
    return st == DS_OK ? DS_OK : ds_state_refuse(err, st, "no memory to check the disks");
}

ds_status ds_ed_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_legacy *legacy, ds_error *err)
{
    const size_t n = sim->world.n;
    if (ds_ed_alloc(sim) != DS_OK)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the events of %zu disks", n);
    ds_events *e = sim->state;
    e->radius = sim->disks.r;
    e->mass = sim->disks.m;
    /* Rules that lose energy go by each disk's time of last collision. */
    if (e->inelastic && !e->last_hit)
        return ds_state_refuse(err, DS_ERR_FORMAT,
                               "its collisions lose energy but it has no times of last collision");
    e->epoch = ds_get_f64(r);
    const double rebase_time = ds_get_f64(r);
    e->tested = ds_get_u64(r);
    /* The grid a growth built for radii 5% past its last rebuild
     * (event_growth.c) has fewer, wider cells than the radii of now would
     * choose: any grid no finer than that is one a run could have. */
    const uint32_t nx = ds_get_u32(r), ny = ds_get_u32(r);
    if (r->failed || !(nx >= 1u && nx <= e->cells.nx && ny >= 1u && ny <= e->cells.ny))
        return ds_state_refuse(err, DS_ERR_FORMAT, "the event cells do not match the box");
    if (nx != e->cells.nx || ny != e->cells.ny) {
        ds_cells_free(&e->cells);
        if (ds_cells_init_shape(&e->cells, n, e->box.side[0], e->box.side[1], nx, ny) != DS_OK)
            return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the event cells");
    }
    /* The clock: the epoch is a step boundary, the present one at most
     * one rebase time ago. */
    const double now = (double)sim->steps * sim->world.dt - e->epoch;
    if (!isfinite(e->epoch) || rebase_time != e->rebase_time || !(now >= 0.0) ||
        !(now <= 2.0 * rebase_time + sim->world.dt))
        return ds_state_refuse(err, DS_ERR_FORMAT, "the event clock is not this run's");
    ds_status st = read_records(e, n, now, r, err);
    if (st == DS_OK)
        st = read_cells(e, n, r, err);
    if (st == DS_OK)
        st = read_growth(sim, e, now, r, version, legacy, err);
    if (st == DS_OK)
        st = read_shear(sim, e, now, r, version, err);
    if (st == DS_OK)
        st = check_records(sim, e, now, err);
    if (st == DS_OK)
        ds_ed_start(e, now);
    return st;
}
