/* SPDX-License-Identifier: MIT */
/* Whether any two disks overlap: a state to start from or to load must
 * have none (disk_sim.h, DS_CONTACT_TOLERANCE). Not installed. */
#ifndef DS_OVERLAP_H
#define DS_OVERLAP_H

#include "core/core.h"

/* The n = w->n centres (x[i], y[i]) of disks of radii r[i] (r NULL: all
 * of the world's radius), inside world w's box: DS_OK if no two are
 * closer than their contact distance r_a + r_b by a relative
 * DS_CONTACT_TOLERANCE, through the nearest image in a periodic box; else
 * DS_ERR_OVERLAP with the first such pair (in the order of the disks) in
 * *a < *b. DS_ERR_NOMEM without memory for the cell grid. O(n). */
ds_status ds_find_overlap(const ds_world *w, const double *x, const double *y, const double *r,
                          size_t *a, size_t *b);

#endif
