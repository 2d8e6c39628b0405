/* SPDX-License-Identifier: MIT */
/* The integrators, by their ds_integrator value, and the protocols, by
 * their kind: a new integrator is its folder (or file) with its table,
 * and one line here; a new protocol its file and one line. */
#include "sim/sim.h"
#include "event/event.h"
#include "protocols/protocols.h"
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

const ds_protocol_ops *const ds_protocol_table[DS_PROTOCOL_KIND_COUNT] = {
    [DS_PROTOCOL_GROWTH] = &ds_growth_ops,
};
