/* SPDX-License-Identifier: MIT */
/* Granular gases: Sim.set_restitution (ds_sim_set_restitution),
 * Sim.set_contact_time, Sim.set_gravity, Sim.set_drive and the gravity
 * property; the other granular properties (restitution, energy books) are
 * rows of properties.c. What the library refuses is raised with its
 * sentence, field, value and limit: the module holds none of these
 * arguments to a rule of its own. */
#include "disksim_py.h" /* first: Python.h sets the feature macros */

const char dspy_set_restitution_doc[] =
    "set_restitution($self, /, restitution, wall_restitution=None)\n--\n\n"
    "The coefficients of normal restitution of disk-disk collisions and of wall\n"
    "turns (wall_restitution None: as it is), each in (0, 1], from now on: a\n"
    "pair's relative normal velocity leaves -e times what it came in, a wall turns\n"
    "a disk's normal velocity into -e times itself, and the energy they take is\n"
    "energy_lost. 1 is the elastic collision, to the bit. integrator='event'\n"
    "follows the TC model: a collision within contact_time of a disk's previous\n"
    "one is elastic, so no run collapses (infinitely many collisions in finite\n"
    "time). ArgumentError for a coefficient not in (0, 1], or e < 1 while a growth\n"
    "grows.";

PyObject *dspy_sim_set_restitution(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"restitution", "wall_restitution", NULL};
    PyObject *e_obj, *wall_obj = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|O:set_restitution", keywords, &e_obj,
                                     &wall_obj))
        return NULL;
    double e, wall = NAN;
    if (dspy_double_arg(e_obj, "restitution", &e) < 0 ||
        (wall_obj != Py_None && dspy_double_arg(wall_obj, "wall_restitution", &wall) < 0))
        return NULL;
    /* Fetched after the conversions, which may run Python code. */
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_restitution(
            sim, e, wall_obj == Py_None ? ds_sim_get_wall_restitution(sim) : wall, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

const char dspy_set_contact_time_doc[] =
    "set_contact_time($self, /, contact_time)\n--\n\n"
    "The TC model's contact time t_c (> 0; 0 for the default, DS_CONTACT_TIME_DEFAULT\n"
    "= 1e-4 of the time a disk of radius takes to cross its diameter at the initial\n"
    "speed): with integrator='event' and a restitution below 1, a collision within\n"
    "t_c of a disk's previous one is elastic. A disk resting on a wall under a field\n"
    "hops about once per t_c. ArgumentError for another value.";

PyObject *dspy_sim_set_contact_time(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"contact_time", NULL};
    PyObject *obj;
    double t;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:set_contact_time", keywords, &obj) ||
        dspy_double_arg(obj, "contact_time", &t) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_contact_time(sim, t, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

const char dspy_set_gravity_doc[] =
    "set_gravity($self, /, gx, gy)\n--\n\n"
    "A uniform field from now on: every disk accelerates by (gx, gy), box units per\n"
    "time squared (gravity g is (0, -g); (0, 0) turns it off), and has the\n"
    "potential energy -m (gx x + gy y) (potential_energy). With integrator='event'\n"
    "the disks fly parabolas, exactly, and an elastic run conserves kinetic plus\n"
    "potential energy to rounding; with 'step' each step adds g dt to every\n"
    "velocity. ArgumentError for a component not finite, beyond 1e12 in magnitude,\n"
    "or other than 0 along a periodic axis (boundary='channel' has walls along y).";

PyObject *dspy_sim_set_gravity(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"gx", "gy", NULL};
    PyObject *gx_obj, *gy_obj;
    double gx, gy;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "OO:set_gravity", keywords, &gx_obj, &gy_obj) ||
        dspy_double_arg(gx_obj, "gx", &gx) < 0 || dspy_double_arg(gy_obj, "gy", &gy) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_gravity(sim, gx, gy, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

const char dspy_set_drive_doc[] =
    "set_drive($self, /, strength)\n--\n\n"
    "White-noise driving (van Noije and Ernst 1998) from now on: at the end of\n"
    "every step each velocity component of every disk changes by a Gaussian number\n"
    "of variance strength * dt, their mass-weighted mean taken out (the momentum\n"
    "stays); energy goes in at (n - 1) m strength per unit time (power_input).\n"
    "dt must be short beside the mean free time for the kicks to be white noise.\n"
    "The numbers come from the simulation's seed (a stream of the drive's own);\n"
    "checkpoints and pickles carry it. 0 stops the drive. ArgumentError for a\n"
    "strength < 0, not finite or above 1e24, or while a growth grows.";

PyObject *dspy_sim_set_drive(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"strength", NULL};
    PyObject *obj;
    double s;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:set_drive", keywords, &obj) ||
        dspy_double_arg(obj, "strength", &s) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_drive(sim, s, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

PyObject *dspy_gravity_property(dspy_sim *self, void *closure)
{
    (void)closure;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    double gx = 0.0, gy = 0.0;
    ds_sim_get_gravity(sim, &gx, &gy);
    return Py_BuildValue("(dd)", gx, gy);
}
