/* The event-driven integrator's state, shared by its parts:
 * event_driven.c (the events, the run, creation), event_predict.c (a
 * disk's next event) and event_fetch.c (fetching memory ahead of events).
 * Not installed. */
#ifndef DS_EVENT_DRIVEN_H
#define DS_EVENT_DRIVEN_H

#include "cells.h"
#include "event_queue.h"
#include "sim_internal.h"

/* What a disk's scheduled event is, kept in its partner field above any
 * disk index (the integrator takes n < 2^30, ds_check_params). */
#define EV_WALL_X (UINT32_MAX - 1)
#define EV_WALL_Y (UINT32_MAX - 2)
#define EV_CELL_X (UINT32_MAX - 3)
#define EV_CELL_Y (UINT32_MAX - 4)
#define EV_NONE (UINT32_MAX - 5) /* nothing ahead, ever: the disk is at rest */

/* A centre closer than 2R (1 - this) to another is an overlap that ds_set
 * refuses; closer than 2R by less is contact up to rounding. */
#define CONTACT_TOLERANCE 1e-9

/* A disk's partner_changes holds the partner's change count in its low
 * 28 bits and, in the top 4, where the partner's cell is: (dx + 1) +
 * 3 (dy + 1) from the disk's, or unknown (a shift across a periodic edge,
 * or no partner). Fetching ahead reads it (event_fetch.c). The count is
 * compared mod 2^28: a stale collision would be taken for current only if
 * its partner had changed course a multiple of 2^28 (2.7 x 10^8) times
 * before it came up, where a disk changes course a few times per mean
 * free time. */
#define CHANGES_MASK 0x0fffffffu
#define PARTNER_CELL_SHIFT 28
#define PARTNER_CELL_UNKNOWN 15u

/* Predicting (event_predict.c) and fetching (event_fetch.c) read a
 * cell as four slots at once (C99 has no static assertion). */
typedef char ds_ed_cells_have_four_slots[DS_CELL_SLOTS == 4 ? 1 : -1];

/* Disks named by the calendar ahead of their events (a power of two), and
 * the size of state from which that pays (see "Fetching ahead"). */
#define AHEAD_MASK 63u
#define FETCH_AHEAD_BYTES (8u << 20)
/* Times the calendar keeps sorted ahead while fetching: the disks whose
 * buckets it has read are a few events ahead of their turn. */
#define FETCH_LOOKAHEAD 16

/* One disk: everything an event reads or writes about it, in one 64-byte
 * cache line. Events visit disks in no spatial order, so a disk's fields
 * side by side cost one memory access where separate arrays cost five.
 * The time of its scheduled event is here and only here: the calendar
 * reads and writes it in place (ds_eq_create's times), and predicting a
 * neighbour reads it beside the neighbour's state. */
typedef struct ed_disk {
    double x, y, vx, vy;
    double t;                 /* the time x, y belong to */
    double next;              /* the time of its scheduled event (the calendar's) */
    uint16_t column, row;     /* its cell (DS_CELLS_MAX_SIDE per side) */
    uint32_t changes;         /* velocity changes so far */
    uint32_t partner;         /* the scheduled event: a disk or an EV_* */
    uint32_t partner_changes; /* the partner's changes when predicted, its cell */
} ed_disk;

struct ds_events {
    ed_disk *disk; /* n, 64-byte aligned */
    ds_cells cells;
    ds_event_queue *queue;
    int fetching; /* fetch ahead (large systems) */
    /* Disks whose events come up soon (the calendar's drained times), for
     * fetching ahead; see "Fetching ahead". */
    uint32_t ahead[AHEAD_MASK + 1];
    uint32_t ahead_tag[AHEAD_MASK + 1]; /* the event count at its last stage */
    double ahead_until[AHEAD_MASK + 1]; /* its calendar entry's end of time */
    uint32_t ahead_tail, ahead_second, ahead_third;
    uint32_t events;    /* events handled, mod 2^32 */
    double epoch;       /* simulated time of the integrator's t = 0 */
    double rebase_time; /* integrator time after which the epoch moves */
    double box_x, box_y, lo_x, hi_x, lo_y, hi_y, sigma2;
    int periodic;
};
typedef struct ds_events ds_events;

/* The cells around (column, row): up to 9, each with the shift of the
 * image it stands for (a periodic box), or fewer at walls. */
typedef struct ds_ed_stencil_cells {
    uint32_t count;
    uint32_t cell[9];
    double sx[9], sy[9];
} ds_ed_stencil_cells;

void ds_ed_stencil(const ds_events *e, uint32_t column, uint32_t row, ds_ed_stencil_cells *st);

/* Whether the 3 x 3 cells around (column, row) are all inside the grid,
 * none across an edge (unsigned arithmetic: column 0 wraps to a huge
 * column - 1). */
static inline int ds_ed_interior_at(const ds_cells *cells, uint32_t column, uint32_t row)
{
    return column - 1u < cells->nx - 2u && row - 1u < cells->ny - 2u;
}

/* The same for disk d's 3 x 3 cells. */
static inline int ds_ed_interior(const ds_cells *cells, const ed_disk *d)
{
    return ds_ed_interior_at(cells, d->column, d->row);
}

/* Finds disk i's earliest event from its state at its own time (event_predict.c):
 * records it in the disk and returns its time. */
double ds_ed_predict(ds_sim *sim, ds_events *e, uint32_t i);

/* Fetching ahead (event_fetch.c): the calendar's ds_eq_on_soon callback,
 * and the step run before each event. */
void ds_ed_on_soon(void *ctx, uint32_t i, double until);
void ds_ed_fetch_ahead(ds_events *e);

#endif
