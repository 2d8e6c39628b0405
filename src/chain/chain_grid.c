/* SPDX-License-Identifier: MIT */
/* The event-chain integrator's cell grid (chain_state.h): its shape,
 * putting a disk in a cell and taking it out. */
#include <math.h>
#include <stdlib.h>

#include "chain/chain_state.h"
#include "core/grid.h"
#include "core/large_alloc.h"

/* Cells along each axis: as many as are at least the largest diameter
 * wide, but no more than about four per disk in all (a dilute gas does
 * not need a huge empty grid: its cells overflow instead), and at least
 * two along a periodic axis, so that a disk's own image is never in the
 * cells ahead of it (a periodic side is over two diameters, so half of it
 * is over one). Brute force keeps the same grid, whose edges stop the
 * chains at the same places: only its candidates differ. */
static void grid_shape(const ds_world *w, size_t n, uint32_t count[2])
{
    const double total = 4.0 * (double)n + 16.0, sx = w->box.side[0], sy = w->box.side[1];
    const double cap[2] = {ceil(sqrt(total * sx / sy)), ceil(sqrt(total * sy / sx))};
    for (int a = 0; a < 2; ++a) {
        size_t c = ds_grid_cells_along(w->box.side[a], 2.0 * w->radius_max,
                                       (size_t)fmin(cap[a], (double)CH_MAX_SIDE));
        if (c < 2 && ds_box_periodic(&w->box, a))
            c = 2;
        count[a] = (uint32_t)c;
    }
}

size_t ds_ch_grid_bytes(const ds_world *w)
{
    uint32_t count[2];
    grid_shape(w, w->n, count);
    const size_t cells = (size_t)count[0] * count[1] + 1;
    const size_t per_cell = 2 * CH_SLOTS * sizeof(double) + (CH_SLOTS + 1) * sizeof(uint32_t) +
                            (w->radius_min < w->radius_max ? CH_SLOTS * sizeof(double) : 0);
    size_t axes = 0;
    for (int a = 0; a < 2; ++a)
        axes +=
            (count[a] + 1) * sizeof(double) + 2 * count[a] * (sizeof(uint32_t) + sizeof(double));
    return cells * per_cell + axes;
}

void ds_ch_grid_free(ch_grid *g)
{
    for (int a = 0; a < 2; ++a) {
        free(g->edge[a]);
        free(g->near[a]);
        free(g->shift[a]);
        g->edge[a] = g->shift[a] = NULL;
        g->near[a] = NULL;
    }
    free(g->pos);
    free(g->radius);
    free(g->who);
    free(g->more);
    g->pos = g->radius = NULL;
    g->who = g->more = NULL;
}

/* The edges and neighbours along axis a. */
static void make_axis(ch_grid *g, const ds_box *box, int a)
{
    const uint32_t count = g->count[a];
    const double side = box->side[a];
    for (uint32_t c = 0; c < count; ++c)
        g->edge[a][c] = side * (double)c / (double)count;
    g->edge[a][count] = side;
    for (uint32_t c = 0; c < count; ++c)
        for (int up = 0; up < 2; ++up) {
            double shift = 0.0;
            const long k = ds_box_cell_along(box, a, (long)c + (up ? 1 : -1), (long)count, &shift);
            g->near[a][2 * c + (uint32_t)up] = k < 0 ? CH_NONE : (uint32_t)k;
            g->shift[a][2 * c + (uint32_t)up] = shift;
        }
}

ds_status ds_ch_grid_alloc(ch_grid *g, const ds_world *w, size_t n, int mixture)
{
    grid_shape(w, n, g->count);
    g->cells = (size_t)g->count[0] * g->count[1];
    g->overflowing = 0;
    const size_t cells = g->cells + 1;
    int ok = 1;
    for (int a = 0; a < 2; ++a) {
        g->edge[a] = malloc((g->count[a] + 1) * sizeof *g->edge[a]);
        g->near[a] = malloc(2 * g->count[a] * sizeof *g->near[a]);
        g->shift[a] = malloc(2 * g->count[a] * sizeof *g->shift[a]);
        ok &= g->edge[a] && g->near[a] && g->shift[a];
    }
    g->pos = ds_large_alloc(cells * 2 * CH_SLOTS * sizeof *g->pos);
    g->who = malloc(cells * CH_SLOTS * sizeof *g->who);
    g->more = malloc(cells * sizeof *g->more);
    g->radius = mixture ? malloc(cells * CH_SLOTS * sizeof *g->radius) : NULL;
    if (!ok || !g->pos || !g->who || !g->more || (mixture && !g->radius)) {
        ds_ch_grid_free(g);
        return DS_ERR_NOMEM;
    }
    for (int a = 0; a < 2; ++a)
        make_axis(g, &w->box, a);
    for (size_t s = 0; s < cells * 2 * CH_SLOTS; ++s)
        g->pos[s] = INFINITY;
    for (size_t s = 0; s < cells * CH_SLOTS; ++s) {
        g->who[s] = CH_NONE;
        if (g->radius)
            g->radius[s] = 0.0;
    }
    for (size_t k = 0; k < cells; ++k)
        g->more[k] = CH_NONE;
    return DS_OK;
}

