/* SPDX-License-Identifier: MIT */
/* The Sim type: one ds_sim, created from keyword arguments, advanced with
 * the GIL released. Its properties are in properties.c, its arrays and
 * set_state in state.c, frames in frames.c, analysis in analysis.c, ASE in
 * ase.c. */

#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <math.h>
#include <string.h>

/* run() gives the GIL back between chunks of steps, to take Ctrl-C
 * (KeyboardInterrupt) and signals: chunks double from one step while
 * they last less than this, so the check costs nothing measurable. */
#define CHUNK_SECONDS 0.1

ds_sim *dspy_sim_of(dspy_sim *self)
{
    if (self->busy) {
        PyErr_SetString(dspy_Error, "this Sim is in use by another thread (a Sim is used by one "
                                    "thread at a time; give each thread its own)");
        return NULL;
    }
    if (!self->sim) {
        PyErr_SetString(dspy_Error, "this Sim is closed");
        return NULL;
    }
    return self->sim;
}

/* ---------------------------------------------------------------- life */

static const char sim_doc[] = DSPY_SIM_SIGNATURE
    "\n--\n\n"
    "N hard disks of one radius in a box (or a mixture of radii and masses):\n"
    "elastic billiards, through libdisksim.\n"
    "\n"
    "Sim(400, 5.0) is the command's `disks 400 5`: 400 disks of radius 5 placed at\n"
    "random in the box [0, 1000]^2 with walls, every disk at speed 100 in a random\n"
    "direction, advanced by the fixed time step dt = 0.001. Lengths are in box\n"
    "units, time in simulated seconds, masses are 1.\n"
    "\n"
    "n           number of disks, >= 1.\n"
    "radius      disk radius: below half the box's shorter side with walls, below a\n"
    "            quarter of it in a periodic box.\n"
    "seed        seed of the placement and of the initial directions, 0 .. 2**64-1;\n"
    "            the same arguments give the same simulation, to the bit.\n"
    "integrator  'step': the fixed time step (move by v dt, reflect at the walls,\n"
    "            swap the normal velocities of overlapping, approaching pairs; fast,\n"
    "            collisions seen up to one step late). 'event': exact event-driven\n"
    "            dynamics, every collision at its own time at distance exactly 2R;\n"
    "            step() still advances by exactly dt. 'chain': event-chain Monte\n"
    "            Carlo, the same equilibrium sampled without dynamics by straight\n"
    "            chains along +x and +y; a step carries n speed dt of chain\n"
    "            displacement, the velocities never change, the pressure comes\n"
    "            from the chains' liftings.\n"
    "boundary    'walls' (a centre turns at R from each wall) or 'periodic' (a disk\n"
    "            leaving at one edge comes back at the other, pairs interact through\n"
    "            the nearest image, positions stay in [0, box) x [0, box_y)).\n"
    "placement   'random' (random sequential, up to area fraction 0.54) or\n"
    "            'lattice' (a triangular lattice, up to close packing 0.9069; in a\n"
    "            periodic box the total momentum is made zero).\n"
    "box         width of the box, > 0 and <= 1e9.\n"
    "box_y       height of the box; None for a square box (box_y = box).\n"
    "dt          the time step, > 0 and <= 1: the time step() advances.\n"
    "speed       the initial speed of every disk, > 0 and <= 1e9.\n"
    "broadphase  how candidate pairs are found, all giving the same pairs: 'auto'\n"
    "            (the fastest for the integrator), or for 'step' 'sap', 'strips',\n"
    "            'brute'; for 'event' and 'chain' 'cells', 'brute'.\n"
    "\n"
    "A mixture, given as species or disk by disk (one of the two):\n"
    "species     [(count, radius), ...] or [(count, radius, mass), ...]: counts that\n"
    "            add up to n; disks 0 .. count_0 - 1 are of the first kind, and so on.\n"
    "radii       per disk: n radii, in generation order (an (n,) array).\n"
    "masses      per disk, with radii: n masses (None: by the mass rule).\n"
    "mass        the rule for the masses not given: 'equal' (1, whatever the radius)\n"
    "            or 'area' ((r / R)^2, R = radius: disks of radius R weigh 1).\n"
    "Each disk then has its own radius and mass: pairs touch at the sum of their\n"
    "radii, a collision is elastic along the line of centres for the two masses,\n"
    "walls turn a disk at its own radius. radius is the reference radius R (of\n"
    "mass='area', and what the radius property returns); the disks' radii come from\n"
    "the mixture, and the limits above hold with every radius. Random placement\n"
    "places the largest disks first; the lattice puts them on sites at least the\n"
    "largest diameter apart, in an order drawn from the seed. A mixture of one kind\n"
    "of radius R and mass 1 is exactly the plain simulation. Without species or\n"
    "radii every disk weighs 1 by either rule.\n"
    "\n"
    "Compression: set_growth() grows every radius (integrator='event', periodic),\n"
    "growth_state and growth_z follow it, contacts() counts a packing's contacts.\n"
    "Ensembles: set_thermostat() holds the temperature (Andersen's heat bath, the\n"
    "canonical ensemble), set_barostat() the pressure (Monte Carlo moves of a\n"
    "periodic box, the isobaric ensemble).\n"
    "\n"
    "Raises ArgumentError (a ValueError) with the library's sentence for a value it\n"
    "refuses (e.field names the argument; 'mixture' for the mixture's values), NoMemoryError for "
    "more disks than this\n"
    "machine's memory holds, TypeError for an argument of the wrong type. A request\n"
    "that runs with degraded physics (a time step so long that head-on pairs can\n"
    "pass through each other) gives a RuntimeWarning saying so.\n"
    "\n"
    "Threads: run() releases the GIL, so threads with one Sim each run in parallel\n"
    "on as many cores. A Sim is used by one thread at a time: any use of it while\n"
    "another thread is inside its run() raises Error. The arrays returned are\n"
    "copies: changing them changes nothing until set_state().\n"
    "\n"
    "A Sim is a context manager: `with Sim(...) as s:` frees its memory at the end\n"
    "of the block, as close() does; afterwards every use raises Error.";

