/* SPDX-License-Identifier: MIT */
/* Sim's properties: each is one row of the table at the end, its getter
 * in the library and its docstring, so a new observable of the library is
 * one line here. Every getter goes through dspy_sim_of, so a closed Sim or
 * one in use by another thread raises instead of being read. */
#include "disksim_py.h" /* first: Python.h sets the feature macros */

/* A property is one row: its getter in the library and its docstring.
 * The closures hold the library's function behind a struct, as C has no
 * conversion between function and data pointers. */
typedef struct real_getter {
    double (*get)(const ds_sim *);
} real_getter;
typedef struct count_getter {
    uint64_t (*get)(const ds_sim *);
} count_getter;

static uint64_t count_of(const ds_sim *sim) { return ds_sim_get_count(sim); }
/* psi6, NaN where the library refuses it (a periodic box too narrow). */
static double psi6_or_nan(const ds_sim *sim)
{
    double psi6 = NAN;
    (void)ds_sim_get_psi6(sim, &psi6, NULL);
    return psi6;
}

static const real_getter get_time = {ds_sim_get_time}, get_radius = {ds_sim_get_radius},
                         get_box = {ds_sim_get_box_width}, get_box_y = {ds_sim_get_box_height},
                         get_dt = {ds_sim_get_dt}, get_kinetic_energy = {ds_sim_get_kinetic_energy},
                         get_pressure = {ds_sim_get_pressure},
                         get_virial_pressure = {ds_sim_get_virial_pressure},
                         get_psi6 = {psi6_or_nan}, get_wall_impulse = {ds_sim_get_wall_impulse},
                         get_collision_seconds = {ds_sim_get_collision_seconds},
                         get_radius_max = {ds_sim_get_radius_max},
                         get_area_fraction = {ds_sim_get_area_fraction},
                         get_growth_z = {ds_sim_get_growth_z},
                         get_thermostat_kt = {ds_sim_get_thermostat_temperature},
                         get_barostat_pressure = {ds_sim_get_barostat_pressure},
                         get_barostat_acceptance = {ds_sim_get_barostat_acceptance},
                         get_shear_rate = {ds_sim_get_shear},
                         get_shear_shift = {ds_sim_get_shear_shift},
                         get_shear_offset = {ds_sim_get_shear_offset},
                         get_temperature = {ds_sim_get_temperature},
                         get_compressibility_factor = {ds_sim_get_compressibility_factor},
                         get_restitution = {ds_sim_get_restitution},
                         get_wall_restitution = {ds_sim_get_wall_restitution},
                         get_contact_time = {ds_sim_get_contact_time},
                         get_drive = {ds_sim_get_drive}, get_energy_lost = {ds_sim_get_energy_lost},
                         get_energy_input = {ds_sim_get_energy_input},
                         get_power_lost = {ds_sim_get_power_lost},
                         get_power_input = {ds_sim_get_power_input},
                         get_potential_energy = {ds_sim_get_potential_energy};
static const count_getter get_steps = {ds_sim_get_steps}, get_n = {count_of},
                          get_collision_count = {ds_sim_get_collision_count},
                          get_wall_count = {ds_sim_get_wall_count},
                          get_pairs_tested = {ds_sim_get_pairs_tested};

static PyObject *real_property(dspy_sim *self, void *closure)
{
    ds_sim *sim = dspy_sim_of(self);
    return sim ? PyFloat_FromDouble(((const real_getter *)closure)->get(sim)) : NULL;
}

static PyObject *count_property(dspy_sim *self, void *closure)
{
    ds_sim *sim = dspy_sim_of(self);
    return sim ? PyLong_FromUnsignedLongLong(((const count_getter *)closure)->get(sim)) : NULL;
}

