/* SPDX-License-Identifier: MIT */
/* Protocols (protocols/): what acts on a running simulation from outside
 * its dynamics, each a table of hooks (core/protocol.h) and a setter the
 * public API calls. growth.c: the Lubachevsky-Stillinger compression;
 * drive.c: white-noise driving; thermostat.c: a heat bath (Andersen's,
 * isokinetic); barostat.c: Monte Carlo moves of the box at a pressure;
 * shear.c: Lees-Edwards boundaries.
 * Not installed. */
#ifndef DS_PROTOCOLS_H
#define DS_PROTOCOLS_H

#include "core/core.h"

extern const ds_protocol_ops ds_growth_ops;
extern const ds_protocol_ops ds_drive_ops;

/* Growth at rate (relative to the radii of now) until the area fraction
 * reaches until_eta (0: no target) or Z passes until_z (> 1), checked by
 * the caller; rate 0 stops a growth. DS_ERR_ARG for an integrator
 * without growing radii or a box that is not periodic, DS_ERR_NOMEM with
 * nothing changed. */
ds_status ds_growth_start(ds_sim *sim, double rate, double until_eta, double until_z);
/* Where growth stands (a ds_growth_state) and the Z of its last window
 * (0 before the first, and without a growth). */
int ds_growth_state_get(const ds_sim *sim, double *z);

/* A 2.x checkpoint's growth (core/protocol.h): the protocol's part as it
 * was, installed. */
ds_status ds_growth_adopt(ds_sim *sim, const ds_growth_record *r);

/* White-noise driving of strength S (checked by the caller: >= 0 and at
 * most DS_DRIVE_MAX; 0 stops it), installed with its stream from the
 * simulation's seed or, already there, going on with its stream:
 * DS_ERR_NOMEM with nothing changed. The strength installed (0 for none). */
ds_status ds_drive_start(ds_sim *sim, double strength);
double ds_drive_strength(const ds_sim *sim);
extern const ds_protocol_ops ds_thermostat_ops;
extern const ds_protocol_ops ds_barostat_ops;

/* A heat bath of kind (not DS_THERMOSTAT_NONE) at kt, Andersen's at rate
 * collisions per disk per unit time, from now on, checked by the caller
 * (sim/protocols.c): set again, it keeps its stream. DS_ERR_NOMEM with
 * nothing changed. */
ds_status ds_thermostat_start(ds_sim *sim, ds_thermostat kind, double kt, double rate);
/* The kind installed (DS_THERMOSTAT_NONE without) and its kT (0). */
ds_thermostat ds_thermostat_get(const ds_sim *sim, double *kt);

/* Moves of the box at reduced pressure beta P sigma^2, at the end of
 * every `every`-th step, of ln A (and with aspect of the aspect) by up to
 * max_step, checked by the caller: set again, it keeps its stream and
 * counts its acceptance afresh. DS_ERR_NOMEM with nothing changed. */
ds_status ds_barostat_start(ds_sim *sim, double pressure, uint64_t every, double max_step,
                            int aspect);
/* The pressure set (0 without a barostat) and the fraction of the area
 * moves accepted since (0 before the first). */
double ds_barostat_get(const ds_sim *sim, double *acceptance);

extern const ds_protocol_ops ds_shear_ops;

/* Lees-Edwards boundaries at rate (dv_x / dy, checked by the caller) from
 * now on, set again: the images go on from where they stand at the new
 * speed, and the disks take the change of the profile. DS_ERR_NOMEM with
 * nothing changed. The rate installed (0 without). */
ds_status ds_shear_start(ds_sim *sim, double rate);
double ds_shear_rate(const ds_sim *sim);

#endif
