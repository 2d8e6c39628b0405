/* SPDX-License-Identifier: MIT */
/* The cell grid (see grid.h). */
#include <math.h>
#include <stdlib.h>

#include "core/grid.h"

/* The relative slack keeps the cells wider than min_side after rounding:
 * two centres closer than min_side must never be two cells apart because
 * one sits a rounding error past a cell edge. */
size_t ds_grid_cells_along(double len, double min_side, size_t cap)
{
    const double fit = floor(len / (min_side * (1.0 + 1e-9)));
    if (!(fit >= 1.0))
        return 1;
    return fit >= (double)cap ? cap : (size_t)fit;
}

void ds_grid_init(ds_grid *g, const ds_box *box, double min_side, size_t cap)
{
    const double box_x = box->side[0], box_y = box->side[1];
    g->nx = ds_grid_cells_along(box_x, min_side, cap);
    g->ny = ds_grid_cells_along(box_y, min_side, cap);
    while ((double)g->nx * (double)g->ny > (double)cap) {
        if (g->nx >= g->ny)
            g->nx = (g->nx + 1) / 2;
        else
            g->ny = (g->ny + 1) / 2;
    }
    g->inv_wx = (double)g->nx / box_x;
    g->inv_wy = (double)g->ny / box_y;
    g->wrap[0] = ds_box_periodic(box, 0);
    g->wrap[1] = ds_box_periodic(box, 1);
}

void ds_grid_init_line(ds_grid *g, double len, double min_side, size_t cap, int wrap)
{
    g->nx = ds_grid_cells_along(len, min_side, cap);
    g->ny = 1;
    g->inv_wx = (double)g->nx / len;
    g->inv_wy = 0.0;
    g->wrap[0] = wrap;
    g->wrap[1] = 0;
}

void ds_grid_bins_free(ds_grid_bins *b)
{
    free(b->start);
    free(b->order);
    free(b->cell);
    b->start = b->order = b->cell = NULL;
}

ds_status ds_grid_bin(const ds_grid *g, size_t n, const double *x, const double *y, ds_grid_bins *b)
{
    const size_t cells = g->nx * g->ny;
    b->start = calloc(cells + 1, sizeof *b->start);
    b->order = malloc((n ? n : 1) * sizeof *b->order);
    b->cell = malloc((n ? n : 1) * sizeof *b->cell);
    if (!b->start || !b->order || !b->cell) {
        ds_grid_bins_free(b);
        return DS_ERR_NOMEM;
    }
    for (size_t j = 0; j < n; ++j) {
        b->cell[j] = ds_grid_row(g, y[j]) * g->nx + ds_grid_column(g, x[j]);
        ++b->start[b->cell[j] + 1];
    }
    for (size_t c = 0; c < cells; ++c)
        b->start[c + 1] += b->start[c];
    for (size_t j = 0; j < n; ++j)
        b->order[b->start[b->cell[j]]++] = j;
    /* The scatter moved each start to the next cell's: shift back. */
    for (size_t c = cells; c > 0; --c)
        b->start[c] = b->start[c - 1];
    b->start[0] = 0;
    return DS_OK;
}
