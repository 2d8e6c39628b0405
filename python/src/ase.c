/* SPDX-License-Identifier: MIT */
/* Sim.to_ase: the disks as an ase.Atoms, the same as ASE reads from the
 * library's extended XYZ frame (src/io/xyz.c): a flat layer of dummy
 * atoms "X" at z = 0 in a cell box x box_y x 2 r_max, pbc along each
 * periodic axis, per-atom arrays "type" (the kinds' names), "radius",
 * "velo", "momenta" (so get_velocities() is the velocities), "mass" and
 * "masses" (get_masses()), "map_shift" (the image counts, in a periodic
 * box), info "Time". ASE is imported when called, so the module needs it
 * only for this. */
#include "disksim_py.h"

/* A new (n, 3) float64 array of the disks' positions, velocities or
 * momenta (velocities times masses), z = 0. */
enum { POSITIONS, VELOCITIES, MOMENTA };
static PyObject *xyz_array(const ds_disk *disks, const double *masses, size_t n, int what)
{
    npy_intp dims[2] = {(npy_intp)n, 3};
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!a)
        return NULL;
    double *out = (double *)PyArray_DATA(a);
    for (size_t i = 0; i < n; ++i) {
        const double m = what == MOMENTA ? masses[i] : 1.0;
        out[3 * i] = what == POSITIONS ? disks[i].x : m * disks[i].vx;
        out[3 * i + 1] = what == POSITIONS ? disks[i].y : m * disks[i].vy;
        out[3 * i + 2] = 0.0;
    }
    return (PyObject *)a;
}

/* A new (n,) array of type (float64 or int64, zeros), or (n, 3) int32 of
 * the image counts and 0. */
static PyObject *zeros(size_t n, int type, int columns)
{
    npy_intp dims[2] = {(npy_intp)n, columns};
    return PyArray_ZEROS(columns > 1 ? 2 : 1, dims, type, 0);
}

/* The (n,) object array of each disk's kind's name. */
static PyObject *type_array(const ds_sim *sim, size_t n)
{
    npy_intp dims[1] = {(npy_intp)n};
    uint32_t *kinds = PyMem_RawMalloc(n * sizeof *kinds + 1);
    PyObject *a = kinds ? PyArray_SimpleNew(1, dims, NPY_OBJECT) : PyErr_NoMemory();
    if (a)
        ds_sim_get_kinds(sim, kinds, NULL);
    for (size_t i = 0; a && i < n; ++i) {
        PyObject *name = PyUnicode_FromString(ds_sim_get_kind_name(sim, kinds[i]));
        if (!name)
            Py_CLEAR(a);
        else
            ((PyObject **)PyArray_DATA((PyArrayObject *)a))[i] = name; /* was NULL */
    }
    PyMem_RawFree(kinds);
    return a;
}

/* The per-atom arrays, name by name, onto atoms; -1 with an exception. */
static int set_arrays(PyObject *atoms, const char *const *names, PyObject *const *arrays,
                      size_t count)
{
    for (size_t k = 0; k < count; ++k) {
        if (!arrays[k])
            continue; /* map_shift outside a periodic box */
        PyObject *r = PyObject_CallMethod(atoms, "set_array", "sO", names[k], arrays[k]);
        if (!r)
            return -1;
        Py_DECREF(r);
    }
    return 0;
}

/* An ase.Atoms of numbers (all "X"), positions, cell and pbc, with info
 * Time = t; NULL with an exception. */
