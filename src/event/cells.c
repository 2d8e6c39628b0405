/* SPDX-License-Identifier: MIT */
/* The cell grid of the event-driven integrator (see cells.h). */
#include <math.h>
#include <stdlib.h>

#include "core/large_alloc.h"
#include "event/cells.h"

/* Cells per dimension for a side of length box: the most that are still
 * at least min_side wide, at most cap. The relative slack keeps the cells
 * wider than min_side after rounding: a pair in contact must never be two
 * cells apart because a centre sits a rounding error past a cell edge. */
static uint32_t cells_along(double box, double min_side, double cap)
{
    double count = floor(box / (min_side * (1.0 + 1e-9)));
    if (count > cap)
        count = cap;
    return count < 1.0 ? 1u : (uint32_t)count;
}

static void grid_shape(size_t n, double box_x, double box_y, double min_side, uint32_t max_side,
                       uint32_t *nx, uint32_t *ny)
{
    /* About four cells per disk at most (a dense gas has 1.6 at area
     * fraction 0.5): sqrt(4 n) cells per side of a square box, shared out
     * by aspect for a rectangle. */
    const double total = 4.0 * (double)n + 16.0;
    const double cap_x = fmin(ceil(sqrt(total * box_x / box_y)), (double)max_side);
    const double cap_y = fmin(ceil(sqrt(total * box_y / box_x)), (double)max_side);
    *nx = cells_along(box_x, min_side, fmin(cap_x, (double)DS_CELLS_MAX_SIDE));
    *ny = cells_along(box_y, min_side, fmin(cap_y, (double)DS_CELLS_MAX_SIDE));
}

size_t ds_cells_bytes(size_t n, double box_x, double box_y, double min_side,
                      uint32_t max_side_cells)
{
    uint32_t nx, ny;
    grid_shape(n, box_x, box_y, min_side, max_side_cells ? max_side_cells : 1, &nx, &ny);
    return ((size_t)nx * ny * (DS_CELL_SLOTS + 1) + n) * sizeof(uint32_t);
}

ds_status ds_cells_init(ds_cells *cells, size_t n, double box_x, double box_y, double min_side,
                        uint32_t max_side_cells)
{
    uint32_t nx, ny;
    grid_shape(n, box_x, box_y, min_side, max_side_cells ? max_side_cells : 1, &nx, &ny);
    return ds_cells_init_shape(cells, n, box_x, box_y, nx, ny);
}

ds_status ds_cells_init_shape(ds_cells *cells, size_t n, double box_x, double box_y, uint32_t nx,
                              uint32_t ny)
{
    cells->nx = nx;
    cells->ny = ny;
    cells->wx = box_x / cells->nx;
    cells->wy = box_y / cells->ny;
    cells->inv_wx = cells->nx / box_x;
    cells->inv_wy = cells->ny / box_y;
    cells->empty = (uint32_t)n;
    const size_t count = (size_t)cells->nx * cells->ny;
    cells->slot = ds_large_alloc(count * DS_CELL_SLOTS * sizeof *cells->slot);
    cells->more = malloc(count * sizeof *cells->more);
    cells->next = malloc((n ? n : 1) * sizeof *cells->next);
    if (!cells->slot || !cells->more || !cells->next) {
        ds_cells_free(cells);
        return DS_ERR_NOMEM;
    }
    for (size_t s = 0; s < count * DS_CELL_SLOTS; ++s)
        cells->slot[s] = cells->empty;
    for (size_t c = 0; c < count; ++c)
        cells->more[c] = cells->empty;
    /* Read only along a list, but a checkpoint writes all of it. */
    for (size_t k = 0; k < n; ++k)
        cells->next[k] = cells->empty;
    return DS_OK;
}

void ds_cells_free(ds_cells *cells)
{
    free(cells->slot);
    free(cells->more);
    free(cells->next);
    cells->slot = cells->more = cells->next = NULL;
}

static uint32_t clamp_cell(double c, uint32_t count)
{
    if (!(c > 0.0))
        return 0;
    return c < (double)count ? (uint32_t)c : count - 1;
}

uint32_t ds_cells_column(const ds_cells *cells, double x)
{
    return clamp_cell(x * cells->inv_wx, cells->nx);
}

uint32_t ds_cells_row(const ds_cells *cells, double y)
{
    return clamp_cell(y * cells->inv_wy, cells->ny);
}

void ds_cells_add(ds_cells *cells, uint32_t cell, uint32_t disk)
{
    uint32_t *slot = cells->slot + (size_t)cell * DS_CELL_SLOTS;
    for (int k = 0; k < DS_CELL_SLOTS; ++k)
        if (slot[k] == cells->empty) {
            slot[k] = disk;
            return;
        }
    cells->next[disk] = cells->more[cell];
    cells->more[cell] = disk;
}

void ds_cells_remove(ds_cells *cells, uint32_t cell, uint32_t disk)
{
    uint32_t *slot = cells->slot + (size_t)cell * DS_CELL_SLOTS;
    const uint32_t empty = cells->empty;
    for (int k = 0; k < DS_CELL_SLOTS; ++k)
        if (slot[k] == disk) {
            /* A slot freed while the overflow list holds disks takes one,
             * so the list stays empty unless every slot is taken; and
             * while the last slot is free, the list (another cache line)
             * is not even read. Otherwise the cell's last disk moves into
             * the freed slot: the disks stay packed from the first slot. */
            if (slot[DS_CELL_SLOTS - 1] != empty && cells->more[cell] != empty) {
                const uint32_t first = cells->more[cell];
                slot[k] = first;
                cells->more[cell] = cells->next[first];
                return;
            }
            int last = DS_CELL_SLOTS - 1;
            while (slot[last] == empty)
                --last;
            slot[k] = slot[last];
            slot[last] = empty;
            return;
        }
    uint32_t *link = &cells->more[cell];
    while (*link != disk)
        link = &cells->next[*link];
    *link = cells->next[disk];
}
