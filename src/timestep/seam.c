/* SPDX-License-Identifier: MIT */
/* The pairs across the seams of a periodic box, for the sweeps.
 *
 * DS_BROADPHASE_SAP and DS_BROADPHASE_STRIPS sweep the box as if it had walls: they find
 * every pair closer than 2R as the coordinates stand. In a periodic box
 * the pairs they miss are those that touch through the boundary, whose
 * nearest image lies one box away along x, along y, or both. Such a pair
 * has one disk within 2R of a seam and the other within 2R of the
 * opposite edge, so these bands (~ 4 n 2R / box disks, a few per cent)
 * are all this pass looks at:
 * - the x seam: disks near x = 0 against those near x = box, bucketed by
 *   y in cells at least 2R tall (the cells wrap: a corner pair touches
 *   across both seams);
 * - the y seam: disks near y = 0 against those near y = box_y, bucketed by
 *   x, for the pairs that do not cross the x seam (those the x seam has
 *   reported).
 * A channel (periodic along x only) has the x seam alone, with no image
 * along y. A pair crosses a seam exactly when ds_nearest shifts its separation
 * along that axis, and since the box is more than 4R wide a pair within
 * 2R as the coordinates stand crosses none; so every pair is reported
 * once, by the sweep or by exactly one of the two seams. */
#include <math.h>
#include <stdlib.h>

#include "core/box.h"
#include "core/grid.h"
#include "timestep/broad_phase.h"

struct ds_seam {
    uint32_t *low, *high; /* disks in the band at each edge */
    uint32_t *sorted;     /* high, bucketed by cell */
    uint32_t *start;      /* cell c holds sorted[start[c] .. start[c + 1]) */
};

ds_status ds_seam_create(ds_bp *bp, size_t n)
{
    ds_seam *s = calloc(1, sizeof *s);
    if (!s)
        return DS_ERR_NOMEM;
    s->low = malloc(n * sizeof *s->low);
    s->high = malloc(n * sizeof *s->high);
    s->sorted = malloc(n * sizeof *s->sorted);
    s->start = malloc((n + 1) * sizeof *s->start); /* never more cells than disks */
    bp->seam = s;
    if (!s->low || !s->high || !s->sorted || !s->start) {
        ds_seam_destroy(bp);
        return DS_ERR_NOMEM;
    }
    return DS_OK;
}

void ds_seam_destroy(ds_bp *bp)
{
    ds_seam *s = bp->seam;
    if (!s)
        return;
    free(s->low);
    free(s->high);
    free(s->sorted);
    free(s->start);
    free(s);
    bp->seam = NULL;
}

size_t ds_seam_bytes(size_t n) { return sizeof(ds_seam) + (4 * n + 1) * sizeof(uint32_t); }

/* How a seam treats the axis along it: periodic, its pairs that also
 * cross the other seam its own (the x seam of a periodic box: the
 * search wraps) or the other seam's (the y seam: they are skipped); or
 * walls (a channel's x seam: no image along it). */
enum along { ALONG_WRAP, ALONG_SKIP, ALONG_WALLS };

/* One seam. u is the coordinate across it (side: its period), w the one
 * along it (length w_side): pairs of a disk within 2R of u = 0 and one
 * within 2R of u = side, nearer through the seam, with the high disks
 * bucketed by w. */
static uint64_t one_seam(const ds_bp *bp, ds_disks *d, const double *u, const double *w,
                         double side, double w_side, enum along along, ds_pair_fn on_pair,
                         void *ctx)
{
    ds_seam *s = bp->seam;
    const size_t n = d->n;
    const double diameter = bp->diameter, d2max = diameter * diameter;
    size_t lows = 0, highs = 0;
    for (size_t k = 0; k < n; ++k) {
        if (u[k] < diameter)
            s->low[lows++] = (uint32_t)k;
        else if (u[k] >= side - diameter)
            s->high[highs++] = (uint32_t)k;
    }
    if (!lows || !highs)
        return 0;

    /* Cells at least 2R long along the seam, no more than disks; w is in
     * [0, w_side), so the column needs no wrap. */
    ds_grid g;
    ds_grid_init_line(&g, w_side, diameter, n, along == ALONG_WRAP);
    const size_t cells = g.nx;
    for (size_t c = 0; c <= cells; ++c)
        s->start[c] = 0;
    for (size_t h = 0; h < highs; ++h)
        ++s->start[ds_grid_column(&g, w[s->high[h]]) + 1];
    for (size_t c = 1; c <= cells; ++c)
        s->start[c] += s->start[c - 1];
    for (size_t h = 0; h < highs; ++h) {
        const uint32_t k = s->high[h];
        s->sorted[s->start[ds_grid_column(&g, w[k])]++] = k;
    }
    for (size_t c = cells; c > 0; --c) /* undo the increments of the fill */
        s->start[c] = s->start[c - 1];
    s->start[0] = 0;

    uint64_t tested = 0;
    for (size_t l = 0; l < lows; ++l) {
        const uint32_t a = s->low[l];
        /* The cells around a's, each once (wrapping along the x seam). */
        size_t around[9];
        const int count = ds_grid_neighbours(&g, ds_grid_column(&g, w[a]), 0, around);
        for (int i = 0; i < count; ++i) {
            const size_t c = around[i];
            for (uint32_t m = s->start[c]; m < s->start[c + 1]; ++m) {
                const uint32_t b = s->sorted[m];
                const double du = u[b] - u[a], dw = w[b] - w[a];
                ++tested;
                if (!(du > 0.5 * side) || (along == ALONG_SKIP && fabs(dw) > 0.5 * w_side))
                    continue;
                const double ru = du - side, rw = along == ALONG_WALLS ? dw : ds_nearest(dw, w_side);
                if (ru * ru + rw * rw < d2max)
                    on_pair(d, a, b, ctx);
            }
        }
    }
    return tested;
}

uint64_t ds_seam_find_pairs(const ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx)
{
    const ds_box *b = &bp->box;
    const int px = ds_box_periodic(b, 0), py = ds_box_periodic(b, 1);
    uint64_t tested = 0;
    if (px)
        tested += one_seam(bp, d, d->x, d->y, b->side[0], b->side[1],
                           py ? ALONG_WRAP : ALONG_WALLS, on_pair, ctx);
    if (py)
        tested += one_seam(bp, d, d->y, d->x, b->side[1], b->side[0],
                           px ? ALONG_SKIP : ALONG_WALLS, on_pair, ctx);
    return tested;
}
