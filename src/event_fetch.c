/* Fetching ahead (event-driven integrator).
 *
 * Events come in time order, which is no order in space: in a large
 * system each one touches memory far from the last (its disk, its partner,
 * the cells around it, their disks), and waits on main memory several
 * times in a row. The calendar knows which disks come up a few events
 * ahead, so their memory is requested then, in three stages a few events
 * apart, each needing what the one before brought in: the disk's record;
 * then its partner's record and its three rows of cells; then the records
 * of the disks in those cells (state and scheduled time, one line each). */
#include "event_driven.h"
#include "prefetch.h"

/* The helpers below only read memory and prefetch, so gcc marks them pure
 * and, their results being unused, deletes the calls (and the prefetches
 * with them) unless they are inlined into a caller that writes. */
#if defined(__GNUC__)
#define FETCHER static inline __attribute__((always_inline))
#else
#define FETCHER static inline
#endif

/* The first slot of the 3 x 3 cells around disk d (three rows of twelve
 * consecutive slots, nx * 4 apart), or NULL at the edge of the grid,
 * where it is not worth the care. A collision's partner, in one of these
 * cells, shares most of them; fetching 5 x 5 for it measured no faster
 * (more requests in flight than the core can hold). */
FETCHER const uint32_t *cells_around(const ds_events *e, const ed_disk *d)
{
    const ds_cells *cells = &e->cells;
    if (!ds_ed_interior(cells, d))
        return NULL;
    return ds_cells_slots(cells, ds_cells_index(cells, d->column - 1u, d->row - 1u));
}

FETCHER void fetch_cell_rows(const ds_events *e, const ed_disk *d)
{
    const uint32_t *slot = cells_around(e, d);
    if (!slot)
        return;
    const size_t stride = (size_t)e->cells.nx * DS_CELL_SLOTS;
    for (int r = 0; r < 3; ++r, slot += stride) {
        ds_prefetch(slot);
        ds_prefetch(slot + 3 * DS_CELL_SLOTS - 1);
    }
}

FETCHER void fetch_cell_disks(const ds_events *e, const ed_disk *d)
{
    const uint32_t *slot = cells_around(e, d);
    if (!slot)
        return;
    const size_t stride = (size_t)e->cells.nx * DS_CELL_SLOTS;
    for (int r = 0; r < 3; ++r, slot += stride)
        for (int k = 0; k < 3 * DS_CELL_SLOTS; ++k)
            if (slot[k] != e->cells.empty)
                ds_prefetch(&e->disk[slot[k]]);
}

/* The calendar names a disk whose event comes up soon: the first stage.
 * Names come in bursts, a bucket at a time, and may outrun the events
 * (stale ones among them), so the ring can fill: then the oldest are
 * dropped, unfetched. */
void ds_ed_on_soon(void *ctx, uint32_t i)
{
    ds_events *e = ctx;
    ds_prefetch(&e->disk[i]);
    const uint32_t tail = e->ahead_tail++;
    e->ahead[tail & AHEAD_MASK] = i;
    /* Named while the calendar finds the next event: tagged with that
     * event, whose fetch_ahead must leave it alone. */
    e->ahead_tag[tail & AHEAD_MASK] = e->events + 1;
    if (e->ahead_tail - e->ahead_third > AHEAD_MASK + 1) {
        e->ahead_third = e->ahead_tail - (AHEAD_MASK + 1);
        if (e->ahead_second < e->ahead_third)
            e->ahead_second = e->ahead_third;
    }
}

/* Before each event: the later stages for every disk that has waited at
 * least one event since its previous stage (an event takes longer than a
 * trip to main memory). */
void ds_ed_fetch_ahead(ds_events *e)
{
    const uint32_t now = ++e->events;
    while (e->ahead_third < e->ahead_second && e->ahead_tag[e->ahead_third & AHEAD_MASK] != now) {
        fetch_cell_disks(e, &e->disk[e->ahead[e->ahead_third & AHEAD_MASK]]);
        ++e->ahead_third;
    }
    while (e->ahead_second < e->ahead_tail && e->ahead_tag[e->ahead_second & AHEAD_MASK] != now) {
        const uint32_t k = e->ahead_second++ & AHEAD_MASK;
        const ed_disk *d = &e->disk[e->ahead[k]];
        if (d->partner < e->cells.empty)
            ds_prefetch(&e->disk[d->partner]);
        fetch_cell_rows(e, d);
        e->ahead_tag[k] = now;
    }
}
