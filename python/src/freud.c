/* SPDX-License-Identifier: MIT */
/* Sim.freud_box and Sim.freud_points: the disks as freud and HOOMD-blue
 * take a system, a box centred on the origin and (n, 3) points with z = 0.
 * The library's box is [0, box) x [0, box_y); theirs is [-L/2, L/2) along
 * each axis, so each centre moves by half a side. Neither package is
 * imported (freud is not in Debian): the box is the dict both
 * Box.from_box read, and the points a float64 array either converts. */
#include "disksim_py.h"

const char dspy_freud_box_doc[] =
    "freud_box($self, /)\n--\n\n"
    "The box as freud.box.Box.from_box() and hoomd.Box.from_box() take it: a new dict\n"
    "{'Lx': box, 'Ly': box_y, 'Lz': 0.0, 'xy': 0.0, 'xz': 0.0, 'yz': 0.0,\n"
    "'dimensions': 2}, a two-dimensional box (Lz = 0, no tilt) centred on the origin,\n"
    "where freud_points() are. freud boxes are periodic along every axis: with\n"
    "walls, set box.periodic = False on the freud.box.Box made from it, in a channel\n"
    "box.periodic_y = False, so that no pair is taken across a wall.";

PyObject *dspy_sim_freud_box(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    return Py_BuildValue("{s:d,s:d,s:d,s:d,s:d,s:d,s:i}", "Lx", ds_sim_get_box_width(sim), "Ly",
                         ds_sim_get_box_height(sim), "Lz", 0.0, "xy", 0.0, "xz", 0.0, "yz", 0.0,
                         "dimensions", 2);
}

const char dspy_freud_points_doc[] =
    "freud_points($self, /)\n--\n\n"
    "The centres as freud and HOOMD-blue take points: a new (n, 3) float64 array, row\n"
    "i disk i (generation order), (x - box/2, y - box_y/2, 0), in the box\n"
    "freud_box() describes, centred on the origin. In a periodic box every point is\n"
    "in [-box/2, box/2) x [-box_y/2, box_y/2), as freud's and HOOMD's wrapped points\n"
    "are (x - box/2 is exact for x >= box/2). freud computes in float32 and converts\n"
    "them; the system is (s.freud_box(), s.freud_points()).";

PyObject *dspy_sim_freud_points(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const size_t n = ds_sim_get_count(sim);
    npy_intp dims[2] = {(npy_intp)n, 3};
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    ds_disk *disks = a ? dspy_get_all(sim) : NULL;
    if (!disks) {
        Py_XDECREF(a);
        return NULL;
    }
    /* Halving is exact, and so is x - box/2 for x in [box/2, box) (Sterbenz):
     * no centre of a periodic box rounds up onto +box/2. */
    const double hx = 0.5 * ds_sim_get_box_width(sim), hy = 0.5 * ds_sim_get_box_height(sim);
    double *out = (double *)PyArray_DATA(a);
    for (size_t i = 0; i < n; ++i) {
        out[3 * i] = disks[i].x - hx;
        out[3 * i + 1] = disks[i].y - hy;
        out[3 * i + 2] = 0.0;
    }
    PyMem_RawFree(disks);
    return (PyObject *)a;
}
