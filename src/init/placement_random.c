/* SPDX-License-Identifier: MIT */
/* Random sequential placement: disk i is drawn uniformly where a centre
 * may be ([R, box - R] x [R, box_y - R] with walls, [0, box) x [0, box_y)
 * in a periodic box) and redrawn until it overlaps none of disks
 * 0..i-1 (through the nearest image in a periodic box). A uniform grid of
 * cells at least 2R wide keeps each overlap test to the 3x3 cells around
 * the candidate (wrapping in a periodic box), so placement is O(N)
 * instead of O(N^2). Directions are drawn afterwards from a second
 * generator. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/box.h"
#include "core/grid.h"
#include "core/prefetch.h"
#include "init/init.h"

/* Draws allowed for one disk before giving up. Near the jamming limit the
 * free area left for a new centre shrinks to nothing, and an unbounded
 * search would hang; 2e6 draws ~ 0.1 s. */
#define MAX_DRAWS_PER_DISK 2000000u

/* Candidates drawn ahead of the one tested (a power of two), and how many
 * tests before its own a candidate's first disks are fetched: its heads get
 * AHEAD - NODES_AHEAD tests (~100 ns each at 10^6 disks) to arrive, its
 * disks NODES_AHEAD. Measured at 10^6 disks: 8/4 places a disk in ~160 ns,
 * 16/4 in ~167 ns and 32/8 in ~195 ns: deeper is slower on this machine,
 * for a reason we have not pinned down. */
#define AHEAD 8u
#define NODES_AHEAD 4u

/* A placed disk as the grid keeps it: its centre next to its list link,
 * so visiting it touches one cache line, not three arrays (at 10^6 disks
 * the lists are scattered over tens of megabytes). */
typedef struct grid_node {
    double x, y;
    uint32_t next; /* next disk in the same cell, UINT32_MAX at the end */
} grid_node;

typedef struct grid {
    ds_grid cells;
    uint32_t *head; /* first disk in each cell, UINT32_MAX when empty */
    grid_node *node;
} grid;

static size_t cell_of(const grid *g, double px, double py)
{
    return ds_grid_row(&g->cells, py) * g->cells.nx + ds_grid_column(&g->cells, px);
}

static int overlaps_in_cell(const grid *g, size_t cell, double px, double py, double d2min)
{
    for (uint32_t k = g->head[cell]; k != UINT32_MAX; k = g->node[k].next) {
        const double dx = g->node[k].x - px, dy = g->node[k].y - py;
        if (dx * dx + dy * dy < d2min)
            return 1;
    }
    return 0;
}

/* Whether a placed disk of a mixture (radii r) overlaps a candidate of
 * radius radius at (px, py) through the nearest image, in the cells
 * around it. */
static int overlaps_mixed(const ds_world *w, const grid *g, const double *r, double radius,
                          double px, double py)
{
    size_t around[9];
    const int count = ds_grid_neighbours(&g->cells, ds_grid_column(&g->cells, px),
                                         ds_grid_row(&g->cells, py), around);
    for (int c = 0; c < count; ++c)
        for (uint32_t k = g->head[around[c]]; k != UINT32_MAX; k = g->node[k].next) {
            double dx = g->node[k].x - px, dy = g->node[k].y - py;
            ds_box_nearest(&w->box, &dx, &dy);
            const double sigma = radius + r[k];
            if (dx * dx + dy * dy < sigma * sigma)
                return 1;
        }
    return 0;
}

/* Whether a placed disk's centre is closer than 2R to (px, py), through
 * the nearest image in a periodic box (the cells past an edge are those
 * at the opposite edge, holding disks one box away). Nearly every
 * candidate of a large box is in the grid's interior, walked row by row
 * (placement's hot loop: a quarter faster at 10^6 disks than through the
 * list of neighbours). */
static int overlaps_any(const ds_world *w, const grid *g, double px, double py)
{
    const double d2min = 4.0 * w->radius * w->radius;
    const size_t cx = ds_grid_column(&g->cells, px), cy = ds_grid_row(&g->cells, py);
    if (ds_grid_interior(&g->cells, cx, cy)) {
        const size_t nx = g->cells.nx, first = (cy - 1) * nx + cx - 1;
        for (size_t r = 0; r < 3; ++r)
            for (size_t c = 0; c < 3; ++c)
                if (overlaps_in_cell(g, first + r * nx + c, px, py, d2min))
                    return 1;
        return 0;
    }
    size_t around[9];
    const int count = ds_grid_neighbours(&g->cells, cx, cy, around);
    for (int c = 0; c < count; ++c)
        for (uint32_t k = g->head[around[c]]; k != UINT32_MAX; k = g->node[k].next) {
            double dx = g->node[k].x - px, dy = g->node[k].y - py;
            ds_box_nearest(&w->box, &dx, &dy);
            if (dx * dx + dy * dy < d2min)
                return 1;
        }
    return 0;
}

