/* SPDX-License-Identifier: MIT */
/* Analysis of any set of centres: pair counts for g(r)
 * (ds_pair_histogram), g(r) itself normalised by the ideal gas in the same
 * box, and psi6 of each disk (ds_psi6_local), as module functions over an
 * (n, 2) array and as Sim methods over its disks. The library's parts run
 * with the GIL released, on copies of the centres. */
#include "disksim_py.h"

#include <math.h>
#include <stdarg.h>
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

/* ---------------------------------------------------------------- g(r) */

/* A refusal of the module's own, with its value and limit, as the
 * library's are raised. */
static PyObject *refuse(const char *field, double value, double limit, const char *fmt, ...)
{
    ds_error err;
    memset(&err, 0, sizeof err);
    err.status = DS_ERR_ARG;
    PyOS_snprintf(err.field, sizeof err.field, "%s", field);
    err.value = value;
    err.limit = limit;
    va_list ap;
    va_start(ap, fmt);
    PyOS_vsnprintf(err.message, sizeof err.message, fmt, ap);
    va_end(ap);
    return dspy_raise_error(&err);
}

/* The rectangle an ideal gas's centres fill, for g(r)'s normalisation:
 * along a periodic axis the whole side; along one with walls the side less
 * 2 radius (where the centres keep radius from the walls). */
typedef struct ideal_box {
    double side[2];
    int walls[2];
} ideal_box;

static int ideal_box_of(const box_args *b, double radius, ideal_box *ib)
{
    int walls_x, walls_y;
    switch (b->boundary) {
    case DS_BOUNDARY_WALLS:
        walls_x = walls_y = 1;
        break;
    case DS_BOUNDARY_PERIODIC:
        walls_x = walls_y = 0;
        break;
    case DS_BOUNDARY_CHANNEL:
        walls_x = 0;
        walls_y = 1;
        break;
    default:
        PyErr_Format(PyExc_NotImplementedError, "rdf: no normalisation for boundary %d",
                     (int)b->boundary);
        return -1;
    }
    if (!(radius >= 0.0 && isfinite(radius))) {
        refuse("radius", radius, 0.0, "radius = %g must be finite and >= 0", radius);
        return -1;
    }
    const double sides[2] = {b->box, b->box_y};
    const int walls[2] = {walls_x, walls_y};
    for (int a = 0; a < 2; ++a) {
        ib->walls[a] = walls[a];
        ib->side[a] = walls[a] ? sides[a] - 2.0 * radius : sides[a];
        if (!(ib->side[a] > 0.0 && isfinite(ib->side[a]))) {
            refuse(a ? "box_y" : "box", sides[a], 2.0 * radius,
                   "%s = %g leaves the centres no room: it must be finite and above 2 radius = %g",
                   a ? "box_y" : "box", sides[a], 2.0 * radius);
            return -1;
        }
    }
    return 0;
}

/* How far g(r) is normalised: F below holds up to half a periodic side
 * (the nearest image is then the only one that near) and up to a side
 * with walls (beyond it the quarter disc leaves the rectangle's span). */
static double ideal_reach(const ideal_box *ib)
{
    double reach = INFINITY;
    for (int a = 0; a < 2; ++a)
        reach = fmin(reach, ib->walls[a] ? ib->side[a] : 0.5 * ib->side[a]);
    return reach;
}

/* F(r1) - F(r0): the probability that two independent centres, uniform in
 * the rectangle a x b of ib, are r0 to r1 apart. The separation's
 * components are independent: |dx| has density 2 (a - u) / a^2 on [0, a]
 * along an axis with walls, 2 / a on [0, a/2] along a periodic one
 * (nearest image). Integrated over the quarter disc u^2 + v^2 <= r^2
 * (inside the span while r is within ideal_reach):
 *   F(r) = (pi a b r^2 - 4/3 (a wy + b wx) r^3 + wx wy r^4 / 2) / (a b)^2,
 * wx, wy 1 along an axis with walls, 0 along a periodic one: pi r^2 / (a b)
 * in a periodic box, less the partners a wall takes from pairs near it.
 * The differences of powers are factored, so a thin shell loses nothing to
 * cancellation. */
