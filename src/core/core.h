/* SPDX-License-Identifier: MIT */
/* What every part of the library shares: the simulation object, what
 * every part reads (the world), what integrators add to (the tally), and
 * the table of operations an integrator fills.
 *
 * The pipeline is create (sim/params.c, init/) -> step (an integrator,
 * through its table: timestep/, event/) -> observe (observe/) -> write
 * (io/). sim/ keeps the public API and dispatches through the table;
 * the parts never call sim/. Refusals are made through core/error.c.
 * Not installed. */
#ifndef DS_CORE_H
#define DS_CORE_H

#include "core/box.h"
#include "core/disk_arrays.h"
#include "core/protocol.h"
#include "core/state_io.h"
#include "disk_sim.h"

#define DS_TWO_PI 6.28318530717958647692

/* For a hot loop's helper that must inline: gcc's size heuristic
 * otherwise keeps a large one out of line (the strips' merge, the
 * event-driven prediction's gathering: 7% per collision measured). */
#if defined(__GNUC__)
#define DS_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define DS_ALWAYS_INLINE inline
#endif

/* How disks meet each other and the walls, and how they fly between
 * (ds_sim_set_restitution, ds_sim_set_contact_time, ds_sim_set_gravity:
 * sim/rules.c writes them, the integrators read them). Elastic and
 * straight when a simulation is created. */
typedef struct ds_rules {
    /* Coefficients of normal restitution, in (0, 1]: the relative normal
     * velocity of a colliding pair, and a disk's normal velocity at a
     * wall, come out -e times what they went in (1: elastic). */
    double restitution, wall_restitution;
    /* The TC model's contact time t_c (> 0): a collision within t_c of
     * either disk's previous one is elastic (the event-driven
     * integrator's; core/collide.h). */
    double contact_time;
    /* The field: every disk's acceleration along x and y (0 along a
     * periodic axis), box units per time squared. */
    double field[2];
} ds_rules;

/* Whether disks lose energy at all (and the event-driven integrator
 * keeps each disk's time of last collision), and whether they fall. */
static inline int ds_rules_inelastic(const ds_rules *r)
{
    return r->restitution < 1.0 || r->wall_restitution < 1.0;
}

static inline int ds_rules_fall(const ds_rules *r)
{
    return r->field[0] != 0.0 || r->field[1] != 0.0;
}

/* What the parts read: the parameters with the defaults resolved, fixed
 * at creation, and three things that may change as the run goes, each
 * with one writer: the box (its sides change only through a state built
 * again for them; sheared images' shift moves with time), the disks'
 * sizes (ds_world_take_radii, whenever radii change: growth) and the
 * rules of collisions and flights (sim/rules.c, through the integrator's
 * take_rules). */
typedef struct ds_world {
    size_t n;
    double radius, speed, dt;
    /* The box: every part asks it (box.h), none keeps a flag of its own. */
    ds_box box;
    /* The disks' smallest and largest radius (both radius for one kind;
     * a mixture's radii are in the disk arrays) and the area they cover,
     * sum of pi r^2. Pruning and cells take the largest. */
    double radius_min, radius_max, covered;
    ds_integrator integrator;
    /* The request's name for the box (ds_sim_get_boundary, checkpoints):
     * the parts read box's edges instead. */
    ds_boundary boundary;
    ds_broadphase broadphase; /* resolved, never DS_BROADPHASE_AUTO */
    ds_placement placement;
    uint64_t seed;
    ds_rules rules;
} ds_world;

/* The box a request names: its sides and, along each axis, walls or
 * periodic as the boundary says (a channel: periodic along x, walls
 * along y). */
static inline ds_box ds_box_of(ds_boundary boundary, double width, double height)
{
    const ds_edge along_x = boundary == DS_BOUNDARY_WALLS ? DS_EDGE_WALLS : DS_EDGE_PERIODIC;
    const ds_edge along_y = boundary == DS_BOUNDARY_PERIODIC ? DS_EDGE_PERIODIC : DS_EDGE_WALLS;
    return ds_box_make(width, height, along_x, along_y);
}

