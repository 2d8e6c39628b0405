/* SPDX-License-Identifier: MIT */
/* Compression and what goes with it: Sim.set_growth (ds_sim_set_growth),
 * Sim.scale_velocities (ds_sim_scale_velocities) and Sim.contacts
 * (ds_sim_get_contacts, a Contacts named tuple). What the library refuses
 * is raised with its sentence, field, value and limit: the module holds
 * none of these arguments to a rule of its own. */
#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <math.h>

static PyTypeObject *contacts_type;

static PyStructSequence_Field contacts_fields[] = {
    {"pairs", "contacts between the disks that are left"},
    {"rattlers", "disks removed: fewer than 3 contacts, again and again until none is left"},
    {"per_disk", "contacts per disk left, 2 pairs / (n - rattlers); 0 if none is left"},
    {"rattler_fraction", "rattlers / n"},
    {NULL, NULL},
};

static PyStructSequence_Desc contacts_desc = {
    "disksim.Contacts",
    "Contacts(pairs, rattlers, per_disk, rattler_fraction): a packing's contacts,\n"
    "rattlers removed (ds_contacts), as Sim.contacts() returns them.",
    contacts_fields,
    4,
};

int dspy_add_contacts_type(PyObject *module)
{
    contacts_type = PyStructSequence_NewType(&contacts_desc);
    if (!contacts_type)
        return -1;
    return PyModule_AddObjectRef(module, "Contacts", (PyObject *)contacts_type);
}

const char dspy_set_growth_doc[] =
    "set_growth($self, /, rate, until_eta=0.0, until_z=0.0)\n--\n\n"
    "Lubachevsky-Stillinger compression, for integrator='event' in a periodic box\n"
    "only: from now on every radius grows in proportion to itself,\n"
    "r(t) = r(now) (1 + rate (t - now)), so the ratios of a mixture stay, until the\n"
    "area fraction reaches until_eta (0: no target), at that exact time, or the\n"
    "reduced pressure Z (watched over windows of 2 n collisions, with the\n"
    "temperature of the internal motion) passes until_z (0 means JAMMED_Z, 1e6; at\n"
    "most 1e9), whichever comes first; rate 0 stops it. Past Z = 10^4 the growth\n"
    "slows as 10^4 / Z, so the disks can rearrange near jamming. Collisions with\n"
    "growing disks add energy: at the end of each window, and when the growth stops,\n"
    "every velocity is scaled back to the kinetic energy of this call. The masses\n"
    "stay. set_state() stops growth; so does a call with other targets, which starts\n"
    "again from now. growth_state and growth_z say how it goes. ArgumentError for\n"
    "another integrator or boundary, a rate < 0 or not finite, a rate at which the\n"
    "largest pair's surfaces recede faster than 10 rms speeds, until_eta not 0 and\n"
    "not between the area fraction of now and 1, until_z not 0 and not in (1, 1e9].";

PyObject *dspy_sim_set_growth(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"rate", "until_eta", "until_z", NULL};
    PyObject *rate_obj, *eta_obj = NULL, *z_obj = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O|OO:set_growth", keywords, &rate_obj, &eta_obj,
                                     &z_obj))
        return NULL;
    double rate, until_eta = 0.0, until_z = 0.0;
    if (dspy_double_arg(rate_obj, "rate", &rate) < 0 ||
        (eta_obj && dspy_double_arg(eta_obj, "until_eta", &until_eta) < 0) ||
        (z_obj && dspy_double_arg(z_obj, "until_z", &until_z) < 0))
        return NULL;
    /* Fetched after the conversions, which may run Python code. */
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_growth(sim, rate, until_eta, until_z, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

const char dspy_scale_velocities_doc[] =
    "scale_velocities($self, /, factor)\n--\n\n"
    "Every velocity times factor (> 0, finite), now: a thermostat's step, or a\n"
    "compression taking out its heat. ArgumentError for another factor, or one that\n"
    "would take a velocity component beyond VELOCITY_MAX (1e12), which set_state\n"
    "refuses too.";

PyObject *dspy_sim_scale_velocities(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"factor", NULL};
    PyObject *factor_obj;
    double factor;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:scale_velocities", keywords, &factor_obj) ||
        dspy_double_arg(factor_obj, "factor", &factor) < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_scale_velocities(sim, factor, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

const char dspy_contacts_doc[] =
    "contacts($self, /, gap=1e-4)\n--\n\n"
    "The contacts of the packing now, as a Contacts(pairs, rattlers, per_disk,\n"
    "rattler_fraction) named tuple: pairs whose centres are closer than\n"
    "(r_i + r_j) (1 + gap), gap in [0, 1). A jammed packing's contacts are what its\n"
    "pressure keeps a hair apart: at Z = 10^6 they are 1e-6 to 1e-4 of their contact\n"
    "distance apart, so the default 1e-4 counts them (docs/physics.md).\n"
    "Rattlers, disks with fewer than 3 contacts (which a disk in the plane needs to\n"
    "be held), are removed, and removed again as their removal leaves others with\n"
    "fewer, until none is left; per_disk is 2 pairs / (n - rattlers). O(n);\n"
    "releases the GIL. ArgumentError for a gap not in [0, 1).";

PyObject *dspy_sim_contacts(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"gap", NULL};
    PyObject *gap_obj = NULL;
    double gap = 1e-4;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "|O:contacts", keywords, &gap_obj) ||
        (gap_obj && dspy_double_arg(gap_obj, "gap", &gap) < 0))
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_contacts c;
    ds_error err;
    ds_status st;
    self->busy = 1;
    Py_BEGIN_ALLOW_THREADS
    st = ds_sim_get_contacts(sim, gap, &c, &err);
    Py_END_ALLOW_THREADS
    self->busy = 0;
    if (st != DS_OK)
        return dspy_raise_error(&err);
    PyObject *result = PyStructSequence_New(contacts_type);
    PyObject *items[4] = {PyLong_FromSize_t(c.pairs), PyLong_FromSize_t(c.rattlers),
                          PyFloat_FromDouble(c.per_disk), PyFloat_FromDouble(c.rattler_fraction)};
    for (int k = 0; k < 4; ++k) {
        if (!items[k] || !result) {
            for (int j = 0; j < 4; ++j)
                Py_XDECREF(items[j]);
            Py_XDECREF(result);
            return NULL;
        }
    }
    for (int k = 0; k < 4; ++k)
        PyStructSequence_SetItem(result, k, items[k]);
    return result;
}
