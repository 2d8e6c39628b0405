/* SPDX-License-Identifier: MIT */
/* The simulation's public API (sim.c, params.c, state.c) over the parts,
 * and the list of integrators (integrators.c). Not installed. */
#ifndef DS_SIM_H
#define DS_SIM_H

#include "core/core.h"

/* The table of an integrator, NULL if it is not one. */
const ds_integrator_ops *ds_integrator_ops_of(ds_integrator integrator);
/* The protocols' tables by ds_protocol_kind (a checkpoint's loader). */
extern const ds_protocol_ops *const ds_protocol_table[DS_PROTOCOL_KIND_COUNT];

/* The world params describe, defaults resolved (broadphase as given,
 * maybe DS_AUTO). No checks. */
ds_world ds_world_of(const ds_params *params);
/* The world of a request, mixture and all (mixture may be NULL), after
 * every check of ds_diagnose_mixture: its status. */
ds_status ds_world_of_request(const ds_params *params, const ds_mixture *mixture, ds_world *world);
/* Disk i's radius and mass in a (checked) mixture; reference_radius is
 * ds_params.radius, the R of DS_MASS_AREA. */
double ds_mixture_radius(const ds_mixture *m, size_t i);
double ds_mixture_mass(const ds_mixture *m, double reference_radius, size_t i);

/* The fastest velocity component a disk may have (ds_set, ds_set_all,
 * ds_scale_velocities). */
#define DS_VELOCITY_MAX 1e12

/* DS_OK, or DS_ERR_ARG and why disk i (radius radius) cannot be d in
 * world w (not finite, too fast, outside the box): what ds_set and
 * ds_set_all refuse as a value (past 0), and a checkpoint's loader, which
 * lets a centre be past the walls' band by past (a saved state's
 * rounding, and the time step's turn after the move). */
ds_status ds_check_disk(const ds_world *w, size_t i, double radius, double past, ds_disk d,
                        ds_state_error *err);

#endif
