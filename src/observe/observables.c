/* SPDX-License-Identifier: MIT */
/* The observables of a simulation: kinetic energy and momentum from the
 * disks, wall pressure and virial pressure from what the integrators
 * tallied since the last reset. */
#include <math.h>

#include "core/core.h"
#include "observe/observe.h"

double ds_sim_get_kinetic_energy(const ds_sim *sim)
{
    if (!sim)
        return 0.0;
    const ds_disks *d = &sim->disks;
    double e = 0.0;
    if (d->m)
        for (size_t k = 0; k < d->n; ++k)
            e += d->m[k] * (d->vx[k] * d->vx[k] + d->vy[k] * d->vy[k]);
    else
        for (size_t k = 0; k < d->n; ++k)
            e += d->vx[k] * d->vx[k] + d->vy[k] * d->vy[k];
    return 0.5 * e;
}

void ds_sim_get_momentum(const ds_sim *sim, double *px, double *py)
{
    double sx = 0.0, sy = 0.0;
    for (size_t k = 0; sim && k < sim->disks.n; ++k) {
        const double m = sim->disks.m ? sim->disks.m[k] : 1.0;
        sx += m * sim->disks.vx[k];
        sy += m * sim->disks.vy[k];
    }
    if (px)
        *px = sx;
    if (py)
        *py = sy;
}

uint64_t ds_sim_get_wall_count(const ds_sim *sim) { return sim ? sim->tally.wall_count : 0; }
double ds_sim_get_wall_impulse(const ds_sim *sim) { return sim ? sim->tally.wall_impulse : 0.0; }

/* Simulated time since the last reset. */
static double elapsed(const ds_sim *sim)
{
    return (double)(sim->steps - sim->observables_since_step) * sim->world.dt;
}

double ds_sim_get_pressure(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    const ds_world *w = &sim->world;
    const double perimeter = ds_box_wall_reached(&w->box, w->radius);
    if (perimeter == 0.0) /* no wall to push on */
        return ds_sim_get_virial_pressure(sim);
    /* A mixture: the partial pressures of its disks add up, each over the
     * perimeter its own centre reaches (the integrators tally it). */
    if (sim->disks.r || sim->disks.m)
        return sim->tally.wall_reach / elapsed(sim);
    return sim->tally.wall_impulse / (elapsed(sim) * perimeter);
}

/* The area the centres reach: along walls they stay R from each; a
 * mixture's disks, each its own R: their mean area. */
static double centre_area(const ds_sim *sim)
{
    const ds_world *w = &sim->world;
    if (!sim->disks.r || (ds_box_periodic(&w->box, 0) && ds_box_periodic(&w->box, 1)))
        return ds_box_area_reached(&w->box, w->radius);
    double sum = 0.0;
    for (size_t k = 0; k < sim->disks.n; ++k)
        sum += ds_box_area_reached(&w->box, sim->disks.r[k]);
    return sum / (double)sim->disks.n;
}

double ds_sim_get_virial_pressure(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    if (sim->integrator->compressibility) /* P A = Z N kT, as the integrator measures them */
        return sim->integrator->compressibility(sim) * (double)sim->world.n *
               ds_sim_get_temperature(sim) / centre_area(sim);
    /* With a heat bath the ideal part is N kT, its mean (the kinetic
     * energy of the end of the run is one draw of it). */
    const double bath = ds_protocols_temperature(sim);
    const double ideal = bath > 0.0 ? (double)sim->world.n * bath : ds_sim_get_kinetic_energy(sim);
    return (ideal + sim->tally.virial / (2.0 * elapsed(sim))) / centre_area(sim);
}

/* The temperature the collisions see. A pair's collision virial is
 * proportional to the second moment of its relative normal velocity, and
 * for hard disks the velocities are independent of the configuration
 * (uniform on the energy shell, less the conserved momentum), so that
 * moment is exactly what a canonical ensemble at some kT gives:
 * - walls: momentum is not conserved, each velocity component has
 *   <m v_x^2> = 2 K / (2 N), so kT = K / N;
 * - periodic: the total momentum P (mass M) is conserved, the centre of
 *   mass carries P^2 / (2 M) that no pair's relative motion sees, and the
 *   internal energy K_int = K - P^2 / (2 M) spreads over 2 (N - 1)
 *   degrees of freedom: <m_i m_j / (m_i + m_j) (v_i - v_j)_x^2> = kT with
 *   kT = K_int / (N - 1). (A single disk: no internal motion, 0.)
 * - a channel conserves P_x alone: K - P_x^2 / (2 M) over 2 N - 1
 *   degrees of freedom, kT = (K - P_x^2 / (2 M)) / (N - 1/2).
 * The rule is core's (ds_kinetic_temperature): a thermostat holds the
 * same. With a heat bath (a thermostat) the temperature is the bath's:
 * the velocities of any instant are one draw of its canonical ensemble,
 * and the rule above averages it (with Andersen's bath the momentum is no
 * longer conserved, and its share P^2 / (2 M) averages kT, so K_int / (N
 * - 1) still averages kT). An integrator that knows its temperature
 * otherwise (a sampler with no velocities) says so through its table. */
/* A sheared box's kinetic energy and momentum of the peculiar
 * velocities, the velocity less the profile's rate (y - H/2) along x:
 * the heat, not the flow. */
