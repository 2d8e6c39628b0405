/* SPDX-License-Identifier: MIT */
/* The event-driven integrator's state (event_state.h): making it from the
 * disk arrays (the slots sorted by cell, the records copied, every disk
 * predicted, the calendar built), freeing it, and showing the disks at a
 * time in the arrays. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/box.h"
#include "core/large_alloc.h"
#include "event/event_state.h"

void ds_ed_show_disk(const ds_events *e, size_t k, double t, const ds_box *box, double turns,
                     double out[4], int32_t image[2])
{
    const ed_disk *d = &e->disk[k];
    ds_ed_lab_at(e, d, t, &out[0], &out[1], &out[2], &out[3]);
    if (!e->image) /* walls */
        return;
    const int32_t iy_before = image[1];
    ds_box_wrap(box, &out[0], &out[1], &image[0], &image[1]);
    if (e->lees_edwards && image[1] != iy_before) {
        /* Wrapped across the top or bottom of a sheared box: the disk
         * takes the image's velocity and keeps its unwrapped centre, as
         * a crossing does (event_driven.c). */
        const int32_t crossed = (int32_t)((uint32_t)image[1] - (uint32_t)iy_before);
        out[2] -= (double)crossed * box->shift_speed;
        image[0] = (int32_t)((uint32_t)image[0] - (uint32_t)crossed * ds_turns_u32(turns));
    }
}

/* Record k is the disk of slot k (created so, see create). */
void ds_ed_show_at(ds_disks *disks, const ds_events *e, double t)
{
    const ds_box box = ds_ed_box_at(e, t);
    double turns = 0.0;
    if (e->lees_edwards)
        (void)ds_ed_shift(e, t, &turns);
    for (size_t k = 0; k < disks->n; ++k) {
        double u[4];
        int32_t image[2] = {0, 0};
        if (e->image) {
            image[0] = e->image[2 * k];
            image[1] = e->image[2 * k + 1];
        }
        ds_ed_show_disk(e, k, t, &box, turns, u, image);
        if (e->image) {
            disks->ix[k] = image[0];
            disks->iy[k] = image[1];
        }
        disks->x[k] = u[0];
        disks->y[k] = u[1];
        disks->vx[k] = u[2];
        disks->vy[k] = u[3];
    }
}

void ds_ed_rebase(ds_events *e, size_t n, double t)
{
    for (size_t k = 0; k < n; ++k) {
        ds_ed_advance(&e->disk[k], t);
        e->disk[k].t = 0.0;
        e->disk[k].next -= t;
    }
    if (e->falls) { /* out of the frame that fell from the old origin */
        const double h = 0.5 * t * t;
        for (size_t k = 0; k < n; ++k) {
            ed_disk *d = &e->disk[k];
            d->x += e->field[0] * h;
            d->y += e->field[1] * h;
            d->vx += e->field[0] * t;
            d->vy += e->field[1] * t;
        }
    }
    if (e->last_hit)
        for (size_t k = 0; k < n; ++k)
            e->last_hit[k] -= t;
    e->offset = ds_ed_offset(e, t);
    ds_eq_build(e->queue, 0.0);
    e->epoch += t;
    e->law.from -= t;
}

/* The time a disk takes to cross the box at the initial speed: by then
 * every disk has had several events, so the O(n) rebase is cheap beside
 * them, and times stay below ~10 crossing times. A field's frame moves
 * g t^2 / 2 from the origin: no further than the box's longer side
 * before the origin moves, so a centre in the frame keeps the digits of
 * one in the box. */
double ds_ed_rebase_time(const ds_world *w, const ds_rules *rules)
{
    const double side = fmax(w->box.side[0], w->box.side[1]);
    const double g = hypot(rules->field[0], rules->field[1]);
    const double crossing = side / w->speed;
    return g > 0.0 ? fmin(crossing, sqrt(2.0 * side / g)) : crossing;
}

