/* SPDX-License-Identifier: MIT */
/* The granular rules of a simulation (disksim/sim.h): the coefficients of
 * restitution, the TC model's contact time and the field, and their part
 * of a checkpoint. Each request is checked here, every limit named in
 * err; the integrator takes the new rules through its table (take_rules)
 * before they become the world's, so a refusal or a lack of memory
 * changes nothing. */
#include <math.h>

#include "sim/sim.h"

/* A coefficient of restitution in (0, 1]. */
static ds_status check_restitution(const char *field, double e, ds_error *err)
{
    if (!(e > 0.0 && e <= 1.0))
        return ds_refuse(err, DS_ERR_ARG, field, e, e > 1.0 ? 1.0 : 0.0,
                         "%s = %g must be in (0, 1] (1: elastic, smaller: more energy lost)", field,
                         e);
    return DS_OK;
}

ds_status ds_rules_check(const ds_world *w, const ds_rules *r, ds_error *err)
{
    ds_status st = check_restitution("restitution", r->restitution, err);
    if (st == DS_OK)
        st = check_restitution("wall_restitution", r->wall_restitution, err);
    if (st != DS_OK)
        return st;
    if (!(r->contact_time > 0.0) || !isfinite(r->contact_time))
        return ds_refuse(err, DS_ERR_ARG, "contact_time", r->contact_time, 0.0,
                         "contact_time = %g must be a finite time > 0 (0 asks for the default)",
                         r->contact_time);
    static const char *const names[2] = {"gx", "gy"};
    for (int a = 0; a < 2; ++a) {
        const double g = r->field[a];
        if (!(fabs(g) <= DS_GRAVITY_MAX))
            return ds_refuse(err, DS_ERR_ARG, names[a], g, DS_GRAVITY_MAX,
                             "%s = %g must be a number of magnitude at most %g", names[a], g,
                             DS_GRAVITY_MAX);
        if (g != 0.0 && ds_box_periodic(&w->box, a))
            return ds_refuse(err, DS_ERR_ARG, names[a], g, 0.0,
                             "%s = %g: the box is periodic along %c, where a field would "
                             "accelerate the disks for ever; it needs walls there (a channel "
                             "has them along y)",
                             names[a], g, a ? 'y' : 'x');
    }
    return DS_OK;
}

/* The checked rules r into the integrator, then into the world. */
static ds_status take(ds_sim *sim, const ds_rules *r, ds_error *err)
{
    const ds_status st = sim->integrator->take_rules ? sim->integrator->take_rules(sim, r) : DS_OK;
    if (st == DS_ERR_ARG)
        return ds_refuse(err, st, "integrator", NAN, NAN,
                         "integrator = %s has no dynamics to make granular: it takes neither a "
                         "restitution below 1 nor a field",
                         sim->integrator->name);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)sim->world.n, NAN,
                         "n = %zu disks: no memory for their times of last collision (the TC "
                         "model's)",
                         sim->world.n);
    sim->world.rules = *r;
    return DS_OK;
}

ds_status ds_sim_set_restitution(ds_sim *sim, double disks, double walls, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    ds_rules r = sim->world.rules;
    r.restitution = disks;
    r.wall_restitution = walls;
    ds_status st = ds_rules_check(&sim->world, &r, err);
    if (st != DS_OK)
        return st;
    /* A growth's collisions are elastic in the frame of the receding
     * surfaces (event/growing.c), and its pressure watch assumes it. */
    if (disks < 1.0 && ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING)
        return ds_refuse(err, DS_ERR_ARG, "restitution", disks, 1.0,
                         "restitution = %g: a growth is growing, and its collisions are "
                         "elastic (stop it first)",
                         disks);
    return take(sim, &r, err);
}

ds_status ds_sim_set_contact_time(ds_sim *sim, double contact_time, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    ds_rules r = sim->world.rules;
    r.contact_time =
        contact_time == 0.0 ? ds_rules_default(&sim->world).contact_time : contact_time;
    const ds_status st = ds_rules_check(&sim->world, &r, err);
    return st != DS_OK ? st : take(sim, &r, err);
}

ds_status ds_sim_set_gravity(ds_sim *sim, double gx, double gy, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    ds_rules r = sim->world.rules;
    r.field[0] = gx;
    r.field[1] = gy;
    const ds_status st = ds_rules_check(&sim->world, &r, err);
    return st != DS_OK ? st : take(sim, &r, err);
}

double ds_sim_get_restitution(const ds_sim *sim)
{
    return sim ? sim->world.rules.restitution : 1.0;
}

double ds_sim_get_wall_restitution(const ds_sim *sim)
{
    return sim ? sim->world.rules.wall_restitution : 1.0;
}

double ds_sim_get_contact_time(const ds_sim *sim)
{
    return sim ? sim->world.rules.contact_time : 0.0;
}

void ds_sim_get_gravity(const ds_sim *sim, double *gx, double *gy)
{
    if (gx)
        *gx = sim ? sim->world.rules.field[0] : 0.0;
    if (gy)
        *gy = sim ? sim->world.rules.field[1] : 0.0;
}

void ds_rules_save(const ds_sim *sim, ds_state_writer *w)
{
    const ds_rules *r = &sim->world.rules;
    ds_put_f64(w, r->restitution);
    ds_put_f64(w, r->wall_restitution);
    ds_put_f64(w, r->contact_time);
    ds_put_f64(w, r->field[0]);
    ds_put_f64(w, r->field[1]);
    ds_put_f64(w, sim->tally.dissipated);
    ds_put_f64(w, sim->tally.injected);
}

ds_status ds_rules_load(ds_sim *sim, ds_reader *r, ds_error *err)
{
    ds_rules rules;
    rules.restitution = ds_get_f64(r);
    rules.wall_restitution = ds_get_f64(r);
    rules.contact_time = ds_get_f64(r);
    rules.field[0] = ds_get_f64(r);
    rules.field[1] = ds_get_f64(r);
    sim->tally.dissipated = ds_get_f64(r);
    sim->tally.injected = ds_get_f64(r);
    ds_error why;
    if (r->failed)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside its rules");
    if (ds_rules_check(&sim->world, &rules, &why) != DS_OK)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its rules are refused: %s", why.message);
    if (!isfinite(sim->tally.dissipated) || !isfinite(sim->tally.injected))
        return ds_state_refuse(err, DS_ERR_FORMAT, "its energy books are not numbers");
    sim->world.rules = rules;
    return DS_OK;
}
