/* SPDX-License-Identifier: MIT */
/* Fetching ahead (event-driven integrator).
 *
 * Events come in time order, which is no order in space: in a large
 * system each one touches memory far from the last (its disk, its partner,
 * the cells around them, their disks), and waits on main memory several
 * times in a row. The calendar knows which disks come up a few events
 * ahead, so their memory is requested then, in three stages an event or
 * more apart, each needing what the one before brought in:
 *
 * 1. the disk's record (ds_fetch_on_soon);
 * 2. its partner's record (its scheduled time too), and the rows of cells
 *    its event will read: for a collision, the cells around both disks
 *    (the record tells where the partner's cell is); for a crossing,
 *    those around the cell it enters;
 * 3. the records of the disks in those cells (state and scheduled time,
 *    one line each).
 *
 * Stage 3 reads cell slots that stage 2 requested; a stage that runs
 * before they arrive waits, so the stages are kept at least one event
 * apart. */
#include "core/prefetch.h"
#include "event/event_state.h"

/* The helpers below only read memory and prefetch, so gcc marks them pure
 * and, their results being unused, deletes the calls (and the prefetches
 * with them) unless they are inlined into a caller that writes. */
#if defined(__GNUC__)
#define FETCHER static inline __attribute__((always_inline))
#else
#define FETCHER static inline
#endif

/* Runs of consecutive cell slots, one per row of cells, stride apart. */
typedef struct region {
    const uint32_t *slot; /* the first slot of the first row */
    int rows, slots;      /* rows, and consecutive slots in each */
} region;

static const region nothing = {NULL, 0, 0};

FETCHER region cells_at(const ds_cells *cells, uint32_t column, uint32_t row, int columns, int rows)
{
    region g = {ds_cells_slots(cells, ds_cells_index(cells, column, row)), rows,
                columns * DS_CELL_SLOTS};
    return g;
}

/* The cells a collision's two disks are predicted from after it, disk d
 * being inside the grid: the 3 x 3 around each, together one block of 3
 * or 4 by 3 or 4 cells, as the partner's cell is the disk's or next to it
 * (the prediction kept it in the disk's partner_changes, see
 * event_fetch.h). Fetched as one block, the cells the two share are
 * fetched once, and the partner's cells need not wait for its record:
 * about 13 cells in one stage rather than 18 in two (cells 2R wide: a
 * partner at 2R in a random direction is in another column with chance
 * 2 / pi, in another row too, in both with 1 / pi, so
 * 9 + 3 (2 / pi) 2 + 1 / pi = 13.1 cells). 0.91 to 1.00 at 10^6 disks
 * (4 in-process A/B runs of 9 to 31 rounds). With the partner's cell at
 * the edge of the grid, or unknown, the disk's own 3 x 3. */
FETCHER region pair_cells(const ds_cells *cells, const ed_disk *d)
{
    const uint32_t at = ds_fetch_note_cell(d->partner_changes);
    const uint32_t dx = at % 3u, dy = at / 3u; /* 0, 1, 2: left of, with, right of d */
    const uint32_t column = d->column + dx - 1u, row = d->row + dy - 1u;
    if (at == DS_FETCH_CELL_UNKNOWN || !ds_ed_interior_at(cells, column, row))
        return cells_at(cells, d->column - 1u, d->row - 1u, 3, 3);
    return cells_at(cells, (dx ? d->column : column) - 1u, (dy ? d->row : row) - 1u, 3 + (dx != 1u),
                    3 + (dy != 1u));
}

/* The cells disk d's event will look at: for a collision, those around
 * both disks (pair_cells); for a cell crossing, the 3 x 3 around the cell
 * it enters (the crossing moves it there, from a cell of that block, and
 * predicts it from there; the row or column it leaves is not read:
 * fetching only the new block, 0.91 at 10^5 disks, 0.97 at 10^6); else
 * the 3 x 3 around it. Nothing at the edge of the grid, where it is not
 * worth the care. */
FETCHER region cells_ahead(const ds_events *e, const ed_disk *d)
{
    const ds_cells *cells = &e->cells;
    if (!ds_ed_interior(cells, d))
        return nothing;
    if (d->partner < cells->empty)
        return pair_cells(cells, d);
    const uint32_t column = d->column - 1u, row = d->row - 1u;
    if (d->partner == EV_CELL_X && (d->vx > 0.0 ? d->column + 2u < cells->nx : d->column >= 2u))
        return cells_at(cells, d->vx > 0.0 ? column + 1u : column - 1u, row, 3, 3);
    if (d->partner == EV_CELL_Y && (d->vy > 0.0 ? d->row + 2u < cells->ny : d->row >= 2u))
        return cells_at(cells, column, d->vy > 0.0 ? row + 1u : row - 1u, 3, 3);
    return cells_at(cells, column, row, 3, 3);
}

FETCHER void fetch_rows(const ds_events *e, region g)
{
    const size_t stride = (size_t)e->cells.nx * DS_CELL_SLOTS;
    for (int r = 0; r < g.rows; ++r, g.slot += stride) {
        ds_prefetch(g.slot);
        ds_prefetch(g.slot + g.slots - 1);
    }
}

