/* SPDX-License-Identifier: MIT */
/* The Python module disksim._disksim: what its files share.
 *
 * One concept per file: the module and its constants (module.c), the
 * exceptions and how a ds_status becomes one (errors.c), the names of the
 * library's enumerations (names.c), argument conversion (convert.c), the
 * parameters of a simulation from keyword arguments (params.c), the Sim
 * type (sim.c), its properties (properties.c), its state as arrays
 * (state.c), exact checkpoints and pickles (checkpoint.c), frames
 * (frames.c), the analysis functions (analysis.c), shear flow
 * (shear.c), ASE (ase.c), freud
 * and HOOMD-blue's view (freud.c) and trajectory files (writer.c). Only
 * the public header disk_sim.h is used: the module is a thin face over
 * the library.
 *
 * Internal names start with dspy_; the module is built with
 * -fvisibility=hidden, so none of them (nor the library's ds_*) leaves it.
 * Every file includes this header first: Python.h must come before any
 * system header, as it sets the feature macros. */
#ifndef DISKSIM_PY_H
#define DISKSIM_PY_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>

/* numpy's C API table, shared by every file of the module: module.c
 * defines it (import_array), the others only use it. */
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#define PY_ARRAY_UNIQUE_SYMBOL dspy_numpy_api
#ifndef DSPY_MODULE_C
#define NO_IMPORT_ARRAY
#endif
/* numpy's import_array casts a data pointer to a function pointer, which
 * -Wpedantic would flag in every file that includes it. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#include <numpy/arrayobject.h>
#pragma GCC diagnostic pop

#include "disk_sim.h"

/* ---------------------------------------------------------------- errors */

/* disksim.Error and its subclasses (errors.c documents each). */
extern PyObject *dspy_Error;         /* Exception */
extern PyObject *dspy_ArgumentError; /* Error, ValueError */
extern PyObject *dspy_FormatError;   /* Error, ValueError */
extern PyObject *dspy_FileError;     /* Error, OSError */
extern PyObject *dspy_NoMemoryError; /* Error, MemoryError */

int dspy_add_exceptions(PyObject *module);
/* Raises the exception status maps to, with message (the library's
 * sentence) and the attributes status (the enumerator's name) and field
 * (a ds_params member, or None). Returns NULL. */
PyObject *dspy_raise(ds_status status, const char *field, const char *message);
/* The library's refusal err (status, message, field) raised, with the
 * attributes value and limit too (None where err has NaN). NULL. */
PyObject *dspy_raise_error(const ds_error *err);
/* dspy_raise with a printf-formatted message. */
PyObject *dspy_raisef(ds_status status, const char *field, const char *fmt, ...);
/* FileError(errnum, message, path) (an OSError with errno, strerror and
 * filename), or FileError("path: message") when errnum is 0. Returns NULL. */
PyObject *dspy_raise_file(int errnum, const char *message, PyObject *path);
/* FormatError("path: line N: message") with attributes line and path. */
PyObject *dspy_raise_format(PyObject *path, size_t line, const char *message);
/* The exception being raised, cleared (a new reference; NULL if none). */
PyObject *dspy_take_exception(void);
/* Makes cause (stolen; NULL does nothing) the __cause__ of the exception
 * being raised, as `raise ... from cause`. */
void dspy_set_cause(PyObject *cause);
/* The name of a status's enumerator, e.g. "DS_ERR_ARG". */
const char *dspy_status_name(ds_status status);

/* ---------------------------------------------------------------- names */

/* The library's enumerations by name: integrators and boundaries from the
 * library's own name functions (a new integrator needs no edit here),
 * placements from a table, broad phases from ds_broadphase_name. */
typedef enum dspy_kind {
    DSPY_INTEGRATOR,
    DSPY_BOUNDARY,
    DSPY_PLACEMENT,
    DSPY_BROADPHASE,
    DSPY_MASS_RULE,    /* ds_mass_rule: "equal", "area" */
    DSPY_GROWTH_STATE, /* ds_growth_state: "none", "growing", "reached_eta", "jammed" */
    DSPY_THERMOSTAT,   /* ds_thermostat: "none", "andersen", "isokinetic" */
    DSPY_FORMAT,       /* ds_format: "frame", "xyz", "gsd" */
    DSPY_KINDS
} dspy_kind;

/* The name of value, or NULL if it has none. */
const char *dspy_name_of(dspy_kind kind, int value);
/* *out = the value named by the str value; TypeError for a non-str,
 * ArgumentError naming field and the accepted names otherwise. */
int dspy_parse_name(dspy_kind kind, PyObject *value, const char *field, int *out);
/* A tuple of every name of kind, in the order of their values. */
PyObject *dspy_names(dspy_kind kind);

/* ---------------------------------------------------------------- conversion */

/* An integer argument in [0, 2**64): TypeError for a non-integer,
 * ArgumentError for a negative one, and beyond 2**64 - 1 NoMemoryError
 * for a count of things held in memory (is_count), else ArgumentError. */
