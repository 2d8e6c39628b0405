/* SPDX-License-Identifier: MIT */
/* The canonical and isobaric ensembles: Sim.set_thermostat
 * (ds_sim_set_thermostat) and Sim.set_barostat (ds_sim_set_barostat).
 * The keywords are the library's names for its arguments, so a refusal's
 * field is the keyword at fault; what the library refuses is raised with
 * its sentence, field, value and limit. */
#include "disksim_py.h" /* first: Python.h sets the feature macros */

const char dspy_set_thermostat_doc[] =
    "set_thermostat($self, /, kind, kt=0.0, collision_rate=0.0)\n--\n\n"
    "A heat bath at temperature kt from now on, with either integrator, in any box;\n"
    "kind 'none' removes it. kt is an energy (mass length^2 / time^2): a disk of\n"
    "mass m has mean kinetic energy kT, so mass 1 at the default speed 100 is\n"
    "kT = 5000; kt 0 means the temperature of now. 'andersen': each disk, at the\n"
    "times of a Poisson process of collision_rate per disk per unit time (0: 0.1\n"
    "sqrt(kT) / sigma, sigma the largest diameter), gets a velocity drawn afresh\n"
    "from Maxwell-Boltzmann with its own mass, from the Sim's seed: the canonical\n"
    "ensemble, exactly ('event' redraws at the exact times, 'step' at the end of the\n"
    "step each falls in). 'isokinetic': every velocity scaled at the end of every\n"
    "step to the kinetic temperature kt (for driven systems); it takes no\n"
    "collision_rate. While one is set, temperature is its kt, and virial_pressure\n"
    "and compressibility_factor take it. Checkpoints (save, pickle) carry it, its\n"
    "random numbers with it. ArgumentError for a kind not in THERMOSTATS, kt < 0 or\n"
    "not finite (or past what keeps every velocity below VELOCITY_MAX), kt 0 with\n"
    "the disks at rest, collision_rate < 0 or not finite, or not 0 for\n"
    "'isokinetic', or a growth that is growing.";

PyObject *dspy_sim_set_thermostat(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"kind", "kt", "collision_rate", NULL};
    PyObject *kind_obj, *kt_obj = NULL, *rate_obj = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|OO:set_thermostat", keywords, &kind_obj,
                                     &kt_obj, &rate_obj))
        return NULL;
    int kind = 0;
    double kt = 0.0, rate = 0.0;
    if (dspy_parse_name(DSPY_THERMOSTAT, kind_obj, "kind", &kind) < 0 ||
        (kt_obj && dspy_double_arg(kt_obj, "kt", &kt) < 0) ||
        (rate_obj && dspy_double_arg(rate_obj, "collision_rate", &rate) < 0))
        return NULL;
    /* Fetched after the conversions, which may run Python code. */
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_thermostat(sim, (ds_thermostat)kind, kt, rate, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

const char dspy_set_barostat_doc[] =
    "set_barostat($self, /, pressure, every=0, max_step=0.0, aspect=False)\n--\n\n"
    "Monte Carlo moves of the box at the reduced pressure beta P sigma^2 (sigma the\n"
    "largest diameter), in a periodic box only, from now on; pressure 0 removes\n"
    "it. At the end of every step whose count is a multiple of every (0: 10) the\n"
    "area makes a random-walk move, ln A by up to max_step (0: 1 / (4 n); at most\n"
    "1), the sides and every centre scaled with it (velocities and image counts\n"
    "kept), accepted with probability min(1, exp(-beta P dA + (n + 1) d ln A))\n"
    "unless two disks would overlap; with aspect=True the aspect moves too, at\n"
    "fixed area (a crystal's box must find its own shape; a fluid's drifts). The\n"
    "isobaric ensemble, with either integrator, with a heat bath or without\n"
    "(hard disks have no potential energy). box, box_y and area_fraction follow\n"
    "the moves; barostat_acceptance says how many are accepted. Checkpoints carry\n"
    "it. ArgumentError for another boundary, a pressure < 0, not finite or above\n"
    "1e9, a max_step < 0, not finite or above 1, or a growth that is growing.";

PyObject *dspy_sim_set_barostat(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"pressure", "every", "max_step", "aspect", NULL};
    PyObject *pressure_obj, *every_obj = NULL, *step_obj = NULL;
    int aspect = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|OOp:set_barostat", keywords, &pressure_obj,
                                     &every_obj, &step_obj, &aspect))
        return NULL;
    double pressure = 0.0, max_step = 0.0;
    uint64_t every = 0;
    if (dspy_double_arg(pressure_obj, "pressure", &pressure) < 0 ||
        (every_obj && dspy_uint64_arg(every_obj, "every", 0, &every) < 0) ||
        (step_obj && dspy_double_arg(step_obj, "max_step", &max_step) < 0))
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_barostat(sim, pressure, every, max_step, aspect, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}
