/* SPDX-License-Identifier: MIT */
/*
 * disksim: hard disks (2D elastic billiards) in a square box.
 *
 * The one public header of libdisksim. Every exported symbol starts with
 * `ds_`. The library never prints, never exits and keeps no global mutable
 * state: errors come back as a ds_status, which ds_status_str() describes.
 *
 * Units: lengths in box units (the box is [0,box]^2, box = 1000 by default),
 * time in simulated seconds, unit masses.
 */
#ifndef DISK_SIM_H
#define DISK_SIM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define DS_VERSION_MAJOR 2
#define DS_VERSION_MINOR 1
#define DS_VERSION_PATCH 0
#define DS_VERSION_STRING "2.1.0"

/* ------------------------------------------------------------------ */
/* Status codes                                                        */
/* ------------------------------------------------------------------ */

typedef enum ds_status {
    DS_OK = 0,
    DS_ERR_ARG,       /* an argument is out of range or NULL */
    DS_ERR_NOMEM,     /* an allocation failed or would not fit in memory */
    DS_ERR_PLACEMENT, /* the disks cannot be placed (see DS_RANDOM, DS_LATTICE) */
    DS_ERR_IO,        /* a read or write failed */
    DS_ERR_FORMAT,    /* a frame or checkpoint is malformed (ds_frame_error, ds_state_error) */
    DS_ERR_OVERLAP    /* ds_set or ds_set_all would make two disks overlap */
} ds_status;

/* A static English description of a status; never NULL. */
const char *ds_status_str(ds_status status);

/* Library version as "MAJOR.MINOR.PATCH" (same as DS_VERSION_STRING). */
const char *ds_version(void);

/* ------------------------------------------------------------------ */
/* Random numbers: xorshift64* (Vigna 2016), one state per generator    */
/* ------------------------------------------------------------------ */

typedef struct ds_rng {
    uint64_t state; /* never 0 */
} ds_rng;

/* Seeds the generator; any seed (0 included) gives a valid, distinct stream. */
void ds_rng_seed(ds_rng *rng, uint64_t seed);
/* 64 random bits. */
uint64_t ds_rng_next(ds_rng *rng);
/* Uniform double in [a, b) built from the top 53 random bits. */
double ds_rng_uniform(ds_rng *rng, double a, double b);

/* ------------------------------------------------------------------ */
/* Timer: accumulates CLOCK_MONOTONIC seconds over start/stop pairs     */
/* ------------------------------------------------------------------ */

typedef struct ds_timer {
    double started; /* monotonic seconds at the last start */
    double total;   /* accumulated seconds of completed start/stop pairs */
    int running;
} ds_timer;

/* Monotonic clock reading in seconds (arbitrary origin, never decreases). */
double ds_now(void);
void ds_timer_reset(ds_timer *timer);
void ds_timer_start(ds_timer *timer);
void ds_timer_stop(ds_timer *timer);
/* Accumulated seconds, including the running interval if started. */
double ds_timer_seconds(const ds_timer *timer);

/* ------------------------------------------------------------------ */
/* Simulation                                                          */
/* ------------------------------------------------------------------ */

typedef struct ds_sim ds_sim; /* opaque */

typedef struct ds_disk {
    double x, y, vx, vy;
} ds_disk;

/* How the dynamics is integrated. */
typedef enum ds_integrator {
    /* The seed's fixed time step: move every disk by v dt, then reflect at
     * the walls and swap the normal velocities of overlapping, approaching
     * pairs. Fast and simple; collisions are seen up to one step late. */
    DS_TIME_STEP = 0,
    /* Exact event-driven dynamics: every collision at its exact time, at
     * centre distance exactly 2R, every wall turn at exactly R from the
     * wall. ds_step still advances time by exactly dt. */
    DS_EVENT_DRIVEN
} ds_integrator;

/* What happens at the edges of the box. */
typedef enum ds_boundary {
    DS_WALLS = 0, /* hard walls: a centre turns at R from each wall */
    /* Periodic in x and y: a disk leaving at one edge comes back at the
     * opposite one, and pairs interact through their nearest image.
     * Positions stay in [0, box) x [0, box_y), however far a step takes a
     * disk. Needs R < box/4 and R < box_y/4 (so a pair touches through
     * one image only). */
    DS_PERIODIC
} ds_boundary;

/* Where the disks start. */
typedef enum ds_placement {
    /* Random sequential: the seed's, up to area fraction 0.54. In a
     * periodic box (with more than one disk) the mean velocity is taken
     * out and the speeds scaled back to the same kinetic energy,
     * n speed^2 / 2, so the centre of mass stands still, at any speed
     * and masses (if rounding leaves every disk the same velocity, as it
     * can below the smallest normal speed, 2.2e-308, they start at
     * rest); with walls the velocities are the seed's. */
    DS_RANDOM = 0,
    /* A triangular lattice of m rows of c sites (c m >= n, empty sites
     * spread evenly), the (c, m) whose closest sites are farthest apart;
     * it fits without strain, up to close packing (area fraction
     * pi / (2 sqrt 3) = 0.9069), in a periodic box of aspect
     * box_y / box = sqrt(3) m / (2 c). ds_check_params refuses
     * (DS_ERR_PLACEMENT) a request whose best lattice would overlap, and
     * for the event-driven integrator one whose closest sites are less than
     * DS_ROOM_TO_MOVE of a diameter apart beyond contact (at close packing
     * every disk touches its neighbours, and collisions would cascade
     * without time ever advancing). In a periodic box (with more than one
     * disk) the total momentum is made zero, as for DS_RANDOM. */
    DS_LATTICE
} ds_placement;

