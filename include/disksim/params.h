/* SPDX-License-Identifier: MIT */
/*
 * disksim: what a simulation is asked to be. The choices (integrator,
 * boundary, placement, broad phase, mass rule), the parameters, mixtures,
 * and checking a request before creating it. Included by disk_sim.h.
 *
 * Units: lengths in box units (the box is [0, box] x [0, box_y], 1000 x
 * 1000 by default), time in simulated seconds, masses in units of the
 * mass of a disk of ds_params.radius (1 unless a mixture says otherwise),
 * energies in mass length^2 / time^2.
 */
#ifndef DISKSIM_PARAMS_H
#define DISKSIM_PARAMS_H

#include "disksim/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* The choices. Each enumeration has its default at 0, a _COUNT after  */
/* its last value, a name (what the command and Python call it;        */
/* "unknown" out of range) and a parse from that name: DS_ERR_ARG, with */
/* the known names in err, for a name that is none of them.             */
/* ------------------------------------------------------------------ */

/* How the dynamics is integrated. */
typedef enum ds_integrator {
    /* "step": the seed's fixed time step: move every disk by v dt, then
     * reflect at the walls and swap the normal velocities of
     * overlapping, approaching pairs. Fast and simple; collisions are
     * seen up to one step late. */
    DS_INTEGRATOR_TIME_STEP = 0,
    /* "event": exact event-driven dynamics: every collision at its exact
     * time, at centre distance exactly r_i + r_j, every wall turn at
     * exactly r from the wall. ds_sim_step still advances time by
     * exactly dt. */
    DS_INTEGRATOR_EVENT_DRIVEN,
    /* "chain": event-chain Monte Carlo (Bernard, Krauth and Wilson 2009):
     * straight chains along +x and +y in turn (along walls, up or down,
     * turning at the walls), each a quarter of the square root of the
     * box's area long, sample the canonical ensemble without dynamics. A
     * step of dt carries n speed dt of chain displacement in all; the
     * velocities are never changed and stand for kT = K / N; Z comes from
     * the chains' liftings (ds_sim_get_compressibility_factor). */
    DS_INTEGRATOR_EVENT_CHAIN,
    DS_INTEGRATOR_COUNT
} ds_integrator;
const char *ds_integrator_name(ds_integrator integrator); /* "step", "event", "chain" */
ds_status ds_integrator_parse(const char *name, ds_integrator *out, ds_error *err);

/* What happens at the edges of the box. */
typedef enum ds_boundary {
    /* "walls": hard walls on all four sides: a centre turns at r from each. */
    DS_BOUNDARY_WALLS = 0,
    /* "periodic": periodic in x and y: a disk leaving at one edge comes
     * back at the opposite one, and pairs interact through their nearest
     * image. Positions stay in [0, box) x [0, box_y), however far a step
     * takes a disk. Needs every radius below box/4 and box_y/4 (so a pair
     * touches through one image only). */
    DS_BOUNDARY_PERIODIC,
    /* "channel": periodic along x, walls along y (a channel, or a floor
     * for a field along -y): each axis as above. Needs every radius below
     * box/4 and below box_y/2. */
    DS_BOUNDARY_CHANNEL,
    DS_BOUNDARY_COUNT
} ds_boundary;
const char *ds_boundary_name(ds_boundary boundary); /* "walls", "periodic", "channel" */
ds_status ds_boundary_parse(const char *name, ds_boundary *out, ds_error *err);

/* Where the disks start. */
typedef enum ds_placement {
    /* "random": random sequential: the seed's, up to area fraction 0.54.
     * In a periodic box (with more than one disk) the mean velocity is
     * taken out and the speeds scaled back to the same kinetic energy,
     * n speed^2 / 2, so the centre of mass stands still, at any speed and
     * masses (if rounding leaves every disk the same velocity, as it can
     * below the smallest normal speed, 2.2e-308, they start at rest);
     * with walls the velocities are the seed's. */
    DS_PLACEMENT_RANDOM = 0,
    /* "lattice": a triangular lattice of m rows of c sites (c m >= n,
     * empty sites spread evenly), the (c, m) whose closest sites are
     * farthest apart; it fits without strain, up to close packing (area
     * fraction pi / (2 sqrt 3) = 0.9069), in a periodic box of aspect
     * box_y / box = sqrt(3) m / (2 c). ds_params_check refuses
     * (DS_ERR_PLACEMENT) a request whose best lattice would overlap, and
     * for the event-driven integrator one whose closest sites are less
     * than DS_ROOM_TO_MOVE of a diameter apart beyond contact (at close
     * packing every disk touches its neighbours, and collisions would
     * cascade without time ever advancing). In a periodic box (with more
     * than one disk) the total momentum is made zero, as for
     * DS_PLACEMENT_RANDOM. */
    DS_PLACEMENT_LATTICE,
    DS_PLACEMENT_COUNT
} ds_placement;
const char *ds_placement_name(ds_placement placement); /* "random", "lattice" */
ds_status ds_placement_parse(const char *name, ds_placement *out, ds_error *err);

