/* SPDX-License-Identifier: MIT */
/* The event-driven integrator's cell grid: the box cut into nx by ny cells
 * at least 2R (a diameter) wide, each holding the disks whose centres it
 * holds. Two disks in contact are then in the same or adjacent cells, so
 * a disk's possible partners are the disks of the 3 x 3 cells around its
 * own.
 *
 * Each cell has four slots, side by side: a row of three cells is twelve
 * consecutive disk numbers, read without following a link. A cell less
 * than 2 sqrt(2) R wide cannot hold a fifth centre of non-overlapping
 * disks (five points in a square of side w are at most w / sqrt(2) apart),
 * which is the usual case; a larger cell (a dilute gas, whose grid would
 * otherwise be huge) keeps its further disks in an overflow list, used
 * only while all four slots are taken. A cell's disks fill its slots from
 * the first, the empty ones after them: a cell is read as four slots at
 * once and a count.
 *
 * Not installed; used by event_driven.c and the tests. */
#ifndef DS_CELLS_H
#define DS_CELLS_H

#include <stddef.h>
#include <stdint.h>

#include "disk_sim.h"

#define DS_CELL_SLOTS 4
/* Cells per dimension at most: a column or row fits in 16 bits. */
#define DS_CELLS_MAX_SIDE 65535u

typedef struct ds_cells {
    uint32_t nx, ny; /* cells per row and per column */
    double wx, wy;   /* cell width and height */
    double inv_wx, inv_wy;
    /* nx * ny * 4 slots, row-major: a disk number, or `empty` (= n, the
     * number of disks). A cell's overflow list is not empty only while
     * all four of its slots are taken. */
    uint32_t *slot;
    uint32_t *more; /* nx * ny: first disk of each overflow list, or empty */
    uint32_t *next; /* n: the next disk of an overflow list */
    uint32_t empty;
} ds_cells;

/* Cells for disks 0..n-1 (n < 2^31) in a box_x by box_y box: as many as
 * fit at least min_side wide, but no more than about 4 per disk (a dilute
 * gas does not need a huge empty grid), and no more than max_side_cells
 * per dimension (1 gives one cell: every disk is everyone's candidate). */
ds_status ds_cells_init(ds_cells *cells, size_t n, double box_x, double box_y, double min_side,
                        uint32_t max_side_cells);
/* The same with a shape of nx x ny cells given (1 <= nx, ny <= the
 * shape ds_cells_init would choose: cells no narrower than its): a
 * checkpoint's grid, built for radii larger than now. */
ds_status ds_cells_init_shape(ds_cells *cells, size_t n, double box_x, double box_y, uint32_t nx,
                              uint32_t ny);
void ds_cells_free(ds_cells *cells);
size_t ds_cells_bytes(size_t n, double box_x, double box_y, double min_side,
                      uint32_t max_side_cells);

/* The cell column (row) of coordinate x (y), clamped into the grid. */
uint32_t ds_cells_column(const ds_cells *cells, double x);
uint32_t ds_cells_row(const ds_cells *cells, double y);

static inline uint32_t ds_cells_index(const ds_cells *cells, uint32_t column, uint32_t row)
{
    return row * cells->nx + column;
}

void ds_cells_add(ds_cells *cells, uint32_t cell, uint32_t disk);
/* Removes disk from cell (it must be there). */
void ds_cells_remove(ds_cells *cells, uint32_t cell, uint32_t disk);

static inline const uint32_t *ds_cells_slots(const ds_cells *cells, uint32_t cell)
{
    return cells->slot + (size_t)cell * DS_CELL_SLOTS;
}

/* The first disk of cell's overflow list (walk on with cells->next until
 * `empty`); only worth asking when its last slot is taken. */
static inline uint32_t ds_cells_overflow(const ds_cells *cells, uint32_t cell)
{
    return cells->more[cell];
}

#endif
