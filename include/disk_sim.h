/* SPDX-License-Identifier: MIT */
/*
 * disksim: hard disks (2D elastic billiards) in a box.
 *
 * The public face of libdisksim: this header includes the headers of
 * include/disksim/, one per concept (docs/library.md lists the API by
 * task, docs/architecture.md its naming scheme):
 *
 *   disksim/base.h       version, statuses and error details, rng, timer
 *   disksim/params.h     the choices, ds_params, mixtures, checking a request
 *   disksim/sim.h        creating and running a simulation, its disks
 *   disksim/protocols.h  what acts on a running simulation: growth
 *   disksim/observe.h    energy, pressures, temperature, order, g(r), transport
 *   disksim/io.h         text frames, extended XYZ, writers, checkpoints
 *
 * Every exported symbol starts with `ds_`. The library never prints,
 * never exits and keeps no global mutable state: every call that can fail
 * returns a ds_status and fills an optional ds_error with the reason.
 */
#ifndef DISK_SIM_H
#define DISK_SIM_H

#include "disksim/base.h"
#include "disksim/params.h"
#include "disksim/sim.h"
#include "disksim/protocols.h"
#include "disksim/observe.h"
#include "disksim/io.h"

#endif /* DISK_SIM_H */
