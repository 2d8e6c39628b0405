/* SPDX-License-Identifier: MIT */
/* Sim's mixture arguments as a ds_mixture: species=[(count, radius[,
 * mass][, name]), ...], or radii= (and masses=) per disk, and mass=, the
 * rule for the masses not given.
 *
 * The library judges the values (ds_params_check: counts that do not
 * add up to n, radii or masses that are not positive finite numbers,
 * both forms or neither) and its sentence is what is raised; the module
 * refuses only what the library cannot see: wrong types, negative counts,
 * arrays of another length than n, and masses beside species (which the
 * library would ignore). */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <string.h>

const char *const dspy_mixture_names[4] = {"species", "radii", "masses", "mass"};
enum { SPECIES, RADII, MASSES, MASS };

int dspy_mixture_keyword(const char *name)
{
    for (int k = 0; k < 4; ++k)
        if (strcmp(name, dspy_mixture_names[k]) == 0)
            return k;
    return -1;
}

const ds_mixture *dspy_mixture_of(const dspy_mixture *m) { return m->any ? &m->mixture : NULL; }

void dspy_mixture_free(dspy_mixture *m)
{
    PyMem_RawFree(m->kinds);
    PyMem_RawFree(m->radii);
    PyMem_RawFree(m->masses);
    m->kinds = NULL;
    m->radii = m->masses = NULL;
    m->mixture.kinds = NULL;
    m->mixture.radii = m->mixture.masses = NULL;
}

/* The exception being raised, if a disksim.Error, names field. */
static void name_field(const char *field)
{
    PyObject *exc = dspy_take_exception();
    if (!exc)
        return;
    if (PyObject_IsInstance(exc, dspy_Error) == 1) {
        PyObject *f = PyUnicode_FromString(field);
        if (!f || PyObject_SetAttrString(exc, "field", f) < 0)
            PyErr_Clear();
        Py_XDECREF(f);
    }
    PyErr_Clear();
    PyErr_SetObject((PyObject *)Py_TYPE(exc), exc);
    Py_DECREF(exc);
}

#define SPECIES_FORMS                                                                              \
    "(count, radius), (count, radius, mass), (count, radius, name) or (count, radius, mass, name)"

/* One species, (count, radius[, mass][, name]), into *kind; the same as
 * a tuple of an int, floats and the name into *normal. The name (a str,
 * the kind's name in output files: GSD's types, XYZ's type column) is
 * judged by the library; kind->name points into the str, which *normal
 * holds as long as the Sim keeps its arguments. */
static int one_species(PyObject *item, Py_ssize_t k, ds_species *kind, PyObject **normal)
{
    PyObject *t = PySequence_Check(item) && !PyUnicode_Check(item) ? PySequence_Tuple(item) : NULL;
    if (!t) {
        if (!PyErr_Occurred() || PyErr_ExceptionMatches(PyExc_TypeError)) {
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError,
                         "species[%zd] must be a tuple " SPECIES_FORMS ", not %.100s", k,
                         Py_TYPE(item)->tp_name);
        }
        return -1;
    }
    const Py_ssize_t len = PyTuple_GET_SIZE(t);
    PyObject *name = len >= 3 && PyUnicode_Check(PyTuple_GET_ITEM(t, len - 1))
                         ? PyTuple_GET_ITEM(t, len - 1)
                         : NULL;
    const Py_ssize_t numbers = name ? len - 1 : len;
    if (len < 2 || numbers > 3) {
        Py_DECREF(t);
        dspy_raisef(DS_ERR_ARG, "species", "species[%zd] has %zd items: it must be " SPECIES_FORMS,
                    k, len);
        return -1;
    }
    char label[3][48];
    PyOS_snprintf(label[0], sizeof label[0], "species[%zd] count", k);
    PyOS_snprintf(label[1], sizeof label[1], "species[%zd] radius", k);
    PyOS_snprintf(label[2], sizeof label[2], "species[%zd] mass", k);
    uint64_t count = 0;
    double radius = 0.0, mass = 0.0;
    const char *text = NULL;
    Py_ssize_t text_len = 0;
    int ok = dspy_uint64_arg(PyTuple_GET_ITEM(t, 0), label[0], 1, &count) == 0 &&
             dspy_double_arg(PyTuple_GET_ITEM(t, 1), label[1], &radius) == 0 &&
             (numbers == 2 || dspy_double_arg(PyTuple_GET_ITEM(t, 2), label[2], &mass) == 0) &&
             (!name || (text = PyUnicode_AsUTF8AndSize(name, &text_len)) != NULL);
    if (ok && count > SIZE_MAX) {
        dspy_raisef(DS_ERR_NOMEM, "species", "%s = %llu cannot be held in memory", label[0],
                    (unsigned long long)count);
        ok = 0;
    }
    if (ok && text && strlen(text) != (size_t)text_len) {
        dspy_raisef(DS_ERR_ARG, "species", "species[%zd] name contains a NUL character", k);
        ok = 0;
    }
    if (!ok) {
        Py_DECREF(t);
        name_field("species");
        return -1;
    }
    kind->count = (size_t)count;
    kind->radius = radius;
    kind->mass = mass;
    kind->name = text; /* NULL: "A", "B", ... */
    if (numbers == 2)
        *normal = name ? Py_BuildValue("(KdO)", (unsigned long long)count, radius, name)
                       : Py_BuildValue("(Kd)", (unsigned long long)count, radius);
    else
        *normal = name ? Py_BuildValue("(KddO)", (unsigned long long)count, radius, mass, name)
                       : Py_BuildValue("(Kdd)", (unsigned long long)count, radius, mass);
    Py_DECREF(t);
    return *normal ? 0 : -1;
}