static void peculiar(const ds_sim *sim, ds_kinetic *k)
{
    const ds_disks *d = &sim->disks;
    const double height = sim->world.box.side[1], rate = sim->world.box.shift_speed / height;
    double e = 0.0, px = 0.0, py = 0.0;
    for (size_t i = 0; i < d->n; ++i) {
        const double m = d->m ? d->m[i] : 1.0, cx = d->vx[i] - rate * (d->y[i] - 0.5 * height);
        e += m * (cx * cx + d->vy[i] * d->vy[i]);
        px += m * cx;
        py += m * d->vy[i];
    }
    k->k = 0.5 * e;
    k->px = px;
    k->py = py;
}

double ds_sim_get_temperature(const ds_sim *sim)
{
    if (!sim || sim->world.n == 0)
        return 0.0;
    if (sim->integrator->temperature)
        return sim->integrator->temperature(sim);
    const double bath = ds_protocols_temperature(sim);
    if (bath > 0.0)
        return bath;
    ds_kinetic k = {ds_sim_get_kinetic_energy(sim), 0.0, 0.0, (double)sim->world.n};
    ds_sim_get_momentum(sim, &k.px, &k.py);
    if (sim->disks.m) {
        k.mass = 0.0;
        for (size_t i = 0; i < sim->disks.n; ++i)
            k.mass += sim->disks.m[i];
    }
    if (sim->world.box.shift_speed != 0.0)
        peculiar(sim, &k);
    return ds_kinetic_temperature(&sim->world.box, sim->world.n, &k);
}

/* The canonical Z. The virial theorem with the collisions' impulses
 * (ds_sim_get_virial_pressure) gives P A = N kT + W / (2 t), W the sum over the
 * collisions of r_ij . dp_i; in the canonical ensemble at temperature kT
 * the ideal term is N kT (N disks, whatever the boundary: in a periodic
 * box the configurational integral of N disks still has N positions),
 * and W / (2 t) is the canonical one at the kT of ds_sim_get_temperature (see
 * there). So Z = P A / (N kT) = 1 + W / (2 t N kT), with the area A the
 * centres reach. With walls kT = K / N, and this is ds_sim_get_virial_pressure A
 * / K; periodic, it differs from that by the centre of mass's energy and
 * by N / (N - 1) in the collision term: (Z - 1) / N relative at equal
 * momentum zero. Two disks in a periodic box give (1 + A / (A - pi
 * sigma^2)) / 2, the canonical value (tests/test_canonical.c). */
double ds_sim_get_compressibility_factor(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    if (sim->integrator->compressibility)
        return sim->integrator->compressibility(sim);
    const double kt = ds_sim_get_temperature(sim);
    if (!(kt > 0.0))
        return 1.0; /* no relative motion, no collisions: the ideal gas */
    return 1.0 + sim->tally.virial / (2.0 * elapsed(sim)) / ((double)sim->world.n * kt);
}

void ds_sim_reset_observables(ds_sim *sim)
{
    if (!sim)
        return;
    sim->tally.wall_count = 0;
    sim->tally.wall_impulse = 0.0;
    sim->tally.wall_reach = 0.0;
    sim->tally.virial = 0.0;
    sim->tally.dissipated = 0.0;
    sim->tally.injected = 0.0;
    sim->observables_since_step = sim->steps;
}

double ds_sim_get_energy_lost(const ds_sim *sim) { return sim ? sim->tally.dissipated : 0.0; }
double ds_sim_get_energy_input(const ds_sim *sim) { return sim ? sim->tally.injected : 0.0; }

double ds_sim_get_power_lost(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    return sim->tally.dissipated / elapsed(sim);
}

double ds_sim_get_power_input(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    return sim->tally.injected / elapsed(sim);
}

double ds_sim_get_potential_energy(const ds_sim *sim)
{
    if (!sim || !ds_rules_fall(&sim->world.rules))
        return 0.0;
    const ds_disks *d = &sim->disks;
    const double gx = sim->world.rules.field[0], gy = sim->world.rules.field[1];
    double u = 0.0;
    for (size_t k = 0; k < d->n; ++k)
        u -= (d->m ? d->m[k] : 1.0) * (gx * d->x[k] + gy * d->y[k]);
    return u;
}

/* The kinetic part is the tally's integral, which the integrators carry
 * to the end of each run (sim->tally.stress_clock); the collisions' part
 * is their virial tensor (core/collide.h). In an isotropic fluid the
 * integrated correlations of the pressure tensor are (kT / A) (eta
 * (d_ac d_bd + d_ad d_bc) + (zeta - eta) d_ab d_cd) in two dimensions
 * (zeta the bulk viscosity), so P_xy and (P_xx - P_yy) / 2 both have eta
 * as their Green-Kubo integral, and their time integrals s the Helfand
 * (Einstein) form of it. */
ds_status ds_sim_get_stress_integral(const ds_sim *sim, double s[3], ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !s)
        return ds_refuse(err, DS_ERR_ARG, sim ? "s" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "s" : "sim");
    for (int c = 0; c < 3; ++c)
        s[c] = sim->tally.kinetic_integral[c] + sim->tally.stress_virial[c];
    return DS_OK;
}