/* How candidate pairs are found. In the same state every one finds the
 * same pairs; each resolves them in its own order, so the time step's
 * trajectories are the same to the bit only until a step in which a disk
 * overlaps two others, and the event-driven ones the same up to rounding
 * (docs/library.md, "What the broad phases share"). */
typedef enum ds_broadphase {
    DS_SAP = 0,     /* sweep and prune along x, insertion sort (the seed's) */
    DS_BRUTE_FORCE, /* all pairs, O(N^2): the reference (both integrators) */
    DS_SAP_STRIPS,  /* sweep and prune in horizontal strips: O(N) at fixed density */
    DS_AUTO,        /* the fastest for the integrator: DS_SAP or DS_SAP_STRIPS
                     * for the time step, DS_CELLS for events */
    DS_CELLS        /* the event-driven integrator's cell grid (event-driven only) */
} ds_broadphase;

/* The parameters of a simulation. A zeroed struct asks for the defaults
 * of every field that has one, but its broadphase is DS_SAP (0), which
 * serves the time step only: start from ds_default_params (DS_AUTO). */
typedef struct ds_params {
    size_t n;                 /* number of disks, >= 1 */
    double radius;            /* disk radius: < box/2 and box_y/2 (walls), /4 (periodic) */
    uint64_t seed;            /* seed of the placement and direction generator */
    double box;               /* width, in (0, 1e9]; 0 means 1000 */
    double speed;             /* initial speed, in (0, 1e9]; 0 means 100 */
    double dt;                /* the step, in (0, 1]; 0 means 0.001 */
    ds_broadphase broadphase; /* DS_AUTO in ds_default_params; see above */
    ds_integrator integrator; /* DS_TIME_STEP by default */
    ds_boundary boundary;     /* DS_WALLS by default */
    ds_placement placement;   /* DS_RANDOM by default */
    double box_y;             /* height of the box, in (0, 1e9]; 0 means box (square) */
} ds_params;

/* The least room the event-driven integrator takes, as a fraction of a
 * diameter: between a lattice's closest sites beyond contact, and for a
 * centre between the walls (box - 2R and box_y - 2R). With less, its
 * events cascade at one instant (disks in contact on every side) or
 * follow each other a rounding error apart (a disk in a band a rounding
 * error wider than itself): a step would not end. ds_check_params refuses
 * such a request with DS_ERR_PLACEMENT (the lattice) or DS_ERR_ARG (the
 * radius). */
#define DS_ROOM_TO_MOVE 1e-6

#define DS_DEFAULT_SEED 20260101u

/* n, radius, seed DS_DEFAULT_SEED, defaults for the rest, DS_AUTO,
 * DS_TIME_STEP. */
ds_params ds_default_params(size_t n, double radius);

/* Validates params without allocating: DS_ERR_ARG for impossible values,
 * DS_ERR_PLACEMENT for a packing refused up front (see DS_MANY_DISKS),
 * DS_ERR_NOMEM for an n whose arrays cannot be addressed. If warnings is
 * not NULL, it receives a bit set of DS_WARN_* flags for requests that run
 * but with degraded physics. */
ds_status ds_check_params(const ds_params *params, unsigned *warnings);

/* Why ds_check_params refuses a request, or what it warns about. */
typedef struct ds_params_error {
    /* The ds_params member at fault: "n", "radius", "box", "box_y",
     * "speed", "dt", "integrator", "boundary", "placement" or
     * "broadphase"; "" when the fault is no one field's (params NULL). */
    char field[16];
    /* One sentence that begins with the field's name and names its value,
     * e.g. "radius = 600 does not fit a box 1000 x 1000: it must be below
     * half of its shorter side (500)"; "" for DS_OK. */
    char message[256];
    /* For DS_OK with warnings: the first DS_WARN_* explained; else "". */
    char warning[256];
} ds_params_error;

/* ds_check_params, saying why: the same status and warnings, and, if err
 * is not NULL, the field at fault and a sentence for a person to read. */
ds_status ds_diagnose_params(const ds_params *params, unsigned *warnings, ds_params_error *err);

/* Bytes ds_create would allocate for params (DS_ERR_ARG / DS_ERR_NOMEM as
 * ds_check_params, DS_ERR_ARG if bytes is NULL), so a caller can refuse a
 * request before trying it. */
ds_status ds_memory_needed(const ds_params *params, size_t *bytes);

/* Random placement (DS_RANDOM) is sequential: disk i is drawn uniformly and redrawn
 * until it overlaps none of disks 0..i-1. ds_check_params (so ds_create)
 * refuses with DS_ERR_PLACEMENT, before trying, only:
 *  - more disks than can fit at all: n > (2/sqrt 3) s^2 + 2 s + 1 with
 *    s = (box - 2R) / 2R (Oler's bound; for many disks it is the hexagonal
 *    packing, area fraction pi / (2 sqrt 3) = 0.907); one disk always fits;
 *  - more than DS_MANY_DISKS disks covering more than DS_MAX_AREA_FRACTION
 *    of the box: random sequential placement of many disks jams near 0.547,
 *    and a try bound to fail costs ~0.2 ms per disk (minutes at 10^6).
 * Anything else is tried: a disk that finds no free spot in 2 million draws
 * ends ds_create with DS_ERR_PLACEMENT; up to DS_MANY_DISKS disks a try
 * that failed took 0.02 to 0.4 s when measured. A few disks can
 * go well above 0.54 (one disk of R = 499.9 covers 0.785), though the
 * denser, the more seeds fail. */
