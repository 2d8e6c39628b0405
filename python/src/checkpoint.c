/* SPDX-License-Identifier: MIT */
/* Exact checkpoints (ds_checkpoint_save, ds_checkpoint_load, ds_checkpoint_format,
 * ds_checkpoint_parse): Sim.save and disksim.load for files, and pickling, so
 * also copy.copy and copy.deepcopy, through the same bytes. A Sim made
 * from a checkpoint goes on bit for bit as the saved one would have. The
 * checkpoint does not tell the seed, the speed or the placement, so a Sim
 * from load() does not claim them; a pickle carries them beside it. */
#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A new instance of type (Sim or a subclass) owning sim. */
static PyObject *new_sim(PyTypeObject *type, ds_sim *sim, const ds_params *params, unsigned unknown,
                         PyObject *mixture_args)
{
    PyObject *empty = PyTuple_New(0);
    PyObject *obj = empty ? dspy_SimType.tp_new(type, empty, NULL) : NULL;
    Py_XDECREF(empty);
    if (!obj || dspy_sim_adopt((dspy_sim *)obj, sim, params, unknown, mixture_args) < 0) {
        if (!obj) {
            ds_sim_destroy(sim);
            Py_XDECREF(mixture_args);
        }
        Py_XDECREF(obj);
        return NULL;
    }
    return obj;
}

/* The library's refusal of a checkpoint (err, status st), or the file's:
 * errnum, or err's message for a file that is not a regular one. */
static PyObject *raise_state_error(ds_status st, int errnum, const ds_error *err, PyObject *path)
{
    if (st == DS_ERR_IO)
        return dspy_raise_file(errnum, errnum ? strerror(errnum) : err->message, path);
    if (st == DS_ERR_FORMAT && path)
        return dspy_raise_format(path, 0, err->message);
    return dspy_raise_error(err);
}

PyObject *dspy_sim_save(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"path", NULL};
    PyObject *path_obj, *path;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:save", keywords, &path_obj) ||
        dspy_path_arg(path_obj, &path) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim) {
        Py_DECREF(path);
        return NULL;
    }
    const char *name = PyBytes_AS_STRING(path);
    ds_status st;
    ds_error err;
    int errnum = 0;
    self->busy = 1;
    Py_BEGIN_ALLOW_THREADS
    errno = 0;
    FILE *f = fopen(name, "wb");
    if (!f) {
        st = DS_ERR_IO;
        errnum = errno;
    } else {
        st = ds_checkpoint_save(sim, f, &err);
        errnum = st == DS_ERR_IO ? errno : 0;
        if (fclose(f) != 0 && st == DS_OK) {
            st = DS_ERR_IO;
            errnum = errno;
        }
    }
    Py_END_ALLOW_THREADS
    self->busy = 0;
    Py_DECREF(path);
    if (st != DS_OK) {
        if (!errnum && st == DS_ERR_IO)
            PyOS_snprintf(err.message, sizeof err.message, "the checkpoint could not be written");
        return raise_state_error(st, errnum, &err, path_obj);
    }
    Py_RETURN_NONE;
}

const char dspy_load_doc[] =
    "load(path)\n--\n\n"
    "The Sim saved by Sim.save(path): the same simulation, to the bit, at the time\n"
    "it was saved (positions, velocities, the integrator's state, the observables'\n"
    "accumulators). A checkpoint does not record the seed, the speed or the\n"
    "placement: the loaded Sim's params leave them out and its placement is None.\n"
    "FormatError (a ValueError) for a truncated, corrupted, foreign or newer\n"
    "checkpoint, with the library's reason; FileError (an OSError) if it cannot be\n"
    "read or is not a regular file (a device such as /dev/zero would never end; a\n"
    "named pipe is refused at once, not waited on for a writer).";

PyObject *dspy_load(PyObject *module, PyObject *args, PyObject *kwargs)
{
    (void)module;
    static char *keywords[] = {"path", NULL};
    PyObject *path_obj, *path;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:load", keywords, &path_obj) ||
        dspy_path_arg(path_obj, &path) < 0)
        return NULL;
    const char *name = PyBytes_AS_STRING(path);
    ds_sim *sim = NULL;
    ds_error err;
    memset(&err, 0, sizeof err);
    ds_status st;
    int errnum = 0;
    Py_BEGIN_ALLOW_THREADS
    errno = 0;
    /* ds_checkpoint_load reads to the end of the file: from a device such as
     * /dev/zero that is never, so only regular files are read. Opened
     * without blocking, since opening a named pipe waits for a writer,
     * possibly forever; then what was opened is judged (no other file can
     * take its name between a check and the open); then reads block. */
    const int fd = open(name, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat info;
    int flags = -1;
    FILE *f = NULL;
    if (fd < 0) {
        st = DS_ERR_IO;
        errnum = errno;
    } else if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        st = DS_ERR_IO;
        snprintf(err.message, sizeof err.message, "not a regular file");
        close(fd);
    } else if ((flags = fcntl(fd, F_GETFL)) < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0 ||
               !(f = fdopen(fd, "rb"))) {
        st = DS_ERR_IO;
        errnum = errno;
        close(fd);
    } else {
        st = ds_checkpoint_load(f, &sim, &err);
        errnum = st == DS_ERR_IO ? errno : 0;
        fclose(f);
    }
    Py_END_ALLOW_THREADS
    Py_DECREF(path);
    if (st != DS_OK)
        return raise_state_error(st, errnum, &err, path_obj);
    return new_sim(&dspy_SimType, sim, NULL, 0, NULL);
}

