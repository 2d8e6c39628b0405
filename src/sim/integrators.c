/* SPDX-License-Identifier: MIT */
/* The integrators, by their ds_integrator value: a new integrator is its
 * folder (or file) with its table, and one line here. */
#include "sim/sim.h"
#include "event/event.h"
#include "timestep/timestep.h"

static const ds_integrator_ops *const integrators[] = {
    [DS_TIME_STEP] = &ds_time_step_ops,
    [DS_EVENT_DRIVEN] = &ds_event_driven_ops,
};

const ds_integrator_ops *ds_integrator_ops_of(ds_integrator integrator)
{
    const unsigned k = (unsigned)integrator;
    return k < sizeof integrators / sizeof integrators[0] ? integrators[k] : NULL;
}

const char *ds_integrator_name(ds_integrator integrator)
{
    const ds_integrator_ops *ops = ds_integrator_ops_of(integrator);
    return ops ? ops->name : "unknown";
}