static PyObject *sim_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    (void)args;
    (void)kwargs;
    dspy_sim *self = (dspy_sim *)type->tp_alloc(type, 0);
    if (self) {
        self->sim = NULL;
        self->busy = 0;
        self->unknown = 0;
        self->mixture_args = NULL;
        memset(&self->params, 0, sizeof self->params);
    }
    return (PyObject *)self;
}

static int sim_init(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    if (self->busy) {
        PyErr_SetString(dspy_Error, "this Sim is in use by another thread");
        return -1;
    }
    ds_params p;
    dspy_mixture mix = DSPY_MIXTURE_INIT;
    char warning[256] = "";
    if (dspy_params_from_args(args, kwargs, &p, &mix, warning) < 0)
        return -1;
    const ds_mixture *mixture = dspy_mixture_of(&mix);
    size_t bytes = 0;
    ds_error err;
    const ds_status need = ds_params_memory(&p, mixture, &bytes, &err);
    char what[64];
    PyOS_snprintf(what, sizeof what, "n = %zu disks", p.n);
    ds_sim *sim = NULL;
    ds_status st = DS_OK;
    if (need != DS_OK)
        dspy_raise_error(&err);
    else if (dspy_check_memory((double)bytes, what) < 0)
        ;
    else if (warning[0] && PyErr_WarnEx(PyExc_RuntimeWarning, warning, 1) < 0)
        ; /* warnings turned into errors */
    else {
        self->busy = 1;
        Py_BEGIN_ALLOW_THREADS
        st = ds_sim_create(&p, mixture, &sim, &err);
        Py_END_ALLOW_THREADS
        self->busy = 0;
        if (st != DS_OK)
            dspy_raise_error(&err);
    }
    dspy_mixture_free(&mix);
    if (!sim) {
        Py_XDECREF(mix.args);
        return -1;
    }
    return dspy_sim_adopt(self, sim, &p, 0, mix.args);
}

