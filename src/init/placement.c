/* SPDX-License-Identifier: MIT */
/* Placement: the initial state as ds_params.placement asks for it. */
#include <math.h>

#include "init/init.h"

void ds_stop_centre_of_mass(ds_disks *d, const ds_world *w)
{
    const size_t n = d->n;
    if (n < 2)
        return; /* one disk at rest would have no speed at all */
    /* With masses: the velocity of the centre of mass, and the kinetic
     * energy sum m speed^2 / 2 every disk started with. */
    double mx = 0.0, my = 0.0, mass = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double m = d->m ? d->m[i] : 1.0;
        mx += m * d->vx[i];
        my += m * d->vy[i];
        mass += m;
    }
    mx /= mass;
    my /= mass;
    double v2 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        d->vx[i] -= mx;
        d->vy[i] -= my;
        v2 += (d->m ? d->m[i] : 1.0) * (d->vx[i] * d->vx[i] + d->vy[i] * d->vy[i]);
    }
    const double scale = sqrt(mass * w->speed * w->speed / v2);
    for (size_t i = 0; i < n; ++i) {
        d->vx[i] *= scale;
        d->vy[i] *= scale;
    }
}

ds_status ds_place(ds_disks *d, const ds_world *w)
{
    switch (w->placement) {
    case DS_LATTICE:
        return ds_place_lattice(d, w);
    case DS_RANDOM:
        break;
    }
    return ds_place_random(d, w);
}