static double ideal_shell(const ideal_box *ib, double r0, double r1)
{
    const double a = ib->side[0], b = ib->side[1], wx = ib->walls[0], wy = ib->walls[1];
    const double dr = r1 - r0, s = r1 + r0;
    const double d2 = dr * s, d3 = dr * (r1 * r1 + r1 * r0 + r0 * r0),
                 d4 = dr * s * (r1 * r1 + r0 * r0);
    const double pi = 3.14159265358979323846;
    return (pi * a * b * d2 - 4.0 / 3.0 * (a * wy + b * wx) * d3 + 0.5 * wx * wy * d4) /
           (a * b * a * b);
}

/* (r, g) of the centres c in box b, centres radius from any wall. */
static PyObject *rdf(centres *c, const box_args *b, double radius, double r_max, uint64_t bins)
{
    ideal_box ib;
    if (ideal_box_of(b, radius, &ib) < 0)
        return NULL;
    if (c->n < 2)
        return refuse("positions", (double)c->n, 2.0,
                      "g(r) needs at least two centres, and positions has %zu", c->n);
    const double reach = ideal_reach(&ib);
    if (!(r_max > 0.0 && r_max <= reach))
        return refuse("r_max", r_max, reach,
                      "r_max = %g must be > 0 and at most %g: half of each periodic side and "
                      "each side the walls leave the centres (box - 2 radius), where g(r)'s "
                      "ideal count holds",
                      r_max, reach);
    if (bins == 0)
        return refuse("bins", 0.0, 1.0, "bins = 0: there must be one");
    /* Bins of width dr from 0, their range no longer than r_max (which the
     * library's check of a periodic range needs to the last bit). */
    double dr = r_max / (double)bins;
    while (dr > 0.0 && (double)bins * dr > r_max)
        dr = nextafter(dr, 0.0);
    if (!(dr > 0.0))
        return refuse("bins", (double)bins, NAN, "bins = %llu: the bins of r_max = %g are empty",
                      (unsigned long long)bins, r_max);
    PyObject *counts = histogram(c, b, dr, bins);
    if (!counts)
        return NULL;
    npy_intp dims[1] = {(npy_intp)bins};
    PyArrayObject *r = (PyArrayObject *)PyArray_SimpleNew(1, dims, NPY_DOUBLE);
    PyArrayObject *g = r ? (PyArrayObject *)PyArray_SimpleNew(1, dims, NPY_DOUBLE) : NULL;
    if (!g) {
        Py_XDECREF(r);
        Py_DECREF(counts);
        return NULL;
    }
    const uint64_t *count = (const uint64_t *)PyArray_DATA((PyArrayObject *)counts);
    double *rs = (double *)PyArray_DATA(r), *gs = (double *)PyArray_DATA(g);
    const double pairs = 0.5 * (double)c->n * (double)(c->n - 1);
    for (uint64_t k = 0; k < bins; ++k) {
        const double r0 = (double)k * dr, r1 = (double)(k + 1) * dr;
        rs[k] = r0 + 0.5 * dr;
        gs[k] = (double)count[k] / (pairs * ideal_shell(&ib, r0, r1));
    }
    Py_DECREF(counts);
    return Py_BuildValue("(NN)", r, g);
}