void ds_ed_adopt_rules(ds_events *e, const ds_rules *rules, double *last_hit)
{
    e->inelastic = ds_rules_inelastic(rules);
    e->falls = ds_rules_fall(rules);
    e->restitution = rules->restitution;
    e->wall_restitution = rules->wall_restitution;
    e->contact_time = rules->contact_time;
    e->field[0] = rules->field[0];
    e->field[1] = rules->field[1];
    e->last_hit = last_hit;
}

static ds_broadphase grid_of(ds_broadphase bp)
{
    return bp == DS_BROADPHASE_BRUTE ? bp : DS_BROADPHASE_CELLS;
}

static size_t ed_bytes(size_t n, double radius, double box_x, double box_y, ds_broadphase bp)
{
    size_t cells = ds_cells_bytes(n, box_x, box_y, 2.0 * radius,
                                  grid_of(bp) == DS_BROADPHASE_BRUTE ? 1u : UINT32_MAX);
    return sizeof(ds_events) + n * sizeof(ed_disk) + cells + ds_eq_bytes(n, DS_EQ_CALENDAR);
}

/* What events read and write (fetching ahead pays once it outgrows the
 * caches), and all the state holds: that and the times waiting to be
 * filed (ds_ed_schedule_all). */
static size_t event_bytes(const ds_world *w)
{
    return ed_bytes(w->n, w->radius_max, w->box.side[0], w->box.side[1], w->broadphase) +
           (ds_box_any_periodic(&w->box) ? 2 * w->n * sizeof(int32_t) : 0);
}

size_t ds_ed_bytes(const ds_world *w) { return event_bytes(w) + w->n * sizeof(double); }

void ds_ed_destroy(ds_sim *sim)
{
    ds_events *e = sim->state;
    if (!e)
        return;
    free(e->law.base);
    free(e->times);
    free(e->image);
    ds_eq_destroy(e->queue);
    ds_cells_free(&e->cells);
    free(e->disk);
    free(e);
    sim->state = NULL;
}

/* Orders the slots by cell, row by row: disks that meet in events are
 * then mostly near each other in memory. */
static ds_status sort_slots_by_cell(ds_disks *disks, const ds_cells *cells)
{
    const size_t n = disks->n, count = (size_t)cells->nx * cells->ny;
    uint32_t *start = calloc(count + 1, sizeof *start);
    uint32_t *order = malloc(n * sizeof *order);
    ds_status st = start && order ? DS_OK : DS_ERR_NOMEM;
    if (st == DS_OK) {
        for (size_t k = 0; k < n; ++k)
            ++start[ds_cells_index(cells, ds_cells_column(cells, disks->x[k]),
                                   ds_cells_row(cells, disks->y[k])) +
                    1];
        for (size_t c = 0; c < count; ++c)
            start[c + 1] += start[c];
        for (size_t k = 0; k < n; ++k)
            order[start[ds_cells_index(cells, ds_cells_column(cells, disks->x[k]),
                                       ds_cells_row(cells, disks->y[k]))]++] = (uint32_t)k;
        st = ds_disks_permute(disks, order);
    }
    free(start);
    free(order);
    return st;
}

/* Predicts every disk, then builds the calendar from all the times at once
 * (it sizes its buckets from them). Until then every disk's time is
 * +infinity, so no pair is skipped for its partner's earlier event: the
 * times wait in an array of their own. */
void ds_ed_schedule_all(ds_events *e, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        e->times[k] = ds_ed_predict(e, (uint32_t)k);
    for (size_t k = 0; k < n; ++k)
        e->disk[k].next = e->times[k];
    e->tested = 0; /* the first predictions are not the run's tests */
}

