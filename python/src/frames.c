/* SPDX-License-Identifier: MIT */
/* Frames: Sim.write_frame (ds_frame_write, ds_frame_write) and
 * disksim.read_frame (ds_frame_read) returning a Frame of arrays. Files
 * are read and written with the GIL released. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <errno.h>
#include <stdio.h>
#include <string.h>

static PyTypeObject *frame_type;

static PyStructSequence_Field frame_fields[] = {
    {"positions", "the centres, an (n, 2) float64 array, one row per line of the file"},
    {"radii", "the radii, an (n,) float64 array"},
    {"velocities", "the velocities, an (n, 2) float64 array, or None for a frame of 3 columns"},
    {NULL, NULL},
};

static PyStructSequence_Desc frame_desc = {
    "disksim.Frame",
    "Frame(positions, radii, velocities): a frame file read by read_frame(), as\n"
    "arrays. A named tuple: positions, radii, velocities = read_frame(path).",
    frame_fields,
    3,
};

int dspy_add_frame_type(PyObject *module)
{
    frame_type = PyStructSequence_NewType(&frame_desc);
    if (!frame_type)
        return -1;
    /* The module keeps the type; this file keeps a reference for itself. */
    return PyModule_AddObjectRef(module, "Frame", (PyObject *)frame_type);
}

PyObject *dspy_sim_write_frame(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"path", "velocities", NULL};
    PyObject *path_obj;
    int velocities = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|p:write_frame", keywords, &path_obj,
                                     &velocities))
        return NULL;
    PyObject *path;
    if (dspy_path_arg(path_obj, &path) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim) {
        Py_DECREF(path);
        return NULL;
    }
    const char *name = PyBytes_AS_STRING(path);
    ds_status st = DS_OK;
    ds_error err;
    int errnum = 0;
    self->busy = 1;
    Py_BEGIN_ALLOW_THREADS
    errno = 0;
    FILE *f = fopen(name, "w");
    if (!f) {
        st = DS_ERR_IO;
        errnum = errno;
    } else {
        st = ds_frame_write(sim, velocities != 0, f, &err);
        errnum = st == DS_ERR_IO ? errno : 0;
        if (fclose(f) != 0 && st == DS_OK) {
            st = DS_ERR_IO;
            errnum = errno;
        }
    }
    Py_END_ALLOW_THREADS
    self->busy = 0;
    PyObject *result = NULL;
    if (st == DS_ERR_IO)
        dspy_raise_file(errnum, errnum ? strerror(errnum) : "the frame could not be written",
                        path_obj);
    else if (st != DS_OK)
        dspy_raise_error(&err);
    else
        result = Py_NewRef(Py_None);
    Py_DECREF(path);
    return result;
}

/* A new array of count rows of width columns (1: a vector) from the
 * frame, column first of each disk's values. */
static PyObject *column_array(const ds_frame *frame, int width, int first)
{
    npy_intp dims[2] = {(npy_intp)frame->count, width};
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(width == 1 ? 1 : 2, dims, NPY_DOUBLE);
    if (!a)
        return NULL;
    double *out = (double *)PyArray_DATA(a);
    for (size_t i = 0; i < frame->count; ++i) {
        const ds_frame_disk *d = &frame->disks[i];
        const double values[5] = {d->x, d->y, d->r, d->vx, d->vy};
        for (int c = 0; c < width; ++c)
            out[(size_t)width * i + (size_t)c] = values[first + c];
    }
    return (PyObject *)a;
}

const char dspy_read_frame_doc[] =
    "read_frame(path)\n--\n\n"
    "Read a frame file (as written by the disks command or Sim.write_frame) into a\n"
    "Frame(positions, radii, velocities) of arrays: positions (n, 2), radii (n,),\n"
    "velocities (n, 2) or None when the lines have 3 columns. Every line holds 3\n"
    "or 5 finite numbers, all lines the same count, R > 0; blank lines and lines\n"
    "starting with '#' are skipped. FormatError (a ValueError) naming the line\n"
    "and why otherwise (e.line is the line number), FileError (an OSError) if the\n"
    "file cannot be read.";
PyObject *dspy_read_frame(PyObject *module, PyObject *args, PyObject *kwargs)
{
    (void)module;
    static char *keywords[] = {"path", NULL};
    PyObject *path_obj;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:read_frame", keywords, &path_obj))
        return NULL;
    PyObject *path;
    if (dspy_path_arg(path_obj, &path) < 0)
        return NULL;
    ds_frame frame;
    ds_error err;
    ds_status st;
    int errnum = 0;
    Py_BEGIN_ALLOW_THREADS
    errno = 0;
    st = ds_frame_read(PyBytes_AS_STRING(path), &frame, &err);
    errnum = st == DS_ERR_IO ? errno : 0;
    Py_END_ALLOW_THREADS
    Py_DECREF(path);
    if (st == DS_ERR_IO)
        return dspy_raise_file(errnum, err.message, path_obj);
    if (st == DS_ERR_FORMAT)
        return dspy_raise_format(path_obj, err.index, err.message);
    if (st != DS_OK)
        return dspy_raise_error(&err);
    PyObject *positions = column_array(&frame, 2, 0);
    PyObject *radii = positions ? column_array(&frame, 1, 2) : NULL;
    PyObject *velocities =
        radii ? (frame.columns == 5 ? column_array(&frame, 2, 3) : Py_NewRef(Py_None)) : NULL;
    ds_frame_free(&frame);
    PyObject *result = velocities ? PyStructSequence_New(frame_type) : NULL;
    if (!result) {
        Py_XDECREF(positions);
        Py_XDECREF(radii);
        Py_XDECREF(velocities);
        return NULL;
    }
    PyStructSequence_SetItem(result, 0, positions);
    PyStructSequence_SetItem(result, 1, radii);
    PyStructSequence_SetItem(result, 2, velocities);
    return result;
}