/* The area n disks of radius r cover, n pi r^2, as one expression: the
 * world of one kind of disk, and each term of a mixture's sum (n = 1). */
static inline double ds_covered_by(double n, double r) { return n * DS_TWO_PI * 0.5 * r * r; }

/* The world's radius_min, radius_max and covered from the disk arrays:
 * for one kind (d->r NULL) its radius and ds_covered_by(n, radius); for
 * a mixture the sum of its disks' areas in generation order (slot[]
 * valid), whatever order the slots are in. Every part that sets them
 * (creation, a checkpoint's load, growth) calls this, so an area
 * fraction has the same bits whichever part computed it (core/world.c). */
void ds_world_take_radii(ds_world *w, const ds_disks *d);

/* What the integrators add to as they run, and the observables read. */
typedef struct ds_tally {
    uint64_t collisions;   /* disk-disk collisions resolved */
    uint64_t pairs_tested; /* narrow-phase distance tests */
    uint64_t wall_count;   /* wall reflections since the last reset */
    double wall_impulse;   /* sum of 2 m |v_n| over them */
    /* A mixture's: sum of 2 m |v_n| / L_i, L_i the perimeter disk i's
     * centre reaches (0 for one kind: wall_impulse / L then). */
    double wall_reach;
    double virial; /* sum over collisions of r_ij . dp_i since the reset */
    /* The pressure tensor's parts, components xx, yy, xy, never reset
     * (ds_sim_get_stress_integral): the collisions' virial tensor, sum of
     * (r_i - r_j)_a dp_i,b; the kinetic tensor sum m v_a v_b as a run
     * goes (ds_sim_run computes it at the start, then every collision and
     * wall turn changes it, collide.h); and the kinetic tensor's time
     * integral, which has reached the integrator's time stress_clock. */
    double stress_virial[3], kinetic[3], kinetic_integral[3];
    double stress_clock;
    /* With a field the kinetic tensor changes between collisions too: an
     * integrator whose disks fall continuously (the event-driven one) sets
     * falling and the field, and the momentum and total mass (ds_sim_run
     * sums them with the kinetic tensor) carry it (collide.h). */
    int falling;
    double field[2], momentum[2], mass;
    /* A sheared box (Lees-Edwards): the pressure tensor's kinetic xy part
     * is that of the peculiar velocities, vx less the profile shear_rate
     * (y - H/2): sum m vx vy less shear_rate times the moment sum m (y -
     * H/2) vy, which the flights change at the rate sum m vy^2 and the
     * collisions and crossings by their jumps (collide.h, the integrator
     * that shears sets both at a run's start). 0 without shear. */
    double shear_rate, shear_moment;
    /* The energy books since the reset: kinetic energy the collisions and
     * wall turns took out (a TC model's elastic ones none), and what a
     * drive put in. */
    double dissipated, injected;
} ds_tally;

typedef struct ds_integrator_ops ds_integrator_ops;

struct ds_sim {
    ds_world world;
    /* The disks at ds_sim_get_time in generation-indexed slots (disk_arrays.h).
     * An integrator with records of its own refreshes them after each
     * run. */
    ds_disks disks;
    const ds_integrator_ops *integrator;
    void *state; /* the integrator's own, created and freed through its table */
    uint64_t steps;
    ds_timer collision_timer;
    ds_tally tally;
    uint64_t observables_since_step; /* step count at the last reset */
    /* The kinds of disk (a mixture's species; one, "A", without) and
     * their names: kind_names[k] for k < kind_count (NULL: one kind). A
     * disk's kind is its column kind (absent: 0). */
    size_t kind_count;
    char (*kind_names)[DS_KIND_NAME_MAX];
    /* A caller's text (ds_sim_set_metadata), NULL for none. */
    char *metadata;
    /* What acts on the run from outside its dynamics (core/protocol.h):
     * installed by their setters, their hooks called by the integrator. */
    ds_protocols protocols;
};