/* Asks for the 3 rows of grid heads around (px, py) to be fetched early
 * (the heads of a row are side by side: one line, or two); prefetching
 * is for large grids, whose edges do not matter. */
static void prefetch_cells(const grid *g, double px, double py)
{
    const size_t cx = ds_grid_column(&g->cells, px), cy = ds_grid_row(&g->cells, py);
    if (!ds_grid_interior(&g->cells, cx, cy))
        return;
    const size_t nx = g->cells.nx, first = (cy - 1) * nx + cx - 1;
    for (size_t r = 0; r < 3; ++r)
        ds_prefetch(&g->head[first + r * nx]);
}

/* Asks for the first disk of each of the 9 cells around (px, py): their
 * heads must already be in cache (prefetched some candidates earlier). */
static void prefetch_nodes(const grid *g, double px, double py)
{
    const size_t cx = ds_grid_column(&g->cells, px), cy = ds_grid_row(&g->cells, py);
    if (!ds_grid_interior(&g->cells, cx, cy))
        return;
    const size_t nx = g->cells.nx, first = (cy - 1) * nx + cx - 1;
    for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c) {
            const uint32_t k = g->head[first + r * nx + c];
            if (k != UINT32_MAX)
                ds_prefetch(&g->node[k]);
        }
}

/* u in [0, 1) taken to [lo, hi), as ds_rng_uniform does (the same bits). */
static inline double in_range(double lo, double hi, double u)
{
    const double r = lo + (hi - lo) * u;
    return r < hi ? r : lo;
}

/* Where a disk of radius r may have its centre along each side: all of
 * a periodic one, r from each wall otherwise. */
typedef struct range {
    double lo, hi, lo_y, hi_y;
} range;

static range centre_range(const ds_world *w, double r)
{
    range c;
    ds_box_reach(&w->box, 0, r, &c.lo, &c.hi);
    ds_box_reach(&w->box, 1, r, &c.lo_y, &c.hi_y);
    return c;
}

/* The order of placement: the disks in generation order, or for a
 * mixture the largest first (ties in generation order): a large disk
 * finds room more easily among fewer disks. */
static uint32_t *placement_order(const ds_disks *d)
{
    uint32_t *order = malloc((d->n ? d->n : 1) * sizeof *order);
    if (!order)
        return NULL;
    for (size_t i = 0; i < d->n; ++i)
        order[i] = (uint32_t)i;
    if (!d->r)
        return order;
    /* Insertion of each into the sorted front, found by binary search:
     * O(n log n) comparisons; the moves are cheap memmove's. */
    for (size_t i = 1; i < d->n; ++i) {
        const uint32_t k = order[i];
        size_t lo = 0, hi = i;
        while (lo < hi) {
            const size_t mid = lo + (hi - lo) / 2;
            if (d->r[order[mid]] >= d->r[k])
                lo = mid + 1;
            else
                hi = mid;
        }
        memmove(order + lo + 1, order + lo, (i - lo) * sizeof *order);
        order[lo] = k;
    }
    return order;
}

/* The grid of the placed disks, empty: cells at least the largest
 * diameter wide, but no more than ~4 per disk so tiny radii with few
 * disks do not allocate a huge empty grid. */
static ds_status grid_make(grid *g, const ds_world *w)
{
    ds_grid_init(&g->cells, &w->box, 2.0 * w->radius_max, 4 * w->n + 16);
    const size_t cells = g->cells.nx * g->cells.ny;
    g->head = malloc(cells * sizeof *g->head);
    g->node = malloc((w->n ? w->n : 1) * sizeof *g->node);
    if (!g->head || !g->node) {
        free(g->head);
        free(g->node);
        return DS_ERR_NOMEM;
    }
    for (size_t c = 0; c < cells; ++c)
        g->head[c] = UINT32_MAX;
    return DS_OK;
}

/* The candidate centres drawn ahead of the one tested, as numbers in
 * [0, 1) (taken to the range of the disk that tests them), in a ring of
 * AHEAD. */
typedef struct candidates {
    ds_rng rng;
    double u[AHEAD], v[AHEAD];
    size_t next; /* ring slot of the next candidate */
    int prefetch;
} candidates;

