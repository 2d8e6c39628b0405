/* SPDX-License-Identifier: MIT */
/*
 * disksim: the library's version, statuses and error details, random
 * numbers and the timer. Included by disk_sim.h.
 */
#ifndef DISKSIM_BASE_H
#define DISKSIM_BASE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define DS_VERSION_MAJOR 3
#define DS_VERSION_MINOR 0
#define DS_VERSION_PATCH 0
#define DS_VERSION_STRING "3.0.0"

/* Library version as "MAJOR.MINOR.PATCH" (DS_VERSION_STRING of the
 * library that runs, which may be newer than the header's). */
const char *ds_version(void);

/* ------------------------------------------------------------------ */
/* Statuses and error details                                          */
/* ------------------------------------------------------------------ */

typedef enum ds_status {
    DS_OK = 0,
    DS_ERR_ARG,       /* an argument is out of range, NULL, or not for this simulation */
    DS_ERR_NOMEM,     /* an allocation failed or would not fit in memory */
    DS_ERR_PLACEMENT, /* the disks cannot be placed (see DS_PLACEMENT_RANDOM, _LATTICE) */
    DS_ERR_IO,        /* a read or write failed */
    DS_ERR_FORMAT,    /* a file or text is malformed: a frame, a checkpoint */
    DS_ERR_OVERLAP,   /* the disks would overlap (ds_sim_set_disk, ds_sim_set_disks) */
    DS_STATUS_COUNT
} ds_status;

/* A static English description of a status ("invalid argument"); never
 * NULL ("unknown status" out of range). */
const char *ds_status_name(ds_status status);

/* Why a call failed. Every function that can fail takes a last argument
 * ds_error *err, which may be NULL; on failure it is filled, on success
 * its status is DS_OK and its message empty (a warning may be set, see
 * ds_params_check). The front ends print message and map field to their
 * own names for things; they need not derive the library's rules. */
typedef struct ds_error {
    ds_status status; /* what the call returned */
    /* What is at fault, as the library names it: a ds_params member
     * ("n", "radius", "box", "box_y", "speed", "dt", "integrator",
     * "boundary", "placement", "broadphase", "seed"), "mixture", a
     * "mass_rule" or "format" to parse, an argument ("rate",
     * "until_eta", "until_z", "factor", "gap", "disk", "disks", "steps",
     * "sim", "out", ... as the header names it), "checkpoint", "frame",
     * "state", or "" when none applies. */
    char field[32];
    /* The value refused and the limit it broke, where they are numbers;
     * NaN otherwise. */
    double value, limit;
    /* The disk at fault (generation order) for "disk", "disks" and
     * "state", the 1-based line for "frame" (0 if not about a line); 0
     * otherwise. */
    size_t index;
    /* One sentence naming the value, e.g. "radius = 600 does not fit a
     * box of 1000 x 1000: it must be below half of its shorter side
     * (500)": a refusal of a request or of an argument begins with the
     * field ("radius = ...", "rate = ...", "mixture: ...", "disk 3 ...");
     * a frame's is the reason alone ("expected 3 or 5 numbers"), a
     * checkpoint's what is wrong with it ("the checksum does not match:
     * the file is corrupted"). "" on success. */
    char message[256];
    /* A call that succeeded with a warning (ds_params_check): the first
     * warning as a sentence; "" otherwise. */
    char warning[256];
} ds_error;

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
double ds_timer_now(void);
void ds_timer_reset(ds_timer *timer);
void ds_timer_start(ds_timer *timer);
void ds_timer_stop(ds_timer *timer);
/* Accumulated seconds, including the running interval if started. */
double ds_timer_seconds(const ds_timer *timer);

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_BASE_H */
