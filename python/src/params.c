/* SPDX-License-Identifier: MIT */
/* Sim's arguments as a ds_params: one table row per argument, so a new
 * member of ds_params is one row here, one line of DSPY_SIM_SIGNATURE and
 * one paragraph of Sim's docstring. The mixture's arguments (species,
 * radii, masses, mass) are a ds_mixture beside it, made in mixture.c.
 *
 * The library judges every value (ds_params_check) and its sentence
 * is what is raised; the module refuses only what Python adds: wrong
 * types, negative integers, and 0 for a length, which the C API reads as
 * "the default" but which from Python, where the defaults are written
 * out, is a mistake to report rather than to replace. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <stddef.h>
#include <string.h>

typedef enum arg_kind {
    ARG_COUNT,          /* size_t, an int >= 0 */
    ARG_SEED,           /* uint64_t, an int in [0, 2**64) */
    ARG_REAL,           /* double, any float */
    ARG_LENGTH,         /* double, any float but 0 */
    ARG_LENGTH_OR_NONE, /* double, None stored as 0 (the library's "as box") */
    ARG_NAME            /* an enumeration, by name */
} arg_kind;

typedef struct param_arg {
    const char *name; /* the keyword, and the ds_params member */
    arg_kind kind;
    size_t offset;   /* of the member in ds_params */
    double fallback; /* ARG_LENGTH: the default, written out */
    dspy_kind names; /* ARG_NAME: which names */
} param_arg;

#define MEMBER(m) offsetof(ds_params, m)
/* The first two are positional too, in this order; the rest are
 * keyword-only. The order is the signature's. */
static const param_arg param_args[] = {
    {"n", ARG_COUNT, MEMBER(n), 0.0, DSPY_KINDS},
    {"radius", ARG_REAL, MEMBER(radius), 0.0, DSPY_KINDS},
    {"seed", ARG_SEED, MEMBER(seed), 0.0, DSPY_KINDS},
    {"integrator", ARG_NAME, MEMBER(integrator), 0.0, DSPY_INTEGRATOR},
    {"boundary", ARG_NAME, MEMBER(boundary), 0.0, DSPY_BOUNDARY},
    {"placement", ARG_NAME, MEMBER(placement), 0.0, DSPY_PLACEMENT},
    {"box", ARG_LENGTH, MEMBER(box), 1000.0, DSPY_KINDS},
    {"box_y", ARG_LENGTH_OR_NONE, MEMBER(box_y), 0.0, DSPY_KINDS},
    {"dt", ARG_LENGTH, MEMBER(dt), 0.001, DSPY_KINDS},
    {"speed", ARG_LENGTH, MEMBER(speed), 100.0, DSPY_KINDS},
    {"broadphase", ARG_NAME, MEMBER(broadphase), 0.0, DSPY_BROADPHASE},
};
#define PARAM_ARGS (sizeof param_args / sizeof param_args[0])
#define POSITIONAL 2

/* Enumerations are stored through memcpy of an int: the same bits as long
 * as each enum is int-sized, which this checks at compile time. */
typedef char enums_are_int_sized[sizeof(ds_integrator) == sizeof(int) &&
                                         sizeof(ds_boundary) == sizeof(int) &&
                                         sizeof(ds_placement) == sizeof(int) &&
                                         sizeof(ds_broadphase) == sizeof(int)
                                     ? 1
                                     : -1];

static void *member(ds_params *p, const param_arg *a) { return (char *)p + a->offset; }
static const void *cmember(const ds_params *p, const param_arg *a)
{
    return (const char *)p + a->offset;
}