ds_status ds_ed_alloc(ds_sim *sim)
{
    const ds_world *w = &sim->world;
    const size_t n = w->n;
    ds_events *e = calloc(1, sizeof *e);
    if (!e)
        return DS_ERR_NOMEM;
    sim->state = e;
    e->box = w->box;
    /* A sheared box's images go on from where they stand now. */
    e->lees_edwards = w->box.offset != 0.0 || w->box.shift_speed != 0.0;
    e->offset = w->box.offset;
    e->one_radius = w->radius;
    e->sigma2 = 4.0 * w->radius * w->radius;
    /* The clock starts at the present step boundary (ds_sim_set_disks comes
     * here later in a run). */
    e->epoch = (double)sim->steps * w->dt;
    e->rebase_time = ds_ed_rebase_time(w, &w->rules);
    ds_ed_adopt_rules(e, &w->rules, sim->disks.last_hit);
    e->law.scale = 1.0;
    e->disk = ds_large_alloc(n * sizeof(ed_disk));
    e->times = malloc((n ? n : 1) * sizeof *e->times);
    ds_status st = e->disk && e->times ? DS_OK : DS_ERR_NOMEM;
    if (st == DS_OK && ds_box_any_periodic(&e->box) &&
        !(e->image = calloc(2 * (n ? n : 1), sizeof *e->image)))
        st = DS_ERR_NOMEM;
    if (st == DS_OK)
        st = ds_cells_init(&e->cells, n, e->box.side[0], e->box.side[1], 2.0 * w->radius_max,
                           w->broadphase == DS_BROADPHASE_BRUTE ? 1u : UINT32_MAX);
    if (st == DS_OK)
        e->shear_cell = (int64_t)floor(e->offset * e->cells.inv_wx);
    if (st == DS_OK)
        st = ds_eq_create(&e->queue, n, DS_EQ_CALENDAR, &e->disk[0].next, sizeof(ed_disk));
    /* Fetching ahead pays once the state outgrows the caches; below, it is
     * work for nothing. Measured at area fraction 0.5 (median of 3, ns per
     * collision, off / on): 10^4 disks 870 / 995, 3 10^4 992 / 1093,
     * 10^5 2064 / 1188, 3 10^5 1882 / 1279. */
    e->fetching = event_bytes(w) > DS_FETCH_AHEAD_BYTES;
    return st; /* on failure the table's destroy frees what was made */
}

void ds_ed_start(ds_events *e, double now)
{
    ds_eq_build(e->queue, now);
    if (e->fetching)
        ds_eq_on_soon(e->queue, ds_fetch_on_soon, e, DS_FETCH_LOOKAHEAD);
}

/* The records are copied from the disk arrays in slot order, once the
 * slots are sorted by cell: record k is slot k's disk, which show_at
 * copies back. */
ds_status ds_ed_create(ds_sim *sim)
{
    const size_t n = sim->world.n;
    ds_status st = ds_ed_alloc(sim);
    ds_events *e = sim->state;
    if (st == DS_OK)
        st = sort_slots_by_cell(&sim->disks, &e->cells);
    if (st != DS_OK)
        return st;
    /* After the cell sort (which moved the arrays). A new state forgets
     * the disks' last collisions (their times were the old clock's). */
    e->radius = sim->disks.r;
    e->mass = sim->disks.m;
    e->last_hit = sim->disks.last_hit;
    for (size_t k = 0; e->last_hit && k < n; ++k)
        e->last_hit[k] = -INFINITY;
    const ds_disks *disks = &sim->disks;
    for (size_t k = n; k-- > 0;) {
        ed_disk *d = &e->disk[k];
        memset(d, 0, sizeof *d);
        d->x = disks->x[k];
        d->y = disks->y[k];
        d->vx = disks->vx[k];
        d->vy = disks->vy[k];
        d->column = (uint16_t)ds_cells_column(&e->cells, d->x);
        d->row = (uint16_t)ds_cells_row(&e->cells, d->y);
        d->next = INFINITY;
        ds_cells_add(&e->cells, ds_cells_index(&e->cells, d->column, d->row), (uint32_t)k);
        if (e->image) { /* the arrays' centres are in the box: no wrap to undo */
            e->image[2 * k] = disks->ix[k];
            e->image[2 * k + 1] = disks->iy[k];
        }
    }
    ds_ed_schedule_all(e, n);
    ds_ed_start(e, 0.0);
    return DS_OK;
}
