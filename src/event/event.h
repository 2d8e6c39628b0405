/* SPDX-License-Identifier: MIT */
/* The event-driven integrator (DS_INTEGRATOR_EVENT_DRIVEN): exact dynamics of hard
 * disks, every collision at its own time (event_driven.c and its parts:
 * event_predict.c, event_fetch.c, event_queue.c, cells.c). The rest of
 * the library sees only its table. Not installed. */
#ifndef DS_EVENT_H
#define DS_EVENT_H

#include "core/core.h"

extern const ds_integrator_ops ds_event_driven_ops;

#endif
