/* SPDX-License-Identifier: MIT */
/* The event-driven integrator's state, shared by its parts:
 * event_driven.c (the events, the run, creation), event_predict.c (a
 * disk's next event) and event_fetch.c (fetching memory ahead of events).
 * Private to event/; the rest of the library sees event.h. */
#ifndef DS_EVENT_STATE_H
#define DS_EVENT_STATE_H

#include "core/core.h"
#include "event/cells.h"
#include "event/event_fetch.h"
#include "event/event_queue.h"

/* What a disk's scheduled event is, kept in its partner field above any
 * disk index (the integrator takes n < 2^30, ds_params_check). */
#define EV_WALL_X (UINT32_MAX - 1)
#define EV_WALL_Y (UINT32_MAX - 2)
#define EV_CELL_X (UINT32_MAX - 3)
#define EV_CELL_Y (UINT32_MAX - 4)
#define EV_NONE (UINT32_MAX - 5) /* nothing ahead, ever: the disk is at rest */

/* Predicting (event_predict.c) and fetching (event_fetch.c) read a
 * cell as four slots at once (C99 has no static assertion). */
typedef char ds_ed_cells_have_four_slots[DS_CELL_SLOTS == 4 ? 1 : -1];

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
    uint32_t partner_changes; /* the partner note (event_fetch.h): its changes, its cell */
} ed_disk;

/* One record is one cache line: an event reads a disk with one memory
 * access, and the fetching ahead asks for one line per disk. */
typedef char ds_ed_disk_is_one_line[sizeof(ed_disk) == 64 ? 1 : -1];

/* Growing radii (growing.c), the dynamics of growth: every radius grows
 * in proportion, r_i(t) = base_i (1 + rate (t - from)), so a pair's
 * contact distance is linear in time, (base_i + base_j) (1 + rate (t -
 * from)). Each restart takes base to its time and divides rate by the
 * factor, so the radii stay linear in time across restarts: dr_i/dt =
 * r_i(start) rate scale, r_i(start) the radius when the growth started.
 * The growth protocol (protocols/growth.c) decides when and how fast. */
typedef struct ds_ed_law {
    double rate;  /* per unit time, relative to base; 0: not growing */
    double scale; /* base over the radii at the growth's start */
    double from;  /* the integrator time base[] holds at */
    double eta;   /* the area fraction at from */
    double *base; /* radii at `from`, by record; NULL if nothing ever grew */
} ds_ed_law;

/* The growth factor of the radii at integrator time t. */
static inline double ds_ed_factor(const ds_ed_law *g, double t)
{
    return 1.0 + g->rate * (t - g->from);
}

struct ds_events {
    ed_disk *disk; /* n, 64-byte aligned */
    ds_cells cells;
    ds_event_queue *queue;
    int fetching;       /* fetch ahead (large systems) */
    ds_fetch fetch;     /* event_fetch.c's */
    uint64_t tested;    /* pair tests not yet added to the tally */
    double epoch;       /* simulated time of the integrator's t = 0 */
    double rebase_time; /* integrator time after which the epoch moves */
    /* The box (a copy: a state is built again when it changes), the
     * radius of one kind of disk and its contact distance squared. */
    ds_box box;
    double one_radius, sigma2;
    /* A mixture's radii and masses by record (the disk arrays', whose
     * slot k is record k), or NULL for one radius (lo_x, ... and sigma2
     * above) and mass 1. */
    const double *radius, *mass;
    /* A periodic box's image counters by record, x then y (image[2 k],
     * image[2 k + 1]): the boxes crossed by the record's own x, y, which
     * cross_cell keeps; the arrays' counts are these plus whatever the
     * wrap of showing adds (ds_ed_show_at). Outside the 64-byte record:
     * only a crossing of the box edge writes them. NULL with walls. */
    int32_t *image;
    /* n predicted times waiting to be filed (ds_ed_schedule_all), kept
     * with the state so that predicting everyone again, which a growth's
     * restart does in the middle of a run, needs no memory. */
    double *times;
    ds_ed_law law;
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

/* The integrator's state for sim's world, its records, cells and
 * calendar allocated and empty (ed_state.c); ds_ed_start then builds
 * the calendar from the records' times, at integrator time now. */
ds_status ds_ed_alloc(ds_sim *sim);
void ds_ed_start(ds_events *e, double now);

/* Writes every disk at integrator time t into the simulation's arrays
 * (record k is slot k), wrapped into a periodic box, with its image
 * counts (ed_state.c). */
void ds_ed_show_at(ds_disks *disks, const ds_events *e, double t);

static inline void ds_ed_advance(ed_disk *d, double t)
{
    const double lag = t - d->t;
    d->x += d->vx * lag;
    d->y += d->vy * lag;
    d->t = t;
}

/* Creating and freeing the state, and predicting every disk afresh
 * (ed_state.c): what a restart at one instant needs. */
ds_status ds_ed_create(ds_sim *sim);
void ds_ed_destroy(ds_sim *sim);
/* Bytes the state allocates for world w (the table's bytes). */
size_t ds_ed_bytes(const ds_world *w);
void ds_ed_schedule_all(ds_events *e, size_t n);

/* Growing radii (growing.c): a disk's next event with growing radii
 * (event_predict.c); the collision of a growing pair; every disk taken to
 * integrator time t and predicted again there, the radii growing from
 * then at speed (relative to the radii at the growth's start; 0:
 * stopped), or as they were (go_on); the radii of t into the arrays; the
 * table's growth services (core.h: grow, growth_law, widen). */
double ds_ed_predict_growing(ds_events *e, uint32_t i);
void ds_ed_collide_growing(ds_sim *sim, ds_events *e, uint32_t i, uint32_t j, double t);
void ds_ed_restart_at(ds_events *e, size_t n, double t, double speed);
void ds_ed_growth_go_on(ds_events *e, size_t n, double t);
void ds_ed_show_radii(ds_sim *sim, const ds_events *e, double t);
ds_status ds_ed_grow(ds_sim *sim, double t, double factor, double speed, int fresh);
void ds_ed_growth_law(const ds_sim *sim, ds_growth_law *law);
ds_status ds_ed_widen(ds_sim *sim, double until, int *rebuilt);

/* A checkpoint of the integrator's state (event_checkpoint.c): the
 * table's save and load. */
void ds_ed_save(const ds_sim *sim, ds_state_writer *w);
ds_status ds_ed_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_legacy *legacy,
                     ds_error *err);

/* Finds disk i's earliest event from its state at its own time (event_predict.c):
 * records it in the disk and returns its time. */
double ds_ed_predict(ds_events *e, uint32_t i);

#endif
