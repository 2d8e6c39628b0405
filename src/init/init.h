/* SPDX-License-Identifier: MIT */
/* Initial states: where the disks start and how they move. Random
 * sequential placement (placement_random.c) or a triangular lattice
 * (placement_lattice.c), both filling the disk arrays in generation
 * order. Not installed. */
#ifndef DS_INIT_H
#define DS_INIT_H

#include "core/core.h"

/* Memory random placement borrows per disk while it runs: its grid's
 * node (centre and link). */
#define DS_PLACEMENT_BYTES_PER_DISK (3 * sizeof(double))

/* Places the w->n disks of world w into d (slots in generation order) as
 * w->placement asks; DS_ERR_PLACEMENT if they do not fit. */
ds_status ds_place(ds_disks *d, const ds_world *w);

ds_status ds_place_random(ds_disks *d, const ds_world *w);

/* Takes the mean velocity out of the disks (more than one) and scales the
 * speeds back to the kinetic energy n speed^2 / 2 (velocities.c): in a
 * periodic box the total momentum is conserved, so the centre of mass
 * then stands still for ever. */
void ds_stop_centre_of_mass(ds_disks *d, const ds_world *w);
ds_status ds_place_lattice(ds_disks *d, const ds_world *w);

/* Whether the best triangular lattice of n disks has its closest sites at
 * least 2R apart (placement_lattice.c), and how far apart they are (0 if
 * there is no lattice: no sites). */
int ds_lattice_fits(size_t n, double radius, const ds_box *box);
double ds_lattice_closest(size_t n, double radius, const ds_box *box);

#endif