const char dspy_rdf_doc[] =
    "rdf(positions, r_max, bins, *, box=1000.0, box_y=None, boundary='walls', radius=0.0)\n"
    "--\n\n"
    "The radial distribution function g(r) of the centres (an (n, 2) array, n >= 2):\n"
    "a tuple (r, g) of new (bins,) float64 arrays, r the middle of each of bins bins\n"
    "of width r_max / bins from 0, g the pairs counted in it (pair_histogram) over\n"
    "the pairs an ideal gas of n centres would have there on average, so that an\n"
    "ideal gas has g = 1 at every r, walls or not. That is n (n - 1) / 2 times the\n"
    "probability F(r1) - F(r0) that two uniform centres are r0 to r1 apart:\n"
    "periodic ('periodic'), F(r) = pi r^2 / (a b), the usual normalisation, with\n"
    "a x b = box x box_y; with walls, the centres fill a = box - 2 radius by\n"
    "b = box_y - 2 radius (radius: how far they keep from the walls, the disks'\n"
    "radius), and pairs near a wall lose the partners beyond it:\n"
    "F(r) = (pi a b r^2 - 4/3 (a + b) r^3 + r^4 / 2) / (a b)^2 ('walls');\n"
    "F(r) = (pi a b r^2 - 4/3 a r^3) / (a b)^2 in a channel (periodic along x,\n"
    "walls along y: b = box_y - 2 radius). r_max is at most half a periodic side\n"
    "and at most a side the walls leave (a, b), where F holds. ArgumentError for a\n"
    "value refused.";

PyObject *dspy_rdf(PyObject *module, PyObject *args, PyObject *kwargs)
{
    (void)module;
    static char *keywords[] = {"positions", "r_max",    "bins",   "box",
                               "box_y",     "boundary", "radius", NULL};
    PyObject *positions, *r_max_obj, *bins_obj, *box = NULL, *box_y = NULL, *boundary = NULL,
                                                *radius_obj = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "OOO|$OOOO:rdf", keywords, &positions,
                                     &r_max_obj, &bins_obj, &box, &box_y, &boundary, &radius_obj))
        return NULL;
    double r_max, radius = 0.0;
    uint64_t bins;
    box_args b;
    centres c = {0, NULL, NULL};
    if (dspy_double_arg(r_max_obj, "r_max", &r_max) < 0 ||
        dspy_uint64_arg(bins_obj, "bins", 1, &bins) < 0 ||
        box_from_args(&b, box, box_y, boundary) < 0 ||
        (radius_obj && dspy_double_arg(radius_obj, "radius", &radius) < 0) ||
        centres_from_array(&c, positions) < 0)
        return NULL;
    PyObject *r = rdf(&c, &b, radius, r_max, bins);
    centres_free(&c);
    return r;
}

/* The mean radius: where a mixture's centres keep from the walls, on
 * average over pairs (the ideal count of a pair i, j goes as
 * 1 / (box - r_i - r_j), whose mean over pairs the mean radius gives to
 * first order in the radii over the box; exact for disks of one radius). */
static int mean_radius(const ds_sim *sim, double *mean)
{
    const size_t n = ds_sim_get_count(sim);
    double *radii = PyMem_RawMalloc(n * sizeof *radii + 1);
    if (!radii) {
        PyErr_NoMemory();
        return -1;
    }
    ds_sim_get_radii(sim, radii, NULL);
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i)
        sum += radii[i];
    PyMem_RawFree(radii);
    *mean = sum / (double)n;
    return 0;
}

PyObject *dspy_sim_rdf(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"r_max", "bins", NULL};
    PyObject *r_max_obj, *bins_obj;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "OO:rdf", keywords, &r_max_obj, &bins_obj))
        return NULL;
    double r_max, radius;
    uint64_t bins;
    if (dspy_double_arg(r_max_obj, "r_max", &r_max) < 0 ||
        dspy_uint64_arg(bins_obj, "bins", 1, &bins) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    centres c = {0, NULL, NULL};
    if (!sim || mean_radius(sim, &radius) < 0 || centres_from_sim(&c, sim) < 0)
        return NULL;
    const box_args b = {ds_sim_get_box_width(sim), ds_sim_get_box_height(sim),
                        ds_sim_get_boundary(sim)};
    PyObject *r = rdf(&c, &b, radius, r_max, bins);
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
