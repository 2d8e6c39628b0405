/* SPDX-License-Identifier: MIT */
/* The public API of a simulation over the parts (sim.c: creating and
 * running; params.c: the request; disks.c: getting and setting the
 * disks; protocols.c: growth; checkpoint.c: saving and loading), and the
 * lists of integrators and writers (tables.c). Not installed. */
#ifndef DS_SIM_H
#define DS_SIM_H

#include "core/core.h"

/* The table of an integrator, NULL if it is not one (tables.c). */
const ds_integrator_ops *ds_integrator_ops_of(ds_integrator integrator);
/* The protocols' tables by ds_protocol_kind (a checkpoint's loader). */
extern const ds_protocol_ops *const ds_protocol_table[DS_PROTOCOL_KIND_COUNT];

/* The kinds of disk (kinds.c): a mixture's species names checked (each
 * printable, none twice); made for a new simulation (mixture may be
 * NULL: one kind), their column filled; a checkpoint's part. */
ds_status ds_kinds_check(const ds_mixture *m, ds_error *err);
ds_status ds_kinds_make(ds_sim *sim, const ds_mixture *m);
void ds_kinds_save(const ds_sim *sim, ds_state_writer *w);
ds_status ds_kinds_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_error *err);

/* metadata.c: the caller's text in a checkpoint (format 3: a length and
 * the bytes, after the protocols; earlier formats had none). */
void ds_metadata_save(const ds_sim *sim, ds_state_writer *w);
ds_status ds_metadata_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_error *err);

/* The world params describe, defaults resolved (broadphase as given,
 * maybe DS_BROADPHASE_AUTO). No checks. */
ds_world ds_world_of(const ds_params *params);
/* The world of a request, mixture and all (mixture may be NULL), after
 * every check of ds_params_check, which fills err: its status. */
ds_status ds_world_of_request(const ds_params *params, const ds_mixture *mixture, ds_world *world,
                              ds_error *err);
/* Disk i's radius and mass in a (checked) mixture; reference_radius is
 * ds_params.radius, the R of DS_MASS_AREA. */
double ds_mixture_radius(const ds_mixture *m, size_t i);
double ds_mixture_mass(const ds_mixture *m, double reference_radius, size_t i);

/* DS_OK, or DS_ERR_ARG and why disk i (radius radius) cannot be d in
 * world w (not finite, too fast, outside the box; field "disk", index
 * i): what ds_sim_set_disk and ds_sim_set_disks refuse as a value (past
 * 0), and a checkpoint's loader, which lets a centre be past the walls'
 * band by past (a saved state's rounding, and the time step's turn after
 * the move). disks.c. */
ds_status ds_check_disk(const ds_world *w, size_t i, double radius, double past, ds_disk d,
                        ds_error *err);

#endif