/* How candidate pairs are found. In the same state every one finds the
 * same pairs; each resolves them in its own order, so the time step's
 * trajectories are the same to the bit only until a step in which a disk
 * overlaps two others, and the event-driven ones the same up to rounding
 * (docs/library.md, "What the broad phases share"). */
typedef enum ds_broadphase {
    /* "auto": the fastest for the integrator and the system: SAP or
     * strips for the time step, cells for the event-driven integrator. */
    DS_BROADPHASE_AUTO = 0,
    DS_BROADPHASE_SAP,    /* "sap": sweep and prune along x, insertion sort (the seed's) */
    DS_BROADPHASE_STRIPS, /* "strips": sweep and prune in horizontal strips: O(N) at fixed density
                           */
    DS_BROADPHASE_CELLS,  /* "cells": the event-driven or event-chain integrator's cell grid */
    DS_BROADPHASE_BRUTE,  /* "brute": all pairs, O(N^2): the reference (every integrator) */
    DS_BROADPHASE_COUNT
} ds_broadphase;
const char *ds_broadphase_name(ds_broadphase broadphase); /* "auto", "sap", ... */
ds_status ds_broadphase_parse(const char *name, ds_broadphase *out, ds_error *err);

/* The mass of a disk of a mixture whose mass is not given. */
typedef enum ds_mass_rule {
    DS_MASS_EQUAL = 0, /* "equal": 1, whatever the radius: the seed's rule */
    DS_MASS_AREA,      /* "area": (r / R)^2, R the radius of ds_params: disks of R weigh 1 */
    DS_MASS_RULE_COUNT
} ds_mass_rule;
const char *ds_mass_rule_name(ds_mass_rule rule); /* "equal", "area" */
ds_status ds_mass_rule_parse(const char *name, ds_mass_rule *out, ds_error *err);

/* ------------------------------------------------------------------ */
/* Parameters                                                          */
/* ------------------------------------------------------------------ */

/* The parameters of a simulation. Every field but n and radius has a
 * default, which a zero asks for: a zeroed struct with n and radius set
 * is a valid request (seed 0 is a seed like any other; ds_params_default
 * gives DS_DEFAULT_SEED). */
typedef struct ds_params {
    size_t n;                 /* number of disks, >= 1 */
    double radius;            /* disk radius: < box/2 and box_y/2 (walls), /4 (periodic) */
    uint64_t seed;            /* seed of the placement and direction generator */
    double box;               /* width, in (0, 1e9]; 0 means 1000 */
    double box_y;             /* height, in (0, 1e9]; 0 means box (square) */
    double speed;             /* initial speed, in (0, 1e9]; 0 means 100 */
    double dt;                /* the step, in (0, 1]; 0 means 0.001 */
    ds_integrator integrator; /* 0: DS_INTEGRATOR_TIME_STEP */
    ds_boundary boundary;     /* 0: DS_BOUNDARY_WALLS */
    ds_placement placement;   /* 0: DS_PLACEMENT_RANDOM */
    ds_broadphase broadphase; /* 0: DS_BROADPHASE_AUTO */
} ds_params;

#define DS_DEFAULT_SEED 20260101u

/* n and radius given, seed DS_DEFAULT_SEED, every other field 0 (its
 * default). */
ds_params ds_params_default(size_t n, double radius);

/* The least room the event-driven integrator takes, as a fraction of a
 * diameter: between a lattice's closest sites beyond contact, and for a
 * centre between the walls (box - 2R and box_y - 2R). With less, its
 * events cascade at one instant (disks in contact on every side) or
 * follow each other a rounding error apart (a disk in a band a rounding
 * error wider than itself): a step would not end. ds_params_check
 * refuses such a request with DS_ERR_PLACEMENT (the lattice) or
 * DS_ERR_ARG (the radius). */
#define DS_ROOM_TO_MOVE 1e-6

