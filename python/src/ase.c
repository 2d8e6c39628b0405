/* SPDX-License-Identifier: MIT */
/* Sim.to_ase: the disks as an ase.Atoms, the same as ASE's reading of the
 * library's extended XYZ frame (src/io/xyz.c): a flat layer of dummy
 * atoms "X" at z = 0 in a cell box x box_y x 2R, pbc along x and y in a
 * periodic box, per-atom arrays "radius" and "velo" (z = 0), info "Time".
 * ASE is imported when called, so the module needs it only for this. */
#include "disksim_py.h"

/* A new (n, 3) float64 array of disks' positions (or velocities), z = 0. */
static PyObject *xyz_array(const ds_disk *disks, size_t n, int velocities)
{
    npy_intp dims[2] = {(npy_intp)n, 3};
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!a)
        return NULL;
    double *out = (double *)PyArray_DATA(a);
    for (size_t i = 0; i < n; ++i) {
        out[3 * i] = velocities ? disks[i].vx : disks[i].x;
        out[3 * i + 1] = velocities ? disks[i].vy : disks[i].y;
        out[3 * i + 2] = 0.0;
    }
    return (PyObject *)a;
}

static PyObject *filled(size_t n, double value, int type)
{
    npy_intp dims[1] = {(npy_intp)n};
    PyArrayObject *a = (PyArrayObject *)PyArray_ZEROS(1, dims, type, 0);
    if (a && type == NPY_DOUBLE) {
        double *out = (double *)PyArray_DATA(a);
        for (size_t i = 0; i < n; ++i)
            out[i] = value;
    }
    return (PyObject *)a;
}

PyObject *dspy_sim_to_ase(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    /* Imported first: importing runs Python code, which might close this
     * Sim; the ds_sim is fetched afterwards. */
    PyObject *ase = PyImport_ImportModule("ase");
    if (!ase) {
        if (PyErr_ExceptionMatches(PyExc_ImportError)) {
            PyObject *cause = dspy_take_exception();
            PyErr_SetString(PyExc_ImportError,
                            "Sim.to_ase needs ASE, which is not installed (Debian: python3-ase)");
            dspy_set_cause(cause);
        }
        return NULL;
    }
    ds_sim *sim = dspy_sim_of(self);
    ds_disk *disks = sim ? dspy_get_all(sim) : NULL;
    if (!disks) {
        Py_DECREF(ase);
        return NULL;
    }
    const size_t n = ds_sim_get_count(sim);
    /* The library's XYZ: each disk's radius, the cell 2 r_max high. */
    const double r = ds_sim_get_radius_max(sim), box = ds_sim_get_box_width(sim),
                 box_y = ds_sim_get_box_height(sim), t = ds_sim_get_time(sim);
    /* Periodic along x in a channel and a periodic box, along y in a
     * periodic box only. */
    const ds_boundary boundary = ds_sim_get_boundary(sim);
    const int periodic = boundary == DS_BOUNDARY_PERIODIC;
    const int periodic_x = periodic || boundary == DS_BOUNDARY_CHANNEL;
    PyObject *positions = xyz_array(disks, n, 0), *velo = xyz_array(disks, n, 1);
    PyMem_RawFree(disks);
    PyObject *numbers = filled(n, 0.0, NPY_INT64), *radius = filled(n, r, NPY_DOUBLE);
    if (radius)
        ds_sim_get_radii(sim, (double *)PyArray_DATA((PyArrayObject *)radius), NULL);
    PyObject *cell = Py_BuildValue("[ddd]", box, box_y, 2.0 * r);
    PyObject *pbc = Py_BuildValue("[OOO]", periodic_x ? Py_True : Py_False,
                                  periodic ? Py_True : Py_False, Py_False);
    PyObject *atoms = NULL;
    if (positions && velo && numbers && radius && cell && pbc) {
        PyObject *atoms_type = PyObject_GetAttrString(ase, "Atoms");
        PyObject *kwargs = atoms_type ? Py_BuildValue("{sOsOsOsO}", "numbers", numbers, "positions",
                                                      positions, "cell", cell, "pbc", pbc)
                                      : NULL;
        PyObject *empty = kwargs ? PyTuple_New(0) : NULL;
        atoms = empty ? PyObject_Call(atoms_type, empty, kwargs) : NULL;
        PyObject *a =
            atoms ? PyObject_CallMethod(atoms, "set_array", "sO", "radius", radius) : NULL;
        PyObject *b = a ? PyObject_CallMethod(atoms, "set_array", "sO", "velo", velo) : NULL;
        PyObject *info = b ? PyObject_GetAttrString(atoms, "info") : NULL;
        PyObject *key = info ? PyUnicode_FromString("Time") : NULL;
        PyObject *time = key ? PyFloat_FromDouble(t) : NULL;
        if (!time || PyObject_SetItem(info, key, time) < 0)
            Py_CLEAR(atoms);
        Py_XDECREF(time);
        Py_XDECREF(key);
        Py_XDECREF(info);
        Py_XDECREF(b);
        Py_XDECREF(a);
        Py_XDECREF(empty);
        Py_XDECREF(kwargs);
        Py_XDECREF(atoms_type);
    }
    Py_XDECREF(positions);
    Py_XDECREF(velo);
    Py_XDECREF(numbers);
    Py_XDECREF(radius);
    Py_XDECREF(cell);
    Py_XDECREF(pbc);
    Py_DECREF(ase);
    return atoms;
}
