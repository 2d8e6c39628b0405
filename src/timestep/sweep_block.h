/* SPDX-License-Identifier: MIT */
/* The sweeps' inner loops, shared by sap.c and strips.c:
 * a fixed block of four candidates tested without a
 * data-dependent branch, and the bounded window walk for the rest.
 *
 * A sweep window holds a few disks and its length varies from disk to
 * disk, so a loop that stops at the first x >= xlim mispredicts its exit
 * about once per disk, which costs more than the tests themselves. Testing
 * a whole block, each result masked by x < xlim, needs a branch only when
 * the block is entirely inside the window or a pair overlaps (both rare).
 * Same arithmetic as the scalar test dx*dx + dy*dy < d2max (separate
 * multiply and add, no fused multiply-add), so the same pairs to the bit;
 * two lanes at a time (core/lanes.h). */
#ifndef DS_SWEEP_BLOCK_H
#define DS_SWEEP_BLOCK_H

#include <stddef.h>

#include "timestep/broad_phase.h"

#include "core/lanes.h"

/* Tests candidates j .. j+3 (which must be readable) against the disk at
 * (xi, yi): bit k of *inside says x[j+k] < xlim, bit k of the result says
 * the centres are closer than sqrt(d2max). */
static inline unsigned ds_test_four(const double *x, const double *y, size_t j, double xi,
                                    double yi, double xlim, double d2max, unsigned *inside)
{
    const ds_x2 vxi = ds_x2_set1(xi), vyi = ds_x2_set1(yi);
    const ds_x2 lim = ds_x2_set1(xlim), d2 = ds_x2_set1(d2max);
    const ds_x2 xa = ds_x2_load(x + j), xb = ds_x2_load(x + j + 2);
    const ds_x2 dxa = ds_x2_sub(xa, vxi), dxb = ds_x2_sub(xb, vxi);
    const ds_x2 dya = ds_x2_sub(ds_x2_load(y + j), vyi);
    const ds_x2 dyb = ds_x2_sub(ds_x2_load(y + j + 2), vyi);
    const ds_x2 closea = ds_x2_lt(ds_x2_add(ds_x2_mul(dxa, dxa), ds_x2_mul(dya, dya)), d2);
    const ds_x2 closeb = ds_x2_lt(ds_x2_add(ds_x2_mul(dxb, dxb), ds_x2_mul(dyb, dyb)), d2);
    *inside = ds_x2_bits_pair(ds_x2_lt(xa, lim), ds_x2_lt(xb, lim));
    return ds_x2_bits_pair(closea, closeb);
}

/* Bit k says x[j+k] <= v, for k < 4 (x[j .. j+3] must be readable). */
static inline unsigned ds_at_most_four(const double *x, size_t j, double v)
{
    const ds_x2 vv = ds_x2_set1(v);
    return ds_x2_bits_pair(ds_x2_le(ds_x2_load(x + j), vv), ds_x2_le(ds_x2_load(x + j + 2), vv));
}

/* The bits of a block of four that lie before `end`, for a block starting
 * `avail` = end - j disks before it. */
static inline unsigned ds_block_mask(size_t avail)
{
    return avail >= 4 ? 0xFu : (1u << avail) - 1u;
}

/* The number of trailing ones of a mask below 2^31: how many candidates of
 * a block are inside the window (x is sorted, so they form a prefix). */
static inline unsigned ds_prefix_length(unsigned mask)
{
#if defined(__GNUC__)
    return (unsigned)__builtin_ctz(~mask); /* one instruction (bsf/tzcnt) */
#else
    unsigned c = 0;
    for (; mask & 1u; mask >>= 1)
        ++c;
    return c;
#endif
}

/* Reports the overlapping pairs (i, j) for j from j on while j < end and
 * x[j] < xlim, and returns where the window ended. Hits are rare, so the
 * loop only records them and the callback runs once the loop is done: a
 * call inside it would force xi, yi and the limits out of registers (no
 * callee-saved floating-point registers on x86-64). The callback changes
 * velocities only and the sweep reads positions only, so deferring it
 * changes nothing; pairs arrive in the same order. */
#define DS_HITS_CAP 32

static inline size_t ds_sweep_range(ds_disks *d, double diameter, size_t i, size_t j, size_t end,
                                    double xlim, ds_pair_fn on_pair, void *ctx)
{
    const double *restrict x = d->x, *restrict y = d->y;
    const double xi = x[i], yi = y[i], d2max = diameter * diameter;
    uint32_t hits[DS_HITS_CAP];
    size_t nh;
    do {
        nh = 0;
        for (; j < end && x[j] < xlim; ++j) {
            const double dx = x[j] - xi, dy = y[j] - yi;
            if (dx * dx + dy * dy < d2max) {
                hits[nh++] = (uint32_t)j;
                if (nh == DS_HITS_CAP) {
                    ++j; /* full: report these, then resume after j */
                    break;
                }
            }
        }
        for (size_t h = 0; h < nh; ++h)
            on_pair(d, i, hits[h], ctx);
    } while (nh == DS_HITS_CAP);
    return j;
}

#endif