/* Random placement (DS_PLACEMENT_RANDOM) is sequential: disk i is drawn
 * uniformly and redrawn until it overlaps none of disks 0..i-1.
 * ds_params_check (so ds_sim_create) refuses with DS_ERR_PLACEMENT,
 * before trying, only:
 *  - more disks than can fit at all: n > (2/sqrt 3) s^2 + 2 s + 1 with
 *    s = (box - 2R) / 2R (Oler's bound; for many disks it is the
 *    hexagonal packing, area fraction pi / (2 sqrt 3) = 0.907); one disk
 *    always fits;
 *  - more than DS_MANY_DISKS disks covering more than
 *    DS_MAX_AREA_FRACTION of the box: random sequential placement of many
 *    disks jams near 0.547, and a try bound to fail costs ~0.2 ms per
 *    disk (minutes at 10^6).
 * Anything else is tried: a disk that finds no free spot in 2 million
 * draws ends ds_sim_create with DS_ERR_PLACEMENT; up to DS_MANY_DISKS
 * disks a try that failed took 0.02 to 0.4 s when measured. A few disks
 * can go well above 0.54 (one disk of R = 499.9 covers 0.785), though the
 * denser, the more seeds fail. */
#define DS_MAX_AREA_FRACTION 0.54
#define DS_MANY_DISKS 1000

/* The warnings of ds_params_check, bits of *warnings. A head-on pair at
 * speed speed_max can pass through each other between two steps:
 * 2 speed_max dt > 4 r_min (speed_max taken as 3x the initial speed,
 * which the Rayleigh tail exceeds with probability e^-9). */
#define DS_WARN_TUNNELING 1u

/* ------------------------------------------------------------------ */
/* Mixtures: disks of several radii and masses                          */
/* ------------------------------------------------------------------ */

/* One kind of disk of a mixture. */
typedef struct ds_species {
    size_t count;  /* disks of this kind */
    double radius; /* > 0 */
    double mass;   /* > 0, or 0 for the mixture's mass rule */
    /* Its name in output files (GSD's type names): 1 to DS_KIND_NAME_MAX
     * - 1 printable characters, no space, each species its own; NULL for
     * "A", "B", ... in order ("K26", "K27", ... past "Z"). */
    const char *name;
} ds_species;

#define DS_KIND_NAME_MAX 16

/* A mixture, given as species or disk by disk (one of the two):
 * - species: kinds[0 .. species) with counts that add up to ds_params.n;
 *   disks 0 .. count_0 - 1 are of the first kind, and so on; each disk
 *   knows its kind (ds_sim_get_kinds), which checkpoints carry;
 * - per disk: radii[i] and, if masses is not NULL, masses[i], for every
 *   disk i < n (kinds NULL, species 0); every disk is of one kind, "A".
 * Each disk then has its own radius and mass: the pair test is the sum of
 * the two radii, a collision is elastic along the line of centres for the
 * two masses, walls turn a disk at its own radius. ds_params.radius is the
 * reference radius R of DS_MASS_AREA (and what ds_sim_get_radius
 * returns); the disks' radii come from the mixture. Broad phases prune
 * with the largest diameter; ds_params_check's limits hold with every
 * radius. Random placement places the largest disks first (ties in the
 * order of the disks), each uniformly where its centre may be; the
 * lattice puts the disks on sites at least the largest diameter apart, in
 * an order drawn from the seed (not sorted by kind). A mixture of one kind
 * of radius R and mass 1 is exactly the simulation without one. */
typedef struct ds_mixture {
    size_t species;          /* kinds, or 0 for radii per disk */
    const ds_species *kinds; /* species entries */
    const double *radii;     /* per disk: n radii, in generation order */
    const double *masses;    /* per disk: n masses, or NULL for the rule (species: NULL) */
    ds_mass_rule mass_rule;  /* for masses not given (0 or NULL) */
} ds_mixture;

/* ------------------------------------------------------------------ */
/* Checking a request                                                  */
/* ------------------------------------------------------------------ */

/* Validates params (and mixture, which may be NULL: disks of one kind)
 * without allocating: DS_ERR_ARG for impossible values, DS_ERR_PLACEMENT
 * for a packing refused up front (see DS_MANY_DISKS), DS_ERR_NOMEM for an
 * n whose arrays cannot be addressed; err names the field at fault, its
 * value and the limit it broke, with a sentence. If warnings is not NULL,
 * it receives a bit set of DS_WARN_* for requests that run with degraded
 * physics (err->warning explains the first). A refusal of the mixture
 * names the field "mixture" (a count that does not add up, a radius or
 * mass that is not a positive finite number, an unknown rule, species
 * with radii or masses per disk) or a field of params. */
ds_status ds_params_check(const ds_params *params, const ds_mixture *mixture, unsigned *warnings,
                          ds_error *err);

/* Bytes ds_sim_create would allocate for the request (whose checks must
 * pass but for the packing, DS_ERR_PLACEMENT, where memory is still a
 * meaningful answer; DS_ERR_ARG if bytes is NULL), so a caller can refuse
 * a request before trying it. */
ds_status ds_params_memory(const ds_params *params, const ds_mixture *mixture, size_t *bytes,
                           ds_error *err);

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_PARAMS_H */
