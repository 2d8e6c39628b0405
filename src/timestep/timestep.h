/* SPDX-License-Identifier: MIT */
/* The time step integrator (DS_INTEGRATOR_TIME_STEP), the seed's: each step moves
 * every disk by v dt, turns those past a wall or wraps them in a periodic
 * box (free_flight.c), then the broad phase (broad_phase.h) finds the
 * overlapping pairs and the approaching ones exchange their normal
 * velocities. Not installed. */
#ifndef DS_TIMESTEP_H
#define DS_TIMESTEP_H

#include "core/core.h"

extern const ds_integrator_ops ds_time_step_ops;

/* Free flight for one step of dt (free_flight.c): along an axis with
 * walls a disk outside its band and moving further out turns, its
 * impulse tallied (with the wall restitution, or a field, it is mirrored
 * back into the band too); along a periodic axis it wraps, its crossings
 * counted. */
void ds_move(ds_disks *d, const ds_world *w, ds_tally *t);
/* A field's share of one step (free_flight.c): every velocity plus g dt
 * at once, and the stress tally's kinetic tensor summed again at them
 * (the time step changes it in one go, where the event-driven
 * integrator's disks fall continuously). */
void ds_fall(ds_disks *d, const ds_world *w, ds_tally *t);

#endif
