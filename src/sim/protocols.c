/* SPDX-License-Identifier: MIT */
/* Protocols, what acts on a running simulation from outside its dynamics:
 * growth, driving, a thermostat, a barostat (disksim/protocols.h). The
 * request is checked here, every limit named in err; the protocol
 * (protocols/) carries it out through the integrator's services. */
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
    if (rate > 0.0 && ds_protocols_get(sim, DS_PROTOCOL_SHEAR))
        return ds_refuse(err, DS_ERR_ARG, "shear", ds_shear_rate(sim), NAN,
                         "shear: growth needs a box at rest, not a sheared one");
    /* Growth takes out its own heat, in a box of its own. */
    if (rate > 0.0 && (ds_protocols_get(sim, DS_PROTOCOL_THERMOSTAT) ||
                       ds_protocols_get(sim, DS_PROTOCOL_BAROSTAT)))
        return ds_refuse(err, DS_ERR_ARG, "rate", rate, NAN,
                         "rate = %g: growth takes out its own heat in a box of fixed sides: remove "
                         "the %s first",
                         rate,
                         ds_protocols_get(sim, DS_PROTOCOL_THERMOSTAT) ? "thermostat" : "barostat");
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

/* Whether a growth is growing: a heat bath or a barostat would fight it. */
static int growing(const ds_sim *sim) { return ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING; }

/* The largest kT at which no disk can pass DS_VELOCITY_MAX: Andersen's
 * draws reach 8.5717 sqrt(kT / m) (Box and Muller's radius,
 * sqrt(-2 ln 2^-53)); the isokinetic scaling puts at most the whole
 * kinetic energy, n kT, into the lightest disk, sqrt(2 n kT / m). */
static double hottest(const ds_sim *sim, ds_thermostat kind)
{
    double lightest = INFINITY;
    for (size_t i = 0; i < sim->disks.n; ++i)
        lightest = fmin(lightest, sim->disks.m ? sim->disks.m[i] : 1.0);
    const double reach = kind == DS_THERMOSTAT_ANDERSEN ? 74.0 : 2.0 * (double)sim->world.n;
    return lightest * DS_VELOCITY_MAX * DS_VELOCITY_MAX / reach;
}

/* kt checked, 0 taken for the temperature of now. */
static ds_status check_kt(const ds_sim *sim, ds_thermostat kind, double *kt, ds_error *err)
{
    if (!(*kt >= 0.0) || !isfinite(*kt))
        return ds_refuse(err, DS_ERR_ARG, "kt", *kt, 0.0,
                         "kt = %g must be a temperature > 0 (0: the temperature of now)", *kt);
    const double asked = *kt;
    if (asked == 0.0)
        *kt = ds_sim_get_temperature(sim);
    if (!(*kt > 0.0))
        return ds_refuse(err, DS_ERR_ARG, "kt", asked, 0.0,
                         "kt = 0 asks for the temperature of now, and the disks have none (at "
                         "rest, or moving as one): give a temperature > 0");
    const double most = hottest(sim, kind);
    if (!(*kt <= most))
        return ds_refuse(err, DS_ERR_ARG, "kt", *kt, most,
                         "kt = %g would let a disk pass the speed limit %g: at most %g", *kt,
                         DS_VELOCITY_MAX, most);
    return DS_OK;
}

/* Andersen's rate, 0 taken for 0.1 sqrt(kT) / sigma; the isokinetic
 * thermostat has none. */
static ds_status check_rate_of(const ds_sim *sim, ds_thermostat kind, double kt, double *rate,
                               ds_error *err)
{
    if (kind == DS_THERMOSTAT_ISOKINETIC && *rate != 0.0)
        return ds_refuse(err, DS_ERR_ARG, "collision_rate", *rate, 0.0,
                         "collision_rate = %g: the isokinetic thermostat has no rate (it scales "
                         "the velocities at every step's end): give 0",
                         *rate);
    if (!(*rate >= 0.0) || !isfinite(*rate))
        return ds_refuse(err, DS_ERR_ARG, "collision_rate", *rate, 0.0,
                         "collision_rate = %g must be a number > 0 of collisions with the bath "
                         "per disk per unit time (0: the default)",
                         *rate);
    if (*rate == 0.0)
        *rate = 0.1 * sqrt(kt) / (2.0 * sim->world.radius_max);
    return DS_OK;
}