static int convert_species(dspy_mixture *m, PyObject *value, PyObject **normal)
{
    /* A tuple of its own: converting an item runs Python code, which could
     * change a list under the loop. */
    PyObject *all =
        PySequence_Check(value) && !PyUnicode_Check(value) ? PySequence_Tuple(value) : NULL;
    if (!all) {
        if (!PyErr_Occurred() || PyErr_ExceptionMatches(PyExc_TypeError)) {
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError,
                         "species must be a sequence of " SPECIES_FORMS ", not %.100s",
                         Py_TYPE(value)->tp_name);
        }
        return -1;
    }
    const Py_ssize_t kinds = PyTuple_GET_SIZE(all);
    m->kinds = (size_t)kinds < PY_SSIZE_T_MAX / sizeof *m->kinds
                   ? PyMem_RawMalloc((size_t)kinds * sizeof *m->kinds + 1)
                   : NULL;
    *normal = m->kinds ? PyTuple_New(kinds) : NULL;
    if (!*normal) {
        Py_DECREF(all);
        if (!PyErr_Occurred())
            PyErr_NoMemory();
        return -1;
    }
    for (Py_ssize_t k = 0; k < kinds; ++k) {
        PyObject *one = NULL;
        if (one_species(PyTuple_GET_ITEM(all, k), k, &m->kinds[k], &one) < 0) {
            Py_DECREF(all);
            Py_CLEAR(*normal);
            return -1;
        }
        PyTuple_SET_ITEM(*normal, k, one);
    }
    Py_DECREF(all);
    m->mixture.species = (size_t)kinds;
    m->mixture.kinds = m->kinds;
    return 0;
}

/* radii or masses: n numbers into *out (PyMem_Raw), a copy of them as a
 * new array into *normal. */
static int convert_vector(PyObject *value, const char *field, size_t n, double **out,
                          PyObject **normal)
{
    PyArrayObject *a = dspy_vector_array(value, field, n);
    if (!a)
        return -1;
    *out = PyMem_RawMalloc(n * sizeof **out + 1);
    *normal = *out ? PyArray_NewCopy(a, NPY_CORDER) : PyErr_NoMemory();
    if (*normal)
        memcpy(*out, PyArray_DATA(a), n * sizeof **out);
    Py_DECREF(a);
    return *normal ? 0 : -1;
}

int dspy_mixture_convert(dspy_mixture *m, size_t n)
{
    PyObject *normal[4] = {Py_None, Py_None, Py_None, NULL};
    PyObject **given = m->given;
    int rule = DS_MASS_EQUAL, ok = 1;
    for (int k = 0; k < 3; ++k)
        Py_INCREF(normal[k]);
    if (given[MASS] && dspy_parse_name(DSPY_MASS_RULE, given[MASS], "mass", &rule) < 0)
        ok = 0;
    if (ok && given[SPECIES] && given[SPECIES] != Py_None) {
        Py_CLEAR(normal[SPECIES]);
        ok = convert_species(m, given[SPECIES], &normal[SPECIES]) == 0;
    }
    if (ok && given[RADII] && given[RADII] != Py_None) {
        Py_CLEAR(normal[RADII]);
        ok = convert_vector(given[RADII], "radii", n, &m->radii, &normal[RADII]) == 0;
    }
    if (ok && given[MASSES] && given[MASSES] != Py_None) {
        Py_CLEAR(normal[MASSES]);
        if (m->kinds) {
            dspy_raise(DS_ERR_ARG, "masses",
                       "masses is per disk, given with radii: a species' mass is the third item "
                       "of its tuple, (count, radius, mass)");
            ok = 0;
        } else {
            ok = convert_vector(given[MASSES], "masses", n, &m->masses, &normal[MASSES]) == 0;
        }
    }
    normal[MASS] = ok ? PyUnicode_FromString(dspy_name_of(DSPY_MASS_RULE, rule)) : NULL;
    m->args = normal[MASS]
                  ? Py_BuildValue("{sOsOsOsO}", "species", normal[SPECIES], "radii", normal[RADII],
                                  "masses", normal[MASSES], "mass", normal[MASS])
                  : NULL;
    for (int k = 0; k < 4; ++k)
        Py_XDECREF(normal[k]);
    if (!m->args) {
        dspy_mixture_free(m);
        return -1;
    }
    m->mixture.radii = m->radii;
    m->mixture.masses = m->masses;
    m->mixture.mass_rule = (ds_mass_rule)rule;
    /* mass= alone is no mixture: one kind of disk weighs 1 by either rule. */
    m->any = m->kinds || m->radii || m->masses;
    return 0;
}
