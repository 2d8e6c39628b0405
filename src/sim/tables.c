/* SPDX-License-Identifier: MIT */
/* The lists of the library's interchangeable parts, by their
 * enumerators: the integrators (ds_integrator), the protocols
 * (ds_protocol_kind) and the writers (ds_format). A new integrator is its
 * folder with its table and one line here; a new protocol or output format
 * its file with its table and one line here (docs/architecture.md, "Where
 * new things go"). */
#include "sim/sim.h"
#include "chain/chain.h"
#include "event/event.h"
#include "io/io.h"
#include "protocols/protocols.h"
#include "timestep/timestep.h"

static const ds_integrator_ops *const integrators[DS_INTEGRATOR_COUNT] = {
    [DS_INTEGRATOR_TIME_STEP] = &ds_time_step_ops,
    [DS_INTEGRATOR_EVENT_DRIVEN] = &ds_event_driven_ops,
    [DS_INTEGRATOR_EVENT_CHAIN] = &ds_event_chain_ops,
};

const ds_protocol_ops *const ds_protocol_table[DS_PROTOCOL_KIND_COUNT] = {
    [DS_PROTOCOL_GROWTH] = &ds_growth_ops,
    [DS_PROTOCOL_DRIVE] = &ds_drive_ops,
    [DS_PROTOCOL_THERMOSTAT] = &ds_thermostat_ops,
    [DS_PROTOCOL_BAROSTAT] = &ds_barostat_ops,
    [DS_PROTOCOL_SHEAR] = &ds_shear_ops,
};

static const ds_writer_ops *const writers[DS_FORMAT_COUNT] = {
    [DS_FORMAT_FRAME] = &ds_frame_writer,
    [DS_FORMAT_XYZ] = &ds_xyz_writer,
    [DS_FORMAT_GSD] = &ds_gsd_writer,
};

const ds_integrator_ops *ds_integrator_ops_of(ds_integrator integrator)
{
    const unsigned k = (unsigned)integrator;
    return k < DS_INTEGRATOR_COUNT ? integrators[k] : NULL;
}

const ds_writer_ops *ds_writer_ops_of(ds_format format)
{
    const unsigned k = (unsigned)format;
    return k < DS_FORMAT_COUNT ? writers[k] : NULL;
}

const char *ds_integrator_name(ds_integrator integrator)
{
    const ds_integrator_ops *ops = ds_integrator_ops_of(integrator);
    return ops ? ops->name : "unknown";
}

static const char *integrator_name_of(int v) { return ds_integrator_name((ds_integrator)v); }

ds_status ds_integrator_parse(const char *name, ds_integrator *out, ds_error *err)
{
    int v = 0;
    const ds_status st = ds_parse_name("integrator", name, DS_INTEGRATOR_COUNT, integrator_name_of,
                                       out ? &v : NULL, err);
    if (st == DS_OK)
        *out = (ds_integrator)v;
    return st;
}
