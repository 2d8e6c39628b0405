/* SPDX-License-Identifier: MIT */
/* The exceptions of disksim and how a ds_status becomes one.
 *
 * Every failure the library reports raises disksim.Error or a subclass,
 * with the library's own sentence as the message. The subclasses also
 * derive from the built-in exception a Python caller would catch for that
 * kind of failure, so `except ValueError` and `except OSError` work:
 *
 *   ArgumentError  (Error, ValueError)   DS_ERR_ARG, DS_ERR_PLACEMENT,
 *                                        DS_ERR_OVERLAP: a value refused
 *   FormatError    (Error, ValueError)   DS_ERR_FORMAT: a malformed frame
 *                                        or checkpoint
 *   FileError      (Error, OSError)      DS_ERR_IO: a file not read or written
 *   NoMemoryError  (Error, MemoryError)  DS_ERR_NOMEM, or more than the
 *                                        machine's memory asked for
 *
 * Each carries `status`, the name of the ds_status enumerator, `field`,
 * what the library names at fault (a ds_params member, an argument:
 * ds_error's field; else None), and `value` and `limit`, the number
 * refused and the limit it broke (else None): the library's reason, which
 * the module passes on without deriving its rules again. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

PyObject *dspy_Error, *dspy_ArgumentError, *dspy_FormatError, *dspy_FileError, *dspy_NoMemoryError;

static const char error_doc[] =
    "Error(message)\n\n"
    "Every failure disksim reports: the library's sentence saying what was refused\n"
    "and why. Attributes: status, the name of the library's ds_status (e.g.\n"
    "'DS_ERR_ARG'); field, what is at fault as the library names it (e.g. 'radius',\n"
    "'rate') or None; value and limit, the number refused and the limit it broke, or\n"
    "None. Subclasses: ArgumentError, FormatError, FileError, NoMemoryError.";
static const char argument_error_doc[] =
    "A value the library refuses: a parameter of Sim (field names it), a\n"
    "number of steps, a state whose disks are outside the box or overlap\n"
    "(DS_ERR_OVERLAP), a packing that cannot be placed (DS_ERR_PLACEMENT).\n"
    "Also a ValueError. (An argument of the wrong type raises TypeError.)";
static const char format_error_doc[] =
    "A malformed frame file or checkpoint (DS_ERR_FORMAT); line is the 1-based\n"
    "line at fault of a frame (0 if not about one line), path the file. Also a\n"
    "ValueError.";
static const char file_error_doc[] =
    "A file that cannot be read or written (DS_ERR_IO); errno, strerror and\n"
    "filename as for any OSError, of which it is a subclass.";
static const char no_memory_error_doc[] =
    "Not enough memory (DS_ERR_NOMEM), or a request larger than this machine's\n"
    "physical memory, refused before trying. Also a MemoryError.";

static PyObject *new_error(PyObject *module, const char *name, PyObject *bases, const char *doc)
{
    char full[64];
    snprintf(full, sizeof full, "disksim.%s", name);
    /* Class attributes, so an Error raised without them still has them. */
    PyObject *attrs = Py_BuildValue("{sOsOsOsO}", "status", Py_None, "field", Py_None, "value",
                                    Py_None, "limit", Py_None);
    PyObject *type = bases && attrs ? PyErr_NewExceptionWithDoc(full, doc, bases, attrs) : NULL;
    Py_XDECREF(bases);
    Py_XDECREF(attrs);
    if (!type)
        return NULL;
    /* A reference stays here for the module's lifetime (the module is
     * never unloaded); PyModule_AddObjectRef takes its own. */
    if (PyModule_AddObjectRef(module, name, type) < 0) {
        Py_DECREF(type);
        return NULL;
    }
    return type;
}

/* Error first: the others derive from it and from a built-in exception. */
static const struct {
    const char *name;
    PyObject **type;
    PyObject **builtin;
    const char *doc;
} errors[] = {
    {"Error", &dspy_Error, &PyExc_Exception, error_doc},
    {"ArgumentError", &dspy_ArgumentError, &PyExc_ValueError, argument_error_doc},
    {"FormatError", &dspy_FormatError, &PyExc_ValueError, format_error_doc},
    {"FileError", &dspy_FileError, &PyExc_OSError, file_error_doc},
    {"NoMemoryError", &dspy_NoMemoryError, &PyExc_MemoryError, no_memory_error_doc},
};

int dspy_add_exceptions(PyObject *module)
{
    for (size_t k = 0; k < sizeof errors / sizeof errors[0]; ++k) {
        PyObject *bases = k == 0 ? Py_NewRef(*errors[k].builtin)
                                 : PyTuple_Pack(2, dspy_Error, *errors[k].builtin);
        *errors[k].type = new_error(module, errors[k].name, bases, errors[k].doc);
        if (!*errors[k].type)
            return -1;
    }
    return 0;
}

const char *dspy_status_name(ds_status status)
{
    switch (status) {
    case DS_OK:
        return "DS_OK";
    case DS_ERR_ARG:
        return "DS_ERR_ARG";
    case DS_ERR_NOMEM:
        return "DS_ERR_NOMEM";
    case DS_ERR_PLACEMENT:
        return "DS_ERR_PLACEMENT";
    case DS_ERR_IO:
        return "DS_ERR_IO";
    case DS_ERR_FORMAT:
        return "DS_ERR_FORMAT";
    case DS_ERR_OVERLAP:
        return "DS_ERR_OVERLAP";
    case DS_STATUS_COUNT:
        break;
    }
    return "unknown";
}

