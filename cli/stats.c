/* SPDX-License-Identifier: MIT */
/* The --stats file: a header, then a row a frame of the observables at
 * that frame (docs/cli.md, "Observables as CSV"). Numbers are written to their
 * last bit (%.17g), so a restart's rows are the uninterrupted run's to
 * the byte; a value the run does not have is "nan" (psi6 in a box too
 * narrow, the shear stress of the first row, the viscosity without
 * shear). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>

#include "cli.h"

const char stats_header[] =
    "frame,time,kinetic_energy,px,py,collisions,wall_reflections,pressure,virial_pressure,psi6,"
    "area_fraction,granular_temperature,energy_lost,energy_input,power_lost,power_input,"
    "potential_energy,shear_rate,shear_stress,viscosity\n";

void stats_mark(stats_books *b, const ds_sim *sim)
{
    double s[3];
    b->marked = ds_sim_get_stress_integral(sim, s, NULL) == DS_OK;
    b->s_xy = s[2];
    b->time = ds_sim_get_time(sim);
}

/* The shear stress P_xy over the time since the mark, the change of the
 * stress integral's xy part over the area and that time (observe.h): in
 * a periodic box, whose area is W H; with walls the integral's area is
 * the one the centres reach, which the library does not give, and the
 * column is nan. */
static double shear_stress_since(const stats_books *b, const ds_sim *sim)
{
    double s[3];
    const double t = ds_sim_get_time(sim) - b->time;
    if (!b->marked || !(t > 0.0) || ds_sim_get_boundary(sim) != DS_BOUNDARY_PERIODIC ||
        ds_sim_get_stress_integral(sim, s, NULL) != DS_OK)
        return NAN;
    return (s[2] - b->s_xy) / (ds_sim_get_box_width(sim) * ds_sim_get_box_height(sim) * t);
}

void stats_row(output *out, long frame, const ds_sim *sim, stats_books *b)
{
    char row[768];
    double px, py, psi6 = NAN; /* psi6 NaN where the library has none: a box too narrow */
    ds_sim_get_momentum(sim, &px, &py);
    (void)ds_sim_get_psi6(sim, &psi6, NULL);
    int l =
        snprintf(row, sizeof row, "%ld,%.6f,%.17g,%.17g,%.17g,%llu,%llu,%.17g,%.17g,%.17g,%.17g,",
                 frame, ds_sim_get_time(sim), ds_sim_get_kinetic_energy(sim), px, py,
                 (unsigned long long)ds_sim_get_collision_count(sim),
                 (unsigned long long)ds_sim_get_wall_count(sim), ds_sim_get_pressure(sim),
                 ds_sim_get_virial_pressure(sim), psi6, ds_sim_get_area_fraction(sim));
    /* The granular gas's: its temperature (ds_sim_get_temperature, of
     * the peculiar velocities under shear) and energy books. */
    l += snprintf(row + l, sizeof row - (size_t)l, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,",
                  ds_sim_get_temperature(sim), ds_sim_get_energy_lost(sim),
                  ds_sim_get_energy_input(sim), ds_sim_get_power_lost(sim),
                  ds_sim_get_power_input(sim), ds_sim_get_potential_energy(sim));
    /* The shear flow's: its rate, the stress it answers with over the
     * interval, and the apparent viscosity -P_xy / rate (P_xy < 0 where
     * the flow along x grows with y). */
    const double rate = ds_sim_get_shear(sim), p_xy = shear_stress_since(b, sim);
    l += snprintf(row + l, sizeof row - (size_t)l, "%.17g,%.17g,%.17g\n", rate, p_xy,
                  rate != 0.0 && !isnan(p_xy) ? -p_xy / rate : NAN);
    output_write(out, row, (size_t)l);
    stats_mark(b, sim);
}
