/* SPDX-License-Identifier: MIT */
/* Analysis of any set of centres: pair counts for g(r)
 * (ds_pair_histogram) and psi6 of each disk (ds_psi6_local), as module
 * functions over an (n, 2) array and as Sim methods over its disks. Both
 * run with the GIL released, on copies of the centres. */
#include "disksim_py.h"

#include <string.h>

/* The library's refusal, raised in the functions' names for their
 * arguments: its box_x is box, its x and y are positions. */
static PyObject *raise_refusal(ds_error *err)
{
    static const char *const names[][2] = {
        {"box_x", "box"}, {"x", "positions"}, {"y", "positions"}};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
        const size_t flen = strlen(names[k][0]);
        if (strcmp(err->field, names[k][0]) != 0 || strncmp(err->message, err->field, flen) != 0)
            continue;
        char words[sizeof err->message];
        PyOS_snprintf(words, sizeof words, "%s%s", names[k][1], err->message + flen);
        memcpy(err->message, words, sizeof words);
        PyOS_snprintf(err->field, sizeof err->field, "%s", names[k][1]);
        break;
    }
    return dspy_raise_error(err);
}

typedef struct centres {
    size_t n;
    double *x, *y;
} centres;

static void centres_free(centres *c)
{
    PyMem_RawFree(c->x);
    PyMem_RawFree(c->y);
    c->x = c->y = NULL;
}

static int centres_alloc(centres *c, size_t n)
{
    c->n = n;
    c->x = n <= PY_SSIZE_T_MAX / sizeof(double) ? PyMem_RawMalloc(n * sizeof(double) + 1) : NULL;
    c->y = c->x ? PyMem_RawMalloc(n * sizeof(double) + 1) : NULL;
    if (!c->y) {
        centres_free(c);
        PyErr_NoMemory();
        return -1;
    }
    return 0;
}

static int centres_from_array(centres *c, PyObject *value)
{
    PyArrayObject *a = dspy_xy_array(value, "positions", (size_t)-1);
    if (!a || centres_alloc(c, (size_t)PyArray_DIM(a, 0)) < 0) {
        Py_XDECREF(a);
        return -1;
    }
    const double *xy = (const double *)PyArray_DATA(a);
    for (size_t i = 0; i < c->n; ++i) {
        c->x[i] = xy[2 * i];
        c->y[i] = xy[2 * i + 1];
    }
    Py_DECREF(a);
    return 0;
}

static int centres_from_sim(centres *c, const ds_sim *sim)
{
    ds_disk *disks = dspy_get_all(sim);
    if (!disks || centres_alloc(c, ds_sim_get_count(sim)) < 0) {
        PyMem_RawFree(disks);
        return -1;
    }
    for (size_t i = 0; i < c->n; ++i) {
        c->x[i] = disks[i].x;
        c->y[i] = disks[i].y;
    }
    PyMem_RawFree(disks);
    return 0;
}

/* The box of the module functions: box, box_y (None: as box), boundary. */
typedef struct box_args {
    double box, box_y;
    ds_boundary boundary;
} box_args;

static int box_from_args(box_args *b, PyObject *box, PyObject *box_y, PyObject *boundary)
{
    int bnd = DS_BOUNDARY_WALLS;
    b->box = 1000.0;
    if (box && dspy_double_arg(box, "box", &b->box) < 0)
        return -1;
    b->box_y = b->box;
    if (box_y && box_y != Py_None && dspy_double_arg(box_y, "box_y", &b->box_y) < 0)
        return -1;
    if (boundary && dspy_parse_name(DSPY_BOUNDARY, boundary, "boundary", &bnd) < 0)
        return -1;
    b->boundary = (ds_boundary)bnd;
    return 0;
}

static PyObject *histogram(centres *c, const box_args *b, double dr, uint64_t bins)
{
    if (dspy_check_memory(8.0 * (double)bins, "bins") < 0)
        return NULL;
    npy_intp dims[1] = {(npy_intp)bins};
    PyArrayObject *counts = (PyArrayObject *)PyArray_ZEROS(1, dims, NPY_UINT64, 0);
    if (!counts)
        return NULL;
    uint64_t *out = (uint64_t *)PyArray_DATA(counts);
    ds_status st;
    ds_error err;
    Py_BEGIN_ALLOW_THREADS
    st = ds_pair_histogram(c->n, c->x, c->y, b->box, b->box_y, b->boundary, dr, (size_t)bins, out,
                           &err);
    Py_END_ALLOW_THREADS
    if (st != DS_OK) {
        Py_DECREF(counts);
        return raise_refusal(&err);
    }
    return (PyObject *)counts;
}

static PyObject *psi6(centres *c, const box_args *b, double cutoff)
{
    npy_intp dims[1] = {(npy_intp)c->n};
    PyArrayObject *out = (PyArrayObject *)PyArray_SimpleNew(1, dims, NPY_CDOUBLE);
    double *re = out ? PyMem_RawMalloc(c->n * sizeof *re + 1) : NULL;
    double *im = re ? PyMem_RawMalloc(c->n * sizeof *im + 1) : NULL;
    if (!im) {
        Py_XDECREF(out);
        PyMem_RawFree(re);
        return out ? PyErr_NoMemory() : NULL;
    }
    ds_status st;
    ds_error err;
    Py_BEGIN_ALLOW_THREADS
    st = ds_psi6_local(c->n, c->x, c->y, b->box, b->box_y, b->boundary, cutoff, re, im, &err);
    Py_END_ALLOW_THREADS
    if (st == DS_OK) {
        /* complex128 is two doubles, real then imaginary. */
        double *z = (double *)PyArray_DATA(out);
        for (size_t i = 0; i < c->n; ++i) {
            z[2 * i] = re[i];
            z[2 * i + 1] = im[i];
        }
    }
    PyMem_RawFree(re);
    PyMem_RawFree(im);
    if (st != DS_OK) {
        Py_DECREF(out);
        return raise_refusal(&err);
    }
    return (PyObject *)out;
}

