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
    /* The rules (core.h's ds_rules, taken by ds_ed_take_rules): whether
     * disks lose energy (then each disk's integrator time of its last
     * collision is the disk arrays' last_hit, by record, the TC model's),
     * the coefficients and the contact time; whether they fall, and the
     * field. With a field the records keep the falling frame (see
     * ds_ed_lab_at). */
    int inelastic, falls;
    double restitution, wall_restitution, contact_time;
    double field[2];
    double *last_hit;
    /* Lees-Edwards (a sheared periodic box, ds_sim_set_shear): nonzero
     * once a shear was set. The image above then stands offset +
     * box.shift_speed t further along x at integrator time t (offset
     * unwrapped; box.shift is its value modulo the width, at the time the
     * disks were last shown), and the boundary rows' stencils reach
     * across the top and bottom to the columns shear_cell whole cell
     * widths along, which the shear protocol's moments move one at a
     * time (ds_ed_shear). */
    int lees_edwards;
    double offset;
    int64_t shear_cell;
};
typedef struct ds_events ds_events;

/* The falling frame. With a field g every disk flies x(t) = x0 + v0 t + g
 * t^2 / 2, and two disks' relative motion is straight: in the frame that
 * falls with the field from the origin of integrator time, X = x - g t^2
 * / 2 and V = v - g t, every disk flies straight. So the records keep X
 * and V (without a field the two frames are one): pair times,
 * collisions and the delayed states are those of straight flights, to
 * the line, and only what meets the box (walls, cell edges: falling.c)
 * and what shows the disks turn them back into x and v. The frame's
 * offset g t^2 / 2 stays below the box's side (ds_ed_rebase_time), so it
 * costs the positions no more digits than a periodic wrap. */
static inline void ds_ed_lab_at(const ds_events *e, const ed_disk *d, double t, double *x,
                                double *y, double *vx, double *vy)
{
    const double lag = t - d->t;
    *x = d->x + d->vx * lag;
    *y = d->y + d->vy * lag;
    *vx = d->vx;
    *vy = d->vy;
    if (e->falls) {
        const double h = 0.5 * t * t;
        *x += e->field[0] * h;
        *y += e->field[1] * h;
        *vx += e->field[0] * t;
        *vy += e->field[1] * t;
    }
}

/* Disk d's centre along axis, at its own time, in the box (not the
 * falling frame). */
static inline double ds_ed_lab_coordinate(const ds_events *e, const ed_disk *d, int axis)
{
    const double u = axis ? d->y : d->x;
    return e->falls ? u + e->field[axis] * 0.5 * d->t * d->t : u;
}

/* Whether disk d, crossing a cell edge along axis at its own time, leaves
 * through the cell's far edge (up, right): without a field its velocity
 * says, with one (whose disks may cross an edge at the top of their arc)
 * which edge it is at. */
static inline int ds_ed_leaves_up(const ds_events *e, const ed_disk *d, int axis)
{
    if (!e->falls)
        return (axis ? d->vy : d->vx) > 0.0;
    const double w = axis ? e->cells.wy : e->cells.wx;
    return ds_ed_lab_coordinate(e, d, axis) > ((axis ? d->row : d->column) + 0.5) * w;
}

/* The image above's offset along x at integrator time t, unwrapped, and
 * modulo the width into [0, width) with the whole widths in *turns: the
 * one function every part takes it from, so that they agree to the bit. */
static inline double ds_ed_offset(const ds_events *e, double t)
{
    return e->offset + e->box.shift_speed * t;
}

static inline double ds_ed_shift(const ds_events *e, double t, double *turns)
{
    const double o = ds_ed_offset(e, t), width = e->box.side[0];
    double w = floor(o / width), s = o - w * width;
    if (s >= width) { /* rounding */
        s -= width;
        w += 1.0;
    } else if (s < 0.0) {
        s += width;
        w -= 1.0;
    }
    *turns = w;
    return s;
}

/* Whole widths (a double from ds_ed_shift) as an image count's change,
 * modulo 2^32 as the counts wrap. */
static inline uint32_t ds_turns_u32(double turns)
{
    const double t = fmod(turns, 4294967296.0);
    return (uint32_t)(int64_t)(t == t ? t : 0.0);
}

/* The box as it stands at integrator time t: its images' shift then. */
static inline ds_box ds_ed_box_at(const ds_events *e, double t)
{
    ds_box b = e->box;
    if (e->lees_edwards) {
        double turns;
        b.shift = ds_ed_shift(e, t, &turns);
    }
    return b;
}

/* The shear's streaming velocity along x at height y (the profile whose
 * slope is the rate, 0 at mid-height), for a disk of a sheared box. */
static inline double ds_ed_streaming(const ds_events *e, double y)
{
    return e->box.shift_speed / e->box.side[1] * (y - 0.5 * e->box.side[1]);
}

/* The separation (*rx, *ry) of two disks at t to its nearest image, and
 * in a sheared box their relative velocity along x *dvx that of the
 * images that meet, as they stand and move at t. */
