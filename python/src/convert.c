/* SPDX-License-Identifier: MIT */
/* Arguments from Python values, with the module's rule for what is raised:
 * TypeError for a value of the wrong type, ArgumentError (a ValueError)
 * for a value of the right type that cannot be used, NoMemoryError for a
 * size this machine cannot hold. Ranges beyond that are the library's to
 * judge, in its words. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <string.h>
#include <unistd.h>

int dspy_uint64_arg(PyObject *value, const char *field, int is_count, uint64_t *out)
{
    /* A bool is an int to Python, but True for n or a seed is a slip, not a
     * count: refused as numpy refuses np.zeros(True). */
    if (PyBool_Check(value) || PyArray_IsScalar(value, Bool)) {
        PyErr_Format(PyExc_TypeError, "%s must be an int, not %.100s", field,
                     Py_TYPE(value)->tp_name);
        return -1;
    }
    if (!PyIndex_Check(value)) {
        PyErr_Format(PyExc_TypeError, "%s must be an int, not %.100s", field,
                     Py_TYPE(value)->tp_name);
        return -1;
    }
    PyObject *index = PyNumber_Index(value);
    if (!index)
        return -1;
    int overflow = 0;
    const long long small = PyLong_AsLongLongAndOverflow(index, &overflow);
    if (small == -1 && !overflow && PyErr_Occurred()) {
        Py_DECREF(index);
        return -1;
    }
    int status = 0;
    if (overflow < 0 || (!overflow && small < 0)) {
        PyObject *message = PyUnicode_FromFormat("%s = %S must not be negative", field, index);
        const char *text = message ? PyUnicode_AsUTF8(message) : NULL;
        if (text)
            dspy_raise(DS_ERR_ARG, field, text);
        Py_XDECREF(message);
        status = -1;
    } else {
        const unsigned long long big = PyLong_AsUnsignedLongLong(index);
        if (big == (unsigned long long)-1 && PyErr_Occurred()) {
            PyErr_Clear();
            /* Beyond 2**64 - 1: for a count of things in memory, too many to
             * hold, as the library says of a count beyond what it can hold. */
            PyObject *message = PyUnicode_FromFormat(is_count ? "%s = %S cannot be held in memory"
                                                              : "%s = %S is beyond 2**64 - 1",
                                                     field, index);
            const char *text = message ? PyUnicode_AsUTF8(message) : NULL;
            if (text)
                dspy_raise(is_count ? DS_ERR_NOMEM : DS_ERR_ARG, field, text);
            Py_XDECREF(message);
            status = -1;
        } else {
            *out = (uint64_t)big;
        }
    }
    Py_DECREF(index);
    return status;
}

int dspy_double_arg(PyObject *value, const char *field, double *out)
{
    if (PyFloat_Check(value)) {
        *out = PyFloat_AS_DOUBLE(value);
        return 0;
    }
    const PyNumberMethods *nb = Py_TYPE(value)->tp_as_number;
    if (!nb || (!nb->nb_float && !nb->nb_index)) {
        PyErr_Format(PyExc_TypeError, "%s must be a real number, not %.100s", field,
                     Py_TYPE(value)->tp_name);
        return -1;
    }
    const double v = PyFloat_AsDouble(value);
    if (v == -1.0 && PyErr_Occurred()) {
        if (PyErr_ExceptionMatches(PyExc_OverflowError)) {
            PyErr_Clear();
            dspy_raisef(DS_ERR_ARG, field, "%s is too large to be a float", field);
        }
        return -1;
    }
    *out = v;
    return 0;
}

uint64_t dspy_physical_memory(void)
{
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? (uint64_t)pages * (uint64_t)page : 0;
}

int dspy_check_memory(double bytes, const char *what)
{
    const uint64_t physical = dspy_physical_memory();
    if (physical && !(bytes <= (double)physical)) {
        dspy_raisef(DS_ERR_NOMEM, NULL,
                    "%s needs %.3g GB, more than the %.3g GB of memory of this machine", what,
                    bytes / 1e9, (double)physical / 1e9);
        return -1;
    }
    return 0;
}