static PyObject *name_property(dspy_sim *self, void *closure)
{
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const dspy_kind kind = (dspy_kind)(*(const int *)closure);
    int value = 0;
    switch (kind) {
    case DSPY_INTEGRATOR:
        value = (int)ds_sim_get_integrator(sim);
        break;
    case DSPY_BOUNDARY:
        value = (int)ds_sim_get_boundary(sim);
        break;
    case DSPY_BROADPHASE:
        value = (int)ds_sim_get_broadphase(sim);
        break;
    case DSPY_PLACEMENT:
        if (dspy_param_unknown(self->unknown, "placement"))
            Py_RETURN_NONE; /* a loaded checkpoint does not say */
        value = (int)self->params.placement;
        break;
    case DSPY_GROWTH_STATE:
        value = (int)ds_sim_get_growth_state(sim);
        break;
    case DSPY_THERMOSTAT:
        value = (int)ds_sim_get_thermostat(sim);
        break;
    case DSPY_MASS_RULE:
    case DSPY_FORMAT:
    case DSPY_KINDS:
        break;
    }
    const char *name = dspy_name_of(kind, value);
    return PyUnicode_FromString(name ? name : "unknown");
}
static const int integrator_kind = DSPY_INTEGRATOR, boundary_kind = DSPY_BOUNDARY,
                 broadphase_kind = DSPY_BROADPHASE, placement_kind = DSPY_PLACEMENT,
                 growth_state_kind = DSPY_GROWTH_STATE, thermostat_kind = DSPY_THERMOSTAT;

/* Every disk's radius (masses 0) or mass (1) as a new (n,) array. */
static PyObject *per_disk(dspy_sim *self, int masses)
{
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    npy_intp dims[1] = {(npy_intp)ds_sim_get_count(sim)};
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(1, dims, NPY_DOUBLE);
    ds_error err;
    if (a && (masses ? ds_sim_get_masses(sim, (double *)PyArray_DATA(a), &err)
                     : ds_sim_get_radii(sim, (double *)PyArray_DATA(a), &err)) != DS_OK) {
        Py_DECREF(a);
        return dspy_raise_error(&err);
    }
    return (PyObject *)a;
}

static PyObject *radii_property(dspy_sim *self, void *closure)
{
    (void)closure;
    return per_disk(self, 0);
}

static PyObject *masses_property(dspy_sim *self, void *closure)
{
    (void)closure;
    return per_disk(self, 1);
}

/* Every disk's kind as a new (n,) uint32 array. */
static PyObject *kinds_property(dspy_sim *self, void *closure)
{
    (void)closure;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    npy_intp dims[1] = {(npy_intp)ds_sim_get_count(sim)};
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(1, dims, NPY_UINT32);
    ds_error err;
    if (a && ds_sim_get_kinds(sim, (uint32_t *)PyArray_DATA(a), &err) != DS_OK) {
        Py_DECREF(a);
        return dspy_raise_error(&err);
    }
    return (PyObject *)a;
}

/* The kinds' names, a tuple of str by kind. */
static PyObject *kind_names_property(dspy_sim *self, void *closure)
{
    (void)closure;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const size_t count = ds_sim_get_kind_count(sim);
    PyObject *names = PyTuple_New((Py_ssize_t)count);
    for (size_t k = 0; names && k < count; ++k) {
        PyObject *name = PyUnicode_FromString(ds_sim_get_kind_name(sim, k));
        if (!name) {
            Py_CLEAR(names);
            break;
        }
        PyTuple_SET_ITEM(names, (Py_ssize_t)k, name);
    }
    return names;
}

static PyObject *momentum_property(dspy_sim *self, void *closure)
{
    (void)closure;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    double px, py;
    ds_sim_get_momentum(sim, &px, &py);
    return Py_BuildValue("(dd)", px, py);
}

/* The stress integral's (xx, yy, xy): a tuple, as momentum. */
static PyObject *stress_integral_property(dspy_sim *self, void *closure)
{
    (void)closure;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    double s[3];
    ds_sim_get_stress_integral(sim, s, NULL);
    return Py_BuildValue("(ddd)", s[0], s[1], s[2]);
}