#define DS_MAX_AREA_FRACTION 0.54
#define DS_MANY_DISKS 1000

/* A head-on pair at speed speed_max can pass through each other between two
 * steps: 2 * speed_max * dt > 4 R (speed_max taken as 3x the initial speed,
 * which the Rayleigh tail exceeds with probability e^-9). */
#define DS_WARN_TUNNELING 1u

/* Creates and places the disks. On success *out owns the simulation. */
ds_status ds_create(const ds_params *params, ds_sim **out);
void ds_destroy(ds_sim *sim); /* NULL is allowed */

/* ------------------------------------------------------------------ */
/* Mixtures: disks of several radii and masses                          */
/* ------------------------------------------------------------------ */

/* One kind of disk of a mixture. */
typedef struct ds_species {
    size_t count;  /* disks of this kind */
    double radius; /* > 0 */
    double mass;   /* > 0, or 0 for the mixture's mass rule */
} ds_species;

/* The mass of a disk whose mass is not given. */
typedef enum ds_mass_rule {
    DS_MASS_EQUAL = 0, /* 1, whatever the radius: the seed's rule */
    DS_MASS_AREA       /* (r / R)^2, R the radius of ds_params: disks of R weigh 1 */
} ds_mass_rule;

/* A mixture, given as species or disk by disk (one of the two):
 * - species: kinds[0 .. species) with counts that add up to ds_params.n;
 *   disks 0 .. count_0 - 1 are of the first kind, and so on;
 * - per disk: radii[i] and, if masses is not NULL, masses[i], for every
 *   disk i < n (kinds NULL, species 0).
 * Each disk then has its own radius and mass: the pair test is the sum of
 * the two radii, a collision is elastic along the line of centres for the
 * two masses, walls turn a disk at its own radius. ds_params.radius is the
 * reference radius R of DS_MASS_AREA (and what ds_radius returns); the
 * disks' radii come from the mixture. Broad phases prune with the largest
 * diameter; ds_check_params's limits hold with every radius. Random
 * placement places the largest disks first (ties in the order of the
 * disks), each uniformly where its centre may be; the lattice puts the
 * disks on sites at least the largest diameter apart, in an order drawn
 * from the seed (not sorted by kind). A mixture of one kind of radius R
 * and mass 1 is exactly ds_create's simulation. */
typedef struct ds_mixture {
    size_t species;          /* kinds, or 0 for radii per disk */
    const ds_species *kinds; /* species entries */
    const double *radii;     /* per disk: n radii, in generation order */
    const double *masses;    /* per disk: n masses, or NULL for the rule (species: NULL) */
    ds_mass_rule mass_rule;  /* for masses not given (0 or NULL) */
} ds_mixture;

/* ds_diagnose_params, ds_memory_needed and ds_create for a mixture; a
 * NULL mixture is ds_params alone. A refusal of the mixture names the
 * field "mixture" (a count that does not add up, a radius or mass that is
 * not a positive finite number, an unknown rule, species with radii or
 * masses per disk) or a field of params. */
ds_status ds_diagnose_mixture(const ds_params *params, const ds_mixture *mixture,
                              unsigned *warnings, ds_params_error *err);
ds_status ds_memory_needed_mixture(const ds_params *params, const ds_mixture *mixture,
                                   size_t *bytes);
ds_status ds_create_mixture(const ds_params *params, const ds_mixture *mixture, ds_sim **out);

/* Disk i's radius and mass (generation order; 0 out of range), every
 * disk's at once into arrays of ds_count(sim) (either may be NULL), and
 * the largest radius. With one kind of disk: ds_radius and 1. */
double ds_radius_of(const ds_sim *sim, size_t i);
double ds_mass_of(const ds_sim *sim, size_t i);
ds_status ds_get_radii(const ds_sim *sim, double *radii, double *masses);
double ds_radius_max(const ds_sim *sim);
/* The fraction of the box the disks cover, sum of pi r^2 over box box_y. */
double ds_area_fraction(const ds_sim *sim);

/* Growth (Lubachevsky-Stillinger compression), event-driven integrator in
 * a periodic box only (DS_ERR_ARG otherwise): from now on every radius
 * grows in proportion to itself, r(t) = r(now) (1 + rate (t - now)), so
 * the ratios of a mixture stay, until the area fraction reaches
 * until_eta (0: no target), at that exact time, or the reduced pressure Z
 * (watched over windows of 2 n collisions, with the temperature of the
 * internal motion, K_int / (N - 1)) passes until_z (0 means
 * DS_JAMMED_Z; at most 1e9), whichever comes first; rate 0 stops it.
 * Past Z = 10^4 the growth slows as 10^4 / Z, so the disks can rearrange
 * near jamming (docs/physics.md). A collision reflects the pair's normal
 * velocity in the frame of their receding surfaces, which adds energy:
 * at the end of each window, and when the growth stops, every velocity is
 * scaled back to the kinetic energy of the call. The masses stay. ds_set_all stops growth; so does a
 * call with other targets, which starts again from now. DS_ERR_ARG for a
 * rate < 0 or not finite, a rate at which the largest pair's surfaces
 * would recede faster than 10 rms speeds (2 r_max rate > 10 sqrt(2 K /
 * M), M the total mass; so any rate > 0 with every disk at rest), until_eta
 * not 0 and not between the area fraction of now and 1, until_z not 0
 * and not in (1, 1e9]. The step in
 * which growth stops at Z is finished without it: near jamming that step
 * has many collisions (about 4 (Z - 1) sqrt(kT / (pi m)) / sigma per disk
 * per unit time). */
