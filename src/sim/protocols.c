/* SPDX-License-Identifier: MIT */
/* Protocols, what acts on a running simulation from outside its dynamics:
 * growth and driving (disksim/protocols.h). The request is checked here, every limit
 * named in err; the protocol (protocols/growth.c) carries it out through
 * the integrator's services. */
#include <math.h>

#include "protocols/protocols.h"
#include "sim/sim.h"

/* The targets checked: until_eta 0 or between the area fraction of now
 * and 1, until_z 0 or in (1, 1e9]. */
static ds_status check_targets(const ds_sim *sim, double until_eta, double until_z, ds_error *err)
{
    const double eta = ds_sim_get_area_fraction(sim);
    if (!(until_eta >= 0.0 && until_eta < 1.0))
        return ds_refuse(err, DS_ERR_ARG, "until_eta", until_eta, until_eta < 1.0 ? 0.0 : 1.0,
                         "until_eta = %g must be an area fraction between 0 and 1", until_eta);
    if (until_eta > 0.0 && until_eta <= eta)
        return ds_refuse(err, DS_ERR_ARG, "until_eta", until_eta, eta,
                         "until_eta = %g must be above the start's area fraction %.6g", until_eta,
                         eta);
    if (!(until_z == 0.0 || (until_z > 1.0 && until_z <= 1e9)))
        return ds_refuse(err, DS_ERR_ARG, "until_z", until_z, until_z > 1.0 ? 1e9 : 1.0,
                         "until_z = %g must be a reduced pressure > 1 and <= 1e9", until_z);
    return DS_OK;
}

/* The compression must be slow beside the motion: the surfaces of the
 * largest pair recede at 2 r_max rate, at most 10 rms speeds (past 1000,
 * 20 disks made no step in 20 s: every collision sends a pair off at
 * twice the surfaces' speed, and the growth outruns them). */
static ds_status check_rate(const ds_sim *sim, double rate, ds_error *err)
{
    if (!(rate >= 0.0) || !isfinite(rate))
        return ds_refuse(err, DS_ERR_ARG, "rate", rate, 0.0,
                         "rate = %g must be a finite number >= 0 (0 stops growth)", rate);
    double mass = 0.0;
    for (size_t i = 0; i < sim->disks.n; ++i)
        mass += sim->disks.m ? sim->disks.m[i] : 1.0;
    const double rms = mass > 0.0 ? sqrt(2.0 * ds_sim_get_kinetic_energy(sim) / mass) : 0.0;
    const double r_max = ds_sim_get_radius_max(sim), most = 10.0 * rms / (2.0 * r_max);
    if (rate > 0.0 && !(2.0 * r_max * rate <= 10.0 * rms))
        return ds_refuse(err, DS_ERR_ARG, "rate", rate, most,
                         "rate = %g is too fast: the largest disks' surfaces would recede at %g, "
                         "more than 10 times the rms speed %g; at most %.6g",
                         rate, 2.0 * r_max * rate, rms, most);
    return DS_OK;
}

ds_status ds_sim_set_growth(ds_sim *sim, double rate, double until_eta, double until_z,
                            ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    if (!sim->integrator->grow)
        return ds_refuse(err, DS_ERR_ARG, "integrator", NAN, NAN,
                         "integrator = %s: growth needs the event-driven integrator (its exact "
                         "contact times)",
                         sim->integrator->name);
    if (sim->world.boundary != DS_BOUNDARY_PERIODIC)
        return ds_refuse(err, DS_ERR_ARG, "boundary", NAN, NAN,
                         "boundary = %s: growth needs a periodic box",
                         ds_boundary_name(sim->world.boundary));
    /* Growth compresses an elastic gas: its window scales the heat its
     * collisions add back out, and would scale a drive's too. */
    if (rate > 0.0 && sim->world.rules.restitution < 1.0)
        return ds_refuse(err, DS_ERR_ARG, "restitution", sim->world.rules.restitution, 1.0,
                         "restitution = %g: growth compresses an elastic gas (set it to 1 first)",
                         sim->world.rules.restitution);
    if (rate > 0.0 && ds_drive_strength(sim) > 0.0)
        return ds_refuse(err, DS_ERR_ARG, "drive", ds_drive_strength(sim), 0.0,
                         "drive = %g: growth takes out the heat a drive puts in (stop it first)",
                         ds_drive_strength(sim));
    ds_status st = check_targets(sim, until_eta, until_z, err);
    if (st == DS_OK)
        st = check_rate(sim, rate, err);
    if (st != DS_OK)
        return st;
    st = ds_growth_start(sim, rate, until_eta, until_z == 0.0 ? DS_JAMMED_Z : until_z);
    if (st != DS_OK)
        return ds_refuse(err, st, "rate", rate, NAN,
                         "rate = %g: no memory for the growing radii of %zu disks", rate,
                         sim->world.n);
    return DS_OK;
}

ds_growth_state ds_sim_get_growth_state(const ds_sim *sim)
{
    double z = 0.0;
    return sim ? (ds_growth_state)ds_growth_state_get(sim, &z) : DS_GROWTH_NONE;
}

double ds_sim_get_growth_z(const ds_sim *sim)
{
    double z = 0.0;
    if (sim)
        (void)ds_growth_state_get(sim, &z);
    return z;
}

ds_status ds_sim_set_drive(ds_sim *sim, double strength, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    if (!(strength >= 0.0 && strength <= DS_DRIVE_MAX))
        return ds_refuse(err, DS_ERR_ARG, "strength", strength,
                         strength > DS_DRIVE_MAX ? DS_DRIVE_MAX : 0.0,
                         "strength = %g must be a number >= 0 and <= %g (0 stops the drive)",
                         strength, DS_DRIVE_MAX);
    if (strength > 0.0 && ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING)
        return ds_refuse(err, DS_ERR_ARG, "growth", NAN, NAN,
                         "growth: a growth is growing, and takes out the heat a drive would put "
                         "in (stop it first)");
    if (!sim->integrator->kick)
        return ds_refuse(err, DS_ERR_ARG, "integrator", NAN, NAN, "integrator = %s takes no kicks",
                         sim->integrator->name);
    if (ds_drive_start(sim, strength) != DS_OK)
        return ds_refuse(err, DS_ERR_NOMEM, "n", (double)sim->world.n, NAN,
                         "n = %zu disks: no memory for their kicks", sim->world.n);
    return DS_OK;
}

double ds_sim_get_drive(const ds_sim *sim) { return sim ? ds_drive_strength(sim) : 0.0; }