static PyObject *params_property(dspy_sim *self, void *closure)
{
    (void)closure;
    return dspy_sim_of(self) ? dspy_params_dict(&self->params, self->unknown, self->mixture_args)
                             : NULL;
}

static PyObject *closed_property(dspy_sim *self, void *closure)
{
    (void)closure;
    return PyBool_FromLong(!self->sim && !self->busy);
}

static PyObject *running_property(dspy_sim *self, void *closure)
{
    (void)closure;
    return PyBool_FromLong(self->busy);
}

#define REAL(name, doc)                                                                            \
    {                                                                                              \
#name, (getter)real_property, NULL, doc, (void *)&get_##name                               \
    }
#define COUNT(name, doc)                                                                           \
    {                                                                                              \
#name, (getter)count_property, NULL, doc, (void *)&get_##name                              \
    }
#define NAME(name, doc)                                                                            \
    {                                                                                              \
#name, (getter)name_property, NULL, doc, (void *)&name##_kind                              \
    }

PyGetSetDef dspy_sim_getset[] = {
    COUNT(n, "Number of disks."),
    REAL(radius, "Disk radius; in a mixture the reference radius R (mass='area' weighs a\n"
                 "disk (r / R)^2), the disks' own being radii."),
    {"radii", (getter)radii_property, NULL,
     "Every disk's radius as a new (n,) float64 array, in generation order (a copy;\n"
     "radius for each disk of one kind). Growth makes them grow.",
     NULL},
    {"masses", (getter)masses_property, NULL,
     "Every disk's mass as a new (n,) float64 array, in generation order (a copy;\n"
     "1 for each disk of one kind).",
     NULL},
    {"kinds", (getter)kinds_property, NULL,
     "Every disk's kind as a new (n,) uint32 array, in generation order: its\n"
     "species' index in species= (0 without species).",
     NULL},
    {"kind_names", (getter)kind_names_property, NULL,
     "The kinds' names by kind, a tuple of str: 'A', 'B', ... in the order of\n"
     "species= (('A',) without species).",
     NULL},
    REAL(radius_max, "The largest radius (radius with one kind of disk)."),
    REAL(area_fraction, "The fraction of the box the disks cover: sum of pi r^2 over box box_y."),
    REAL(box, "Width of the box."),
    REAL(box_y, "Height of the box (box when square)."),
    REAL(dt, "The time step: the simulated time one step() advances."),
    NAME(integrator, "The integrator: 'step', 'event' or 'chain'."),
    NAME(boundary, "The boundary: 'walls' or 'periodic'."),
    NAME(placement, "How the disks were placed: 'random' or 'lattice' (None for a Sim from\n"
                    "load(), whose checkpoint does not say)."),
    NAME(broadphase, "The broad phase in use, never 'auto' ('sap', 'strips', 'brute', 'cells')."),
    REAL(time, "Simulated time: steps * dt (a product, so it carries no rounding drift)."),
    COUNT(steps, "Steps taken since creation."),
    {"positions", (getter)dspy_positions_property, NULL,
     "The centres as a new (n, 2) float64 array, row i disk i (generation order):\n"
     "a copy, made at each read; changing it changes nothing (see set_state).",
     NULL},
    {"velocities", (getter)dspy_velocities_property, NULL,
     "The velocities as a new (n, 2) float64 array, row i disk i: a copy, as\n"
     "positions.",
     NULL},
    {"unwrapped", (getter)dspy_unwrapped_property, NULL,
     "The unwrapped centres as a new (n, 2) float64 array, row i disk i: the\n"
     "position plus the box side times the times disk i has crossed the box that\n"
     "way since it was placed (set_state starts them again), so displacements over\n"
     "any time are differences of these; with walls, the positions. Under shear\n"
     "(set_shear) each crossing of the top adds shear_offset along x too.",
     NULL},
    {"images", (getter)dspy_images_property, NULL,
     "The periodic image counts as a new (n, 2) int32 array, row i disk i: how many\n"
     "times disk i has crossed the box along x and along y since it was placed (+1\n"
     "leaving through the far edge, -1 through 0; LAMMPS' ix iy, GSD's\n"
     "particles/image), so unwrapped = positions + images * (box, box_y). set_state\n"
     "sets them to 0; checkpoints and pickles carry them; with walls (and along a\n"
     "channel's y) they are 0. They wrap past 2**31 crossings. Under shear\n"
     "unwrapped adds images[:, 1] * shear_offset along x.",
     NULL},
    REAL(kinetic_energy, "Kinetic energy, the sum of m v^2 / 2 (masses 1 unless a mixture's)."),
    {"momentum", (getter)momentum_property, NULL,
     "Total momentum (px, py), the sum of m v. Pairs conserve it; walls do not.", NULL},
    {"stress_integral", (getter)stress_integral_property, NULL,
     "The time integral of the pressure tensor times the area since creation,\n"
     "(s_xx, s_yy, s_xy) (ds_sim_get_stress_integral; not reset, checkpoints carry\n"
     "it): the kinetic part integrated exactly between velocity changes, the\n"
     "collisions' impulses added. The mean pressure tensor over a stretch is its\n"
     "change over A t (A = box * box_y in a periodic box), so under shear the\n"
     "apparent viscosity is -(change of s_xy) / (A t shear_rate); the kinetic xy\n"
     "part is then the peculiar velocities'. At rest its increments are the\n"
     "Helfand moments of the shear viscosity.",
     NULL},
    REAL(pressure, "Wall pressure: the wall impulse per unit time per unit length of wall the\n"
                   "centres reach (perimeter 2 (box - 2R) + 2 (box_y - 2R)), averaged since the\n"
                   "last reset; 0 before any step. A force per length: the ideal gas has\n"
                   "P A = N <v^2> / 2. A periodic box has no walls: there it is virial_pressure."),
    REAL(virial_pressure,
         "Pressure from the collision virial, averaged since the last reset, 0 before\n"
         "any step: P A = E + (1 / (2 t)) sum over collisions of r_ij . dp_i, with E the\n"
         "kinetic energy (N kT = E in 2D) and A the area the centres reach, (box - 2R)\n"
         "(box_y - 2R) with walls, box box_y in a periodic box. The compressibility\n"
         "factor is Z = compressibility_factor. With the time step the collisions happen\n"
         "a little inside 2R, which biases it low."),
    REAL(temperature,
         "The temperature the collisions see: kT = kinetic_energy / n with walls; in a\n"
         "periodic box, where the momentum is conserved, kT = K_int / (n - 1), K_int the\n"
         "kinetic energy less the centre of mass's (0 for one disk)."),
    REAL(compressibility_factor,
         "The canonical compressibility factor Z = P A / (n kT), kT = temperature,\n"
         "averaged since the last reset (0 before any step): the Z Monte Carlo gives at\n"
         "the same n. With walls it is virial_pressure * A / kinetic_energy; periodic,\n"
         "that is high by about (Z - 1) / n and this is not."),
    REAL(psi6, "Global bond-orientational order |(1/N) sum_j psi6_j| of the disks now, with\n"
               "cutoff 1.4 d (d = 2R): near 1 for a crystal of one orientation, O(1/sqrt N)\n"
               "for a liquid. Computed when read, O(N). NaN for a periodic box narrower than\n"
               "2.8 d. Per disk: local_psi6()."),
    COUNT(collision_count,
          "Disk-disk collisions resolved since creation (reset_observables keeps it); with\n"
          "'chain', the chains' liftings."),
    COUNT(wall_count, "Wall reflections since the last reset (with 'chain', wall turns)."),
    REAL(wall_impulse, "Momentum handed to the walls since the last reset: the sum of 2 |v_n|\n"
                       "(with 'chain', 4 kT / speed a wall turn: what the dynamics would hand)."),
    COUNT(pairs_tested, "Narrow-phase distance tests since creation."),
    REAL(collision_seconds,
         "Wall-clock seconds spent on collisions, summed over all steps: with 'step',\n"
         "sorting, pruning, testing and resolving pairs; with 'event', processing\n"
         "events (collisions, wall turns, cell crossings) and their predictions; with\n"
         "'chain', moving the chains."),
    NAME(growth_state,
         "Growth (set_growth): 'none' (never grown, stopped with rate 0, ended by\n"
         "set_state, or stopped by run() for want of memory, which raises\n"
         "NoMemoryError), 'growing', 'reached_eta' (stopped at until_eta) or 'jammed'\n"
         "(stopped when Z passed until_z)."),
    REAL(growth_z, "The reduced pressure Z growth measured over its last window of 2 n\n"
                   "collisions (when it jammed, the window that stopped it); 0 before its\n"
                   "first window, and for a simulation that never grew."),
    REAL(restitution, "The coefficient of restitution of disk-disk collisions (set_restitution;\n"
                      "1: elastic)."),
    REAL(wall_restitution, "The coefficient of restitution of wall turns (1: elastic)."),
    REAL(contact_time, "The TC model's contact time t_c (set_contact_time)."),
    {"gravity", (getter)dspy_gravity_property, NULL,
     "The field (gx, gy) every disk accelerates by (set_gravity; (0, 0): none).", NULL},
    REAL(drive, "The strength of the white-noise drive (set_drive; 0: none)."),
    REAL(energy_lost, "Kinetic energy the collisions and wall turns took out since the last\n"
                      "reset (restitution below 1)."),
    REAL(energy_input, "Energy the drive's kicks put in since the last reset."),
    REAL(power_lost, "energy_lost per unit time since the last reset (0 before any step)."),
    REAL(power_input, "energy_input per unit time since the last reset (0 before any step);\n"
                      "in a steady state it equals power_lost within their fluctuations."),
    REAL(potential_energy, "The field's potential energy, -sum m (gx x + gy y) (0 without one):\n"
                           "an elastic run keeps kinetic_energy + potential_energy."),
    NAME(thermostat, "The heat bath set (set_thermostat): 'none', 'andersen' or 'isokinetic'."),
    REAL(thermostat_kt, "The heat bath's temperature kT (set_thermostat), an energy; 0 without\n"
                        "one."),
    REAL(barostat_pressure, "The reduced pressure beta P sigma^2 of the barostat (set_barostat);\n"
                            "0 without one."),
    REAL(barostat_acceptance,
         "The fraction of the barostat's area moves accepted since it was set (0 before\n"
         "the first): about a third to a half is a good max_step."),
    REAL(shear_rate, "The shear rate dv_x/dy of set_shear (0 without a shear)."),
    REAL(shear_shift, "How far along x the image above the box stands now, in [0, box): the\n"
                      "Lees-Edwards images' offset (0 without a shear; the image below stands\n"
                      "-shear_shift)."),
    REAL(shear_offset, "shear_shift unwrapped (plus whole box widths), continuous in time: an\n"
                       "unwrapped centre is x + ix box + iy shear_offset (unwrapped takes it)."),
    {"params", (getter)params_property, NULL,
     "The arguments this Sim was created with, as a dict: Sim(**s.params) makes the\n"
     "same simulation at time 0. A Sim from load() has those the library tells: no\n"
     "seed, speed, placement or mixture arguments (its radii and masses are radii\n"
     "and masses).",
     NULL},
    {"closed", (getter)closed_property, NULL, "Whether close() has freed this Sim.", NULL},
    {"running", (getter)running_property, NULL,
     "Whether a thread is inside this Sim's run() (or step(), set_state(),\n"
     "write_frame()) now; not while run() calls its callback, when the Sim is free.\n"
     "Never raises.",
     NULL},
    {NULL, NULL, NULL, NULL, NULL},
};