static int store(ds_params *p, const param_arg *a, PyObject *value)
{
    uint64_t u = 0;
    double d = 0.0;
    int e = 0;
    switch (a->kind) {
    case ARG_COUNT:
        if (dspy_uint64_arg(value, a->name, 1, &u) < 0)
            return -1;
        if (u > SIZE_MAX) {
            dspy_raisef(DS_ERR_NOMEM, a->name, "%s = %llu cannot be held in memory", a->name,
                        (unsigned long long)u);
            return -1;
        }
        *(size_t *)member(p, a) = (size_t)u;
        return 0;
    case ARG_SEED:
        if (dspy_uint64_arg(value, a->name, 0, &u) < 0)
            return -1;
        *(uint64_t *)member(p, a) = u;
        return 0;
    case ARG_LENGTH_OR_NONE:
        if (value == Py_None) {
            *(double *)member(p, a) = 0.0;
            return 0;
        }
        /* fall through */
    case ARG_REAL:
    case ARG_LENGTH:
        if (dspy_double_arg(value, a->name, &d) < 0)
            return -1;
        if (d == 0.0 && a->kind != ARG_REAL) {
            if (a->kind == ARG_LENGTH)
                dspy_raisef(DS_ERR_ARG, a->name, "%s = 0 must be > 0 (the default is %s=%g)",
                            a->name, a->name, a->fallback);
            else
                dspy_raisef(DS_ERR_ARG, a->name,
                            "%s = 0 must be > 0 (None, the default, means as box)", a->name);
            return -1;
        }
        *(double *)member(p, a) = d;
        return 0;
    case ARG_NAME:
        if (dspy_parse_name(a->names, value, a->name, &e) < 0)
            return -1;
        memcpy(member(p, a), &e, sizeof e);
        return 0;
    }
    return 0;
}

static const param_arg *find(PyObject *key)
{
    const char *name = PyUnicode_Check(key) ? PyUnicode_AsUTF8(key) : NULL;
    if (!name) {
        PyErr_Clear();
        return NULL;
    }
    for (size_t k = 0; k < PARAM_ARGS; ++k)
        if (strcmp(name, param_args[k].name) == 0)
            return &param_args[k];
    return NULL;
}

static int mixture_keyword(PyObject *key)
{
    const char *name = PyUnicode_Check(key) ? PyUnicode_AsUTF8(key) : NULL;
    if (!name) {
        PyErr_Clear();
        return -1;
    }
    return dspy_mixture_keyword(name);
}

/* Python's own rules for calling: at most two positional arguments, each
 * argument once, no unknown keyword, n and radius given. The mixture's
 * arguments are kept (borrowed) in m->given, to be converted once n is
 * known. */
static int parse(PyObject *args, PyObject *kwargs, ds_params *p, dspy_mixture *m)
{
    const Py_ssize_t given = args ? PyTuple_GET_SIZE(args) : 0;
    if (given > POSITIONAL) {
        PyErr_Format(PyExc_TypeError,
                     "Sim() takes 2 positional arguments (n, radius) but %zd were given; the "
                     "others are keyword-only",
                     given);
        return -1;
    }
    int seen[PARAM_ARGS] = {0};
    for (Py_ssize_t k = 0; k < given; ++k) {
        if (store(p, &param_args[k], PyTuple_GET_ITEM(args, k)) < 0)
            return -1;
        seen[k] = 1;
    }
    Py_ssize_t pos = 0;
    PyObject *key, *value;
    while (kwargs && PyDict_Next(kwargs, &pos, &key, &value)) {
        const param_arg *a = find(key);
        const int mk = a ? -1 : mixture_keyword(key);
        if (mk >= 0) {
            m->given[mk] = value; /* a dict has each key once */
            continue;
        }
        if (!a) {
            PyErr_Format(PyExc_TypeError, "Sim() got an unexpected keyword argument %R", key);
            return -1;
        }
        const size_t k = (size_t)(a - param_args);
        if (seen[k]) {
            PyErr_Format(PyExc_TypeError, "Sim() got multiple values for argument '%s'", a->name);
            return -1;
        }
        if (store(p, a, value) < 0)
            return -1;
        seen[k] = 1;
    }
    for (size_t k = 0; k < POSITIONAL; ++k)
        if (!seen[k]) {
            PyErr_Format(PyExc_TypeError, "Sim() missing required argument '%s'",
                         param_args[k].name);
            return -1;
        }
    return 0;
}

