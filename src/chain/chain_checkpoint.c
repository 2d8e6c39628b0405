/* SPDX-License-Identifier: MIT */
/* A checkpoint of the event-chain integrator: what its next lifting
 * depends on, to the bit. The chain in progress (its disk, axis, sign and
 * what is left of it), the generator that starts the next ones, the
 * chain length, and where each disk sits in the cells (its slot decides
 * which of two disks at the same distance a scan finds first). The
 * centres are the disk columns, which sim/checkpoint.c writes; the
 * step's tally has gone to sim->tally at the step's end. */
#include <math.h>
#include <stdlib.h>

#include "chain/chain_state.h"

void ds_ch_save(const ds_sim *sim, ds_state_writer *w)
{
    const ds_chain *c = sim->state;
    ds_put_f64(w, c->length);
    ds_put_u64(w, c->rng.state);
    ds_put_u64(w, c->chains);
    ds_put_u32(w, c->chain.active);
    ds_put_u32(w, c->chain.axis);
    ds_put_f64(w, c->chain.sign);
    ds_put_f64(w, c->chain.left);
    ds_put_u64(w, c->chain.stalled);
    ds_put_u32(w, c->grid.count[0]);
    ds_put_u32(w, c->grid.count[1]);
    for (size_t k = 0; k < c->n; ++k) {
        ds_put_u32(w, c->disk[k].cell);
        ds_put_u32(w, c->disk[k].slot);
        ds_put_u32(w, c->disk[k].next);
    }
    for (size_t cell = 0; cell < c->grid.cells; ++cell)
        ds_put_u32(w, c->grid.more[cell]);
}

static ds_status read_chain(ds_chain *c, ds_reader *r, ds_error *err)
{
    c->length = ds_get_f64(r);
    c->rng.state = ds_get_u64(r);
    c->chains = ds_get_u64(r);
    ch_chain *ch = &c->chain;
    ch->active = ds_get_u32(r);
    ch->axis = ds_get_u32(r);
    ch->sign = ds_get_f64(r);
    ch->left = ds_get_f64(r);
    ch->stalled = ds_get_u64(r);
    if (r->failed)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside the chain");
    /* A step ends with something of the chain left (a chain used up
     * starts the next at once); it moves down only along walls. */
    if (!(c->length > 0.0 && c->length < 1e300) || c->rng.state == 0 || ch->active >= c->n ||
        ch->axis > 1 || !(ch->sign == 1.0 || ch->sign == -1.0) ||
        (ch->sign < 0.0 && ds_box_periodic(&c->box, (int)ch->axis)) ||
        !(ch->left > 0.0 && ch->left <= c->length) || ch->stalled > c->n)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its chain is not one a run leaves");
    return DS_OK;
}

/* Whether disk k's centre is in cell (column, row), up to rounding past
 * an edge (a chain stops at an edge to a rounding error). */
static int holds(const ch_grid *g, const ds_disks *d, size_t k, uint32_t column, uint32_t row)
{
    const double slack_x = 1e-9 * g->edge[0][g->count[0]], slack_y = 1e-9 * g->edge[1][g->count[1]];
    return d->x[k] >= g->edge[0][column] - slack_x && d->x[k] <= g->edge[0][column + 1] + slack_x &&
           d->y[k] >= g->edge[1][row] - slack_y && d->y[k] <= g->edge[1][row + 1] + slack_y;
}

/* Each disk's cell and slot, then the overflow lists: every disk once,
 * in the cell that holds its centre, no list looping. */