ds_status ds_sim_set_thermostat(ds_sim *sim, ds_thermostat kind, double kt, double collision_rate,
                                ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    if ((unsigned)kind >= (unsigned)DS_THERMOSTAT_COUNT)
        return ds_refuse(err, DS_ERR_ARG, "thermostat", (double)kind, DS_THERMOSTAT_COUNT,
                         "thermostat = %d is not a ds_thermostat", (int)kind);
    if (kind == DS_THERMOSTAT_NONE) {
        ds_protocols_remove(sim, DS_PROTOCOL_THERMOSTAT);
        return DS_OK;
    }
    const ds_integrator_ops *in = sim->integrator;
    if (!in->set_velocity || !in->kinetic || !in->now || !in->scale_velocities)
        return ds_refuse(err, DS_ERR_ARG, "integrator", NAN, NAN,
                         "integrator = %s: a thermostat needs an integrator with velocities",
                         in->name);
    if (growing(sim))
        return ds_refuse(err, DS_ERR_ARG, "thermostat", (double)kind, NAN,
                         "thermostat = %s: a growth is growing, and takes out its own heat: stop "
                         "it first (rate 0)",
                         ds_thermostat_name(kind));
    if (kind == DS_THERMOSTAT_ANDERSEN && ds_shear_rate(sim) != 0.0)
        return ds_refuse(err, DS_ERR_ARG, "thermostat", (double)kind, NAN,
                         "thermostat = andersen draws velocities about rest, not the shear's "
                         "profile: use the isokinetic one, which scales the peculiar velocities");
    ds_status st = check_kt(sim, kind, &kt, err);
    if (st == DS_OK)
        st = check_rate_of(sim, kind, kt, &collision_rate, err);
    if (st == DS_OK && ds_thermostat_start(sim, kind, kt, collision_rate) != DS_OK)
        st = ds_refuse(err, DS_ERR_NOMEM, "thermostat", (double)kind, NAN,
                       "thermostat = %s: no memory for it", ds_thermostat_name(kind));
    return st;
}

ds_thermostat ds_sim_get_thermostat(const ds_sim *sim)
{
    double kt = 0.0;
    return sim ? ds_thermostat_get(sim, &kt) : DS_THERMOSTAT_NONE;
}

double ds_sim_get_thermostat_temperature(const ds_sim *sim)
{
    double kt = 0.0;
    if (sim)
        (void)ds_thermostat_get(sim, &kt);
    return kt;
}

/* The barostat's request: a box it can move, and its numbers. */
static ds_status check_barostat(const ds_sim *sim, double pressure, double max_step, ds_error *err)
{
    if (!ds_box_periodic(&sim->world.box, 0) || !ds_box_periodic(&sim->world.box, 1))
        return ds_refuse(err, DS_ERR_ARG, "boundary", NAN, NAN,
                         "boundary = %s: the barostat moves a periodic box only (walls would "
                         "have to move with the disks)",
                         ds_boundary_name(sim->world.boundary));
    if (!sim->integrator->resize)
        return ds_refuse(err, DS_ERR_ARG, "integrator", NAN, NAN,
                         "integrator = %s: it cannot rescale its box, which the barostat needs",
                         sim->integrator->name);
    if (growing(sim))
        return ds_refuse(err, DS_ERR_ARG, "pressure", pressure, NAN,
                         "pressure = %g: a growth is growing in this box: stop it first (rate 0)",
                         pressure);
    if (!(max_step >= 0.0 && max_step <= DS_BAROSTAT_MAX_STEP))
        return ds_refuse(err, DS_ERR_ARG, "max_step", max_step,
                         max_step > 0.0 ? DS_BAROSTAT_MAX_STEP : 0.0,
                         "max_step = %g must be a change of ln A between 0 and %g (0: the "
                         "default)",
                         max_step, DS_BAROSTAT_MAX_STEP);
    return DS_OK;
}

ds_status ds_sim_set_barostat(ds_sim *sim, double pressure, uint64_t every, double max_step,
                              int aspect, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    if (!(pressure >= 0.0 && pressure <= DS_BAROSTAT_MAX_PRESSURE))
        return ds_refuse(err, DS_ERR_ARG, "pressure", pressure,
                         pressure > 0.0 ? DS_BAROSTAT_MAX_PRESSURE : 0.0,
                         "pressure = %g must be a reduced pressure beta P sigma^2 > 0 and <= %g "
                         "(0 removes the barostat)",
                         pressure, DS_BAROSTAT_MAX_PRESSURE);
    if (pressure == 0.0) {
        ds_protocols_remove(sim, DS_PROTOCOL_BAROSTAT);
        return DS_OK;
    }
    if (ds_protocols_get(sim, DS_PROTOCOL_SHEAR))
        return ds_refuse(err, DS_ERR_ARG, "shear", NAN, NAN,
                         "shear: a sheared box cannot change its sides");
    ds_status st = check_barostat(sim, pressure, max_step, err);
    if (st != DS_OK)
        return st;
    /* A move every 10 steps: a rebuild of the state (O(n)) each time one
     * is accepted stays a small part of the run. Moves of 1 / (4 n): a
     * compression by d overlaps the pairs closer than d / 2 of a diameter,
     * about 2 eta g(sigma) n d of them (g the contact value), so at 0.70
     * (g near 6) about one in eight of the largest compressions passes. */
    if (every == 0)
        every = 10;
    if (max_step == 0.0)
        max_step = fmin(DS_BAROSTAT_MAX_STEP, 0.25 / (double)sim->world.n);
    if (ds_barostat_start(sim, pressure, every, max_step, aspect) != DS_OK)
        return ds_refuse(err, DS_ERR_NOMEM, "pressure", pressure, NAN,
                         "pressure = %g: no memory for the barostat", pressure);
    return DS_OK;
}

