/* SPDX-License-Identifier: MIT */
/* One cell grid for the parts that look for neighbours: random placement
 * (init/), psi6 and g(r) (observe/) and the periodic seam pass
 * (timestep/). The box is cut into nx by ny cells at least min_side wide,
 * so two centres closer than min_side are in the same cell or in
 * neighbouring ones (ds_grid_neighbours), wrapping across the edges of a
 * periodic box.
 *
 * The event-driven integrator keeps cells of its own (event/cells.h):
 * four disk slots a cell, read as one block by its vector code, is the
 * point of that layout. Not installed. */
#ifndef DS_GRID_H
#define DS_GRID_H

#include <stddef.h>
#include <stdint.h>

#include "core/box.h"
#include "disk_sim.h"

typedef struct ds_grid {
    size_t nx, ny;         /* cells per row, rows */
    double inv_wx, inv_wy; /* cells per unit length */
    int wrap[2];           /* whether the cells wrap along x, along y (the box's periodic axes) */
} ds_grid;

/* Cells along a side of length len, each wider than min_side by a
 * relative 1e-9 at least: from 1 to cap. */
size_t ds_grid_cells_along(double len, double min_side, size_t cap);

/* The grid of the box with cells at least min_side wide, wrapping along
 * its periodic axes, at most cap cells in all (a dilute system would want
 * far more, mostly empty: past cap the larger count is halved, which keeps
 * every cell at least min_side wide). */
void ds_grid_init(ds_grid *g, const ds_box *box, double min_side, size_t cap);

/* A grid of one row along a side of length len (a seam), cells at least
 * min_side long, at most cap, wrapping if wrap; every coordinate of the
 * other axis is in row 0. */
void ds_grid_init_line(ds_grid *g, double len, double min_side, size_t cap, int wrap);

/* The column (row) of coordinate x (y), clamped into the grid. In a
 * periodic grid the coordinates must be in the box already (ds_wrap_any
 * brings a caller's there). Inline: placement calls these for every
 * candidate centre. */
static inline size_t ds_grid_index_along(double v, double inv_w, size_t cells)
{
    /* Truncation is floor for c >= 0, without a call to floor() (which
     * x86-64 without SSE4.1 makes a library call: placement was a
     * quarter slower with it). */
    const double c = v * inv_w;
    if (!(c >= 0.0))
        return 0;
    /* v == len after rounding, or a centre outside a wall box. */
    return c < (double)cells ? (size_t)c : cells - 1;
}

static inline size_t ds_grid_column(const ds_grid *g, double x)
{
    return ds_grid_index_along(x, g->inv_wx, g->nx);
}

static inline size_t ds_grid_row(const ds_grid *g, double y)
{
    return ds_grid_index_along(y, g->inv_wy, g->ny);
}

/* The neighbour indices along one side, each once: -1 past a wall. */
static inline int ds_grid_along(size_t c, size_t cells, int wrap, long out[3])
{
    if (wrap && cells < 3) {
        for (size_t k = 0; k < cells; ++k)
            out[k] = (long)k;
        return (int)cells;
    }
    for (int k = 0; k < 3; ++k) {
        long s = (long)c + k - 1;
        if (s < 0 || s >= (long)cells)
            s = !wrap ? -1 : s < 0 ? s + (long)cells : s - (long)cells;
        out[k] = s;
    }
    return 3;
}

/* The cells around (column, row), the cell itself among them, each once,
 * row by row: those past a wall are left out, those past a periodic edge
 * wrap (with fewer than three cells along a side, each of them once, in
 * order). Returns how many (at most 9). */
/* Whether the 3 x 3 cells around (column, row) are all inside the grid,
 * none across an edge (nearly every cell of a large grid): then they are
 * three rows of three consecutive cells, from cell (column - 1, row - 1).
 * Unsigned: column 0 wraps to a huge column - 1. */
static inline int ds_grid_interior(const ds_grid *g, size_t column, size_t row)
{
    return column - 1 < g->nx - 2 && row - 1 < g->ny - 2 && g->nx >= 3 && g->ny >= 3;
}

static inline int ds_grid_neighbours(const ds_grid *g, size_t column, size_t row, size_t out[9])
{
    if (ds_grid_interior(g, column, row)) {
        const size_t first = (row - 1) * g->nx + column - 1;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                out[3 * r + c] = first + (size_t)r * g->nx + (size_t)c;
        return 9;
    }
    long cx[3], cy[3];
    const int kx = ds_grid_along(column, g->nx, g->wrap[0], cx),
              ky = ds_grid_along(row, g->ny, g->wrap[1], cy);
    int count = 0;
    for (int b = 0; b < ky; ++b)
        for (int a = 0; a < kx; ++a)
            if (cx[a] >= 0 && cy[b] >= 0)
                out[count++] = (size_t)cy[b] * g->nx + (size_t)cx[a];
    return count;
}

/* The n centres sorted by cell (a counting sort): the centres of cell c
 * are order[start[c] .. start[c + 1]), cell[j] is centre j's cell. */
typedef struct ds_grid_bins {
    size_t *start; /* nx ny + 1 */
    size_t *order; /* n */
    size_t *cell;  /* n */
} ds_grid_bins;

ds_status ds_grid_bin(const ds_grid *g, size_t n, const double *x, const double *y,
                      ds_grid_bins *bins);
void ds_grid_bins_free(ds_grid_bins *bins);

#endif
