/* SPDX-License-Identifier: MIT */
/* Placement: the initial state as ds_params.placement asks for it. */
#include "init/init.h"

ds_status ds_place(ds_disks *d, const ds_world *w)
{
    switch (w->placement) {
    case DS_PLACEMENT_LATTICE:
        return ds_place_lattice(d, w);
    case DS_PLACEMENT_RANDOM:
    case DS_PLACEMENT_COUNT:
        break;
    }
    return ds_place_random(d, w);
}