#define DS_JAMMED_Z 1e6
ds_status ds_set_growth(ds_sim *sim, double rate, double until_eta, double until_z);

typedef enum ds_growth_state {
    /* Never grown, stopped with rate 0, or stopped by ds_run at a step's
     * end for want of memory for the wider cells growth needed there
     * (the run goes on at the radii of then, every step taken, the heat
     * out; ds_run returns no status in 2.x). */
    DS_GROWTH_NONE = 0,
    DS_GROWING,            /* growing */
    DS_GROWTH_REACHED_ETA, /* stopped at until_eta */
    DS_GROWTH_JAMMED       /* stopped when Z passed until_z */
} ds_growth_state;
ds_growth_state ds_growth_state_of(const ds_sim *sim);
/* The reduced pressure Z growth measured over its last window of 2 n
 * collisions (when it jammed, the window that stopped it); 0 before its
 * first window, and for a simulation that never grew. */
double ds_growth_z(const ds_sim *sim);

/* Every velocity times factor, at ds_time: a thermostat's step, or a
 * compression taking out its heat. DS_ERR_ARG, changing nothing, for a
 * factor not > 0 and finite, or one that takes a velocity component past
 * 1e12 (ds_set's limit). */
ds_status ds_scale_velocities(ds_sim *sim, double factor);

/* The contacts of a packing at ds_time: pairs whose centres are closer
 * than (r_i + r_j) (1 + gap), gap >= 0 (a jammed packing's contacts are
 * what its pressure keeps a hair apart: at Z = 10^6 they are 1e-6 to
 * 1e-4 of their contact distance apart, and gap 1e-4 counts 4.00 per disk
 * of 1024 where 1e-3 counts 1.5% more; docs/physics.md). Rattlers, disks with fewer than 3
 * contacts (which a disk in the plane needs to be held), are removed,
 * and removed again as their removal leaves others with fewer, until
 * none is left. */
typedef struct ds_contacts {
    size_t pairs;            /* contacts between the disks that are left */
    size_t rattlers;         /* disks removed */
    double per_disk;         /* contacts per disk left, 2 pairs / (n - rattlers); 0 if none */
    double rattler_fraction; /* rattlers / n */
} ds_contacts;
/* DS_ERR_ARG for NULL or a gap not in [0, 1); DS_ERR_NOMEM. O(n). */
ds_status ds_count_contacts(const ds_sim *sim, double gap, ds_contacts *out);

/* Advances simulated time by exactly dt. DS_TIME_STEP: move by v dt,
 * reflect at walls, resolve overlapping pairs. DS_EVENT_DRIVEN: process
 * every collision and wall event inside the interval in time order, then
 * show every disk at exactly ds_time. ds_run(sim, k) is k steps. */
void ds_step(ds_sim *sim);
void ds_run(ds_sim *sim, uint64_t steps);

size_t ds_count(const ds_sim *sim);
double ds_radius(const ds_sim *sim);
double ds_box(const ds_sim *sim);   /* width */
double ds_box_y(const ds_sim *sim); /* height (box_y, or box when square) */
double ds_dt(const ds_sim *sim);
double ds_time(const ds_sim *sim);                   /* simulated time = steps * dt */
uint64_t ds_steps(const ds_sim *sim);                /* steps taken since creation */
ds_broadphase ds_broadphase_used(const ds_sim *sim); /* never DS_AUTO */
const char *ds_broadphase_name(ds_broadphase bp);    /* "sap", "cells", ... */
ds_integrator ds_integrator_used(const ds_sim *sim);
const char *ds_integrator_name(ds_integrator integrator); /* "step" or "event" */
ds_boundary ds_boundary_used(const ds_sim *sim);
const char *ds_boundary_name(ds_boundary boundary); /* "walls" or "periodic" */

/* Disk i, in generation order (i < n; out of range gives all zeros). */
ds_disk ds_get(const ds_sim *sim, size_t i);
/* Every disk at once: out[i] = ds_get(sim, i) for i < ds_count(sim), so out
 * must hold ds_count(sim) disks. DS_ERR_ARG if sim or out is NULL. */
ds_status ds_get_all(const ds_sim *sim, ds_disk *out);
/* Periodic images, in generation order as ds_get_all: image[2 i] and
 * image[2 i + 1] are how many times disk i has crossed the box along x
 * and along y since it was placed (+1 each time it leaves through the far
 * edge, -1 through 0), so that its unwrapped centre is x + image[2 i] box,
 * y + image[2 i + 1] box_y (LAMMPS' ix iy, OVITO's periodic image). image
 * holds 2 ds_count(sim) values; with walls they are all 0. ds_set keeps
 * the disk's counts, ds_set_all sets them all to 0 (a new state starts
 * in the box), checkpoints carry them. The counts wrap past 2^31
 * crossings. DS_ERR_ARG if sim or image is NULL. */
ds_status ds_get_images(const ds_sim *sim, int32_t *image);
/* Unwrapped centres, generation order: xy[2 i], xy[2 i + 1] = x + ix box,
 * y + iy box_y (ds_get_images), each one rounding of the sum from the
 * exact image sum. With walls the centres themselves. A free disk's
 * unwrapped centre is x0 + v t up to the rounding of its flight: within
 * (s + 2) eps (box + |x0 + v t|) after s steps of the time step or s events
 * of the event-driven integrator (eps = DBL_EPSILON). xy holds 2
 * ds_count(sim) values; DS_ERR_ARG if sim or xy is NULL. */