/* The next candidate for a disk whose centre ranges over at, into (*px,
 * *py); the candidate AHEAD on takes its slot, its heads fetched now, and
 * NODES_AHEAD candidates before its test its first disks (the heads have
 * arrived by then). */
static void draw(candidates *c, const grid *g, const range *at, double *px, double *py)
{
    *px = in_range(at->lo, at->hi, c->u[c->next]);
    *py = in_range(at->lo_y, at->hi_y, c->v[c->next]);
    c->u[c->next] = ds_rng_uniform(&c->rng, 0.0, 1.0);
    c->v[c->next] = ds_rng_uniform(&c->rng, 0.0, 1.0);
    if (c->prefetch) {
        prefetch_cells(g, in_range(at->lo, at->hi, c->u[c->next]),
                       in_range(at->lo_y, at->hi_y, c->v[c->next]));
        const size_t soon = (c->next + NODES_AHEAD) & (AHEAD - 1);
        prefetch_nodes(g, in_range(at->lo, at->hi, c->u[soon]),
                       in_range(at->lo_y, at->hi_y, c->v[soon]));
    }
    c->next = (c->next + 1) & (AHEAD - 1);
}

/* Disk i at its first free candidate, added to the grid; DS_ERR_PLACEMENT
 * after MAX_DRAWS_PER_DISK draws. */
static ds_status place_one(ds_disks *d, const ds_world *w, grid *g, candidates *c,
                           const range *at, uint32_t i)
{
    const double radius = d->r ? d->r[i] : w->radius;
    double px, py;
    unsigned draws = 0;
    do {
        if (++draws > MAX_DRAWS_PER_DISK)
            return DS_ERR_PLACEMENT;
        draw(c, g, at, &px, &py);
    } while (d->r ? overlaps_mixed(w, g, d->r, radius, px, py) : overlaps_any(w, g, px, py));
    d->x[i] = px;
    d->y[i] = py;
    const size_t cell = cell_of(g, px, py);
    g->node[i].x = px;
    g->node[i].y = py;
    g->node[i].next = g->head[cell];
    g->head[cell] = i;
    return DS_OK;
}

ds_status ds_place_random(ds_disks *d, const ds_world *w)
{
    grid g;
    if (grid_make(&g, w) != DS_OK)
        return DS_ERR_NOMEM;
    uint32_t *order = placement_order(d);
    if (!order) {
        free(g.head);
        free(g.node);
        return DS_ERR_NOMEM;
    }
    /* Centres and directions come from two generators, so the sequence of
     * candidate centres does not depend on which of them are accepted: it
     * can be drawn ahead, and the grid cells of candidates still to come
     * fetched while the current one is tested. Below ~1 MB of heads the
     * grid stays in cache and prefetching only costs instructions. */
    candidates c;
    ds_rng directions;
    ds_rng_seed(&c.rng, w->seed);
    ds_rng_seed(&directions, ds_rng_next(&c.rng));
    c.next = 0;
    c.prefetch = g.cells.nx * g.cells.ny >= ((size_t)1 << 18);
    range at = centre_range(w, d->r ? d->r[order[0]] : w->radius);
    for (size_t k = 0; k < AHEAD; ++k) {
        c.u[k] = ds_rng_uniform(&c.rng, 0.0, 1.0);
        c.v[k] = ds_rng_uniform(&c.rng, 0.0, 1.0);
        if (c.prefetch)
            prefetch_cells(&g, in_range(at.lo, at.hi, c.u[k]), in_range(at.lo_y, at.hi_y, c.v[k]));
    }
    ds_status status = DS_OK;
    for (size_t o = 0; o < w->n && status == DS_OK; ++o) {
        if (d->r)
            at = centre_range(w, d->r[order[o]]);
        status = place_one(d, w, &g, &c, &at, order[o]);
    }
    if (status == DS_OK) {
        /* Directions uniform in [0, 2 pi), one per disk in generation order. */
        for (size_t i = 0; i < w->n; ++i) {
            double angle = ds_rng_uniform(&directions, 0.0, DS_TWO_PI);
            d->vx[i] = w->speed * cos(angle);
            d->vy[i] = w->speed * sin(angle);
        }
        /* With walls the seed's velocities, as they are (the walls take
         * the momentum); along a periodic axis nothing does: the centre of
         * mass would drift for ever. */
        if (ds_box_any_periodic(&w->box))
            ds_stop_centre_of_mass(d, w);
    }
    free(g.head);
    free(g.node);
    free(order);
    return status;
}