/* The arguments converted, the defaults written out, not yet judged. */
static int convert(PyObject *args, PyObject *kwargs, ds_params *p, dspy_mixture *mixture)
{
    *p = ds_params_default(0, 0.0);
    for (size_t k = 0; k < PARAM_ARGS; ++k)
        if (param_args[k].kind == ARG_LENGTH)
            *(double *)member(p, &param_args[k]) = param_args[k].fallback;
    return parse(args, kwargs, p, mixture) < 0 || dspy_mixture_convert(mixture, p->n) < 0 ? -1 : 0;
}

int dspy_params_from_args(PyObject *args, PyObject *kwargs, ds_params *params,
                          dspy_mixture *mixture, char warning[256])
{
    ds_params p;
    if (convert(args, kwargs, &p, mixture) < 0)
        return -1;
    unsigned warnings = 0;
    ds_error err;
    const ds_status st = ds_params_check(&p, dspy_mixture_of(mixture), &warnings, &err);
    if (st != DS_OK) {
        dspy_mixture_free(mixture);
        Py_CLEAR(mixture->args);
        dspy_raise_error(&err);
        return -1;
    }
    if (warning)
        memcpy(warning, err.warning, sizeof err.warning);
    *params = p;
    return 0;
}

/* The mixture's arguments into dict, arrays copied (so that changing
 * them changes nothing). */
static int add_mixture_args(PyObject *dict, PyObject *mixture_args)
{
    Py_ssize_t pos = 0;
    PyObject *key, *value;
    while (mixture_args && PyDict_Next(mixture_args, &pos, &key, &value)) {
        PyObject *v = PyArray_Check(value) ? PyArray_NewCopy((PyArrayObject *)value, NPY_CORDER)
                                           : Py_NewRef(value);
        const int r = v ? PyDict_SetItem(dict, key, v) : -1;
        Py_XDECREF(v);
        if (r < 0)
            return -1;
    }
    return 0;
}

PyObject *dspy_params_dict(const ds_params *p, unsigned unknown, PyObject *mixture_args)
{
    PyObject *dict = PyDict_New();
    for (size_t k = 0; dict && k < PARAM_ARGS; ++k) {
        const param_arg *a = &param_args[k];
        if (unknown & (1u << k))
            continue;
        PyObject *value = NULL;
        double d;
        int e;
        switch (a->kind) {
        case ARG_COUNT:
            value = PyLong_FromSize_t(*(const size_t *)cmember(p, a));
            break;
        case ARG_SEED:
            value = PyLong_FromUnsignedLongLong(*(const uint64_t *)cmember(p, a));
            break;
        case ARG_REAL:
        case ARG_LENGTH:
        case ARG_LENGTH_OR_NONE:
            d = *(const double *)cmember(p, a);
            value = a->kind == ARG_LENGTH_OR_NONE && d == 0.0 ? Py_NewRef(Py_None)
                                                              : PyFloat_FromDouble(d);
            break;
        case ARG_NAME:
            memcpy(&e, cmember(p, a), sizeof e);
            value = PyUnicode_FromString(dspy_name_of(a->names, e));
            break;
        }
        if (!value || PyDict_SetItemString(dict, a->name, value) < 0)
            Py_CLEAR(dict);
        Py_XDECREF(value);
    }
    if (dict && add_mixture_args(dict, mixture_args) < 0)
        Py_CLEAR(dict);
    return dict;
}

/* ", species=..." for each mixture argument that is not its default. */
static PyObject *mixture_repr(PyObject *text, PyObject *mixture_args)
{
    for (int k = 0; text && mixture_args && k < 4; ++k) {
        const char *name = dspy_mixture_names[k];
        PyObject *v = PyDict_GetItemString(mixture_args, name);
        const int plain = !v || v == Py_None ||
                          (PyUnicode_Check(v) && PyUnicode_CompareWithASCIIString(
                                                     v, ds_mass_rule_name(DS_MASS_EQUAL)) == 0);
        if (plain)
            continue;
        PyObject *part = PyUnicode_FromFormat(", %s=%R", name, v);
        PyObject *joined = part ? PyUnicode_Concat(text, part) : NULL;
        Py_XDECREF(part);
        Py_SETREF(text, joined);
    }
    return text;
}