/* The disks' kinetic energy k, momentum (px, py) and total mass. */
typedef struct ds_kinetic {
    double k, px, py, mass;
} ds_kinetic;

/* The temperature the collisions see in box b of n disks (the rule
 * observe/observables.c explains at ds_sim_get_temperature): the kinetic
 * energy less what the box conserves of the momentum (a periodic axis
 * conserves its component, and the centre of mass's motion along it is
 * no pair's), over the degrees of freedom left. A thermostat holds it
 * (protocols/thermostat.c). */
/* The kinetic energy, momentum and mass of the disk columns: the kinetic
 * service of the integrators whose state they are (the time step, event
 * chains). */
static inline void ds_disks_kinetic(const ds_sim *sim, ds_kinetic *out)
{
    const ds_disks *d = &sim->disks;
    double k = 0.0, px = 0.0, py = 0.0, mass = 0.0;
    for (size_t i = 0; i < d->n; ++i) {
        const double m = d->m ? d->m[i] : 1.0;
        k += m * (d->vx[i] * d->vx[i] + d->vy[i] * d->vy[i]);
        px += m * d->vx[i];
        py += m * d->vy[i];
        mass += m;
    }
    out->k = 0.5 * k;
    out->px = px;
    out->py = py;
    out->mass = mass;
}

static inline double ds_kinetic_temperature(const ds_box *b, size_t n, const ds_kinetic *k)
{
    if (n == 0)
        return 0.0;
    const int px_kept = ds_box_periodic(b, 0), py_kept = ds_box_periodic(b, 1);
    if (!px_kept && !py_kept)
        return k->k / (double)n;
    if (n < 2)
        return 0.0;
    const double kept = px_kept && py_kept ? k->px * k->px + k->py * k->py
                        : px_kept          ? k->px * k->px
                                           : k->py * k->py;
    const double internal = k->k - kept / (2.0 * k->mass);
    return (internal > 0.0 ? internal : 0.0) /
           (px_kept && py_kept ? (double)n - 1.0 : (double)n - 0.5);
}

/* Where an integrator's growing radii stand (ds_integrator_ops.growth):
 * since integrator time `from` every radius is r_i(from) (1 + rate (t -
 * from)); scale is r_i(from) over the radius at the growth's start, so
 * that a speed relative to those (dr_i / dt over it) is rate scale; eta
 * the area fraction at from. */
typedef struct ds_growth_law {
    double rate, scale, from, eta;
} ds_growth_law;

/* One integrator: a way to advance the disks by whole steps of dt. Each
 * fills one table (timestep/time_step.c, event/event_driven.c), listed in
 * sim/tables.c by its ds_integrator value. */