int dspy_uint64_arg(PyObject *value, const char *field, int is_count, uint64_t *out);
/* A float argument (any real number, NaN and infinities included: the
 * library says what it accepts). TypeError for a non-number. */
int dspy_double_arg(PyObject *value, const char *field, double *out);
/* Bytes of physical memory on this machine; 0 if unknown. */
uint64_t dspy_physical_memory(void);
/* NoMemoryError if bytes exceed this machine's physical memory. */
int dspy_check_memory(double bytes, const char *what);
/* An (n, 2) float64 C-contiguous array from any array-like (a new
 * reference), n == want unless want is (size_t)-1. ArgumentError for
 * another shape or values numpy cannot read as numbers. */
PyArrayObject *dspy_xy_array(PyObject *value, const char *field, size_t want);
/* A new (n, 2) float64 array. */
PyArrayObject *dspy_new_xy(size_t n);
/* A path argument (str, bytes or os.PathLike) as a bytes object. */
int dspy_path_arg(PyObject *value, PyObject **bytes);
/* A 1-D float64 C-contiguous array of want numbers from any array-like (a
 * new reference); ArgumentError for another shape or values numpy cannot
 * read as numbers. */
PyArrayObject *dspy_vector_array(PyObject *value, const char *field, size_t want);

/* ---------------------------------------------------------------- mixtures */

/* Sim's mixture arguments (mixture.c): species, radii, masses, mass. */
typedef struct dspy_mixture {
    PyObject *given[4]; /* the arguments as passed (borrowed), NULL if not */
    ds_mixture mixture; /* what the library is given, pointing into the below */
    ds_species *kinds;  /* PyMem_Raw: the species */
    double *radii;      /* PyMem_Raw: radii per disk */
    double *masses;     /* PyMem_Raw: masses per disk */
    int any;            /* species or radii given: a ds_mixture for the library */
    PyObject *args;     /* a new dict of the four, normalised (for params, repr) */
} dspy_mixture;
#define DSPY_MIXTURE_INIT                                                                          \
    {                                                                                              \
        {NULL, NULL, NULL, NULL}, {0, NULL, NULL, NULL, DS_MASS_EQUAL}, NULL, NULL, NULL, 0, NULL  \
    }

/* The index of a mixture keyword (0 .. 3), or -1. */
int dspy_mixture_keyword(const char *name);
/* The given values into a ds_mixture for n disks, and m->args; -1 with an
 * exception (TypeError, ArgumentError for a shape or a negative count). */
int dspy_mixture_convert(dspy_mixture *m, size_t n);
/* The ds_mixture for the library, or NULL for disks of one kind. */
const ds_mixture *dspy_mixture_of(const dspy_mixture *m);
/* Frees the arrays (not args). */
void dspy_mixture_free(dspy_mixture *m);
/* The arguments' names in Sim's order. */
extern const char *const dspy_mixture_names[4];

/* ---------------------------------------------------------------- parameters */

/* ds_params and the mixture from Sim's arguments (n, radius, and the
 * keyword-only rest), checked by ds_params_check: on failure the
 * library's sentence is raised (and the mixture freed). On success the
 * caller frees the mixture (dspy_mixture_free) and owns mixture->args.
 * warning receives the first warning's sentence ("" if none). */
int dspy_params_from_args(PyObject *args, PyObject *kwargs, ds_params *params,
                          dspy_mixture *mixture, char warning[256]);
/* The keyword arguments that recreate params, as a dict (for repr and
 * Sim.params), without the arguments whose bit is set in unknown, with
 * those of mixture_args (a dict, or NULL), arrays copied. */
PyObject *dspy_params_dict(const ds_params *params, unsigned unknown, PyObject *mixture_args);
/* "Sim(400, 5.0, integrator='event')": the arguments that differ from
 * the defaults (and are known). */
PyObject *dspy_params_repr(const ds_params *params, unsigned unknown, PyObject *mixture_args);
/* The parameters of a simulation read back from the library (a loaded
 * checkpoint), as far as it tells them; returns the mask of those it
 * does not (seed, speed, placement). */
unsigned dspy_params_of_sim(const ds_sim *sim, ds_params *params);
/* The parameters of a dict of Sim's keyword arguments (a pickle's),
 * converted as Sim converts them (TypeError, ArgumentError for a name or a
 * mixture's shape) but not judged by ds_params_check: they describe the
 * checkpoint beside them, not a simulation to create (dspy_restore
 * compares them with it). unknown receives the mask of the arguments the
 * dict does not have. On success the caller frees the mixture and owns
 * mixture->args. */
int dspy_params_from_dict(PyObject *dict, ds_params *params, dspy_mixture *mixture,
                          unsigned *unknown);
/* Whether the argument name is in the unknown mask. */
unsigned dspy_param_unknown(unsigned unknown, const char *name);
/* The text of Sim's signature for its docstring. */
#define DSPY_SIM_SIGNATURE                                                                         \
    "Sim(n, radius, *, seed=20260101, integrator='step', boundary='walls', "                       \
    "placement='random', box=1000.0, box_y=None, dt=0.001, speed=100.0, broadphase='auto', "       \
    "species=None, radii=None, masses=None, mass='equal')"

