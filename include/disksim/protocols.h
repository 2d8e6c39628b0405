/* SPDX-License-Identifier: MIT */
/*
 * disksim: protocols, what acts on a running simulation from outside its
 * dynamics: growth (Lubachevsky-Stillinger compression) and driving
 * (white-noise kicks). Each is set on a
 * simulation, acts as ds_sim_run goes, and is carried by checkpoints.
 * Included by disk_sim.h.
 */
#ifndef DISKSIM_PROTOCOLS_H
#define DISKSIM_PROTOCOLS_H

#include "disksim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* Growth                                                              */
/* ------------------------------------------------------------------ */

/* Growth (Lubachevsky-Stillinger compression), event-driven integrator in
 * a periodic box only (DS_ERR_ARG otherwise, err naming "integrator" or
 * "boundary"): from now on every radius grows in proportion to itself,
 * r(t) = r(now) (1 + rate (t - now)), so the ratios of a mixture stay,
 * until the area fraction reaches until_eta (0: no target), at that exact
 * time, or the reduced pressure Z (watched over windows of 2 n
 * collisions, with the temperature of the internal motion, K_int / (N -
 * 1)) passes until_z (0 means DS_JAMMED_Z; at most 1e9), whichever comes
 * first; rate 0 stops it. Past Z = 10^4 the growth slows as 10^4 / Z, so
 * the disks can rearrange near jamming (docs/physics.md). A collision
 * reflects the pair's normal velocity in the frame of their receding
 * surfaces, which adds energy: at the end of each window, and when the
 * growth stops, every velocity is scaled back to the kinetic energy of the
 * call. The masses stay. ds_sim_set_disks stops growth; so does a call
 * with other targets, which starts again from now.
 *
 * DS_ERR_ARG for a rate < 0 or not finite, a rate at which the largest
 * pair's surfaces would recede faster than 10 rms speeds (2 r_max rate >
 * 10 sqrt(2 K / M), M the total mass; so any rate > 0 with every disk at
 * rest), until_eta not 0 and not between the area fraction of now and 1,
 * until_z not 0 and not in (1, 1e9]; err names the argument ("rate",
 * "until_eta", "until_z"), its value and the limit it broke. The step in
 * which growth stops at Z is finished without it: near jamming that step
 * has many collisions (about 4 (Z - 1) sqrt(kT / (pi m)) / sigma per disk
 * per unit time). DS_ERR_NOMEM, nothing changed, without memory for the
 * growing radii. */
#define DS_JAMMED_Z 1e6
ds_status ds_sim_set_growth(ds_sim *sim, double rate, double until_eta, double until_z,
                            ds_error *err);

typedef enum ds_growth_state {
    /* "none": never grown, stopped with rate 0, ended by ds_sim_set_disks,
     * or stopped at a step's end for want of memory for the wider cells
     * it needed there (ds_sim_run then returns DS_ERR_NOMEM, see there). */
    DS_GROWTH_NONE = 0,
    DS_GROWTH_GROWING,     /* "growing" */
    DS_GROWTH_REACHED_ETA, /* "reached_eta": stopped at until_eta */
    DS_GROWTH_JAMMED,      /* "jammed": stopped when Z passed until_z */
    DS_GROWTH_STATE_COUNT
} ds_growth_state;
const char *ds_growth_state_name(ds_growth_state state); /* "none", "growing", ... */
ds_status ds_growth_state_parse(const char *name, ds_growth_state *out, ds_error *err);

ds_growth_state ds_sim_get_growth_state(const ds_sim *sim);
/* The reduced pressure Z growth measured over its last window of 2 n
 * collisions (when it jammed, the window that stopped it); 0 before its
 * first window, and for a simulation that never grew. */
double ds_sim_get_growth_z(const ds_sim *sim);

/* ------------------------------------------------------------------ */
/* Driving                                                             */
/* ------------------------------------------------------------------ */

/* White-noise driving (random kicks; van Noije and Ernst 1998), which
 * holds a granular gas (ds_sim_set_restitution) in a steady state: from
 * now on, at the end of every step, each velocity component of every
 * disk changes by a Gaussian number of variance strength dt, the kicks'
 * mass-weighted mean taken out so that the total momentum stays. The
 * velocities diffuse at S = strength (box units^2 per time^3), and energy
 * goes in at sum over the disks of m_i S (1 - m_i / M) per unit time, (N
 * - 1) m S for N equal masses (ds_sim_get_power_input). The kicks are the
 * noise integrated over a step (Euler-Maruyama): dt must be short beside
 * the mean free time for them to be white noise (docs/physics.md). Both
 * integrators. The numbers come from a stream of the simulation's seed
 * of the drive's own (no number of the placement's), drawn in generation
 * order; checkpoints carry the stream, so a loaded run kicks as the saved
 * one would have; set again, the strength changes and the stream goes
 * on. 0 stops the drive.
 *
 * DS_ERR_ARG (field "strength", value and limit) for a strength < 0, not
 * finite or above DS_DRIVE_MAX, or while a growth grows (err naming
 * "growth": growth takes out the heat its collisions add, and would take
 * the drive's); DS_ERR_NOMEM, nothing changed, without memory for the
 * kicks (16 bytes a disk twice). */
#define DS_DRIVE_MAX 1e24
ds_status ds_sim_set_drive(ds_sim *sim, double strength, ds_error *err);
double ds_sim_get_drive(const ds_sim *sim); /* the strength; 0 without a drive or for NULL */

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_PROTOCOLS_H */