struct ds_integrator_ops {
    const char *name; /* ds_integrator_name */
    /* The least room between disks it takes, as a fraction of a diameter
     * (DS_ROOM_TO_MOVE, or 0): sim/params.c refuses lattices and walls
     * closer than that. */
    double min_room;
    /* Whether broad phase bp (never DS_BROADPHASE_AUTO) serves this
     * integrator. */
    int (*fits)(ds_broadphase bp);
    /* The broad phase DS_BROADPHASE_AUTO means for world w. */
    ds_broadphase (*choose)(const ds_world *w);
    /* Refusals and warnings of its own for world w, beyond those
     * params.c makes for every integrator: DS_OK, or a status with err
     * filled as ds_params_check describes; warnings gets DS_WARN_*
     * bits (err->warning the first one's sentence). */
    ds_status (*check)(const ds_world *w, unsigned *warnings, ds_error *err);
    /* Bytes its state allocates for world w (broad phase resolved). */
    size_t (*bytes)(const ds_world *w);
    /* Builds its state (sim->state) from the disks in sim->disks, in
     * generation order, at the time sim->steps stands for (0 when the
     * simulation is created, later for ds_sim_set_disks); it may permute
     * the slots (ds_disks_permute). A failure (DS_ERR_NOMEM) says why in
     * err. */
    ds_status (*create)(ds_sim *sim, ds_error *err);
    void (*destroy)(ds_sim *sim); /* frees sim->state; safe after a failed create */
    /* Advances steps steps (>= 1) of dt; sim->disks shows the disks at
     * the new time afterwards, slot[] valid. A run that cannot go on
     * (DS_ERR_NOMEM, with err filled: a protocol's step's end failed) stops
     * at the end of a whole step, sim->steps counting it, every part of sim
     * as at that step's end. */
    ds_status (*run)(ds_sim *sim, uint64_t steps, ds_error *err);
    /* Replaces the disk in slot k (already checked to be inside the box,
     * finite), or refuses it without changing anything. */
    ds_status (*set)(ds_sim *sim, size_t k, ds_disk d);
    /* Writes whatever of its state the next step depends on, beyond what
     * sim/checkpoint.c writes (the world, the steps, the tally, the disk
     * arrays in their slots), so that a run loaded from it goes on to the
     * bit as if it had never stopped. */
    void (*save)(const ds_sim *sim, ds_state_writer *w);
    /* Reads that back into sim->state, the rest of sim already restored:
     * DS_OK, or DS_ERR_FORMAT (or DS_ERR_NOMEM) with a reason, leaving
     * what it made for destroy. It checks what could make the library
     * misbehave (indices out of range, lists that loop, times that are
     * not numbers); the checksum catches the rest. version is the file's
     * format version; what an older one kept here that a protocol keeps
     * now goes to legacy (core/protocol.h). */
    ds_status (*load)(ds_sim *sim, ds_reader *r, uint32_t version, ds_legacy *legacy,
                      ds_error *err);
    /* Every velocity times factor (> 0), at the present time, the stress
     * tally's kinetic part with them (a protocol's step's end scales them
     * inside a run). */
    ds_status (*scale_velocities)(ds_sim *sim, double factor);

    /* What only the integrator knows of what it samples (observe/ asks):
     * the temperature kT, and the compressibility factor Z averaged since
     * the last reset (0 before any step). NULL: molecular dynamics, kT
     * from the velocities and Z from the collision virial. A sampler
     * without velocities (event-chain Monte Carlo) fills both. */
    double (*temperature)(const ds_sim *sim);
    double (*compressibility)(const ds_sim *sim);

    /* Services to protocols, at integrator time t inside the present
     * step (each NULL where the integrator has none: a protocol that needs
     * it refuses to start, saying so). */
    /* The integrator time of the present step boundary. */
    double (*now)(const ds_sim *sim);
    /* The kinetic energy, the momentum and the mass of the disks now
     * (ds_kinetic_temperature takes them). */
    void (*kinetic)(const ds_sim *sim, ds_kinetic *k);
    /* At integrator time t, inside the present step and no earlier than
     * the event last handled (the time step: at its step boundary, the
     * only time it has), the disk in slot k flies on at (vx, vy) (finite,
     * within DS_VELOCITY_MAX), the stress tally's kinetic part with it,
     * predicted again: a heat bath's collision with one disk. */
    void (*set_velocity)(ds_sim *sim, size_t k, double t, double vx, double vy);
    /* At the present step boundary, in a periodic box: the box's sides
     * times sx and sy and every centre with them (velocities and image
     * counts kept), the state built again beside the old one and swapped
     * in (ds_rescale_box), the protocols' clocks moved with the
     * integrator's origin. Refused with nothing changed: DS_ERR_OVERLAP
     * when a pair would come closer than contact that was not,
     * DS_ERR_ARG for a box that is not periodic or a side that would
     * leave the largest disk too large for it (a quarter of the side) or
     * pass 1e9, DS_ERR_NOMEM. */
    ds_status (*resize)(ds_sim *sim, double sx, double sy);
    /* At t: every velocity times factor (1: none; the stress tally's
     * kinetic part with them, as a heat bath's step taken out of the
     * run), and from t on radii that grow linearly in time at speed
     * (relative to the radii at the growth's start; 0: radii fixed at
     * those of t), fresh to start a growth from the radii of t; every
     * disk predicted again. DS_ERR_NOMEM, nothing changed, without memory
     * for a growth's radii. */
    ds_status (*grow)(ds_sim *sim, double t, double factor, double speed, int fresh);
    void (*growth_law)(const ds_sim *sim, ds_growth_law *law);
    /* Room for the growing contacts up to integrator time until: the
     * state built again with room for radii 5% larger when it has less
     * (*rebuilt then set; the state's origin is then the present).
     * DS_ERR_NOMEM, nothing changed, without memory for that. */
    ds_status (*widen)(ds_sim *sim, double until, int *rebuilt);
    /* At the present step boundary, slot k's velocity plus (dv[2 k],
     * dv[2 k + 1]) for every k (a drive's kicks): the tally's injected
     * energy, kinetic tensor and momentum follow. */
    void (*kick)(ds_sim *sim, const double *dv);