int dspy_sim_adopt(dspy_sim *self, ds_sim *sim, const ds_params *params, unsigned unknown,
                   PyObject *mixture_args)
{
    if (!mixture_args) /* a loaded checkpoint: its radii and masses are radii, masses */
        mixture_args = PyDict_New();
    if (self->busy || !mixture_args) {
        ds_sim_destroy(sim);
        Py_XDECREF(mixture_args);
        if (self->busy)
            PyErr_SetString(dspy_Error, "this Sim is in use by another thread");
        return -1;
    }
    ds_params p;
    if (params)
        p = *params;
    else
        unknown = dspy_params_of_sim(sim, &p);
    ds_sim_destroy(self->sim); /* __init__ called again: the new one replaces it */
    self->sim = sim;
    self->params = p;
    self->unknown = unknown;
    Py_XSETREF(self->mixture_args, mixture_args);
    return 0;
}

static void sim_dealloc(dspy_sim *self)
{
    ds_sim_destroy(self->sim);
    Py_CLEAR(self->mixture_args);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyObject *sim_close(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    if (self->busy) {
        PyErr_SetString(dspy_Error, "this Sim is in use by another thread");
        return NULL;
    }
    ds_sim_destroy(self->sim);
    self->sim = NULL;
    Py_RETURN_NONE;
}

static PyObject *sim_enter(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    if (!dspy_sim_of(self))
        return NULL;
    return Py_NewRef((PyObject *)self);
}

static PyObject *sim_exit(dspy_sim *self, PyObject *args)
{
    (void)args;
    PyObject *r = sim_close(self, NULL);
    Py_XDECREF(r);
    if (!r)
        return NULL;
    Py_RETURN_FALSE;
}

static PyObject *sim_repr(dspy_sim *self)
{
    PyObject *args = self->sim || self->busy
                         ? dspy_params_repr(&self->params, self->unknown, self->mixture_args)
                         : NULL;
    if (!self->sim && !self->busy)
        return PyUnicode_FromString("<disksim.Sim, closed>");
    if (!args)
        return NULL;
    if (self->busy) {
        PyObject *r = PyUnicode_FromFormat("<disksim.%U, running>", args);
        Py_DECREF(args);
        return r;
    }
    char *time = PyOS_double_to_string(ds_sim_get_time(self->sim), 'r', 0, Py_DTSF_ADD_DOT_0, NULL);
    PyObject *r = time ? PyUnicode_FromFormat("<disksim.%U at t = %s after %llu steps>", args, time,
                                              (unsigned long long)ds_sim_get_steps(self->sim))
                       : PyErr_NoMemory();
    PyMem_Free(time);
    Py_DECREF(args);
    return r;
}

/* ---------------------------------------------------------------- running */

/* steps whole steps, in chunks with the GIL released, taking signals
 * between them; on KeyboardInterrupt the steps done stay done. A run the
 * library stops (a growth without memory for its cells, NoMemoryError)
 * likewise keeps the steps it took. */
static int advance(dspy_sim *self, ds_sim *sim, uint64_t steps)
{
    uint64_t chunk = 1;
    self->busy = 1;
    while (steps > 0) {
        const uint64_t k = chunk < steps ? chunk : steps;
        double seconds;
        ds_status st;
        ds_error err;
        Py_BEGIN_ALLOW_THREADS
        const double t0 = ds_timer_now();
        st = ds_sim_run(sim, k, &err);
        seconds = ds_timer_now() - t0;
        Py_END_ALLOW_THREADS
        if (st != DS_OK) {
            self->busy = 0;
            dspy_raise_error(&err);
            return -1;
        }
        steps -= k;
        if (steps && PyErr_CheckSignals() < 0) {
            self->busy = 0;
            return -1;
        }
        if (seconds < CHUNK_SECONDS / 2 && chunk < (UINT64_MAX >> 1))
            chunk *= 2;
        else if (seconds > 2 * CHUNK_SECONDS && chunk > 1)
            chunk /= 2;
    }
    self->busy = 0;
    return 0;
}

/* A time within this fraction of a step below until counts as reaching it:
 * until / dt carries the rounding of dt (0.001 is not a binary fraction),
 * and run(until=1.0) with dt = 0.001 should be 1000 steps, not 1001. */
#define UNTIL_SLACK 1e-9

/* The step count at which the time, steps * dt, first reaches until (up to
 * UNTIL_SLACK of a step); 0 for an until at or before 0. */
static int steps_until(double until, double dt, uint64_t *target)
{
    if (!isfinite(until)) {
        dspy_raisef(DS_ERR_ARG, "until", "until = %g must be a finite time", until);
        return -1;
    }
    const double k = ceil(until / dt - UNTIL_SLACK);
    if (!(k < 18446744073709551616.0)) { /* 2^64 */
        dspy_raisef(DS_ERR_ARG, "until",
                    "until = %g is beyond 2**64 - 1 steps of dt = %g from time 0", until, dt);
        return -1;
    }
    *target = k > 0.0 ? (uint64_t)k : 0;
    return 0;
}

/* Calls callback(self) at each step count that is a multiple of every,
 * until the step count reaches target. Between calls the Sim runs as
 * advance() runs it (the GIL released, signals taken); during a call it
 * is free, so the callback can read it, change it or even run it: the
 * target is a step count, not a number of steps left. A callback that
 * returns a false value other than None stops the run; one that raises
 * stops it with its exception. The steps done stay done either way. */
static int advance_calling(dspy_sim *self, ds_sim *sim, uint64_t target, PyObject *callback,
                           uint64_t every)
{
    for (uint64_t now = ds_sim_get_steps(sim); now < target; now = ds_sim_get_steps(sim)) {
        const uint64_t to_call = every - now % every, left = target - now;
        if (advance(self, sim, to_call < left ? to_call : left) < 0)
            return -1;
        if (ds_sim_get_steps(sim) % every != 0)
            continue; /* the target came first */
        PyObject *said = PyObject_CallOneArg(callback, (PyObject *)self);
        if (!said)
            return -1;
        const int go_on = said == Py_None ? 1 : PyObject_IsTrue(said);
        Py_DECREF(said);
        if (go_on <= 0)
            return go_on;
        /* The callback may have closed this Sim, re-created it, or left it
         * running in another thread: each refuses to go on. */
        ds_sim *again = dspy_sim_of(self);
        if (!again)
            return -1;
        if (again != sim) {
            PyErr_SetString(dspy_Error,
                            "run(): the callback re-created this Sim (__init__): the run stops");
            return -1;
        }
    }
    return 0;
}

static PyObject *sim_run(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"steps", "until", "callback", "every", NULL};
    PyObject *steps_obj = Py_None, *until_obj = Py_None, *callback = Py_None, *every_obj = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "|O$OOO:run", keywords, &steps_obj, &until_obj,
                                     &callback, &every_obj))
        return NULL;
    if ((steps_obj == Py_None) == (until_obj == Py_None)) {
        PyErr_SetString(PyExc_TypeError, steps_obj == Py_None
                                             ? "run() needs steps or until"
                                             : "run() takes steps or until, not both");
        return NULL;
    }
    if (callback != Py_None && !PyCallable_Check(callback)) {
        PyErr_Format(PyExc_TypeError, "callback must be callable, not %.100s",
                     Py_TYPE(callback)->tp_name);
        return NULL;
    }
    uint64_t steps = 0, every = 1;
    double until = 0.0;
    if ((steps_obj != Py_None && dspy_uint64_arg(steps_obj, "steps", 0, &steps) < 0) ||
        (until_obj != Py_None && dspy_double_arg(until_obj, "until", &until) < 0) ||
        (every_obj && dspy_uint64_arg(every_obj, "every", 0, &every) < 0))
        return NULL;
    if (every == 0)
        return dspy_raise(DS_ERR_ARG, "every", "every = 0 must be >= 1 (steps between calls)");
    /* Fetched after the conversions, which may run Python code. */
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const uint64_t now = ds_sim_get_steps(sim);
    uint64_t target;
    if (until_obj != Py_None) {
        if (steps_until(until, ds_sim_get_dt(sim), &target) < 0)
            return NULL;
        steps = target > now ? target - now : 0;
    } else if (steps > UINT64_MAX - now) {
        return dspy_raisef(DS_ERR_ARG, "steps",
                           "steps = %llu would take the step count, %llu, past 2**64 - 1",
                           (unsigned long long)steps, (unsigned long long)now);
    }
    target = now + steps;
    const int r = callback == Py_None ? advance(self, sim, steps)
                                      : advance_calling(self, sim, target, callback, every);
    if (r < 0)
        return NULL;
    Py_RETURN_NONE;
}

