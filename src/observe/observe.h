/* SPDX-License-Identifier: MIT */
/* Observables (observe/): what a simulation measures of itself, from the
 * disks (observables.c: energy, momentum) and from what the integrators
 * tallied (pressures), structure (psi6.c, pair_histogram.c, contacts.c)
 * and transport (transport.c). Their public face is
 * disk_sim.h; this header holds what they share. Not installed. */
#ifndef DS_OBSERVE_H
#define DS_OBSERVE_H

#include "core/core.h"

#endif