/* pickle and copy: (disksim._disksim._restore, (type, checkpoint, params),
 * the instance's __dict__ for a subclass that has one). The checkpoint is
 * the simulation, to the byte; params only say what it was created with
 * (for repr and Sim.params), and are compared with it, not judged again
 * as a request to create (dspy_params_from_dict). */
PyObject *dspy_sim_reduce(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const size_t size = ds_checkpoint_get_size(sim);
    PyObject *data = size <= PY_SSIZE_T_MAX ? PyBytes_FromStringAndSize(NULL, (Py_ssize_t)size)
                                            : PyErr_NoMemory();
    if (!data)
        return NULL;
    size_t len = 0;
    ds_status st;
    char *buf = PyBytes_AS_STRING(data);
    ds_error err;
    self->busy = 1;
    Py_BEGIN_ALLOW_THREADS
    st = ds_checkpoint_format(sim, buf, size, &len, &err);
    Py_END_ALLOW_THREADS
    self->busy = 0;
    if (st != DS_OK) {
        Py_DECREF(data);
        return dspy_raise_error(&err);
    }
    PyObject *params = dspy_params_dict(&self->params, self->unknown, self->mixture_args);
    PyObject *module = params ? PyImport_ImportModule("disksim._disksim") : NULL;
    PyObject *restore = module ? PyObject_GetAttrString(module, "_restore") : NULL;
    PyObject *dict = restore ? PyObject_GetAttrString((PyObject *)self, "__dict__") : NULL;
    if (restore && !dict && PyErr_ExceptionMatches(PyExc_AttributeError)) {
        PyErr_Clear();
        dict = Py_NewRef(Py_None);
    }
    PyObject *result =
        dict ? Py_BuildValue("O(OOO)O", restore, (PyObject *)Py_TYPE(self), data, params, dict)
             : NULL;
    Py_XDECREF(dict);
    Py_XDECREF(restore);
    Py_XDECREF(module);
    Py_XDECREF(params);
    Py_DECREF(data);
    return result;
}

/* Only the mixture's arguments the pickle had (one of a loaded Sim has
 * none). */
static int keep_given(PyObject *mixture_args, PyObject *params)
{
    for (int k = 0; k < 4; ++k)
        if (!PyDict_GetItemString(params, dspy_mixture_names[k]) &&
            PyDict_DelItemString(mixture_args, dspy_mixture_names[k]) < 0)
            return -1;
    return 0;
}

/* Whether the pickle's arguments p (those not in unknown) are what the
 * checkpoint's simulation says of itself. A periodic box is the one it
 * was created with unless a barostat has moved it (set now or before:
 * ds_sim_set_barostat moves a periodic box only), so its sides are not
 * compared. */
static int same_arguments(const ds_params *p, unsigned unknown, const ds_sim *sim)
{
    ds_params q;
    (void)dspy_params_of_sim(sim, &q);
    const double height = p->box_y == 0.0 ? p->box : p->box_y;
    const int box_kept = q.boundary == DS_BOUNDARY_PERIODIC ||
                         (p->box == q.box && height == ds_sim_get_box_height(sim));
    return p->n == q.n && p->radius == q.radius && box_kept && p->dt == q.dt &&
           p->integrator == q.integrator && p->boundary == q.boundary &&
           (p->broadphase == DS_BROADPHASE_AUTO || p->broadphase == q.broadphase) &&
           (dspy_param_unknown(unknown, "seed") || p->seed == ds_sim_get_seed(sim)) &&
           (dspy_param_unknown(unknown, "placement") || p->placement == ds_sim_get_placement(sim));
}

PyObject *dspy_restore(PyObject *module, PyObject *args)
{
    (void)module;
    PyObject *type, *params;
    Py_buffer data;
    if (!PyArg_ParseTuple(args, "Oy*O!:_restore", &type, &data, &PyDict_Type, &params))
        return NULL;
    PyObject *result = NULL;
    ds_params p;
    dspy_mixture mix = DSPY_MIXTURE_INIT;
    unsigned unknown = 0;
    if (!PyType_Check(type) || !PyType_IsSubtype((PyTypeObject *)type, &dspy_SimType)) {
        PyErr_SetString(PyExc_TypeError, "_restore: the type must be disksim.Sim or a subclass");
    } else if (dspy_params_from_dict(params, &p, &mix, &unknown) == 0 &&
               keep_given(mix.args, params) == 0) {
        dspy_mixture_free(&mix); /* the checkpoint has the radii and masses */
        ds_sim *sim = NULL;
        ds_error err;
        ds_status st;
        Py_BEGIN_ALLOW_THREADS
        st = ds_checkpoint_parse(data.buf, (size_t)data.len, &sim, &err);
        Py_END_ALLOW_THREADS
        if (st == DS_OK && !same_arguments(&p, unknown, sim)) {
            ds_sim_destroy(sim);
            dspy_raise(DS_ERR_ARG, NULL, "_restore: the parameters are not the checkpoint's");
        } else {
            result = st == DS_OK ? new_sim((PyTypeObject *)type, sim, &p, unknown, mix.args)
                                 : raise_state_error(st, 0, &err, NULL);
            if (st == DS_OK)
                mix.args = NULL; /* new_sim took it */
        }
    }
    dspy_mixture_free(&mix);
    Py_XDECREF(mix.args);
    PyBuffer_Release(&data);
    return result;
}