ds_status ds_get_unwrapped(const ds_sim *sim, double *xy);
/* Two centres closer than 2R (1 - DS_CONTACT_TOLERANCE) overlap; closer
 * than 2R by less is contact, up to the rounding of the coordinates. */
#define DS_CONTACT_TOLERANCE 1e-9

/* Replaces disk i. DS_ERR_ARG if i >= n, a value is not finite, a
 * velocity component exceeds 1e12 in magnitude, or the centre is outside
 * the box: [r, box - r] x [r, box_y - r] with walls, r the disk's own
 * radius (ds_radius_of: R with one kind of disk, each disk's own in a
 * mixture), [0, box) x [0, box_y) in a periodic box. The time step does
 * not check overlaps (its next step resolves them); the event-driven
 * integrator refuses a centre that overlaps another (see
 * DS_CONTACT_TOLERANCE) with DS_ERR_OVERLAP, the state unchanged: exact
 * dynamics has no meaning for overlapping hard disks. Moving many disks
 * one by one can fail where the new state is fine (a disk's new place
 * overlaps a disk not yet moved): use ds_set_all. The disk's periodic
 * image counts stay (ds_get_images). */
ds_status ds_set(ds_sim *sim, size_t i, ds_disk d);

/* Why a whole state was refused (ds_set_all, ds_load_state). */
typedef struct ds_state_error {
    char message[192]; /* one sentence, e.g. "disks 3 and 17 overlap: ..." */
} ds_state_error;

/* Replaces every disk at once: disks[i] becomes disk i, for i below
 * ds_count(sim). The whole new state is checked before anything changes:
 * DS_ERR_ARG for a disk ds_set would refuse as a value (or sim or disks
 * NULL), DS_ERR_OVERLAP if two disks overlap (see DS_CONTACT_TOLERANCE;
 * with either integrator: this is a state to start from). err, if not
 * NULL, says which disk and why. On DS_OK the integrator starts afresh
 * from the new state (the event-driven one predicts every event again);
 * the time, the step count and the observables' accumulators go on; the
 * periodic image counts start again at 0 (the new centres are in the
 * box, so ds_get_unwrapped starts from them). A growth (ds_set_growth)
 * ends: the radii stay as grown by now, ds_growth_state_of says
 * DS_GROWTH_NONE and ds_growth_z 0 (a growth that had reached its target
 * or jammed is forgotten too), and the velocities are the ones given, not
 * scaled back as the end of a growth otherwise scales them. */
ds_status ds_set_all(ds_sim *sim, const ds_disk *disks, ds_state_error *err);

/* ------------------------------------------------------------------ */
/* Checkpoints: a simulation saved and loaded to the bit               */
/* ------------------------------------------------------------------ */

/* A checkpoint holds everything the next step depends on: the parameters,
 * the time and step count, every disk's position and velocity to the bit
 * (in the order the broad phase keeps them), the observables'
 * accumulators (wall impulse and count, virial, collision and test
 * counts, the collision timer, the pressure tensor's parts of
 * ds_stress_integral) and the integrator's own state (the time step's
 * strips; the event-driven records, cells and clock). A loaded
 * simulation goes on bit for bit as the saved one would have, for both
 * integrators, both boundaries and every broad phase; its area fraction
 * is the same double.
 *
 * The format (docs/library.md): the 8 bytes "DSIMSTAT", the format
 * version (32 bits, DS_STATE_FORMAT_VERSION), a byte order mark
 * 0x01020304 (32 bits), the library version that wrote it (16 bytes of
 * text), the length of the payload (64 bits), the payload, and an FNV-1a
 * 64-bit checksum of all that precedes it. Every integer and double (by
 * its IEEE 754 bits) is little-endian whatever the machine, so a file
 * moves between machines. This library writes version 2 and reads 1 and
 * 2; version 1 lacks the stress integral's parts (a run loaded from it
 * starts ds_stress_integral at 0). */
#define DS_STATE_FORMAT_VERSION 3

/* Bytes ds_format_state writes for sim (0 for NULL). */
size_t ds_state_size(const ds_sim *sim);
/* The checkpoint into buf (cap bytes); as ds_format_frame, *len receives
 * the bytes needed either way and a cap too small is DS_ERR_ARG. */
ds_status ds_format_state(const ds_sim *sim, void *buf, size_t cap, size_t *len);
/* The checkpoint to out, flushed: DS_ERR_IO if the write fails,
 * DS_ERR_NOMEM without memory for it, DS_ERR_ARG for NULL. */
ds_status ds_save_state(const ds_sim *sim, FILE *out);
/* A simulation from a checkpoint of len bytes: on DS_OK *out owns it.
 * A truncated, corrupted, foreign or future-version checkpoint is
 * DS_ERR_FORMAT with the reason in err (if not NULL), never a crash;
 * so is one (its checksum forged) with a disk ds_set would refuse: not
 * finite, a velocity component beyond 1e12, outside the box (with
 * walls, up to what a saved run may be past the band a radius from
 * them: 1e-9 of the box, and with the time step two steps of its
 * fastest disk). DS_ERR_NOMEM without memory for it. */
ds_status ds_parse_state(const void *data, size_t len, ds_sim **out, ds_state_error *err);
/* The same from a stream, read as far as its header announces and one
 * byte more (DS_ERR_IO if reading fails). Memory grows with the bytes
 * read, so a length beyond the end of the file is DS_ERR_FORMAT
 * ("truncated"), whatever it announces. */
