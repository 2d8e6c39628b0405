/* SPDX-License-Identifier: MIT */
/* Shear flow: Sim.set_shear (ds_sim_set_shear, Lees-Edwards boundaries)
 * and Sim.velocity_profile, the flow and the temperature in bins of y;
 * the rate and the images' offset are rows of properties.c. What the
 * library refuses is raised with its sentence, field, value and limit. */
#include "disksim_py.h" /* first: Python.h sets the feature macros */

#include <math.h>

const char dspy_set_shear_doc[] =
    "set_shear($self, /, rate)\n--\n\n"
    "Shear flow at rate = dv_x/dy (per unit time, either sign) from now on, with\n"
    "Lees-Edwards boundaries (Lees and Edwards 1972): the images above the box move\n"
    "at rate * box_y along x, those below the other way, and a disk leaving through\n"
    "the top comes in at the bottom at the image's place and velocity. The disks\n"
    "take the profile's velocity rate * (y - box_y / 2) added to their vx (set\n"
    "again, the change of it); rate 0 stops the images. The viscous heat is for\n"
    "set_thermostat('isokinetic') to take out: it scales the peculiar velocities\n"
    "(less the profile's), which are also what temperature and the kinetic xy part\n"
    "of the stress integral take, so the apparent viscosity is -P_xy / rate.\n"
    "integrator='event' and boundary='periodic' only. Checkpoints, pickles and\n"
    "copies carry it; shear_rate, shear_shift and shear_offset read it back.\n"
    "ArgumentError (its field the one at fault) for a rate not finite (field\n"
    "'rate'), a strain above SHEAR_MAX_STRAIN_PER_STEP a step ('rate'), images\n"
    "faster than VELOCITY_MAX / 4 ('rate'), another boundary ('boundary') or\n"
    "integrator ('integrator'), Andersen's heat bath ('thermostat'), a barostat\n"
    "('barostat') or a growth that is growing ('growth').";

PyObject *dspy_sim_set_shear(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"rate", NULL};
    PyObject *obj;
    double rate;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:set_shear", keywords, &obj) ||
        dspy_double_arg(obj, "rate", &rate) < 0)
        return NULL;
    /* Fetched after the conversion, which may run Python code. */
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    ds_error err;
    if (ds_sim_set_shear(sim, rate, &err) != DS_OK)
        return dspy_raise_error(&err);
    Py_RETURN_NONE;
}

const char dspy_velocity_profile_doc[] =
    "velocity_profile($self, /, bins)\n--\n\n"
    "The flow and its temperature in bins equal slices of the box along y, now:\n"
    "(y, vx, kt), three (bins,) float64 arrays. y is each slice's centre, (b + 1/2)\n"
    "box_y / bins; vx the slice's flow velocity along x, its disks' mass-weighted\n"
    "mean sum m vx / sum m (a shear flow's is shear_rate * (y - box_y / 2)); kt its\n"
    "kinetic temperature, of the peculiar velocities c = v - (shear_rate * (y -\n"
    "box_y / 2), 0) about their own mean u in the slice: sum m |c - u|^2 / (2 (k -\n"
    "1)) for its k disks. The profile is taken out disk by disk, so that a slice's\n"
    "width adds no spread of the flow to its heat (rate * width across it); the mean\n"
    "taken out costs two degrees of freedom, so the estimate is unbiased, as\n"
    "temperature's K_int / (n - 1) is for the whole box; without shear c is v. A\n"
    "slice with no disk has vx NaN, one with fewer than two kt NaN. One snapshot is\n"
    "noisy: average many, weighting by the disks in each slice, and fit the slope\n"
    "of vx against y for the rate. ArgumentError for bins 0 (field 'bins').";

/* Per slice: the disks' count, mass, momentum and peculiar momentum,
 * then the peculiar kinetic energy about the slice's mean (a second pass:
 * the flow's velocity can be much larger than the thermal spread, which a
 * one-pass difference of sums would lose to rounding). */
typedef struct slice {
    double count, mass, px, cx, py, heat;
} slice;

static size_t slice_of(double y, double height, size_t bins)
{
    const double b = floor(y / height * (double)bins);
    return b < 0.0 ? 0 : b >= (double)bins ? bins - 1 : (size_t)b;
}

PyObject *dspy_sim_velocity_profile(dspy_sim *self, PyObject *args, PyObject *kwargs)
{
    static char *keywords[] = {"bins", NULL};
    PyObject *obj;
    uint64_t bins;
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "O:velocity_profile", keywords, &obj) ||
        dspy_uint64_arg(obj, "bins", 1, &bins) < 0)
        return NULL;
    if (bins == 0)
        return dspy_raisef(DS_ERR_ARG, "bins", "bins = 0: a profile needs at least one slice");
    if (dspy_check_memory(8.0 * 8.0 * (double)bins, "bins") < 0)
        return NULL;
    ds_sim *sim = dspy_sim_of(self);
    if (!sim)
        return NULL;
    const size_t n = ds_sim_get_count(sim), nb = (size_t)bins;
    const double height = ds_sim_get_box_height(sim), rate = ds_sim_get_shear(sim);
    ds_disk *disks = dspy_get_all(sim);
    double *masses = disks ? PyMem_RawMalloc(n * sizeof *masses + 1) : NULL;
    slice *s = masses ? PyMem_RawCalloc(nb, sizeof *s) : NULL;
    npy_intp dims[1] = {(npy_intp)nb};
    PyObject *y = s ? PyArray_SimpleNew(1, dims, NPY_FLOAT64) : NULL;
    PyObject *vx = y ? PyArray_SimpleNew(1, dims, NPY_FLOAT64) : NULL;
    PyObject *kt = vx ? PyArray_SimpleNew(1, dims, NPY_FLOAT64) : NULL;
    PyObject *result = NULL;
    if (!kt) {
        if (!PyErr_Occurred())
            PyErr_NoMemory();
        goto done;
    }
    ds_sim_get_masses(sim, masses, NULL);
    for (size_t i = 0; i < n; ++i) {
        slice *c = &s[slice_of(disks[i].y, height, nb)];
        c->count += 1.0;
        c->mass += masses[i];
        c->px += masses[i] * disks[i].vx;
        c->cx += masses[i] * (disks[i].vx - rate * (disks[i].y - 0.5 * height));
        c->py += masses[i] * disks[i].vy;
    }
    for (size_t i = 0; i < n; ++i) {
        slice *c = &s[slice_of(disks[i].y, height, nb)];
        const double cx = disks[i].vx - rate * (disks[i].y - 0.5 * height);
        const double ux = cx - c->cx / c->mass, uy = disks[i].vy - c->py / c->mass;
        c->heat += masses[i] * (ux * ux + uy * uy);
    }
    double *out_y = PyArray_DATA((PyArrayObject *)y), *out_vx = PyArray_DATA((PyArrayObject *)vx),
           *out_kt = PyArray_DATA((PyArrayObject *)kt);
    for (size_t b = 0; b < nb; ++b) {
        out_y[b] = ((double)b + 0.5) * height / (double)nb;
        out_vx[b] = s[b].count > 0.0 ? s[b].px / s[b].mass : NAN;
        out_kt[b] = s[b].count > 1.0 ? s[b].heat / (2.0 * (s[b].count - 1.0)) : NAN;
    }
    result = PyTuple_Pack(3, y, vx, kt);
done:
    Py_XDECREF(y);
    Py_XDECREF(vx);
    Py_XDECREF(kt);
    PyMem_RawFree(s);
    PyMem_RawFree(masses);
    PyMem_RawFree(disks);
    return result;
}