PyArrayObject *dspy_new_xy(size_t n)
{
    npy_intp dims[2] = {(npy_intp)n, 2};
    return (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
}

PyArrayObject *dspy_xy_array(PyObject *value, const char *field, size_t want)
{
    /* The "safe" casting rule: ints and floats are read, complex numbers
     * and objects are a TypeError, text numpy cannot parse a ValueError. */
    PyArrayObject *a =
        (PyArrayObject *)PyArray_FROMANY(value, NPY_DOUBLE, 0, 0, NPY_ARRAY_IN_ARRAY);
    if (!a) {
        if (PyErr_ExceptionMatches(PyExc_ValueError)) {
            PyObject *cause = dspy_take_exception();
            PyObject *text = cause ? PyObject_Str(cause) : NULL;
            const char *s = text ? PyUnicode_AsUTF8(text) : NULL;
            if (s)
                dspy_raisef(DS_ERR_ARG, field, "%s must be an (n, 2) array of numbers: %s", field,
                            s);
            Py_XDECREF(text);
            dspy_set_cause(cause);
        }
        return NULL;
    }
    const int ndim = PyArray_NDIM(a);
    const npy_intp *dims = PyArray_DIMS(a);
    if (ndim != 2 || dims[1] != 2 || (want != (size_t)-1 && (size_t)dims[0] != want)) {
        char shape[96] = "";
        for (int k = 0; k < ndim && k < 4; ++k)
            PyOS_snprintf(shape + strlen(shape), sizeof shape - strlen(shape), "%s%ld",
                          k ? ", " : "", (long)dims[k]);
        if (ndim == 1)
            strcat(shape, ",");
        if (want == (size_t)-1)
            dspy_raisef(DS_ERR_ARG, field, "%s has shape (%s%s): it must be (n, 2)", field, shape,
                        ndim > 4 ? ", ..." : "");
        else
            dspy_raisef(DS_ERR_ARG, field,
                        "%s has shape (%s%s): it must be (%zu, 2), one row per disk", field, shape,
                        ndim > 4 ? ", ..." : "", want);
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

int dspy_path_arg(PyObject *value, PyObject **bytes)
{
    *bytes = NULL;
    if (PyUnicode_FSConverter(value, bytes))
        return 0;
    if (PyErr_ExceptionMatches(PyExc_ValueError)) {
        PyErr_Clear();
        dspy_raise(DS_ERR_ARG, "path", "path contains a NUL character");
    }
    return -1;
}

PyArrayObject *dspy_vector_array(PyObject *value, const char *field, size_t want)
{
    PyArrayObject *a =
        (PyArrayObject *)PyArray_FROMANY(value, NPY_DOUBLE, 0, 0, NPY_ARRAY_IN_ARRAY);
    if (!a) {
        if (PyErr_ExceptionMatches(PyExc_ValueError)) {
            PyObject *cause = dspy_take_exception();
            PyObject *text = cause ? PyObject_Str(cause) : NULL;
            const char *s = text ? PyUnicode_AsUTF8(text) : NULL;
            if (s)
                dspy_raisef(DS_ERR_ARG, field, "%s must be an (n,) array of numbers: %s", field, s);
            Py_XDECREF(text);
            dspy_set_cause(cause);
        }
        return NULL;
    }
    const int ndim = PyArray_NDIM(a);
    if (ndim != 1 || (size_t)PyArray_DIM(a, 0) != want) {
        char shape[96] = "";
        for (int k = 0; k < ndim && k < 4; ++k)
            PyOS_snprintf(shape + strlen(shape), sizeof shape - strlen(shape), "%s%ld",
                          k ? ", " : "", (long)PyArray_DIM(a, k));
        if (ndim == 1)
            strcat(shape, ",");
        dspy_raisef(DS_ERR_ARG, field, "%s has shape (%s%s): it must be (%zu,), one per disk (n)",
                    field, shape, ndim > 4 ? ", ..." : "", want);
        Py_DECREF(a);
        return NULL;
    }
    return a;
}