static ds_status read_cells(ds_chain *c, const ds_world *w, const ds_disks *d, ds_reader *r,
                            ds_error *err)
{
    ch_grid *g = &c->grid;
    const uint32_t nx = ds_get_u32(r), ny = ds_get_u32(r);
    if (r->failed || nx != g->count[0] || ny != g->count[1])
        return ds_state_refuse(err, DS_ERR_FORMAT, "its cells are not the grid of its box");
    for (size_t k = 0; k < c->n; ++k) {
        ch_disk *cd = &c->disk[k];
        cd->cell = ds_get_u32(r);
        cd->slot = ds_get_u32(r);
        cd->next = ds_get_u32(r);
        if (r->failed)
            return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside the cells");
        if (cd->cell >= g->cells || cd->slot > CH_OVERFLOW ||
            !(cd->next == CH_NONE || cd->next < c->n))
            return ds_state_refuse(err, DS_ERR_FORMAT, "disk %zu's cell is out of range", k);
        cd->column = (uint16_t)(cd->cell % g->count[0]);
        cd->row = (uint16_t)(cd->cell / g->count[0]);
        if (!holds(g, d, k, cd->column, cd->row))
            return ds_state_refuse(err, DS_ERR_FORMAT, "disk %zu is not in its cell", k);
        if (cd->slot == CH_OVERFLOW)
            continue;
        const size_t at = (size_t)cd->cell * CH_SLOTS + cd->slot;
        if (g->who[at] != CH_NONE)
            return ds_state_refuse(err, DS_ERR_FORMAT, "two disks in one slot");
        g->who[at] = (uint32_t)k;
        g->pos[(size_t)cd->cell * 2 * CH_SLOTS + cd->slot] = d->x[k];
        g->pos[(size_t)cd->cell * 2 * CH_SLOTS + CH_SLOTS + cd->slot] = d->y[k];
        if (g->radius)
            g->radius[at] = d->r ? d->r[k] : w->radius;
    }
    /* Packed from the first slot, as the hot loop reads them. */
    for (size_t cell = 0; cell < g->cells; ++cell)
        for (int s = 1; s < CH_SLOTS; ++s)
            if (g->who[cell * CH_SLOTS + (size_t)s] != CH_NONE &&
                g->who[cell * CH_SLOTS + (size_t)s - 1] == CH_NONE)
                return ds_state_refuse(err, DS_ERR_FORMAT, "a cell's slots are not packed");
    size_t listed = 0;
    for (size_t cell = 0; cell < g->cells; ++cell) {
        g->more[cell] = ds_get_u32(r);
        /* Walking at most n links: a list that loops is caught by the
         * count. */
        size_t steps = 0;
        for (uint32_t m = g->more[cell]; m != CH_NONE && !r->failed; m = c->disk[m].next) {
            if (m >= c->n || c->disk[m].cell != cell || c->disk[m].slot != CH_OVERFLOW ||
                ++steps > c->n)
                return ds_state_refuse(err, DS_ERR_FORMAT, "an overflow list is not one");
            ++listed;
        }
    }
    if (r->failed)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside the cells");
    size_t overflow = 0;
    for (size_t k = 0; k < c->n; ++k)
        overflow += c->disk[k].slot == CH_OVERFLOW;
    /* Every overflow disk in its cell's list once: as many listed as
     * there are, none twice (a disk in two lists would be in two cells). */
    if (listed != overflow)
        return ds_state_refuse(err, DS_ERR_FORMAT, "an overflow list is not one");
    g->overflowing = overflow;
    return DS_OK;
}

ds_status ds_ch_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_legacy *legacy, ds_error *err)
{
    (void)legacy; /* 2.x had no chains */
    if (version < 3)
        return ds_state_refuse(err, DS_ERR_FORMAT, "format %u has no event chains",
                               (unsigned)version);
    ds_status st = ds_ch_alloc(sim);
    if (st != DS_OK)
        return ds_state_refuse(err, st, "no memory for the event-chain integrator");
    ds_chain *c = sim->state;
    st = read_chain(c, r, err);
    if (st != DS_OK)
        return st;
    if (ds_ch_grid_alloc(&c->grid, &sim->world, c->n, sim->disks.r != NULL) != DS_OK)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the cells of %zu disks", c->n);
    return read_cells(c, &sim->world, &sim->disks, r, err);
}
