/* SPDX-License-Identifier: MIT */
/* Whether any two disks overlap: a state to start from or to load must
 * have none (disk_sim.h, DS_CONTACT_TOLERANCE). Not installed. */
#ifndef DS_OVERLAP_H
#define DS_OVERLAP_H

#include "core/core.h"

/* The n = w->n centres (x[i], y[i]), inside world w's box: DS_OK if no two
 * are closer than 2R (1 - DS_CONTACT_TOLERANCE), through the nearest image
 * in a periodic box; else DS_ERR_OVERLAP with the first such pair (in the
 * order of the disks) in *a < *b. DS_ERR_NOMEM without memory for the
 * cell grid. O(n). */
ds_status ds_find_overlap(const ds_world *w, const double *x, const double *y, size_t *a,
                          size_t *b);

#endif