static inline void ds_ed_nearest(const ds_events *e, double t, double *rx, double *ry, double *dvx)
{
    if (e->lees_edwards) {
        const ds_box box = ds_ed_box_at(e, t);
        ds_box_nearest_moving(&box, rx, ry, dvx);
    } else {
        ds_box_nearest(&e->box, rx, ry);
    }
}

/* A sheared box's images as they stand at t into the simulation's box
 * (ds_sim_get_shear_shift, _offset); nothing without shear. */
static inline void ds_ed_show_shear(ds_sim *sim, const ds_events *e, double t)
{
    if (!e->lees_edwards)
        return;
    sim->world.box.shift = ds_ed_box_at(e, t).shift;
    sim->world.box.offset = ds_ed_offset(e, t);
}

/* What ds_ed_sheared_collision needs of a pair a, b before their
 * collision: whether it meets across the top or bottom (its separation
 * ry along y was taken to another image), the kinetic tensor and the
 * two velocities. */
static inline void ds_ed_sheared_before(const ds_tally *t, const ed_disk *a, const ed_disk *b,
                                        double ry, int *across, double before[3], double v0[4])
{
    *across = ry != b->y - a->y;
    before[0] = t->kinetic[0];
    before[1] = t->kinetic[1];
    before[2] = t->kinetic[2];
    v0[0] = a->vx;
    v0[1] = a->vy;
    v0[2] = b->vx;
    v0[3] = b->vy;
}

/* Lees-Edwards (sheared.c): a crossing of the top (up) or bottom at t; the
 * stress tally's shear terms at a run's start and after a collision of i
 * and j (across: through the top or bottom; before[], v0[]: the kinetic
 * tensor and the pair's velocities before it); the peculiar velocities
 * scaled at now; the table's shear service (core.h). */
void ds_ed_cross_sheared(ds_sim *sim, ds_events *e, uint32_t i, double t, int up);
void ds_ed_start_shear_tally(ds_sim *sim, const ds_events *e);
void ds_ed_sheared_collision(ds_tally *tally, const ds_events *e, uint32_t i, uint32_t j,
                             int across, const double before[3], const double v0[4]);
void ds_ed_scale_peculiar(ds_sim *sim, ds_events *e, double now, double factor);
double ds_ed_shear(ds_sim *sim, double t, double speed, int moved);

/* The cells around (column, row) at integrator time now: up to 9, or 11
 * for a boundary row of a sheared box (its row, and four columns of the
 * row across the edge, shear_cell along), each with the shift of the
 * image it stands for (a periodic box) and that image's speed along x
 * (a sheared box's images above and below), or fewer at walls. */
#define DS_ED_STENCIL_MAX 12
typedef struct ds_ed_stencil_cells {
    uint32_t count;
    uint32_t cell[DS_ED_STENCIL_MAX];
    double sx[DS_ED_STENCIL_MAX], sy[DS_ED_STENCIL_MAX], su[DS_ED_STENCIL_MAX];
} ds_ed_stencil_cells;

void ds_ed_stencil(const ds_events *e, uint32_t column, uint32_t row, double now,
                   ds_ed_stencil_cells *st);

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

/* Record k's disk at integrator time t (x, y, vx, vy into out), wrapped
 * into box (ds_ed_box_at(e, t), turns its offset's whole widths), its
 * image counts moved by what the wrap crossed (ed_state.c). */
void ds_ed_show_disk(const ds_events *e, size_t k, double t, const ds_box *box, double turns,
                     double out[4], int32_t image[2]);

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
ds_status ds_ed_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_legacy *legacy, ds_error *err);

/* Finds disk i's earliest event from its state at its own time (event_predict.c):
 * records it in the disk and returns its time. */
double ds_ed_predict(ds_events *e, uint32_t i);

/* Moves the integrator's origin to its time t (a step boundary): every
 * disk is advanced to t (out of the falling frame), every scheduled time
 * and time of last collision shifted by -t (ed_state.c). */
void ds_ed_rebase(ds_events *e, size_t n, double t);
/* How long the clock runs before its origin moves (ed_state.c): about
 * the time a disk takes to cross the box, and with a field no longer than
 * the frame's offset g t^2 / 2 takes to reach the box's side. */
double ds_ed_rebase_time(const ds_world *w, const ds_rules *rules);
/* The rules into the state's copy (ed_state.c; last_hit: the disk
 * arrays', which must be there for rules that lose energy). */
void ds_ed_adopt_rules(ds_events *e, const ds_rules *rules, double *last_hit);

/* Disk d's (record i's) earliest wall or cell edge under the field, as
 * the lanes' boundary event does without one (falling.c): into *best and
 * *kind if before *best. */
void ds_ed_boundary_falling(const ds_events *e, const ed_disk *d, uint32_t i, double now,
                            double *best, uint32_t *kind);

/* The granular parts (granular.c): the table's take_rules and kick; a
 * wall turn with the wall restitution, the TC model and the field's
 * floor (the disk taken to t, not predicted again). */
ds_status ds_ed_take_rules(ds_sim *sim, const ds_rules *rules);
void ds_ed_kick(ds_sim *sim, const double *dv);
void ds_ed_turn_granular(ds_sim *sim, ds_events *e, uint32_t i, double t, int axis);

#endif
