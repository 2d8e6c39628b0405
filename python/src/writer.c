/* SPDX-License-Identifier: MIT */
/* disksim.Writer: a trajectory file that frames are written to one by
 * one, in any of the library's output formats (FORMATS: "frame", "xyz",
 * "gsd"), through its writers (ds_writer_open, _write, _close). HOOMD's
 * writers are the model: opened on a file, handed the state to write
 * when the script says, closed at the end (a with block does it). Each
 * write runs with the GIL released. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <errno.h>
#include <stdio.h>
#include <string.h>

typedef struct dspy_writer {
    PyObject_HEAD
    FILE *file;        /* NULL before __init__ and once closed */
    ds_writer *writer; /* writes into file */
    PyObject *path;    /* as given */
    int format;        /* a ds_format */
    uint64_t frames;   /* frames written */
    int busy;          /* a write runs without the GIL */
} dspy_writer;

/* The writer of self, or NULL with Error raised: closed, or writing in
 * another thread. */
static ds_writer *writer_of(dspy_writer *self)
{
    if (self->busy) {
        PyErr_SetString(dspy_Error, "this Writer is writing in another thread (a Writer is used "
                                    "by one thread at a time)");
        return NULL;
    }
    if (!self->writer) {
        PyErr_SetString(dspy_Error, "this Writer is closed");
        return NULL;
    }
    return self->writer;
}

/* Finishes the file and closes it; the first failure is raised (FileError
 * with its errno). Nothing to do once closed. */
static int finish(dspy_writer *self)
{
    if (!self->file)
        return 0;
    ds_writer *w = self->writer;
    FILE *f = self->file;
    self->writer = NULL;
    self->file = NULL;
    ds_status st = DS_OK;
    int errnum = 0;
    Py_BEGIN_ALLOW_THREADS
    errno = 0;
    st = ds_writer_close(w, NULL);
    errnum = st != DS_OK ? errno : 0;
    if (fclose(f) != 0 && st == DS_OK) {
        st = DS_ERR_IO;
        errnum = errno;
    }
    Py_END_ALLOW_THREADS
    if (st == DS_OK)
        return 0;
    dspy_raise_file(errnum, errnum ? strerror(errnum) : "the file could not be finished",
                    self->path);
    return -1;
}

static int writer_init(dspy_writer *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"path", "format", "velocities", "append", NULL};
    PyObject *path_obj, *format_obj = NULL;
    int velocities = 0, append = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|O$pp:Writer", keywords, &path_obj,
                                     &format_obj, &velocities, &append))
        return -1;
    if (self->file || self->busy) {
        PyErr_SetString(dspy_Error, "this Writer is open already: close it, or make another");
        return -1;
    }
    int format = DS_FORMAT_GSD;
    if (format_obj && dspy_parse_name(DSPY_FORMAT, format_obj, "format", &format) < 0)
        return -1;
    PyObject *path;
    if (dspy_path_arg(path_obj, &path) < 0)
        return -1;
    ds_error err;
    ds_status st = DS_OK;
    ds_writer *w = NULL;
    int errnum = 0;
    FILE *f;
    Py_BEGIN_ALLOW_THREADS
    errno = 0;
    /* Appending, the file is read back too (a GSD writer reads its index)
     * and written at its end; a missing one is made. */
    f = fopen(PyBytes_AS_STRING(path), append ? "r+b" : "wb");
    if (!f && append && errno == ENOENT)
        f = fopen(PyBytes_AS_STRING(path), "w+b");
    if (f && append && fseek(f, 0, SEEK_END) != 0) {
        fclose(f);
        f = NULL;
    }
    errnum = f ? 0 : errno;
    if (f) {
        st = ds_writer_open((ds_format)format, f, velocities ? DS_WRITE_VELOCITIES : 0u, &w, &err);
        errnum = st == DS_ERR_IO ? errno : 0;
        if (st != DS_OK)
            fclose(f);
    }
    Py_END_ALLOW_THREADS
    Py_DECREF(path);
    if (!f)
        return dspy_raise_file(errnum, strerror(errnum), path_obj), -1;
    if (st == DS_ERR_IO)
        return dspy_raise_file(errnum, err.message, path_obj), -1;
    if (st == DS_ERR_FORMAT) /* the library's "out: ..." is about path */
        return dspy_raise_format(path_obj, 0,
                                 strncmp(err.message, "out: ", 5) ? err.message : err.message + 5),
               -1;
    if (st != DS_OK)
        return dspy_raise_error(&err), -1;
    Py_XSETREF(self->path, Py_NewRef(path_obj));
    self->file = f;
    self->writer = w;
    self->format = format;
    self->frames = 0;
    return 0;
}

static PyObject *writer_write(dspy_writer *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"sim", NULL};
    PyObject *sim_obj;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O!:write", keywords, &dspy_SimType, &sim_obj))
        return NULL;
    ds_writer *w = writer_of(self);
    dspy_sim *owner = (dspy_sim *)sim_obj;
    ds_sim *sim = w ? dspy_sim_of(owner) : NULL;
    if (!sim)
        return NULL;
    ds_status st;
    ds_error err;
    int errnum = 0;
    self->busy = owner->busy = 1;
    Py_BEGIN_ALLOW_THREADS
    errno = 0;
    st = ds_writer_write(w, sim, &err);
    errnum = st == DS_ERR_IO ? errno : 0;
    Py_END_ALLOW_THREADS
    self->busy = owner->busy = 0;
    if (st == DS_ERR_IO)
        return dspy_raise_file(errnum, errnum ? strerror(errnum) : err.message, self->path);
    if (st != DS_OK)
        return dspy_raise_error(&err);
    ++self->frames;
    Py_RETURN_NONE;
}