double ds_sim_get_barostat_pressure(const ds_sim *sim)
{
    double acceptance = 0.0;
    return sim ? ds_barostat_get(sim, &acceptance) : 0.0;
}

double ds_sim_get_barostat_acceptance(const ds_sim *sim)
{
    double acceptance = 0.0;
    if (sim)
        (void)ds_barostat_get(sim, &acceptance);
    return acceptance;
}

/* ------------------------------------------------------------------ */
/* Shear                                                                */
/* ------------------------------------------------------------------ */

ds_status ds_sim_set_shear(ds_sim *sim, double rate, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    const ds_world *w = &sim->world;
    const double height = w->box.side[1];
    if (!isfinite(rate))
        return ds_refuse(err, DS_ERR_ARG, "rate", rate, NAN,
                         "rate = %g must be a finite shear rate dv_x/dy (0 stops the images)",
                         rate);
    if (fabs(rate) * w->dt > DS_SHEAR_MAX_STRAIN_PER_STEP)
        return ds_refuse(err, DS_ERR_ARG, "rate", rate, DS_SHEAR_MAX_STRAIN_PER_STEP / w->dt,
                         "rate = %g shears %g per step (dt = %g): at most %g, so that a heat bath "
                         "at the steps' ends can hold the temperature",
                         rate, fabs(rate) * w->dt, w->dt, DS_SHEAR_MAX_STRAIN_PER_STEP);
    if (fabs(rate) * height > 0.25 * DS_VELOCITY_MAX)
        return ds_refuse(err, DS_ERR_ARG, "rate", rate, 0.25 * DS_VELOCITY_MAX / height,
                         "rate = %g moves the images at %g, past %g: a disk crossing to them "
                         "would outrun the speed limit %g",
                         rate, fabs(rate) * height, 0.25 * DS_VELOCITY_MAX, DS_VELOCITY_MAX);
    if (!ds_box_periodic(&w->box, 0) || !ds_box_periodic(&w->box, 1))
        return ds_refuse(err, DS_ERR_ARG, "boundary", NAN, NAN,
                         "boundary = %s: a shear needs a box periodic along both axes",
                         ds_boundary_name(w->boundary));
    if (!sim->integrator->shear)
        return ds_refuse(err, DS_ERR_ARG, "integrator", NAN, NAN,
                         "integrator = %s cannot shear its box (the event-driven one can)",
                         sim->integrator->name);
    if (ds_sim_get_thermostat(sim) == DS_THERMOSTAT_ANDERSEN)
        return ds_refuse(err, DS_ERR_ARG, "thermostat", NAN, NAN,
                         "thermostat = andersen draws velocities about rest, not the shear's "
                         "profile: use the isokinetic one, which scales the peculiar velocities");
    if (ds_sim_get_barostat_pressure(sim) > 0.0)
        return ds_refuse(err, DS_ERR_ARG, "barostat", NAN, NAN,
                         "barostat: a box that changes its sides cannot be sheared (remove it "
                         "first)");
    if (growing(sim))
        return ds_refuse(err, DS_ERR_ARG, "growth", NAN, NAN,
                         "growth: a growth is growing (stop it first)");
    if (ds_shear_start(sim, rate) != DS_OK)
        return ds_refuse(err, DS_ERR_NOMEM, "rate", rate, NAN, "rate = %g: no memory for the shear",
                         rate);
    return DS_OK;
}

double ds_sim_get_shear(const ds_sim *sim) { return sim ? ds_shear_rate(sim) : 0.0; }

double ds_sim_get_shear_shift(const ds_sim *sim)
{
    return sim && ds_protocols_get(sim, DS_PROTOCOL_SHEAR) ? sim->world.box.shift : 0.0;
}

double ds_sim_get_shear_offset(const ds_sim *sim)
{
    return sim && ds_protocols_get(sim, DS_PROTOCOL_SHEAR) ? sim->world.box.offset : 0.0;
}
