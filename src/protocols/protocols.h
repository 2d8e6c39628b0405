/* SPDX-License-Identifier: MIT */
/* Protocols (protocols/): what acts on a running simulation from outside
 * its dynamics, each a table of hooks (core/protocol.h) and a setter the
 * public API calls. growth.c: the Lubachevsky-Stillinger compression;
 * drive.c: white-noise driving. Not installed. */
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

#endif
