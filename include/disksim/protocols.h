/* SPDX-License-Identifier: MIT */
/*
 * disksim: protocols, what acts on a running simulation from outside its
 * dynamics: growth (Lubachevsky-Stillinger compression). Each is set on a
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

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_PROTOCOLS_H */
