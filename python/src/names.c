/* SPDX-License-Identifier: MIT */
/* The names of the library's enumerations, as the command takes them:
 * each through the library's own name and parse functions (its one table
 * of each), so a new integrator, boundary or broad phase is a name here
 * without an edit and the module keeps no table of its own. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <string.h>

/* The library's functions of each kind, through int-valued wrappers. */
#define WRAP(type)                                                                                 \
    static const char *type##_name_of(int v) { return type##_name((type)v); }                      \
    static ds_status type##_parse_of(const char *name, int *out, ds_error *err)                    \
    {                                                                                              \
        type v;                                                                                    \
        const ds_status st = type##_parse(name, &v, err);                                          \
        if (st == DS_OK)                                                                           \
            *out = (int)v;                                                                         \
        return st;                                                                                 \
    }
WRAP(ds_integrator)
WRAP(ds_boundary)
WRAP(ds_placement)
WRAP(ds_broadphase)
WRAP(ds_mass_rule)
WRAP(ds_growth_state)
WRAP(ds_thermostat)
WRAP(ds_format)

static const struct {
    int count;
    const char *(*name)(int value);
    ds_status (*parse)(const char *name, int *out, ds_error *err);
} kinds[DSPY_KINDS] = {
    [DSPY_INTEGRATOR] = {DS_INTEGRATOR_COUNT, ds_integrator_name_of, ds_integrator_parse_of},
    [DSPY_BOUNDARY] = {DS_BOUNDARY_COUNT, ds_boundary_name_of, ds_boundary_parse_of},
    [DSPY_PLACEMENT] = {DS_PLACEMENT_COUNT, ds_placement_name_of, ds_placement_parse_of},
    [DSPY_BROADPHASE] = {DS_BROADPHASE_COUNT, ds_broadphase_name_of, ds_broadphase_parse_of},
    [DSPY_MASS_RULE] = {DS_MASS_RULE_COUNT, ds_mass_rule_name_of, ds_mass_rule_parse_of},
    [DSPY_GROWTH_STATE] = {DS_GROWTH_STATE_COUNT, ds_growth_state_name_of,
                           ds_growth_state_parse_of},
    [DSPY_THERMOSTAT] = {DS_THERMOSTAT_COUNT, ds_thermostat_name_of, ds_thermostat_parse_of},
    [DSPY_FORMAT] = {DS_FORMAT_COUNT, ds_format_name_of, ds_format_parse_of},
};

const char *dspy_name_of(dspy_kind kind, int value)
{
    if ((unsigned)kind >= DSPY_KINDS || value < 0 || value >= kinds[kind].count)
        return NULL;
    return kinds[kind].name(value);
}

PyObject *dspy_names(dspy_kind kind)
{
    const int count = (unsigned)kind < DSPY_KINDS ? kinds[kind].count : 0;
    PyObject *tuple = PyTuple_New(count);
    for (int v = 0; tuple && v < count; ++v) {
        PyObject *s = PyUnicode_FromString(kinds[kind].name(v));
        if (!s)
            Py_CLEAR(tuple);
        else
            PyTuple_SET_ITEM(tuple, v, s);
    }
    return tuple;
}

int dspy_parse_name(dspy_kind kind, PyObject *value, const char *field, int *out)
{
    if (!PyUnicode_Check(value)) {
        PyErr_Format(PyExc_TypeError, "%s must be a str, not %.100s", field,
                     Py_TYPE(value)->tp_name);
        return -1;
    }
    const char *given = PyUnicode_AsUTF8(value);
    if (!given)
        return -1;
    ds_error err;
    if (kinds[kind].parse(given, out, &err) == DS_OK)
        return 0;
    /* The library's sentence ("mass_rule = 'volume' is not one of ...")
     * about the module's argument: its name for it ("mass = ..."). */
    const size_t flen = strlen(err.field);
    if (strcmp(err.field, field) != 0 && strncmp(err.message, err.field, flen) == 0) {
        char words[sizeof err.message];
        PyOS_snprintf(words, sizeof words, "%s%s", field, err.message + flen);
        memcpy(err.message, words, sizeof words);
        PyOS_snprintf(err.field, sizeof err.field, "%s", field);
    }
    dspy_raise_error(&err);
    return -1;
}