/* The index along axis a of coordinate u: the cell whose edges hold it
 * (a centre exactly on an edge may be in either cell; this takes the
 * upper one, and a centre outside the box the nearest cell). */
static uint32_t index_along(const ch_grid *g, int a, double u)
{
    const uint32_t count = g->count[a];
    const double side = g->edge[a][count];
    const double guess = u / side * (double)count;
    uint32_t c = guess > 0.0 ? (guess < (double)count ? (uint32_t)guess : count - 1) : 0;
    while (c > 0 && u < g->edge[a][c])
        --c;
    while (c + 1 < count && u >= g->edge[a][c + 1])
        ++c;
    return c;
}

void ds_ch_cell_of(const ch_grid *g, double x, double y, uint32_t *column, uint32_t *row)
{
    *column = index_along(g, 0, x);
    *row = index_along(g, 1, y);
}

void ds_ch_add(ds_chain *c, uint32_t k, uint32_t column, uint32_t row, double x, double y, double r)
{
    ch_grid *g = &c->grid;
    ch_disk *d = &c->disk[k];
    const uint32_t cell = row * g->count[0] + column;
    d->cell = cell;
    d->column = (uint16_t)column;
    d->row = (uint16_t)row;
    d->next = CH_NONE;
    uint32_t *who = g->who + (size_t)cell * CH_SLOTS;
    for (uint32_t s = 0; s < CH_SLOTS; ++s)
        if (who[s] == CH_NONE) {
            who[s] = k;
            d->slot = s;
            double *p = g->pos + (size_t)cell * 2 * CH_SLOTS;
            p[s] = x;
            p[CH_SLOTS + s] = y;
            if (g->radius)
                g->radius[(size_t)cell * CH_SLOTS + s] = r;
            return;
        }
    d->slot = CH_OVERFLOW;
    d->next = g->more[cell];
    g->more[cell] = k;
    ++g->overflowing;
}

/* Empties slot s of cell, keeping the cell's disks packed from its first
 * slot (the hot loop reads a third slot only when it is taken): the
 * first disk of the overflow list takes the slot if there is one (lists
 * are not empty only behind four full slots), else the cell's last disk
 * moves into it. */
static void free_slot(ds_chain *c, uint32_t cell, uint32_t s, const ds_disks *d)
{
    ch_grid *g = &c->grid;
    double *p = g->pos + (size_t)cell * 2 * CH_SLOTS;
    uint32_t *who = g->who + (size_t)cell * CH_SLOTS;
    double *radius = g->radius ? g->radius + (size_t)cell * CH_SLOTS : NULL;
    const uint32_t m = g->more[cell];
    if (m == CH_NONE) {
        uint32_t last = CH_SLOTS - 1;
        while (who[last] == CH_NONE)
            --last;
        if (last != s) {
            who[s] = who[last];
            c->disk[who[s]].slot = s;
            p[s] = p[last];
            p[CH_SLOTS + s] = p[CH_SLOTS + last];
            if (radius)
                radius[s] = radius[last];
        }
        who[last] = CH_NONE;
        p[last] = p[CH_SLOTS + last] = INFINITY;
        return;
    }
    g->more[cell] = c->disk[m].next;
    --g->overflowing;
    g->who[(size_t)cell * CH_SLOTS + s] = m;
    c->disk[m].slot = s;
    c->disk[m].next = CH_NONE;
    p[s] = d->x[m];
    p[CH_SLOTS + s] = d->y[m];
    if (g->radius)
        g->radius[(size_t)cell * CH_SLOTS + s] = d->r[m];
}

void ds_ch_remove(ds_chain *c, uint32_t k, const ds_disks *disks)
{
    ch_disk *d = &c->disk[k];
    if (d->slot < CH_SLOTS) {
        free_slot(c, d->cell, d->slot, disks);
        return;
    }
    uint32_t *link = &c->grid.more[d->cell];
    while (*link != k)
        link = &c->disk[*link].next;
    *link = d->next;
    d->next = CH_NONE;
    --c->grid.overflowing;
}

ds_status ds_ch_grid_make(ds_chain *c, const ds_world *w, const ds_disks *d)
{
    const ds_status st = ds_ch_grid_alloc(&c->grid, w, d->n, d->r != NULL);
    if (st != DS_OK)
        return st;
    for (size_t k = 0; k < d->n; ++k) {
        uint32_t column, row;
        ds_ch_cell_of(&c->grid, d->x[k], d->y[k], &column, &row);
        ds_ch_add(c, (uint32_t)k, column, row, d->x[k], d->y[k], d->r ? d->r[k] : w->radius);
    }
    return DS_OK;
}
