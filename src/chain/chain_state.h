/* SPDX-License-Identifier: MIT */
/* The event-chain integrator's state, shared by its parts: event_chain.c
 * (the table), chain_grid.c (the cells), chain_move.c (the chains, with
 * chain_scan.h, what lies ahead of the moving disk) and
 * chain_checkpoint.c. Private to chain/; the rest of the library sees
 * chain.h.
 *
 * The disks' centres are the simulation's own columns (sim->disks.x, y):
 * the integrator never permutes the slots, so its disk k is slot k, and
 * only the active disk moves, written in place as it goes. Their image
 * counts (periodic) are the columns' too. Velocities are never touched. */
#ifndef DS_CHAIN_STATE_H
#define DS_CHAIN_STATE_H

#include "core/core.h"

/* A cell's slots: its first four disks, read as two pairs of lanes. */
#define CH_SLOTS 4
/* No disk (a free slot, the end of an overflow list), no cell (past a
 * wall). */
#define CH_NONE UINT32_MAX
/* A disk's slot when it is in its cell's overflow list instead. */
#define CH_OVERFLOW CH_SLOTS
/* Cells per side at most: a disk keeps its column and row in 16 bits. */
#define CH_MAX_SIDE 65535u

/* The cell grid: cells at least the largest diameter wide, so a disk in
 * contact with another is in the same or an adjacent cell. The hot loop
 * reads a cell's centres as one 64-byte line, x[4] then y[4] (a free
 * slot: both +infinity, which no test passes): the candidates' centres
 * without a lookup per disk, in the cells ahead of the chain. This is
 * the layout the hot loop is built on, hence its own grid rather than
 * core/pairs.h's. A cell holds four centres at most when it is narrower
 * than 2 sqrt(2) times the smallest radius (five points in a square of
 * side w are at most w / sqrt 2 apart): further disks (a dilute gas, a
 * mixture of very different sizes) wait in an overflow list, read only
 * while some list is not empty.
 *
 * Cell (column, row) is number row * count[0] + column; number `cells`
 * is an empty cell that stands for every neighbour past a wall, so the
 * hot loop reads six cells without asking which exist. */
typedef struct ch_grid {
    uint32_t count[2]; /* cells along x and along y */
    size_t cells;      /* count[0] * count[1] */
    /* Cell edges along each axis: edge[a][c] = c side / count, edge[a][count]
     * the side itself, exactly. */
    double *edge[2];
    /* The neighbours of cell index c along axis a: near[a][2 c] below it,
     * near[a][2 c + 1] above it, an index or CH_NONE past a wall, and the
     * shift of the image each stands for (periodic: -side or +side at the
     * box's edge, else 0). */
    uint32_t *near[2];
    double *shift[2];
    double *pos;        /* (cells + 1) * 8 doubles, 64-byte aligned */
    double *radius;     /* (cells + 1) * 4 radii of a mixture, or NULL */
    uint32_t *who;      /* (cells + 1) * 4 disk numbers, or CH_NONE */
    uint32_t *more;     /* cells + 1: each cell's first overflow disk, or CH_NONE */
    size_t overflowing; /* disks in overflow lists */
} ch_grid;

/* What the integrator keeps per disk: its cell and place in it, and the
 * next disk of an overflow list. */
typedef struct ch_disk {
    uint32_t cell;
    uint16_t column, row;
    uint32_t slot; /* 0..3, or CH_OVERFLOW */
    uint32_t next; /* the next disk of its overflow list, or CH_NONE */
} ch_disk;

typedef char ch_disk_is_sixteen_bytes[sizeof(ch_disk) == 16 ? 1 : -1];

/* The chain in progress: its active disk, the axis and sign it moves
 * along, and what is left of its length. Along a periodic axis a chain
 * moves up (+1) only; along walls it draws its sign, and turns at a wall
 * (see chain_move.c for why both are needed). */
typedef struct ch_chain {
    uint32_t active;
    uint32_t axis; /* 0: along x, 1: along y */
    double sign;   /* +1 or -1 */
    double left;   /* of its length */
    /* Consecutive liftings that moved nothing (disks in contact all along
     * the chain's line): past n the rest of the chain counts as moved
     * (chain_move.c). */
    uint64_t stalled;
} ch_chain;

typedef struct ds_chain {
    ds_box box;
    size_t n;
    int brute; /* DS_BROADPHASE_BRUTE: every disk a candidate (the reference) */
    ch_grid grid;
    ch_disk *disk;
    ch_chain chain;
    double length; /* a chain's length */
    /* How far the active disk goes before it looks again even with no
     * cell edge ahead: half a periodic side less the largest diameter for
     * brute force (whose nearest image is the one ahead only that far),
     * else +infinity. */
    double reach[2];
    double scratch;  /* where a disk of an overflow list writes its coordinate: never read */
    double per_step; /* the displacement a step of dt carries: n speed dt */
    ds_rng rng;      /* the chains' starts and signs */
    /* kT = K / N of the velocities (event_chain.c), kept for the walls'
     * tally; set wherever velocities change. */
    double kt;
    uint64_t chains; /* chains started */
} ds_chain;

/* The grid (chain_grid.c): made for sim's world and disks (every disk
 * put in its cell, in generation order), freed; bytes it takes. */
ds_status ds_ch_grid_make(ds_chain *c, const ds_world *w, const ds_disks *d);
void ds_ch_grid_free(ch_grid *g);
size_t ds_ch_grid_bytes(const ds_world *w);
/* The grid's shape and cells for world w, every cell empty. */
ds_status ds_ch_grid_alloc(ch_grid *g, const ds_world *w, size_t n, int mixture);
/* The cell (column, row) a centre is in. */
void ds_ch_cell_of(const ch_grid *g, double x, double y, uint32_t *column, uint32_t *row);
/* Disk k into cell (column, row) at centre (x, y) (radius r of a
 * mixture), the first free slot or its overflow list; out of its cell. */
void ds_ch_add(ds_chain *c, uint32_t k, uint32_t column, uint32_t row, double x, double y,
               double r);
/* Disk k out of its cell; a disk of the cell's overflow list (its centre
 * and radius from disks) takes a freed slot. */
void ds_ch_remove(ds_chain *c, uint32_t k, const ds_disks *disks);
/* Where the hot loop reads disk k's centre along axis (NULL: in an
 * overflow list, read from the columns). */
static inline double *ds_ch_slot_coord(const ds_chain *c, uint32_t k, uint32_t axis)
{
    const ch_disk *d = &c->disk[k];
    return d->slot < CH_SLOTS
               ? c->grid.pos + (size_t)d->cell * 2 * CH_SLOTS + axis * CH_SLOTS + d->slot
               : NULL;
}

/* The chains (chain_move.c): a new chain (the next axis, a disk and a
 * sign drawn), and one step's displacement of chains, its liftings and
 * wall turns tallied in sim->tally. */
void ds_ch_new_chain(ds_chain *c);
void ds_ch_step(ds_sim *sim, ds_chain *c);

/* A checkpoint (chain_checkpoint.c): the table's save and load. */
void ds_ch_save(const ds_sim *sim, ds_state_writer *w);
ds_status ds_ch_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_legacy *legacy, ds_error *err);

/* The state (chain_state.c): sim->state made for sim's world, every
 * field but the grid, the chain and the generator set (create and load
 * fill those); freed (safe after a failed alloc); kT = K / N of the
 * disks' velocities, which the chains never change. */
ds_status ds_ch_alloc(ds_sim *sim);
void ds_ch_destroy(ds_sim *sim);
double ds_ch_kt(const ds_disks *d);

#endif
