/* SPDX-License-Identifier: MIT */
/* Neighbour pairs: the one loop over the cell grid that every part
 * wanting the pairs of a set of centres within a range calls (overlap
 * checks, contacts, psi6, g(r)). The centres are binned into cells at
 * least the range wide (grid.h), so each looks at the 3 x 3 cells around
 * its own: O(n) at a fixed density. Separations go through the box's
 * nearest image.
 *
 * Random placement keeps its own grid of linked nodes (its speed at 10^6
 * disks is that layout, placement_random.c), and the event-driven
 * integrator its cells of four slots read as one block (event/cells.h).
 * Not installed. */
#ifndef DS_PAIRS_H
#define DS_PAIRS_H

#include "core/box.h"
#include "core/grid.h"

typedef struct ds_pairs {
    ds_grid grid;
    ds_grid_bins bins;
    const ds_box *box;
    size_t n;
    const double *x, *y; /* the centres, wrapped into the box if they were not */
    double *wrapped;     /* the wrapped copies, or NULL */
    double range2;
} ds_pairs;

/* Called for a pair j != k closer than the range, (dx, dy) from j to k's
 * nearest image and r2 its squared length; a nonzero return stops the
 * loop. */
typedef int (*ds_pair_visit)(void *ctx, size_t j, size_t k, double dx, double dy, double r2);

/* Bins n centres for pairs closer than range, in a grid of at most cap
 * cells. Along a periodic axis a centre may be anywhere (it is wrapped
 * into a copy first) unless inside is set (the caller's centres are in
 * the box already); along a walls axis it is taken as it is. The box must
 * outlive the pairs. DS_ERR_NOMEM leaves nothing to end. */
ds_status ds_pairs_begin(ds_pairs *p, const ds_box *box, size_t n, const double *x,
                         const double *y, double range, size_t cap, int inside);
void ds_pairs_end(ds_pairs *p);

/* Visits the pairs closer than the range: j from 0 to n - 1, and for each
 * j the k of the cells around it, cell by cell, row by row, in the order
 * they were given. With `both`, each ordered pair (j, k), k != j, so that
 * a per-disk sum over its neighbours comes in one place; without, each
 * unordered pair once, as (j, k) with k > j. Returns 1 if visit stopped
 * it, else 0. */
int ds_pairs_each(const ds_pairs *p, int both, ds_pair_visit visit, void *ctx);

#endif