/* ---------------------------------------------------------------- Sim */

typedef struct dspy_sim {
    PyObject_HEAD
    ds_sim *sim;            /* NULL once closed (or before __init__) */
    ds_params params;       /* as created, for repr and params */
    unsigned unknown;       /* members of params not known (a loaded checkpoint) */
    PyObject *mixture_args; /* the mixture's arguments as a dict (NULL before __init__) */
    /* Set while a call runs without the GIL (run, step, creation,
     * set_state, writing): any other use of this Sim from another thread
     * then raises Error instead of racing the library. */
    int busy;
} dspy_sim;

extern PyTypeObject dspy_SimType;
/* properties.c: the table of Sim's properties. */
extern PyGetSetDef dspy_sim_getset[];
/* The simulation of self, or NULL with Error raised: closed, or busy in
 * another thread. */
ds_sim *dspy_sim_of(dspy_sim *self);

/* state.c: Sim's arrays and set_state. */
PyObject *dspy_positions_property(dspy_sim *self, void *closure);
PyObject *dspy_velocities_property(dspy_sim *self, void *closure);
PyObject *dspy_unwrapped_property(dspy_sim *self, void *closure);
PyObject *dspy_images_property(dspy_sim *self, void *closure);
PyObject *dspy_sim_set_state(dspy_sim *self, PyObject *args, PyObject *kwargs);
/* Every disk of sim (ds_sim_get_disks) into a new buffer; NULL with MemoryError. */
ds_disk *dspy_get_all(const ds_sim *sim);

/* growth.c: compression, velocities, contacts. */
PyObject *dspy_sim_set_growth(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_scale_velocities(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_contacts(dspy_sim *self, PyObject *args, PyObject *kwargs);
int dspy_add_contacts_type(PyObject *module);
extern const char dspy_set_growth_doc[], dspy_scale_velocities_doc[], dspy_contacts_doc[];

/* granular.c: restitution, the TC model's contact time, a field, a drive. */
PyObject *dspy_sim_set_restitution(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_set_contact_time(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_set_gravity(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_set_drive(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_gravity_property(dspy_sim *self, void *closure);
extern const char dspy_set_restitution_doc[], dspy_set_contact_time_doc[], dspy_set_gravity_doc[],
    dspy_set_drive_doc[];
/* ensembles.c: a heat bath, a barostat. */
PyObject *dspy_sim_set_thermostat(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_set_barostat(dspy_sim *self, PyObject *args, PyObject *kwargs);
extern const char dspy_set_thermostat_doc[], dspy_set_barostat_doc[];
/* shear.c: Lees-Edwards shear, the velocity profile. */
PyObject *dspy_sim_set_shear(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_velocity_profile(dspy_sim *self, PyObject *args, PyObject *kwargs);
extern const char dspy_set_shear_doc[], dspy_velocity_profile_doc[];

/* frames.c */
PyObject *dspy_sim_write_frame(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_read_frame(PyObject *module, PyObject *args, PyObject *kwargs);
int dspy_add_frame_type(PyObject *module);

/* analysis.c */
PyObject *dspy_pair_histogram(PyObject *module, PyObject *args, PyObject *kwargs);
PyObject *dspy_local_psi6(PyObject *module, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_pair_histogram(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_local_psi6(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_rdf(PyObject *module, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_rdf(dspy_sim *self, PyObject *args, PyObject *kwargs);

/* checkpoint.c: exact checkpoints, files and pickles. */
PyObject *dspy_sim_save(dspy_sim *self, PyObject *args, PyObject *kwargs);
PyObject *dspy_sim_reduce(dspy_sim *self, PyObject *unused);
PyObject *dspy_load(PyObject *module, PyObject *args, PyObject *kwargs);
PyObject *dspy_restore(PyObject *module, PyObject *args);
extern const char dspy_load_doc[];
/* Makes self own sim (which it frees on failure), its parameters those of
 * the library's answer, or params if given. */
int dspy_sim_adopt(dspy_sim *self, ds_sim *sim, const ds_params *params, unsigned unknown,
                   PyObject *mixture_args);

/* ase.c */
PyObject *dspy_sim_to_ase(dspy_sim *self, PyObject *unused);

/* freud.c: the disks as freud and HOOMD-blue take a system. */
PyObject *dspy_sim_freud_box(dspy_sim *self, PyObject *unused);
PyObject *dspy_sim_freud_points(dspy_sim *self, PyObject *unused);
extern const char dspy_freud_box_doc[], dspy_freud_points_doc[];

/* writer.c: disksim.Writer, a trajectory file in one of the library's
 * formats. */
extern PyTypeObject dspy_WriterType;

/* The module functions' docstrings, beside their code. */
extern const char dspy_read_frame_doc[];
extern const char dspy_pair_histogram_doc[];
extern const char dspy_local_psi6_doc[];
extern const char dspy_rdf_doc[];

#endif /* DISKSIM_PY_H */