    /* The rules (collide.h, core.h) from the present step boundary on,
     * sim->world.rules still the old ones: what the integrator keeps of
     * them made ready (a field's flights predicted again, each disk's
     * time of last collision). DS_ERR_NOMEM, nothing changed, without
     * memory for that; DS_ERR_ARG, nothing changed, for rules it cannot
     * follow (event chains have no dynamics to make granular). NULL: it
     * reads sim->world.rules as it goes. */
    ds_status (*take_rules)(ds_sim *sim, const ds_rules *rules);

    /* Lees-Edwards: from integrator time t (the present step boundary, or
     * a moment of the shear protocol's, with no event between) the box's
     * images above and below move at +-speed along x (the shear rate
     * times the height) from where they stand at t; moved: the images
     * have just passed a cell edge in that direction (+1 or -1), or 0: a
     * shear set afresh. Returns the time they pass the next (+infinity
     * at rest). NULL: the integrator cannot shear its box. */
    double (*shear)(ds_sim *sim, double t, double speed, int moved);
};

#if defined(__GNUC__)
#define DS_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define DS_PRINTF(f, a)
#endif

/* The box's sides times sx and sy and every centre with them, at the
 * present step boundary, sim's disk columns showing the disks at it
 * (core/rescale.c): the integrators' resize service (see there) less the
 * clocks. */
ds_status ds_rescale_box(ds_sim *sim, double sx, double sy);

/* The error model (core/error.c). ds_error_clear empties err (NULL does
 * nothing): every public call that takes one starts with it. */
void ds_error_clear(ds_error *err);
/* Fills err (if not NULL) with the status, the field at fault, the value
 * and the limit it broke (NAN where they are not numbers) and a
 * printf-style sentence; returns status, so a check reads
 * `return ds_refuse(err, DS_ERR_ARG, "n", (double)n, 1.0, "n = %zu ...", n)`. */
ds_status ds_refuse(ds_error *err, ds_status status, const char *field, double value, double limit,
                    const char *fmt, ...) DS_PRINTF(6, 7);
/* A checkpoint refused: ds_refuse with field "checkpoint" and no numbers. */
ds_status ds_state_refuse(ds_error *err, ds_status status, const char *fmt, ...) DS_PRINTF(3, 4);
/* The disk (or line) at fault, beside a refusal. */
void ds_error_index(ds_error *err, size_t index);
/* The status a public call returns, into err: on DS_OK the refusal parts
 * are emptied (a warning stays), and a failure no refusal explained gets
 * ds_status_name's words. Returns status. */
ds_status ds_error_done(ds_error *err, ds_status status);

/* An enumeration's value by name (core/names.c): *out = the v < count
 * whose name_of(v) is name, or DS_ERR_ARG naming field and the names
 * known. Clears err first. */
ds_status ds_parse_name(const char *field, const char *name, int count,
                        const char *(*name_of)(int value), int *out, ds_error *err);

#endif