ds_status ds_load_state(FILE *in, ds_sim **out, ds_state_error *err);

/* The seed's timing measure, summed over all steps. DS_TIME_STEP: seconds
 * spent sorting, pruning, testing and resolving disk-disk pairs.
 * DS_EVENT_DRIVEN: seconds spent processing events (collisions, wall
 * turns, cell crossings and their predictions), not showing the disks at
 * ds_time afterwards. */
double ds_collision_seconds(const ds_sim *sim);
uint64_t ds_collision_count(const ds_sim *sim); /* disk-disk collisions resolved */
uint64_t ds_pairs_tested(const ds_sim *sim);    /* narrow-phase distance tests */

/* ------------------------------------------------------------------ */
/* Observables                                                         */
/* ------------------------------------------------------------------ */

double ds_kinetic_energy(const ds_sim *sim);                 /* sum of m v^2/2 */
void ds_momentum(const ds_sim *sim, double *px, double *py); /* sum of m v */
uint64_t ds_wall_count(const ds_sim *sim);                   /* wall reflections since reset */
/* Momentum handed to the walls since the last reset: sum of 2 m |v_n|. */
double ds_wall_impulse(const ds_sim *sim);
/* Wall impulse per unit time per unit length of wall the centres reach
 * (perimeter 2 (box - 2R) + 2 (box_y - 2R)), averaged since the last
 * reset; 0 before any step. In 2D this is a force per length, the ideal
 * gas has P A = N <m v^2>/2. In a mixture each disk's impulse is over the
 * perimeter its own centre reaches, so that the partial pressures of the
 * kinds add up. A periodic box has no walls: there it is
 * ds_virial_pressure. */
double ds_pressure(const ds_sim *sim);
/* Pressure from the collision virial, averaged since the last reset, 0
 * before any step: in 2D with unit masses (N kT = E, the kinetic energy)
 * P A = E + (1 / (2 t)) * sum over collisions of r_ij . dp_i, where r_ij
 * joins the centres (nearest image) and dp_i is disk i's change of
 * momentum. A is the area the centres reach: (box - 2R) (box_y - 2R) with
 * walls, where the virial theorem makes it equal to ds_pressure over a
 * long run, and box box_y in a periodic box. For a mixture with walls A
 * is the mean of each disk's (box - 2 r) (box_y - 2 r): the virial theorem
 * weighs each kind's area by its partial pressure, so this differs from
 * ds_pressure at second order in the radii over the box; periodic, it is
 * exact. With the time step the collisions happen a little inside 2R,
 * which biases it low (docs/physics.md). */
double ds_virial_pressure(const ds_sim *sim);
/* The temperature the collisions see (observe/observables.c derives it):
 * with walls kT = K / N; in a periodic box, where the total momentum P
 * (total mass M) is conserved, kT = K_int / (N - 1) with K_int = K - P^2
 * / (2 M) (0 for a single disk). The canonical ensemble at this kT has
 * the pressure a run measures. 0 for NULL. */
double ds_temperature(const ds_sim *sim);
/* The canonical compressibility factor Z = P A / (N kT) with kT of
 * ds_temperature, averaged since the last reset (0 before any step, 1
 * with no relative motion): 1 + W / (2 t N kT), W the collision virial
 * of ds_virial_pressure, A the area the centres reach. With walls it is
 * ds_virial_pressure A / K; periodic it is the Z of the canonical
 * ensemble at every N, which P A / K is not (high by about (Z - 1) / N).
 * Monte Carlo at the same N, A and kT gives the same Z. */
double ds_compressibility(const ds_sim *sim);
/* Zeroes the wall impulse, wall count, collision virial and pressure clock
 * (not the collision count or time), so a relaxation period can be
 * discarded. */
void ds_reset_observables(ds_sim *sim);
/* The time integral of the pressure tensor times the area since
 * ds_create (ds_reset_observables leaves it; a checkpoint carries it,
 * and one of format version 1, which did not, starts it at 0 at the
 * load), components s[0] xx, s[1] yy, s[2] xy:
 *   s_ab = int sum_i m_i v_i,a v_i,b dt + sum over collisions of
 *          (r_i - r_j)_a dp_i,b,
 * the kinetic part integrated exactly between velocity changes (with
 * the time step: over each step at the velocities it starts with), the
 * collisions' part their impulses, r_i - r_j the nearest image. Wall
 * impulses are not in it. The mean pressure tensor over a stretch is
 * the change of s over A times its duration, A the area of
 * ds_virial_pressure, whose pressure is (s_xx + s_yy) / (2 A t) since
 * creation. Its increments are the Helfand moments of the shear
 * viscosity: eta = lim <(s_xy(t0 + t) - s_xy(t0))^2> / (2 A kT t), and
 * the same with (s_xx - s_yy) / 2 (observe/observables.c says why).
 * Each ds_run sums the kinetic tensor afresh from the disks (so that
 * whatever set them between runs is in it): runs split into other
 * ds_run calls agree to rounding, the same calls to the bit.
 * DS_ERR_ARG if sim or s is NULL. */
ds_status ds_stress_integral(const ds_sim *sim, double s[3]);

/* ------------------------------------------------------------------ */
/* Transport: displacement and velocity correlations                   */
/* ------------------------------------------------------------------ */

