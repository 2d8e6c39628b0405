/* SPDX-License-Identifier: MIT */
/* The module disksim._disksim: its functions, constants and types. The
 * package disksim (disksim/__init__.py) re-exports all of it. */
#define DSPY_MODULE_C /* this file defines numpy's API table */
#include "disksim_py.h"

static PyObject *memory_needed(PyObject *module, PyObject *args, PyObject *kwargs)
{
    (void)module;
    ds_params p;
    dspy_mixture mix = DSPY_MIXTURE_INIT;
    if (dspy_params_from_args(args, kwargs, &p, &mix, NULL) < 0)
        return NULL;
    size_t bytes = 0;
    ds_error err;
    const ds_status st = ds_params_memory(&p, dspy_mixture_of(&mix), &bytes, &err);
    dspy_mixture_free(&mix);
    Py_XDECREF(mix.args);
    if (st != DS_OK)
        return dspy_raise_error(&err);
    return PyLong_FromSize_t(bytes);
}

static PyMethodDef module_functions[] = {
    {"read_frame", (PyCFunction)(void (*)(void))dspy_read_frame, METH_VARARGS | METH_KEYWORDS,
     dspy_read_frame_doc},
    {"pair_histogram", (PyCFunction)(void (*)(void))dspy_pair_histogram,
     METH_VARARGS | METH_KEYWORDS, dspy_pair_histogram_doc},
    {"local_psi6", (PyCFunction)(void (*)(void))dspy_local_psi6, METH_VARARGS | METH_KEYWORDS,
     dspy_local_psi6_doc},
    {"rdf", (PyCFunction)(void (*)(void))dspy_rdf, METH_VARARGS | METH_KEYWORDS, dspy_rdf_doc},
    {"load", (PyCFunction)(void (*)(void))dspy_load, METH_VARARGS | METH_KEYWORDS, dspy_load_doc},
    {"_restore", (PyCFunction)dspy_restore, METH_VARARGS,
     "_restore(type, checkpoint, params, /)\n--\n\n"
     "Unpickles a Sim (Sim.__reduce__ names it): not for direct use."},
    {"memory_needed", (PyCFunction)(void (*)(void))memory_needed, METH_VARARGS | METH_KEYWORDS,
     "memory_needed(n, radius, **arguments)\n--\n\n"
     "Bytes Sim(n, radius, **arguments) would allocate (ds_params_memory), without\n"
     "allocating them; the same arguments and the same exceptions as Sim. Sim itself\n"
     "refuses, with NoMemoryError, more than this machine's physical memory."},
    {NULL, NULL, 0, NULL},
};

static const char module_doc[] =
    "The C extension behind the package disksim: hard disks (2D elastic billiards)\n"
    "through libdisksim's public API (include/disk_sim.h and include/disksim/).\n"
    "Use it as `disksim`.";

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT,
    "disksim._disksim",
    module_doc,
    -1,
    module_functions,
    NULL,
    NULL,
    NULL,
    NULL,
};

static int add_constants(PyObject *m)
{
    const dspy_kind kinds[] = {DSPY_INTEGRATOR, DSPY_BOUNDARY,     DSPY_PLACEMENT,  DSPY_BROADPHASE,
                               DSPY_MASS_RULE,  DSPY_GROWTH_STATE, DSPY_THERMOSTAT, DSPY_FORMAT};
    const char *const names[] = {"INTEGRATORS", "BOUNDARIES",    "PLACEMENTS",  "BROADPHASES",
                                 "MASS_RULES",  "GROWTH_STATES", "THERMOSTATS", "FORMATS"};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
        PyObject *t = dspy_names(kinds[k]);
        if (!t || PyModule_AddObject(m, names[k], t) < 0) {
            Py_XDECREF(t);
            return -1;
        }
    }
    if (PyModule_AddStringConstant(m, "library_version", ds_version()) < 0 ||
        PyModule_AddObject(m, "DEFAULT_SEED", PyLong_FromUnsignedLongLong(DS_DEFAULT_SEED)) < 0 ||
        PyModule_AddObject(m, "CONTACT_TOLERANCE", PyFloat_FromDouble(DS_CONTACT_TOLERANCE)) < 0 ||
        PyModule_AddObject(m, "MAX_AREA_FRACTION", PyFloat_FromDouble(DS_MAX_AREA_FRACTION)) < 0 ||
        PyModule_AddIntConstant(m, "MANY_DISKS", DS_MANY_DISKS) < 0 ||
        PyModule_AddObject(m, "JAMMED_Z", PyFloat_FromDouble(DS_JAMMED_Z)) < 0 ||
        PyModule_AddObject(m, "VELOCITY_MAX", PyFloat_FromDouble(DS_VELOCITY_MAX)) < 0 ||
        PyModule_AddObject(m, "SHEAR_MAX_STRAIN_PER_STEP",
                           PyFloat_FromDouble(DS_SHEAR_MAX_STRAIN_PER_STEP)) < 0)
        return -1;
    return 0;
}

PyMODINIT_FUNC PyInit__disksim(void)
{
    import_array();
    if (PyType_Ready(&dspy_SimType) < 0 || PyType_Ready(&dspy_WriterType) < 0)
        return NULL;
    PyObject *m = PyModule_Create(&module_def);
    if (!m)
        return NULL;
    if (dspy_add_exceptions(m) < 0 || dspy_add_frame_type(m) < 0 || dspy_add_contacts_type(m) < 0 ||
        add_constants(m) < 0 || PyModule_AddObjectRef(m, "Sim", (PyObject *)&dspy_SimType) < 0 ||
        PyModule_AddObjectRef(m, "Writer", (PyObject *)&dspy_WriterType) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
