/* SPDX-License-Identifier: MIT */
/* The names of the library's enumerations, as the command takes them:
 * integrators and boundaries through the library's own name functions,
 * so a new integrator is a name here without an edit; placements from a
 * table (the library has no name function for them), as are mass rules
 * and growth states; broad phases through ds_broadphase_name. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <string.h>

/* Values are tried from 0 until the library calls one "unknown"; no
 * enumeration of the library is anywhere near this long. */
#define MOST_VALUES 64

static const char *const placement_names[] = {[DS_RANDOM] = "random", [DS_LATTICE] = "lattice"};
static const char *const mass_rule_names[] = {[DS_MASS_EQUAL] = "equal", [DS_MASS_AREA] = "area"};
static const char *const growth_state_names[] = {[DS_GROWTH_NONE] = "none",
                                                 [DS_GROWING] = "growing",
                                                 [DS_GROWTH_REACHED_ETA] = "reached_eta",
                                                 [DS_GROWTH_JAMMED] = "jammed"};
#define NAME_IN(table, value)                                                                      \
    ((size_t)(value) < sizeof table / sizeof table[0] ? table[value] : NULL)

const char *dspy_name_of(dspy_kind kind, int value)
{
    const char *name = NULL;
    if (value < 0 || value >= MOST_VALUES)
        return NULL;
    switch (kind) {
    case DSPY_INTEGRATOR:
        name = ds_integrator_name((ds_integrator)value);
        break;
    case DSPY_BOUNDARY:
        name = ds_boundary_name((ds_boundary)value);
        break;
    case DSPY_PLACEMENT:
        name = NAME_IN(placement_names, value);
        break;
    case DSPY_MASS_RULE:
        name = NAME_IN(mass_rule_names, value);
        break;
    case DSPY_GROWTH_STATE:
        name = NAME_IN(growth_state_names, value);
        break;
    case DSPY_BROADPHASE:
        name = ds_broadphase_name((ds_broadphase)value);
        break;
    case DSPY_KINDS:
        break;
    }
    return name && strcmp(name, "unknown") != 0 ? name : NULL;
}

PyObject *dspy_names(dspy_kind kind)
{
    PyObject *list = PyList_New(0);
    for (int v = 0; list && dspy_name_of(kind, v); ++v) {
        PyObject *s = PyUnicode_FromString(dspy_name_of(kind, v));
        if (!s || PyList_Append(list, s) < 0)
            Py_CLEAR(list);
        Py_XDECREF(s);
    }
    PyObject *tuple = list ? PyList_AsTuple(list) : NULL;
    Py_XDECREF(list);
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
    char accepted[256] = "";
    for (int v = 0; dspy_name_of(kind, v); ++v) {
        if (strcmp(given, dspy_name_of(kind, v)) == 0) {
            *out = v;
            return 0;
        }
        const size_t used = strlen(accepted);
        PyOS_snprintf(accepted + used, sizeof accepted - used, "%s'%s'", used ? ", " : "",
                      dspy_name_of(kind, v));
    }
    PyObject *message = PyUnicode_FromFormat("%s = %R is not one of %s", field, value, accepted);
    const char *text = message ? PyUnicode_AsUTF8(message) : NULL;
    if (text)
        dspy_raise(DS_ERR_ARG, field, text);
    Py_XDECREF(message);
    return -1;
}
