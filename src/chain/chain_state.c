/* SPDX-License-Identifier: MIT */
/* The event-chain integrator's state (chain_state.h): allocating it for
 * a world, freeing it, and the temperature its velocities stand for. */
#include <math.h>
#include <stdlib.h>

#include "chain/chain.h"
#include "chain/chain_state.h"
#include "core/large_alloc.h"

double ds_ch_kt(const ds_disks *d)
{
    double e = 0.0;
    for (size_t k = 0; k < d->n; ++k)
        e += (d->m ? d->m[k] : 1.0) * (d->vx[k] * d->vx[k] + d->vy[k] * d->vy[k]);
    return d->n ? 0.5 * e / (double)d->n : 0.0;
}

void ds_ch_destroy(ds_sim *sim)
{
    ds_chain *c = sim->state;
    if (!c)
        return;
    ds_ch_grid_free(&c->grid);
    free(c->disk);
    free(c);
    sim->state = NULL;
}

ds_status ds_ch_alloc(ds_sim *sim)
{
    const ds_world *w = &sim->world;
    ds_chain *c = calloc(1, sizeof *c);
    if (!c)
        return DS_ERR_NOMEM;
    sim->state = c;
    c->box = w->box;
    c->n = w->n;
    c->brute = w->broadphase == DS_BROADPHASE_BRUTE;
    c->per_step = (double)w->n * w->speed * w->dt;
    c->length = DS_CHAIN_LENGTH_OF_BOX * sqrt(w->box.side[0] * w->box.side[1]);
    for (int a = 0; a < 2; ++a)
        c->reach[a] = c->brute && ds_box_periodic(&w->box, a)
                          ? 0.5 * w->box.side[a] - 2.0 * w->radius_max
                          : INFINITY;
    c->kt = ds_ch_kt(&sim->disks);
    c->disk = ds_large_alloc((w->n ? w->n : 1) * sizeof *c->disk);
    return c->disk ? DS_OK : DS_ERR_NOMEM;
}
