/* SPDX-License-Identifier: MIT */
/* The library's names for things: one table per enumeration, read by its
 * name and parse functions, so that the command and Python keep no table
 * of their own (the integrators' and the writers' names are in their
 * tables, sim/tables.c), and the library's version. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/core.h"

const char *ds_version(void) { return DS_VERSION_STRING; }

static const char *const boundary_names[DS_BOUNDARY_COUNT] = {
    [DS_BOUNDARY_WALLS] = "walls",
    [DS_BOUNDARY_PERIODIC] = "periodic",
    [DS_BOUNDARY_CHANNEL] = "channel",
};
static const char *const placement_names[DS_PLACEMENT_COUNT] = {
    [DS_PLACEMENT_RANDOM] = "random",
    [DS_PLACEMENT_LATTICE] = "lattice",
};
static const char *const broadphase_names[DS_BROADPHASE_COUNT] = {
    [DS_BROADPHASE_AUTO] = "auto",     [DS_BROADPHASE_SAP] = "sap",
    [DS_BROADPHASE_STRIPS] = "strips", [DS_BROADPHASE_CELLS] = "cells",
    [DS_BROADPHASE_BRUTE] = "brute",
};
static const char *const mass_rule_names[DS_MASS_RULE_COUNT] = {
    [DS_MASS_EQUAL] = "equal",
    [DS_MASS_AREA] = "area",
};
static const char *const growth_state_names[DS_GROWTH_STATE_COUNT] = {
    [DS_GROWTH_NONE] = "none",
    [DS_GROWTH_GROWING] = "growing",
    [DS_GROWTH_REACHED_ETA] = "reached_eta",
    [DS_GROWTH_JAMMED] = "jammed",
};
static const char *const thermostat_names[DS_THERMOSTAT_COUNT] = {
    [DS_THERMOSTAT_NONE] = "none",
    [DS_THERMOSTAT_ANDERSEN] = "andersen",
    [DS_THERMOSTAT_ISOKINETIC] = "isokinetic",
};

/* The name of value in a table of count names; "unknown" outside it. */
static const char *name_in(const char *const *names, int count, int value)
{
    return value >= 0 && value < count ? names[value] : "unknown";
}

const char *ds_boundary_name(ds_boundary b)
{
    return name_in(boundary_names, DS_BOUNDARY_COUNT, (int)b);
}
const char *ds_placement_name(ds_placement p)
{
    return name_in(placement_names, DS_PLACEMENT_COUNT, (int)p);
}
const char *ds_broadphase_name(ds_broadphase bp)
{
    return name_in(broadphase_names, DS_BROADPHASE_COUNT, (int)bp);
}
const char *ds_mass_rule_name(ds_mass_rule rule)
{
    return name_in(mass_rule_names, DS_MASS_RULE_COUNT, (int)rule);
}
const char *ds_growth_state_name(ds_growth_state state)
{
    return name_in(growth_state_names, DS_GROWTH_STATE_COUNT, (int)state);
}
const char *ds_thermostat_name(ds_thermostat kind)
{
    return name_in(thermostat_names, DS_THERMOSTAT_COUNT, (int)kind);
}

ds_status ds_parse_name(const char *field, const char *name, int count,
                        const char *(*name_of)(int value), int *out, ds_error *err)
{
    ds_error_clear(err);
    if (!out)
        return ds_refuse(err, DS_ERR_ARG, "out", NAN, NAN, "out: nowhere to put the %s (NULL)",
                         field);
    for (int v = 0; name && v < count; ++v)
        if (strcmp(name, name_of(v)) == 0) {
            *out = v;
            return DS_OK;
        }
    /* The sentence names every value known: "integrator = 'exact' is not
     * one of 'step', 'event'". */
    char known[192] = "";
    for (int v = 0; v < count; ++v) {
        const size_t used = strlen(known);
        snprintf(known + used, sizeof known - used, "%s'%s'", v ? ", " : "", name_of(v));
    }
    if (!name)
        return ds_refuse(err, DS_ERR_ARG, field, NAN, NAN, "%s: no name (NULL); one of %s", field,
                         known);
    return ds_refuse(err, DS_ERR_ARG, field, NAN, NAN, "%s = '%s' is not one of %s", field, name,
                     known);
}

/* The parse functions over ds_parse_name, one per enumeration: a name's
 * function as an int-valued one, and the value back in its type. */
#define DEFINE_PARSE(type, field, count, table)                                                    \
    static const char *table##_of(int v) { return name_in(table, count, v); }                      \
    ds_status type##_parse(const char *name, type *out, ds_error *err)                             \
    {                                                                                              \
        int v = 0;                                                                                 \
        const ds_status st = ds_parse_name(field, name, count, table##_of, out ? &v : NULL, err);  \
        if (st == DS_OK)                                                                           \
            *out = (type)v;                                                                        \
        return st;                                                                                 \
    }

DEFINE_PARSE(ds_boundary, "boundary", DS_BOUNDARY_COUNT, boundary_names)
DEFINE_PARSE(ds_placement, "placement", DS_PLACEMENT_COUNT, placement_names)
DEFINE_PARSE(ds_broadphase, "broadphase", DS_BROADPHASE_COUNT, broadphase_names)
DEFINE_PARSE(ds_mass_rule, "mass_rule", DS_MASS_RULE_COUNT, mass_rule_names)
DEFINE_PARSE(ds_growth_state, "growth_state", DS_GROWTH_STATE_COUNT, growth_state_names)
DEFINE_PARSE(ds_thermostat, "thermostat", DS_THERMOSTAT_COUNT, thermostat_names)