const char dspy_pair_histogram_doc[] =
    "pair_histogram(positions, dr, bins, *, box=1000.0, box_y=None, boundary='walls')\n--\n\n"
    "Pair separations for the radial distribution function g(r): counts[b] is the\n"
    "number of pairs j < k of the centres (an (n, 2) array) whose distance lies in\n"
    "[b dr, (b + 1) dr), for b < bins, as a uint64 array. With boundary='periodic'\n"
    "distances are nearest images in the box box x box_y (None: square), and\n"
    "bins * dr must be at most half its shorter side; with walls the box only sizes\n"
    "the cell grid that makes this O(n). g(r) of bin b is counts[b] over the pairs\n"
    "an ideal gas of the same n in the same area A would have there,\n"
    "n (n - 1) / 2 * pi (r1^2 - r0^2) / A. ArgumentError for a value refused.";

PyObject *dspy_pair_histogram(PyObject *module, PyObject *args, PyObject *kwargs)
{
    (void)module;
    static char *keywords[] = {"positions", "dr", "bins", "box", "box_y", "boundary", NULL};
    PyObject *positions, *dr_obj, *bins_obj, *box = NULL, *box_y = NULL, *boundary = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "OOO|$OOO:pair_histogram", keywords, &positions,
                                     &dr_obj, &bins_obj, &box, &box_y, &boundary))
        return NULL;
    double dr;
    uint64_t bins;
    box_args b;
    centres c = {0, NULL, NULL};
    if (dspy_double_arg(dr_obj, "dr", &dr) < 0 || dspy_uint64_arg(bins_obj, "bins", 1, &bins) < 0 ||
        box_from_args(&b, box, box_y, boundary) < 0 || centres_from_array(&c, positions) < 0)
        return NULL;
    PyObject *r = histogram(&c, &b, dr, bins);
    centres_free(&c);
    return r;
}

PyObject *dspy_sim_pair_histogram(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"dr", "bins", NULL};
    PyObject *dr_obj, *bins_obj;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "OO:pair_histogram", keywords, &dr_obj,
                                     &bins_obj))
        return NULL;
    double dr;
    uint64_t bins;
    if (dspy_double_arg(dr_obj, "dr", &dr) < 0 || dspy_uint64_arg(bins_obj, "bins", 1, &bins) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    centres c = {0, NULL, NULL};
    if (!sim || centres_from_sim(&c, sim) < 0)
        return NULL;
    const box_args b = {ds_sim_get_box_width(sim), ds_sim_get_box_height(sim),
                        ds_sim_get_boundary(sim)};
    PyObject *r = histogram(&c, &b, dr, bins);
    centres_free(&c);
    return r;
}

const char dspy_local_psi6_doc[] =
    "local_psi6(positions, cutoff, *, box=1000.0, box_y=None, boundary='walls')\n--\n\n"
    "Bond-orientational order of each disk, as a complex array:\n"
    "psi6_j = (1/n_j) sum_k exp(6 i theta_jk) over the n_j disks k whose centres are\n"
    "closer than cutoff to j's (a coincident centre is no bond), theta_jk the angle\n"
    "of the bond j -> k from the x axis; 0 for a disk with no neighbour. |psi6_j| = 1\n"
    "for six neighbours at multiples of 60 degrees, and arg(psi6_j) / 6 is then the\n"
    "lattice's orientation. positions is an (n, 2) array; with boundary='periodic'\n"
    "separations are nearest images in box x box_y (None: square), and cutoff must\n"
    "be below half the shorter side. ArgumentError for a value refused.";

PyObject *dspy_local_psi6(PyObject *module, PyObject *args, PyObject *kwargs)
{
    (void)module;
    static char *keywords[] = {"positions", "cutoff", "box", "box_y", "boundary", NULL};
    PyObject *positions, *cutoff_obj, *box = NULL, *box_y = NULL, *boundary = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "OO|$OOO:local_psi6", keywords, &positions,
                                     &cutoff_obj, &box, &box_y, &boundary))
        return NULL;
    double cutoff;
    box_args b;
    centres c = {0, NULL, NULL};
    if (dspy_double_arg(cutoff_obj, "cutoff", &cutoff) < 0 ||
        box_from_args(&b, box, box_y, boundary) < 0 || centres_from_array(&c, positions) < 0)
        return NULL;
    PyObject *r = psi6(&c, &b, cutoff);
    centres_free(&c);
    return r;
}

PyObject *dspy_sim_local_psi6(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"cutoff", NULL};
    PyObject *cutoff_obj = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "|O:local_psi6", keywords, &cutoff_obj))
        return NULL;
    double cutoff = 0.0;
    if (cutoff_obj != Py_None && dspy_double_arg(cutoff_obj, "cutoff", &cutoff) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    centres c = {0, NULL, NULL};
    if (!sim || centres_from_sim(&c, sim) < 0)
        return NULL;
    if (cutoff_obj == Py_None)
        cutoff = 1.4 * 2.0 * ds_sim_get_radius(sim); /* ds_sim_get_psi6's cutoff */
    const box_args b = {ds_sim_get_box_width(sim), ds_sim_get_box_height(sim),
                        ds_sim_get_boundary(sim)};
    PyObject *r = psi6(&c, &b, cutoff);
    centres_free(&c);
    return r;
}