static PyObject *new_atoms(PyObject *ase, PyObject *numbers, PyObject *positions, const ds_sim *sim)
{
    const ds_boundary boundary = ds_sim_get_boundary(sim);
    /* Periodic along x in a channel and a periodic box, along y in a
     * periodic box only. */
    const int periodic = boundary == DS_BOUNDARY_PERIODIC;
    const int periodic_x = periodic || boundary == DS_BOUNDARY_CHANNEL;
    PyObject *cell = Py_BuildValue("[ddd]", ds_sim_get_box_width(sim), ds_sim_get_box_height(sim),
                                   2.0 * ds_sim_get_radius_max(sim));
    PyObject *pbc = Py_BuildValue("[OOO]", periodic_x ? Py_True : Py_False,
                                  periodic ? Py_True : Py_False, Py_False);
    PyObject *type = PyObject_GetAttrString(ase, "Atoms");
    PyObject *kwargs = cell && pbc && type
                           ? Py_BuildValue("{sOsOsOsO}", "numbers", numbers, "positions", positions,
                                           "cell", cell, "pbc", pbc)
                           : NULL;
    PyObject *empty = kwargs ? PyTuple_New(0) : NULL;
    PyObject *atoms = empty ? PyObject_Call(type, empty, kwargs) : NULL;
    PyObject *info = atoms ? PyObject_GetAttrString(atoms, "info") : NULL;
    PyObject *time = info ? PyFloat_FromDouble(ds_sim_get_time(sim)) : NULL;
    if (!time || PyDict_SetItemString(info, "Time", time) < 0)
        Py_CLEAR(atoms);
    Py_XDECREF(time);
    Py_XDECREF(info);
    Py_XDECREF(empty);
    Py_XDECREF(kwargs);
    Py_XDECREF(type);
    Py_XDECREF(pbc);
    Py_XDECREF(cell);
    return atoms;
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
    /* The columns of the library's XYZ, in its order. */
    enum { TYPE, RADIUS, VELO, MOMENTA_, MASS, MASSES, MAP_SHIFT, COLUMNS };
    static const char *const names[COLUMNS] = {"type", "radius", "velo",     "momenta",
                                               "mass", "masses", "map_shift"};
    PyObject *a[COLUMNS] = {NULL};
    a[TYPE] = type_array(sim, n);
    a[RADIUS] = zeros(n, NPY_DOUBLE, 1);
    a[MASS] = zeros(n, NPY_DOUBLE, 1);
    if (a[RADIUS] && a[MASS]) {
        ds_sim_get_radii(sim, (double *)PyArray_DATA((PyArrayObject *)a[RADIUS]), NULL);
        ds_sim_get_masses(sim, (double *)PyArray_DATA((PyArrayObject *)a[MASS]), NULL);
        a[MASSES] = PyArray_NewCopy((PyArrayObject *)a[MASS], NPY_CORDER);
        a[VELO] = xyz_array(disks, NULL, n, VELOCITIES);
        a[MOMENTA_] =
            xyz_array(disks, (double *)PyArray_DATA((PyArrayObject *)a[MASS]), n, MOMENTA);
    }
    int ok = a[TYPE] && a[RADIUS] && a[VELO] && a[MOMENTA_] && a[MASS] && a[MASSES];
    if (ok && ds_sim_get_boundary(sim) != DS_BOUNDARY_WALLS) {
        /* ix iy from the library's (n, 2) counts, z 0. */
        int32_t *shift = (a[MAP_SHIFT] = zeros(n, NPY_INT32, 3))
                             ? (int32_t *)PyArray_DATA((PyArrayObject *)a[MAP_SHIFT])
                             : NULL;
        int32_t *image = shift ? PyMem_RawMalloc(2 * n * sizeof *image + 1) : NULL;
        ok = image && ds_sim_get_images(sim, image, NULL) == DS_OK;
        for (size_t i = 0; ok && i < n; ++i) {
            shift[3 * i] = image[2 * i];
            shift[3 * i + 1] = image[2 * i + 1];
        }
        if (shift && !image)
            PyErr_NoMemory();
        PyMem_RawFree(image);
    }
    PyObject *numbers = ok ? zeros(n, NPY_INT64, 1) : NULL;
    PyObject *positions = numbers ? xyz_array(disks, NULL, n, POSITIONS) : NULL;
    PyMem_RawFree(disks);
    PyObject *atoms = positions ? new_atoms(ase, numbers, positions, sim) : NULL;
    if (atoms && set_arrays(atoms, names, a, COLUMNS) < 0)
        Py_CLEAR(atoms);
    for (int k = 0; k < COLUMNS; ++k)
        Py_XDECREF(a[k]);
    Py_XDECREF(numbers);
    Py_XDECREF(positions);
    Py_DECREF(ase);
    return atoms;
}
