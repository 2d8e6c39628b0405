/* SPDX-License-Identifier: MIT */
/* The event-chain Monte Carlo integrator (DS_INTEGRATOR_EVENT_CHAIN):
 * straight event chains (Bernard, Krauth and Wilson 2009) in +x and +y
 * in turn, sampling the canonical ensemble of hard disks without
 * velocities (event_chain.c and its parts: chain_grid.c, chain_move.c,
 * chain_checkpoint.c). The rest of the library sees only its table. Not
 * installed. */
#ifndef DS_CHAIN_H
#define DS_CHAIN_H

#include "core/core.h"

extern const ds_integrator_ops ds_event_chain_ops;

/* The default chain length over the square root of the box's area.
 * Measured at N = 1024, area fraction 0.70: every length from 0.05 to 4
 * decorrelates psi6 and Z as fast at the same cost, within 15%; this one
 * is inside that range and the literature's (docs/physics.md, "The chain
 * length"). */
#define DS_CHAIN_LENGTH_OF_BOX 0.25

/* The chain length of sim (an event-chain simulation), and setting it
 * (> 0, finite) from the next chain on: for the tests and the
 * measurement of the default (tests/chain_length.c), not the public API. */
double ds_chain_length(const ds_sim *sim);
void ds_chain_set_length(ds_sim *sim, double length);

#endif