static PyObject *writer_close(dspy_writer *self, PyObject *unused)
{
    (void)unused;
    if (self->busy && !writer_of(self))
        return NULL;
    if (finish(self) < 0)
        return NULL;
    Py_RETURN_NONE;
}

static PyObject *writer_enter(dspy_writer *self, PyObject *unused)
{
    (void)unused;
    if (!writer_of(self))
        return NULL;
    return Py_NewRef((PyObject *)self);
}

static PyObject *writer_exit(dspy_writer *self, PyObject *args)
{
    (void)args;
    PyObject *r = writer_close(self, NULL);
    Py_XDECREF(r);
    if (!r)
        return NULL;
    Py_RETURN_FALSE;
}

/* A Writer collected open is closed; a failure then has no one to tell. */
static void writer_dealloc(dspy_writer *self)
{
    if (self->file && finish(self) < 0)
        PyErr_Clear();
    Py_XDECREF(self->path);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyObject *writer_repr(dspy_writer *self)
{
    const char *format = dspy_name_of(DSPY_FORMAT, self->format);
    if (!self->path)
        return PyUnicode_FromString("<disksim.Writer, not opened>");
    return PyUnicode_FromFormat("<disksim.Writer %R, %s, %llu frames%s>", self->path,
                                format ? format : "?", (unsigned long long)self->frames,
                                self->file ? "" : ", closed");
}

static PyObject *path_property(dspy_writer *self, void *closure)
{
    (void)closure;
    return Py_NewRef(self->path ? self->path : Py_None);
}

static PyObject *format_property(dspy_writer *self, void *closure)
{
    (void)closure;
    return PyUnicode_FromString(dspy_name_of(DSPY_FORMAT, self->format));
}

static PyObject *frames_property(dspy_writer *self, void *closure)
{
    (void)closure;
    return PyLong_FromUnsignedLongLong(self->frames);
}

static PyObject *closed_property(dspy_writer *self, void *closure)
{
    (void)closure;
    return PyBool_FromLong(!self->file && !self->busy);
}

static PyGetSetDef writer_getset[] = {
    {"path", (getter)path_property, NULL, "The file's path, as given.", NULL},
    {"format", (getter)format_property, NULL, "The file's format, one of FORMATS.", NULL},
    {"frames", (getter)frames_property, NULL, "The frames written so far.", NULL},
    {"closed", (getter)closed_property, NULL, "Whether close() has been called.", NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

static PyMethodDef writer_methods[] = {
    {"write", (PyCFunction)(void (*)(void))writer_write, METH_VARARGS | METH_KEYWORDS,
     "write($self, /, sim)\n--\n\n"
     "Write the state of sim at sim.time as the file's next frame, flushed: the\n"
     "file holds whole frames after every write (a GSD file is valid, its index\n"
     "written). FileError (an OSError) if the write fails; Error if this Writer is\n"
     "closed or sim is closed or in use by another thread."},
    {"close", (PyCFunction)writer_close, METH_NOARGS,
     "close($self, /)\n--\n\n"
     "Finish the file and close it (again: nothing). FileError if that fails."},
    {"__enter__", (PyCFunction)writer_enter, METH_NOARGS,
     "__enter__($self, /)\n--\n\nReturn self."},
    {"__exit__", (PyCFunction)writer_exit, METH_VARARGS,
     "__exit__($self, *exc_info, /)\n--\n\nclose(), and let any exception through."},
    {NULL, NULL, 0, NULL},
};

static const char writer_doc[] =
    "Writer(path, format='gsd', *, velocities=False, append=False)\n--\n\n"
    "A trajectory file, written a frame at a time: open it, write a Sim's state\n"
    "whenever the script chooses, close it (a with block closes it):\n"
    "\n"
    "    with disksim.Writer('run.gsd') as w:\n"
    "        for _ in range(100):\n"
    "            s.run(100)\n"
    "            w.write(s)\n"
    "\n"
    "format is one of FORMATS: 'gsd' (GSD in the HOOMD schema, which HOOMD-blue,\n"
    "gsd.hoomd, OVITO, VMD, freud and MDAnalysis read), 'xyz' (extended XYZ, as\n"
    "the command's --trajectory: ASE, OVITO, VMD) or 'frame' (the command's text\n"
    "frames one after another; velocities=True adds vx vy). The file at path is\n"
    "created, or emptied; with append=True a file there is gone on with, the frames\n"
    "written after its own (a GSD file must be one this library wrote: FormatError,\n"
    "a ValueError, otherwise). ArgumentError for an unknown format; FileError (an\n"
    "OSError) if the file cannot be written.";

PyTypeObject dspy_WriterType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "disksim.Writer",
    .tp_basicsize = sizeof(dspy_writer),
    .tp_dealloc = (destructor)writer_dealloc,
    .tp_repr = (reprfunc)writer_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = writer_doc,
    .tp_methods = writer_methods,
    .tp_getset = writer_getset,
    .tp_init = (initproc)writer_init,
    .tp_new = PyType_GenericNew,
};