/* A cell's disks fill its slots from the first (cells.h), and at area
 * fraction 0.5 a cell holds 0.64 disks on average, three or more in
 * under 3% of cells: the first two slots are fetched whatever they hold
 * (an empty slot holds n, one past the last disk, whose line costs less
 * to fetch than a branch taken at random), the last two only when the
 * third is taken. Half the requests of fetching all four: 0.80 to 0.93
 * at 10^6 disks, 0.90 at 10^5 (`tools/bench events N`, alternating). */
FETCHER void fetch_disks(const ds_events *e, region g)
{
    const size_t stride = (size_t)e->cells.nx * DS_CELL_SLOTS;
    const uint32_t empty = e->cells.empty;
    for (int r = 0; r < g.rows; ++r, g.slot += stride)
        for (int k = 0; k < g.slots; k += DS_CELL_SLOTS) {
            const uint32_t *slot = g.slot + k;
            ds_prefetch(&e->disk[slot[0]]);
            ds_prefetch(&e->disk[slot[1]]);
            if (slot[2] != empty) {
                ds_prefetch(&e->disk[slot[2]]);
                ds_prefetch(&e->disk[slot[3]]);
            }
        }
}

/* A mixture's pair test reads each candidate's radius too, a line of its
 * own: the first slot of each cell (slots in a cell are disks of nearby
 * numbers often enough, eight radii to a line). An empty slot holds n:
 * one past the last radius, an address a prefetch may name. */
FETCHER void fetch_radii(const ds_events *e, region g)
{
    const size_t stride = (size_t)e->cells.nx * DS_CELL_SLOTS;
    for (int r = 0; r < g.rows; ++r, g.slot += stride)
        for (int k = 0; k < g.slots; k += DS_CELL_SLOTS) {
            ds_prefetch(&e->radius[g.slot[k]]);
            ds_prefetch(&e->radius[g.slot[k + 1]]);
        }
}

/* A named disk whose record showed, at the second stage, that it has been
 * rescheduled past its bucket: its bucket's entry is stale, and the bucket
 * it has moved to names it again. */
#define DROPPED UINT32_MAX

/* The ring's cursors count names mod 2^32 and wrap in a long run (after
 * some 10^9 events): they are ordered by their difference, never compared
 * as numbers, which after a wrap made the third stage walk 4 10^9 names
 * in one event. They stay within a ring's length of each other. */
static int before(uint32_t a, uint32_t b) { return (uint32_t)(b - a - 1u) < 0x7fffffffu; }

/* The calendar names a disk whose event comes up soon: the first stage.
 * Names come in bursts, a bucket at a time, and may outrun the events
 * (stale ones among them), so the ring can fill: then the oldest are
 * dropped, unfetched. */
void ds_fetch_on_soon(void *ctx, uint32_t i, double until)
{
    ds_events *e = ctx;
    ds_fetch *f = &e->fetch;
    ds_prefetch(&e->disk[i]);
    const uint32_t k = f->tail++ & DS_FETCH_AHEAD_MASK;
    f->ahead[k] = i;
    f->ahead_until[k] = until;
    /* Named while the calendar finds the next event: tagged with that
     * event, whose fetch_ahead must leave it alone. */
    f->ahead_tag[k] = f->events + 1;
    if (f->tail - f->third > DS_FETCH_AHEAD_MASK + 1) {
        f->third = f->tail - (DS_FETCH_AHEAD_MASK + 1);
        if (before(f->second, f->third))
            f->second = f->third;
    }
}

/* Before each event: the later stages for every disk that has waited at
 * least one event since its previous stage (an event takes longer than a
 * trip to main memory). */
void ds_fetch_ahead(ds_events *e)
{
    ds_fetch *f = &e->fetch;
    const uint32_t now = ++f->events, empty = e->cells.empty;
    while (before(f->third, f->second) && f->ahead_tag[f->third & DS_FETCH_AHEAD_MASK] != now) {
        const uint32_t k = f->third++ & DS_FETCH_AHEAD_MASK;
        if (f->ahead[k] == DROPPED)
            continue;
        const ed_disk *d = &e->disk[f->ahead[k]];
        const region g = cells_ahead(e, d);
        fetch_disks(e, g);
        if (e->radius)
            fetch_radii(e, g);
    }
    while (before(f->second, f->tail) && f->ahead_tag[f->second & DS_FETCH_AHEAD_MASK] != now) {
        const uint32_t k = f->second++ & DS_FETCH_AHEAD_MASK;
        const ed_disk *d = &e->disk[f->ahead[k]];
        f->ahead_tag[k] = now;
        /* A quarter to a third of the names are stale entries, most of
         * them of disks rescheduled later (the record, here now, tells):
         * fetching for them only crowded out the fetches that count. (An
         * entry of a disk moved earlier is kept: it may come up before any
         * bucket names it again.) 0.80 to 0.88 at 10^6 disks, 0.93 at
         * 10^5 (`tools/bench events N`, alternating). */
        if (!(d->next < f->ahead_until[k])) {
            f->ahead[k] = DROPPED;
            continue;
        }
        if (d->partner < empty)
            ds_prefetch(&e->disk[d->partner]);
        fetch_rows(e, cells_ahead(e, d));
    }
}
