/* SPDX-License-Identifier: MIT */
/* The simulation's public API (sim.c, params.c, state.c) over the parts,
 * and the list of integrators (integrators.c). Not installed. */
#ifndef DS_SIM_H
#define DS_SIM_H

#include "core/core.h"

/* The table of an integrator, NULL if it is not one. */
const ds_integrator_ops *ds_integrator_ops_of(ds_integrator integrator);

/* The world params describe, defaults resolved (broadphase as given,
 * maybe DS_AUTO). No checks. */
ds_world ds_world_of(const ds_params *params);

/* DS_OK, or why disk i cannot be d in world w (not finite, too fast,
 * outside the box): what ds_set and ds_set_all refuse as a value. */
ds_status ds_check_disk(const ds_world *w, size_t i, ds_disk d, ds_state_error *err);

#endif
