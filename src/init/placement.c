/* SPDX-License-Identifier: MIT */
/* Placement: the initial state as ds_params.placement asks for it. */
#include <math.h>

#include "init/init.h"

void ds_stop_centre_of_mass(ds_disks *d, const ds_world *w)
{
    const size_t n = d->n;
    if (n < 2)
        return; /* one disk at rest would have no speed at all */
    double mx = 0.0, my = 0.0;
    for (size_t i = 0; i < n; ++i) {
        mx += d->vx[i];
        my += d->vy[i];
    }
    mx /= (double)n;
    my /= (double)n;
    double v2 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        d->vx[i] -= mx;
        d->vy[i] -= my;
        v2 += d->vx[i] * d->vx[i] + d->vy[i] * d->vy[i];
    }
    const double scale = sqrt((double)n * w->speed * w->speed / v2);
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