/* An accumulator of the mean-squared displacement and the velocity
 * autocorrelation of n disks with multiple time origins, fed one sample
 * at a time (observe/transport.c):
 *   msd[k]  = < |r_i(t0 + k h) - r_i(t0)|^2 >,
 *   vacf[k] = < v_i(t0) . v_i(t0 + k h) >,
 * for lags k < lags, averaged over the n disks and every time origin t0
 * seen with lag k. h is the caller's interval between samples (the
 * accumulator never sees time: the samples must be equally spaced); every
 * origin_every-th sample, starting with the first, is an origin (1: every
 * sample; more saves work when samples are closer than the dynamics
 * decorrelates). r must be unwrapped (ds_get_unwrapped) and the disks in
 * the same order in every sample. Memory: 4 n ceil(lags / origin_every)
 * doubles; work per sample: that many multiply-adds. */
typedef struct ds_transport ds_transport; /* opaque */

/* A new accumulator into *out. DS_ERR_ARG if out is NULL, n is 0, lags is
 * below 2 or origin_every is 0; DS_ERR_NOMEM without memory for it. */
ds_status ds_transport_create(size_t n, size_t lags, size_t origin_every, ds_transport **out);
void ds_transport_destroy(ds_transport *tr); /* NULL is fine */
/* One sample: unwrapped centres xy[2 i], xy[2 i + 1] and velocities
 * v[2 i], v[2 i + 1] of disk i < n. DS_ERR_ARG (nothing added) if a
 * pointer is NULL or a value is not finite. */
ds_status ds_transport_add(ds_transport *tr, const double *xy, const double *v);
/* The sample of sim at ds_time: ds_get_unwrapped and the velocities, in
 * generation order. DS_ERR_ARG if a pointer is NULL or ds_count(sim) is
 * not the accumulator's n. */
ds_status ds_transport_sample(ds_transport *tr, const ds_sim *sim);
size_t ds_transport_lags(const ds_transport *tr); /* 0 for NULL */
/* The averages so far, each array of ds_transport_lags values (any of
 * them may be NULL): msd, vacf, and origins[k], how many origins have
 * been seen with lag k (a lag not yet reached has msd and vacf 0).
 * DS_ERR_ARG if tr is NULL. */
ds_status ds_transport_get(const ds_transport *tr, double *msd, double *vacf, uint64_t *origins);
/* The self-diffusion coefficient over the window of lags [from, to]
 * (interval h between samples), two ways that agree up to the sampling
 * noise and the O(h^2) error of the trapezoids:
 *   Einstein:    (msd[to] - msd[from]) / (4 (to - from) h), the slope of
 *                msd / 4 in two dimensions;
 *   Green-Kubo:  the mean over the window of D(t) = (1/2) int_0^t vacf,
 *                both integrals by trapezoids on the samples.
 * In two dimensions d msd / dt = 4 D(t) exactly, so the two are the same
 * average of D(t), which for a fluid of disks grows like ln t (the 1/t
 * tail of the autocorrelation, docs/physics.md): quote the window. Either
 * pointer may be NULL. DS_ERR_ARG if tr is NULL, h is not finite and
 * positive, from >= to, to >= lags, or no origin has reached lag to. */
ds_status ds_transport_diffusion(const ds_transport *tr, double interval, size_t from, size_t to,
                                 double *einstein, double *green_kubo);

/* ------------------------------------------------------------------ */
/* Order: bond-orientational order psi6                                */
/* ------------------------------------------------------------------ */

/* Per-disk bond-orientational order of the n centres (x[j], y[j]):
 *   psi6_j = (1/n_j) sum_k exp(6 i theta_jk)  ->  re[j] + i im[j],
 * over the n_j disks k whose centres are closer than cutoff to j's (a
 * coincident centre is no bond), theta_jk the angle of the bond j -> k from
 * the x axis. 0 for a disk with no neighbour. |psi6_j| = 1 for six
 * neighbours at multiples of 60 degrees; arg(psi6_j) / 6 is then the
 * lattice's orientation. The box is [0, box_x] x [0, box_y]; with
 * DS_PERIODIC separations are minimum images (centres anywhere, wrapped),
 * which is unique only if cutoff < min(box_x, box_y) / 2. O(n) with a cell
 * grid allocated inside. n = 0 is DS_OK and reads and writes nothing (the
 * pointers may then be NULL). DS_ERR_ARG if, with n > 0, a pointer is
 * NULL, or if box_x, box_y or cutoff is not finite and positive, a
 * centre is not finite, boundary is unknown, or a periodic cutoff is not
 * below half the shorter side; DS_ERR_NOMEM if the grid cannot be
 * allocated. */
ds_status ds_local_psi6(size_t n, const double *x, const double *y, double box_x, double box_y,
                        ds_boundary boundary, double cutoff, double *re, double *im);
/* Global order |(1/N) sum_j psi6_j| of the disks at ds_time, in the sim's
 * box and boundary, with cutoff 1.4 d (d = 2R: past the first shell of
 * neighbours, short of the dense liquid's first minimum of g(r), 1.55 d at
 * area fraction 0.70, and of a crystal's second shell). Near 1 for a crystal of one
 * orientation, O(1/sqrt N) for a liquid; a lattice sparser than 1.4 d has
 * no bonds and gives 0. NaN if sim is NULL, memory runs out, or a periodic
 * box is narrower than 2.8 d. */
double ds_psi6(const ds_sim *sim);

