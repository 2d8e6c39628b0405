/* SPDX-License-Identifier: MIT */
/* The 2.x calls tools/migrate/disksim3.py cannot finish alone, each to be
 * named on standard error at its line (tests/migrate.sh). Not built. */
#include <disk_sim.h>

double by_hand(ds_sim *sim, double *radii, double *masses, const ds_frame_error *e)
{
    double sum = ds_radius_of(sim, 0);
    sum += ds_mass_of(sim, 1);
    ds_get_radii(sim, radii, masses);
    sum += ds_psi6(sim);
    return sum + e->line;
}
