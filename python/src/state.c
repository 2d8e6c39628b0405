/* SPDX-License-Identifier: MIT */
/* A Sim's state as arrays: positions, velocities, unwrapped centres and
 * image counts out (ds_sim_get_disks, ds_sim_get_unwrapped,
 * ds_sim_get_images, a fresh copy each time), and set_state in
 * (ds_sim_set_disks, which checks the whole state before anything changes).
 *
 * Converting an argument can run Python code (an object's __array__ or
 * __float__), which could close or re-create this very Sim: the ds_sim is
 * therefore fetched only after every argument has been converted. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <string.h>

ds_disk *dspy_get_all(const ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    ds_disk *disks =
        n <= PY_SSIZE_T_MAX / sizeof *disks ? PyMem_RawMalloc(n * sizeof *disks + 1) : NULL;
    if (!disks) {
        PyErr_NoMemory();
        return NULL;
    }
    ds_sim_get_disks(sim, disks, NULL);
    return disks;
}

static PyObject *xy_of(dspy_sim *self, int velocities)
{
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const size_t n = ds_sim_get_count(sim);
    PyArrayObject *a = dspy_new_xy(n);
    ds_disk *disks = a ? dspy_get_all(sim) : NULL;
    if (!disks) {
        Py_XDECREF(a);
        return NULL;
    }
    double *out = (double *)PyArray_DATA(a);
    for (size_t i = 0; i < n; ++i) {
        out[2 * i] = velocities ? disks[i].vx : disks[i].x;
        out[2 * i + 1] = velocities ? disks[i].vy : disks[i].y;
    }
    PyMem_RawFree(disks);
    return (PyObject *)a;
}

PyObject *dspy_positions_property(dspy_sim *self, void *closure)
{
    (void)closure;
    return xy_of(self, 0);
}

PyObject *dspy_velocities_property(dspy_sim *self, void *closure)
{
    (void)closure;
    return xy_of(self, 1);
}

PyObject *dspy_unwrapped_property(dspy_sim *self, void *closure)
{
    (void)closure;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    PyArrayObject *a = dspy_new_xy(ds_sim_get_count(sim));
    if (a)
        ds_sim_get_unwrapped(sim, (double *)PyArray_DATA(a), NULL);
    return (PyObject *)a;
}

PyObject *dspy_images_property(dspy_sim *self, void *closure)
{
    (void)closure;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    npy_intp dims[2] = {(npy_intp)ds_sim_get_count(sim), 2};
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_INT32);
    ds_error err;
    if (a && ds_sim_get_images(sim, (int32_t *)PyArray_DATA(a), &err) != DS_OK) {
        Py_DECREF(a);
        return dspy_raise_error(&err);
    }
    return (PyObject *)a;
}

PyObject *dspy_sim_set_state(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"positions", "velocities", NULL};
    PyObject *positions_obj, *velocities_obj = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|O:set_state", keywords, &positions_obj,
                                     &velocities_obj))
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const size_t n = ds_sim_get_count(sim);
    PyArrayObject *positions = dspy_xy_array(positions_obj, "positions", n);
    PyArrayObject *velocities = positions && velocities_obj != Py_None
                                    ? dspy_xy_array(velocities_obj, "velocities", n)
                                    : NULL;
    ds_disk *disks = NULL;
    PyObject *result = NULL;
    if (!positions || (velocities_obj != Py_None && !velocities))
        goto done;
    /* Fetched again: the conversions may have run Python code. */
    sim = dspy_sim_of(self);
    if (!sim)
        goto done;
    if (ds_sim_get_count(sim) != n) {
        dspy_raisef(DS_ERR_ARG, "positions", "this Sim was re-created with %zu disks meanwhile",
                    ds_sim_get_count(sim));
        goto done;
    }
    disks = dspy_get_all(sim);
    if (!disks)
        goto done;
    const double *xy = (const double *)PyArray_DATA(positions);
    const double *v = velocities ? (const double *)PyArray_DATA(velocities) : NULL;
    for (size_t i = 0; i < n; ++i) {
        disks[i].x = xy[2 * i];
        disks[i].y = xy[2 * i + 1];
        if (v) {
            disks[i].vx = v[2 * i];
            disks[i].vy = v[2 * i + 1];
        }
    }
    ds_error err;
    ds_status st;
    self->busy = 1;
    Py_BEGIN_ALLOW_THREADS
    st = ds_sim_set_disks(sim, disks, &err);
    Py_END_ALLOW_THREADS
    self->busy = 0;
    if (st != DS_OK)
        dspy_raise_error(&err);
    else
        result = Py_NewRef(Py_None);
done:
    PyMem_RawFree(disks);
    Py_XDECREF(positions);
    Py_XDECREF(velocities);
    return result;
}