/* Pair separations for the radial distribution function g(r): counts[b]
 * (b < bins) receives the number of pairs j < k of the n centres whose
 * distance lies in [b dr, (b + 1) dr), nearest image with DS_PERIODIC
 * (then bins dr must be at most half the shorter side, as a second image
 * could be as close beyond it; centres anywhere, wrapped). With walls the
 * box only sizes the cell grid that makes this O(n) at a fixed density.
 * g(r) of bin b is counts[b] over the pairs an ideal gas of the same n in
 * the same area A would have there, n (n - 1) / 2 * pi (r1^2 - r0^2) / A
 * (tools/gr prints it). DS_ERR_ARG if a pointer is NULL (x, y with n > 0),
 * bins is 0, dr or a side is not finite and positive, a centre is not
 * finite, boundary is unknown, or a periodic range is too long;
 * DS_ERR_NOMEM if the grid cannot be allocated. */
ds_status ds_pair_histogram(size_t n, const double *x, const double *y, double box_x, double box_y,
                            ds_boundary boundary, double dr, size_t bins, uint64_t *counts);

/* ------------------------------------------------------------------ */
/* Frames: text files of lines "x y R" or "x y R vx vy"                */
/* ------------------------------------------------------------------ */

/* Writes one line per disk in generation order: x and y with 6 decimals,
 * R in the shortest form that reads back as the same double. */
ds_status ds_write_frame(const ds_sim *sim, FILE *out);
ds_status ds_write_frame_velocities(const ds_sim *sim, FILE *out);

/* Formats the frame into buf (at most cap bytes, no NUL). With cap too small
 * returns DS_ERR_ARG; *len receives the bytes needed either way, so buf NULL
 * with cap 0 asks only for the size. ds_frame_size() tells the capacity that
 * is always enough. */
size_t ds_frame_size(const ds_sim *sim, int velocities);
ds_status ds_format_frame(const ds_sim *sim, int velocities, char *buf, size_t cap, size_t *len);

/* One disk read from a frame file. vx, vy are 0 in 3-column frames. */
typedef struct ds_frame_disk {
    double x, y, r, vx, vy;
} ds_frame_disk;

typedef struct ds_frame {
    ds_frame_disk *disks; /* malloc'd, free with ds_frame_free */
    size_t count;
    int columns; /* 3 or 5 (all lines agree); 0 for an empty frame */
} ds_frame;

/* Where and why a frame failed to parse. */
typedef struct ds_frame_error {
    size_t line;      /* 1-based line number, 0 if not about a line */
    char message[96]; /* e.g. "expected 3 or 5 numbers" */
} ds_frame_error;

/* Parses a frame held in memory (need not be NUL-terminated). Every line
 * must hold 3 or 5 finite numbers, all lines the same count, R > 0.
 * Blank lines and lines starting with '#' are skipped; an empty frame is
 * DS_ERR_FORMAT. err may be NULL. On error *frame is left empty. */
ds_status ds_parse_frame(const char *text, size_t len, ds_frame *frame, ds_frame_error *err);
/* Reads and parses a file (DS_ERR_IO if it cannot be read). On error *frame
 * is left empty, as with ds_parse_frame. */
ds_status ds_read_frame(const char *path, ds_frame *frame, ds_frame_error *err);
void ds_frame_free(ds_frame *frame);

/* ------------------------------------------------------------------ */
/* Trajectories: extended XYZ, read by ASE, OVITO and VMD               */
/* ------------------------------------------------------------------ */

/* One frame of an extended XYZ trajectory; frames written one after
 * another to the same file make the trajectory. A frame is the disk count
 * on a line, the comment line
 *   Lattice="Lx 0 0 0 Ly 0 0 0 H" Properties=species:S:1:pos:R:3:radius:R:1:velo:R:3
 *   Time=T pbc="F F F"
 * with walls, or in a periodic box
 *   Lattice="Lx 0 0 0 Ly 0 0 0 H" Properties=species:S:1:pos:R:3:radius:R:1:velo:R:3:image:I:2
 *   Time=T pbc="T T F"
 * (one line; Lx and Ly the box's sides, ds_box and ds_box_y, and H twice
 * the largest radius, ds_radius_max, each in the shortest form that reads
 * back exactly; T the simulated time with 6 decimals), then one line per
 * disk in generation order,
 *   X x y 0 r vx vy 0         with walls
 *   X x y 0 r vx vy 0 ix iy   in a periodic box
 * with x, y, vx, vy written like frames (6 decimals), r the disk's own
 * radius (ds_radius_of) in the shortest form that reads back exactly, and
 * ix, iy its image counts (ds_get_images), so x + ix Lx, y + iy Ly is its
 * unwrapped centre. The 2D box is written as a cell of height H with every
 * disk at z = 0, periodic along x and y only; "X" is a dummy species. ASE
 * reads positions, cell and pbc, arrays "radius", "velo" and "image" and
 * info "Time"; OVITO maps the columns to Particle Type, Position, Radius
 * and Velocity.
 * ds_format_xyz_frame works like ds_format_frame: with cap too small it
 * returns DS_ERR_ARG, *len receives the bytes needed either way (buf NULL
 * with cap 0 asks only for the size), and ds_xyz_frame_size() is always
 * enough. ds_write_xyz_frame writes one frame to out, flushed (DS_ERR_IO if
 * the write fails). */
size_t ds_xyz_frame_size(const ds_sim *sim);
ds_status ds_format_xyz_frame(const ds_sim *sim, char *buf, size_t cap, size_t *len);
ds_status ds_write_xyz_frame(const ds_sim *sim, FILE *out);

#ifdef __cplusplus
}
#endif

#endif /* DISK_SIM_H */
