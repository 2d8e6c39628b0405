/* SPDX-License-Identifier: MIT */
/* Protocols: what acts on a running simulation from outside its dynamics
 * (growth, driving, a thermostat, a barostat). Each fills one
 * table of hooks; the integrators call the hooks through the inline
 * helpers below and hold no protocol's code. A protocol works in the
 * integrator's time (the time the integrator hands it), and changes the
 * state only through the integrator's services (core.h).
 *
 * The simulation has one slot per kind of protocol; an installed one
 * stays (stopped, it still answers what it did, and checkpoints carry
 * it) until ds_protocols_remove. Not installed. */
#ifndef DS_PROTOCOL_H
#define DS_PROTOCOL_H

#include <stdint.h>

#include "core/state_io.h"
#include "disk_sim.h"


/* The kinds, one slot each; a new protocol is one enumerator here and
 * one line in sim/tables.c. The hooks are called in this order: a drive's
 * kicks, then a heat bath's step's end, then a barostat's move (a
 * shear's moments are its images passing cell edges, between events).
 * Checkpoints name a protocol by its number here: a new one goes last. */
typedef enum ds_protocol_kind {
    DS_PROTOCOL_GROWTH = 0,
    DS_PROTOCOL_DRIVE,
    DS_PROTOCOL_THERMOSTAT,
    DS_PROTOCOL_BAROSTAT,
    DS_PROTOCOL_SHEAR,
    DS_PROTOCOL_KIND_COUNT
} ds_protocol_kind;

/* A collision as a protocol that watches them sees it: the pair (their
 * integrator records), its time, and the kinetic energy it added (0 for
 * an elastic collision in a fixed frame). */
typedef struct ds_collision {
    uint32_t a, b;
    double t, energy;
} ds_collision;

/* Where a protocol stands, as the run loops read it. */
typedef struct ds_protocol_clock {
    /* Its next own moment in integrator time (a target reached, a
     * redraw), or +infinity. */
    double next;
    /* Nonzero: it wants to act before the next event of this step,
     * whatever its time (growth's window, once full). */
    int asap;
    /* Nonzero: it wants every collision (ds_protocol_ops.collided). */
    int watching;
    /* Nonzero: it wants the end of every step (ds_protocol_ops.step_end). */
    int stepping;
} ds_protocol_clock;

typedef struct ds_protocol_ops {
    const char *name;
    ds_protocol_kind kind;
    /* Everything due before the event at integrator time t of the step
     * that ends at end (its own next moment no later than both, or, if
     * it asked, anything at t < end): it acts and updates its clock. */
    void (*fire)(ds_sim *sim, void *self, double t, double end);
    void (*collided)(ds_sim *sim, void *self, const ds_collision *c);
    /* After each whole step, at its end: a status, DS_OK to go on. */
    ds_status (*step_end)(ds_sim *sim, void *self);
    /* The integrator moved its origin: every time it keeps less by (its
     * clock's next is moved for it, with or without this hook). */
    void (*rebased)(void *self, double by);
    /* The integrator built its state again (the same disks, the present
     * time its new origin). */
    void (*rebuilt)(ds_sim *sim, void *self);
    /* A disk was set (all: every disk, a new state), or every velocity
     * scaled by factor (1 when not a scaling). */
    void (*disks_set)(ds_sim *sim, void *self, int all);
    void (*scaled)(ds_sim *sim, void *self, double factor);
    /* Its part of a checkpoint, and reading it back into a fresh state
     * (self allocated by load, which destroy frees). */
    void (*save)(const ds_sim *sim, const void *self, ds_state_writer *w);
    ds_status (*load)(ds_sim *sim, void **self, ds_reader *r, ds_error *err);
    void (*destroy)(void *self);
    /* The temperature it holds the run at (a heat bath's kT), or 0: the
     * observables take it for the run's (observe/observables.c). */
    double (*temperature)(const void *self);
} ds_protocol_ops;

typedef struct ds_protocol_slot {
    const ds_protocol_ops *ops; /* NULL: none installed */
    void *self;
    ds_protocol_clock clock;
} ds_protocol_slot;

typedef struct ds_protocols {
    ds_protocol_slot slot[DS_PROTOCOL_KIND_COUNT];
    /* The slots' clocks combined: the earliest next, whether any asks to
     * act as soon as possible, watches collisions or steps' ends. */
    double next;
    int asap, watching, stepping;
} ds_protocols;

/* What a 2.x checkpoint (format versions 1 and 2) kept in an
 * integrator's part that 3.0 keeps in a protocol's: the event-driven
 * integrator's loader fills it from such a file, and the checkpoint's
 * loader hands it to the protocol (growth.c). */
typedef struct ds_growth_record {
    double asked, stop_time, until_eta, until_z;
    double kinetic, kinetic_target, momentum_energy;
    uint64_t window;
    double window_start, window_virial;
    int stopped, growing;
    double last_z;
} ds_growth_record;

typedef struct ds_legacy {
    int has_growth;
    ds_growth_record growth;
} ds_legacy;

/* Whether a protocol is due before the event at t of the step ending at
 * end: the one test a run loop makes per event. */
static inline int ds_protocols_due(const ds_protocols *p, double t, double end)
{
    return (p->next <= t && p->next <= end) || (p->asap && t < end);
}

/* The hooks, for the integrators (protocol.c). Each calls the hook of
 * every installed protocol that has it, in slot order, and combines their
 * clocks again. */
void ds_protocols_fire(ds_sim *sim, double t, double end);
void ds_protocols_collided(ds_sim *sim, const ds_collision *c);
/* A step's end that fails (DS_ERR_NOMEM) stops there, err naming the
 * protocol and the step. */
ds_status ds_protocols_step_end(ds_sim *sim, ds_error *err);
void ds_protocols_rebased(ds_sim *sim, double by);
void ds_protocols_rebuilt(ds_sim *sim);
void ds_protocols_disks_set(ds_sim *sim, int all);
void ds_protocols_scaled(ds_sim *sim, double factor);

/* The kT a heat bath holds the run at (the first installed protocol
 * that says one), or 0. */
double ds_protocols_temperature(const ds_sim *sim);

/* Installing and removing (protocol.c): install puts self in the kind's
 * slot, destroying what was there; the clocks are combined again. */
void ds_protocols_install(ds_sim *sim, const ds_protocol_ops *ops, void *self);
void ds_protocols_remove(ds_sim *sim, ds_protocol_kind kind);
void ds_protocols_destroy_all(ds_protocols *p);
/* The clocks combined again after a protocol changed its own. */
void ds_protocols_refresh(ds_protocols *p);
/* The state of an installed protocol of that kind, or NULL; its clock,
 * which the protocol sets as its moments change. */
void *ds_protocols_get(const ds_sim *sim, ds_protocol_kind kind);
ds_protocol_clock *ds_protocols_clock(ds_sim *sim, ds_protocol_kind kind);

/* A checkpoint's protocols: their count, then each one's kind and part.
 * Load reads them into sim (every slot empty before), their tables from
 * table[kind] (sim/tables.c's list). */
void ds_protocols_save(const ds_sim *sim, ds_state_writer *w);
ds_status ds_protocols_load(ds_sim *sim, const ds_protocol_ops *const *table, ds_reader *r,
                            ds_error *err);

#endif