static PyObject *type_of(ds_status status)
{
    switch (status) {
    case DS_ERR_ARG:
    case DS_ERR_PLACEMENT:
    case DS_ERR_OVERLAP:
        return dspy_ArgumentError;
    case DS_ERR_NOMEM:
        return dspy_NoMemoryError;
    case DS_ERR_IO:
        return dspy_FileError;
    case DS_ERR_FORMAT:
        return dspy_FormatError;
    case DS_OK:
    case DS_STATUS_COUNT:
        break;
    }
    return dspy_Error;
}

PyObject *dspy_raise(ds_status status, const char *field, const char *message)
{
    PyObject *type = type_of(status);
    PyObject *exc =
        PyObject_CallFunction(type, "s", message && *message ? message : ds_status_name(status));
    if (!exc)
        return NULL;
    PyObject *field_obj = field && *field ? PyUnicode_FromString(field) : Py_NewRef(Py_None);
    PyObject *status_obj = PyUnicode_FromString(dspy_status_name(status));
    if (field_obj && status_obj && PyObject_SetAttrString(exc, "field", field_obj) == 0 &&
        PyObject_SetAttrString(exc, "status", status_obj) == 0)
        PyErr_SetObject(type, exc);
    Py_XDECREF(field_obj);
    Py_XDECREF(status_obj);
    Py_DECREF(exc);
    return NULL;
}

/* A number of ds_error as Python has it: None for NaN. */
static PyObject *number_or_none(double v)
{
    return isnan(v) ? Py_NewRef(Py_None) : PyFloat_FromDouble(v);
}

PyObject *dspy_raise_error(const ds_error *err)
{
    (void)dspy_raise(err->status, err->field, err->message);
    /* The exception being raised gets the numbers too. */
    PyObject *exc = dspy_take_exception();
    PyObject *value = number_or_none(err->value), *limit = number_or_none(err->limit);
    if (exc && value && limit && PyObject_SetAttrString(exc, "value", value) == 0 &&
        PyObject_SetAttrString(exc, "limit", limit) == 0)
        PyErr_SetObject((PyObject *)Py_TYPE(exc), exc);
    Py_XDECREF(value);
    Py_XDECREF(limit);
    Py_XDECREF(exc);
    return NULL;
}

PyObject *dspy_raisef(ds_status status, const char *field, const char *fmt, ...)
{
    char message[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(message, sizeof message, fmt, ap);
    va_end(ap);
    return dspy_raise(status, field, message);
}

PyObject *dspy_raise_file(int errnum, const char *message, PyObject *path)
{
    PyObject *exc = errnum ? PyObject_CallFunction(dspy_FileError, "isO", errnum, message, path)
                           : PyObject_CallFunction(dspy_FileError, "N",
                                                   PyUnicode_FromFormat("%S: %s", path, message));
    PyObject *status = PyUnicode_FromString(dspy_status_name(DS_ERR_IO));
    /* (without an errno, OSError would print a filename as "[Errno None] None") */
    if (exc && status && PyObject_SetAttrString(exc, "status", status) == 0)
        PyErr_SetObject(dspy_FileError, exc);
    Py_XDECREF(status);
    Py_XDECREF(exc);
    return NULL;
}

PyObject *dspy_raise_format(PyObject *path, size_t line, const char *message)
{
    PyObject *text = line ? PyUnicode_FromFormat("%S: line %zu: %s", path, line, message)
                          : PyUnicode_FromFormat("%S: %s", path, message);
    PyObject *exc = text ? PyObject_CallOneArg(dspy_FormatError, text) : NULL;
    PyObject *status = PyUnicode_FromString(dspy_status_name(DS_ERR_FORMAT));
    PyObject *line_obj = PyLong_FromSize_t(line);
    if (exc && status && line_obj && PyObject_SetAttrString(exc, "status", status) == 0 &&
        PyObject_SetAttrString(exc, "line", line_obj) == 0 &&
        PyObject_SetAttrString(exc, "path", path) == 0)
        PyErr_SetObject(dspy_FormatError, exc);
    Py_XDECREF(line_obj);
    Py_XDECREF(status);
    Py_XDECREF(exc);
    Py_XDECREF(text);
    return NULL;
}

PyObject *dspy_take_exception(void)
{
#if PY_VERSION_HEX >= 0x030C0000
    return PyErr_GetRaisedException();
#else
    PyObject *type, *exc, *tb;
    PyErr_Fetch(&type, &exc, &tb);
    PyErr_NormalizeException(&type, &exc, &tb);
    if (exc && tb)
        PyException_SetTraceback(exc, tb);
    Py_XDECREF(type);
    Py_XDECREF(tb);
    return exc;
#endif
}

void dspy_set_cause(PyObject *cause)
{
    if (!cause)
        return;
    if (!PyErr_Occurred()) {
        Py_DECREF(cause);
        return;
    }
#if PY_VERSION_HEX >= 0x030C0000
    PyObject *exc = PyErr_GetRaisedException();
    PyException_SetCause(exc, cause); /* steals cause */
    PyErr_SetRaisedException(exc);
#else
    PyObject *type, *exc, *tb;
    PyErr_Fetch(&type, &exc, &tb);
    PyErr_NormalizeException(&type, &exc, &tb);
    if (exc)
        PyException_SetCause(exc, cause); /* steals cause */
    else
        Py_DECREF(cause);
    PyErr_Restore(type, exc, tb);
#endif
}
