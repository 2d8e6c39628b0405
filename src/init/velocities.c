/* SPDX-License-Identifier: MIT */
/* Initial velocities: the centre of mass brought to rest, the kinetic
 * energy kept (placement_random.c and placement_lattice.c both call it). */
#include <math.h>

#include "init/init.h"

void ds_stop_centre_of_mass(ds_disks *d, const ds_world *w)
{
    const size_t n = d->n;
    if (n < 2)
        return; /* one disk at rest would have no speed at all */
    /* The sums below square velocities and multiply masses. Plain, they
     * lost bits below a speed of about 1e-154, and below 1e-162 both
     * sides of the quotient underflowed to 0: 0 / 0 made every velocity
     * NaN (heavy masses at high speed overflowed the same way). So they
     * are taken of the velocities times 2^-sv and the masses times 2^-sm,
     * which bring the speed and the heaviest mass into [0.5, 1): scaling
     * by a power of two is exact, so wherever the plain sums neither
     * underflowed nor overflowed these give their bits (the runs of
     * ordinary speeds are unchanged), and elsewhere finite velocities. */
    int sv = 0, sm = 0;
    frexp(w->speed, &sv);
    if (d->m) {
        double heaviest = 0.0;
        for (size_t i = 0; i < n; ++i)
            heaviest = fmax(heaviest, d->m[i]);
        frexp(heaviest, &sm);
    }
    /* With masses: the velocity of the centre of mass, and the kinetic
     * energy sum m speed^2 / 2 every disk started with. */
    double mx = 0.0, my = 0.0, mass = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double m = d->m ? ldexp(d->m[i], -sm) : 1.0;
        mx += m * ldexp(d->vx[i], -sv);
        my += m * ldexp(d->vy[i], -sv);
        mass += m;
    }
    mx /= mass;
    my /= mass;
    double v2 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        d->vx[i] = ldexp(d->vx[i], -sv) - mx;
        d->vy[i] = ldexp(d->vy[i], -sv) - my;
        v2 += (d->m ? ldexp(d->m[i], -sm) : 1.0) * (d->vx[i] * d->vx[i] + d->vy[i] * d->vy[i]);
    }
    const double speed = ldexp(w->speed, -sv);
    /* v2 is 0 only if every disk has the same velocity, which rounding
     * can make of speeds below the smallest normal double (2.2e-308):
     * then they stay at rest, the kinetic energy n speed^2 / 2 being 0 in
     * doubles too. */
    const double scale = v2 > 0.0 ? sqrt(mass * speed * speed / v2) : 0.0;
    for (size_t i = 0; i < n; ++i) {
        d->vx[i] = ldexp(d->vx[i] * scale, sv);
        d->vy[i] = ldexp(d->vy[i] * scale, sv);
    }
}