static PyObject *sim_step(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim || advance(self, sim, 1) < 0)
        return NULL;
    Py_RETURN_NONE;
}

static PyObject *sim_reset_observables(dspy_sim *self, PyObject *unused)
{
    (void)unused;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_sim_reset_observables(sim);
    Py_RETURN_NONE;
}

/* len(s) is s.n, as len() of a freud or HOOMD system is its particles'. */
static Py_ssize_t sim_length(dspy_sim *self)
{
    ds_sim *sim = dspy_sim_of(self);
    return sim ? (Py_ssize_t)ds_sim_get_count(sim) : -1;
}

/* Truth is not length: a Sim is true, closed or not, as any object is
 * (with __len__ alone, `if s:` would raise for a closed one). */
static int sim_bool(dspy_sim *self)
{
    (void)self;
    return 1;
}

static PySequenceMethods sim_as_sequence = {.sq_length = (lenfunc)sim_length};
static PyNumberMethods sim_as_number = {.nb_bool = (inquiry)sim_bool};

/* ---------------------------------------------------------------- methods */

static PyMethodDef sim_methods[] = {
    {"step", (PyCFunction)sim_step, METH_NOARGS,
     "step($self, /)\n--\n\n"
     "Advance simulated time by exactly dt. 'step': move by v dt, reflect at the\n"
     "walls, resolve overlapping pairs. 'event': process every collision and wall\n"
     "event inside the interval in time order, then show every disk at the new time.\n"
     "'chain': move the chains by n speed dt in all.\n"
     "Releases the GIL."},
    {"run", (PyCFunction)(void (*)(void))sim_run, METH_VARARGS | METH_KEYWORDS,
     "run($self, /, steps=None, *, until=None, callback=None, every=1)\n--\n\n"
     "Advance by steps steps (an int >= 0; 0 does nothing): the same, to the bit, as\n"
     "calling step() that many times. Or, with until instead of steps, advance to\n"
     "the first step at which the time (steps * dt) reaches until, a time short of it\n"
     "by less than a billionth of a step counting as reaching it (so until=1.0 with\n"
     "dt=0.001 is step 1000, whatever the rounding of 0.001); nothing if the time is\n"
     "already there. Releases the GIL, so threads with one Sim each run in parallel;\n"
     "Ctrl-C (KeyboardInterrupt) stops it between steps, keeping the steps done.\n"
     "\n"
     "callback(sim) is called after every step that brings the step count to a\n"
     "multiple of every (an int >= 1), as HOOMD's periodic trigger: run(1000,\n"
     "callback=f, every=100) calls f 10 times from step 0, and the same again\n"
     "from step 1000. The Sim is free while it runs (running is False): it can\n"
     "read the Sim, change it (set_state, scale_velocities) or save it. It stops\n"
     "the run by returning a false value other than None (False, 0), or by raising,\n"
     "the exception passing through run(); the steps done stay done. Calls cut the\n"
     "run into pieces, which give the same disks to the bit as one run."},
    {"reset_observables", (PyCFunction)sim_reset_observables, METH_NOARGS,
     "reset_observables($self, /)\n--\n\n"
     "Zero the wall impulse, wall count, collision virial and pressure clock (not\n"
     "the collision count or time), so that a relaxation period can be discarded\n"
     "from pressure and virial_pressure."},
    {"set_state", (PyCFunction)(void (*)(void))dspy_sim_set_state, METH_VARARGS | METH_KEYWORDS,
     "set_state($self, /, positions, velocities=None)\n--\n\n"
     "Replace every disk at once: positions and velocities are (n, 2) arrays (or\n"
     "anything numpy reads as one), row i becoming disk i; velocities=None keeps the\n"
     "present ones. The whole state is checked before anything changes (ds_sim_set_disks):\n"
     "ArgumentError if a value is not finite, a velocity component exceeds 1e12, a\n"
     "centre is outside the box ([R, box - R] x [R, box_y - R] with walls,\n"
     "[0, box) x [0, box_y) periodic) or two disks overlap (status DS_ERR_OVERLAP),\n"
     "with the library's sentence naming the disks. The integrator then starts\n"
     "afresh from the new state; time, steps and the observables go on.\n"
     "The arrays are copied: changing them afterwards changes nothing."},
    {"set_growth", (PyCFunction)(void (*)(void))dspy_sim_set_growth, METH_VARARGS | METH_KEYWORDS,
     dspy_set_growth_doc},
    {"set_thermostat", (PyCFunction)(void (*)(void))dspy_sim_set_thermostat,
     METH_VARARGS | METH_KEYWORDS, dspy_set_thermostat_doc},
    {"set_barostat", (PyCFunction)(void (*)(void))dspy_sim_set_barostat,
     METH_VARARGS | METH_KEYWORDS, dspy_set_barostat_doc},
    {"set_shear", (PyCFunction)(void (*)(void))dspy_sim_set_shear, METH_VARARGS | METH_KEYWORDS,
     dspy_set_shear_doc},
    {"velocity_profile", (PyCFunction)(void (*)(void))dspy_sim_velocity_profile,
     METH_VARARGS | METH_KEYWORDS, dspy_velocity_profile_doc},
    {"scale_velocities", (PyCFunction)(void (*)(void))dspy_sim_scale_velocities,
     METH_VARARGS | METH_KEYWORDS, dspy_scale_velocities_doc},
    {"set_restitution", (PyCFunction)(void (*)(void))dspy_sim_set_restitution,
     METH_VARARGS | METH_KEYWORDS, dspy_set_restitution_doc},
    {"set_contact_time", (PyCFunction)(void (*)(void))dspy_sim_set_contact_time,
     METH_VARARGS | METH_KEYWORDS, dspy_set_contact_time_doc},
    {"set_gravity", (PyCFunction)(void (*)(void))dspy_sim_set_gravity, METH_VARARGS | METH_KEYWORDS,
     dspy_set_gravity_doc},
    {"set_drive", (PyCFunction)(void (*)(void))dspy_sim_set_drive, METH_VARARGS | METH_KEYWORDS,
     dspy_set_drive_doc},
    {"contacts", (PyCFunction)(void (*)(void))dspy_sim_contacts, METH_VARARGS | METH_KEYWORDS,
     dspy_contacts_doc},
    {"write_frame", (PyCFunction)(void (*)(void))dspy_sim_write_frame, METH_VARARGS | METH_KEYWORDS,
     "write_frame($self, /, path, velocities=False)\n--\n\n"
     "Write the disks to the text file path as the command's frames are written:\n"
     "one line 'x y R' per disk in generation order (with velocities=True,\n"
     "'x y R vx vy'), x, y, vx, vy with 6 decimals, R in the shortest form that\n"
     "reads back exactly. read_frame() reads it back. FileError if it cannot be\n"
     "written."},
    {"pair_histogram", (PyCFunction)(void (*)(void))dspy_sim_pair_histogram,
     METH_VARARGS | METH_KEYWORDS,
     "pair_histogram($self, /, dr, bins)\n--\n\n"
     "disksim.pair_histogram() of this Sim's disks in its box and boundary: the\n"
     "number of pairs at each distance, in bins of width dr, for g(r)."},
    {"rdf", (PyCFunction)(void (*)(void))dspy_sim_rdf, METH_VARARGS | METH_KEYWORDS,
     "rdf($self, /, r_max, bins)\n--\n\n"
     "disksim.rdf() of this Sim's disks in its box and boundary: (r, g), g(r) in bins\n"
     "of width r_max / bins, normalised by an ideal gas of n centres in the same box\n"
     "(with walls, in the rectangle the centres reach, box - 2R by box_y - 2R, with\n"
     "the partners a wall takes away; a mixture's R is its mean radius, which is\n"
     "exact to first order in the radii over the box)."},
    {"local_psi6", (PyCFunction)(void (*)(void))dspy_sim_local_psi6, METH_VARARGS | METH_KEYWORDS,
     "local_psi6($self, /, cutoff=None)\n--\n\n"
     "disksim.local_psi6() of this Sim's disks in its box and boundary: psi6 of\n"
     "each disk as a complex array. cutoff=None is psi6's, 1.4 d (d = 2R)."},
    {"save", (PyCFunction)(void (*)(void))dspy_sim_save, METH_VARARGS | METH_KEYWORDS,
     "save($self, /, path)\n--\n\n"
     "Write an exact checkpoint of the simulation to path (ds_checkpoint_save): the\n"
     "parameters, time and step count, every disk to the bit, the observables'\n"
     "accumulators and the integrator's own state. disksim.load(path) gives a Sim\n"
     "that goes on bit for bit as this one would have. The format is the library's,\n"
     "portable between machines. FileError if it cannot be written. Pickling and\n"
     "copy.copy() use the same checkpoint, in memory."},
    {"__reduce__", (PyCFunction)dspy_sim_reduce, METH_NOARGS,
     "__reduce__($self, /)\n--\n\n"
     "For pickle and copy: the exact checkpoint (ds_checkpoint_format) and the arguments.\n"
     "The copy is a new, independent simulation that goes on bit for bit as this one."},
    {"to_ase", (PyCFunction)dspy_sim_to_ase, METH_NOARGS,
     "to_ase($self, /)\n--\n\n"
     "The disks as an ase.Atoms, as ASE reads the library's extended XYZ frames:\n"
     "positions with z = 0, the cell box x box_y x 2 radius_max, pbc True along each\n"
     "periodic axis (x and y periodic, x alone in a channel), never along z; dummy\n"
     "atoms 'X' (atomic number 0); arrays 'type' (each disk's kind's name), 'radius',\n"
     "'velo' (n, 3), 'momenta' (n, 3) and 'masses', so that get_velocities() and\n"
     "get_masses() are the disks' ('mass' too, OVITO's name), 'map_shift' (n, 3) the\n"
     "image counts outside a box with walls; info 'Time'. ImportError without ASE\n"
     "(Debian: python3-ase)."},
    {"freud_box", (PyCFunction)dspy_sim_freud_box, METH_NOARGS, dspy_freud_box_doc},
    {"freud_points", (PyCFunction)dspy_sim_freud_points, METH_NOARGS, dspy_freud_points_doc},
    {"close", (PyCFunction)sim_close, METH_NOARGS,
     "close($self, /)\n--\n\n"
     "Free the simulation's memory now; afterwards every use raises Error. Calling\n"
     "it again does nothing."},
    {"__enter__", (PyCFunction)sim_enter, METH_NOARGS, "__enter__($self, /)\n--\n\nReturn self."},
    {"__exit__", (PyCFunction)sim_exit, METH_VARARGS,
     "__exit__($self, *exc_info, /)\n--\n\nclose(), and let any exception through."},
    {NULL, NULL, 0, NULL},
};

PyTypeObject dspy_SimType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "disksim.Sim",
    .tp_basicsize = sizeof(dspy_sim),
    .tp_dealloc = (destructor)sim_dealloc,
    .tp_repr = (reprfunc)sim_repr,
    .tp_as_sequence = &sim_as_sequence,
    .tp_as_number = &sim_as_number,
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_BASETYPE,
    .tp_doc = sim_doc,
    .tp_methods = sim_methods,
    .tp_getset = dspy_sim_getset,
    .tp_init = (initproc)sim_init,
    .tp_new = sim_new,
};