PyObject *dspy_params_repr(const ds_params *p, unsigned unknown, PyObject *mixture_args)
{
    ds_params defaults = ds_params_default(p->n, p->radius);
    for (size_t k = 0; k < PARAM_ARGS; ++k)
        if (param_args[k].kind == ARG_LENGTH)
            *(double *)member(&defaults, &param_args[k]) = param_args[k].fallback;
    PyObject *mine = dspy_params_dict(p, unknown, NULL),
             *plain = dspy_params_dict(&defaults, 0, NULL);
    PyObject *text = mine && plain
                         ? PyUnicode_FromFormat("Sim(%R, %R", PyDict_GetItemString(mine, "n"),
                                                PyDict_GetItemString(mine, "radius"))
                         : NULL;
    for (size_t k = POSITIONAL; text && k < PARAM_ARGS; ++k) {
        if (unknown & (1u << k))
            continue;
        PyObject *v = PyDict_GetItemString(mine, param_args[k].name);
        PyObject *d = PyDict_GetItemString(plain, param_args[k].name);
        const int same = v && d ? PyObject_RichCompareBool(v, d, Py_EQ) : -1;
        PyObject *part = same == 0   ? PyUnicode_FromFormat(", %s=%R", param_args[k].name, v)
                         : same == 1 ? PyUnicode_FromString("")
                                     : NULL;
        PyObject *joined = part ? PyUnicode_Concat(text, part) : NULL;
        Py_XDECREF(part);
        Py_SETREF(text, joined);
    }
    text = mixture_repr(text, mixture_args);
    if (text) {
        PyObject *closed = PyUnicode_FromString(")");
        PyObject *joined = closed ? PyUnicode_Concat(text, closed) : NULL;
        Py_XDECREF(closed);
        Py_SETREF(text, joined);
    }
    Py_XDECREF(mine);
    Py_XDECREF(plain);
    return text;
}

unsigned dspy_params_of_sim(const ds_sim *sim, ds_params *p)
{
    *p = ds_params_default(ds_sim_get_count(sim), ds_sim_get_radius(sim));
    p->box = ds_sim_get_box_width(sim);
    p->box_y =
        ds_sim_get_box_height(sim) == ds_sim_get_box_width(sim) ? 0.0 : ds_sim_get_box_height(sim);
    p->dt = ds_sim_get_dt(sim);
    p->integrator = ds_sim_get_integrator(sim);
    p->boundary = ds_sim_get_boundary(sim);
    p->broadphase = ds_sim_get_broadphase(sim);
    /* What the library does not tell: the rows of the table it leaves out. */
    unsigned unknown = 0;
    for (size_t k = 0; k < PARAM_ARGS; ++k) {
        const char *name = param_args[k].name;
        if (strcmp(name, "seed") == 0 || strcmp(name, "speed") == 0 ||
            strcmp(name, "placement") == 0)
            unknown |= 1u << k;
    }
    return unknown;
}

unsigned dspy_param_unknown(unsigned unknown, const char *name)
{
    for (size_t k = 0; k < PARAM_ARGS; ++k)
        if (strcmp(name, param_args[k].name) == 0)
            return unknown & (1u << k);
    return 0;
}

int dspy_params_from_dict(PyObject *dict, ds_params *p, dspy_mixture *mixture, unsigned *unknown)
{
    /* Converted, not judged as a request to create: what a pickle's
     * arguments describe is its checkpoint, which the library checks as it
     * parses it. Judged as a request, a dict without placement (a loaded
     * Sim's) was a random placement, which the library refuses above area
     * fraction 0.54 for more than 1000 disks, and a loaded mixture's was
     * disks of the reference radius alone: copies of dense Sims failed. */
    PyObject *empty = PyTuple_New(0);
    const int r = empty ? convert(empty, dict, p, mixture) : -1;
    Py_XDECREF(empty);
    *unknown = 0;
    for (size_t k = 0; r == 0 && k < PARAM_ARGS; ++k)
        if (!PyDict_GetItemString(dict, param_args[k].name))
            *unknown |= 1u << k;
    return r;
}
