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
 * multiply and add, no fused multiply-add), so the same pairs to the bit. */
#ifndef DS_SWEEP_BLOCK_H
#define DS_SWEEP_BLOCK_H

#include <stddef.h>

#include "timestep/broad_phase.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* Tests candidates j .. j+3 (which must be readable) against the disk at
 * (xi, yi): bit k of *inside says x[j+k] < xlim, bit k of the result says
 * the centres are closer than sqrt(d2max). */
static inline unsigned ds_test_four(const double *x, const double *y, size_t j, double xi,
                                    double yi, double xlim, double d2max, unsigned *inside)
{
#if defined(__SSE2__)
    const __m128d vxi = _mm_set1_pd(xi), vyi = _mm_set1_pd(yi);
    const __m128d lim = _mm_set1_pd(xlim), d2 = _mm_set1_pd(d2max);
    const __m128d xa = _mm_loadu_pd(x + j), xb = _mm_loadu_pd(x + j + 2);
    const __m128d dxa = _mm_sub_pd(xa, vxi), dxb = _mm_sub_pd(xb, vxi);
    const __m128d dya = _mm_sub_pd(_mm_loadu_pd(y + j), vyi);
    const __m128d dyb = _mm_sub_pd(_mm_loadu_pd(y + j + 2), vyi);
    const __m128d closea = _mm_cmplt_pd(_mm_add_pd(_mm_mul_pd(dxa, dxa), _mm_mul_pd(dya, dya)), d2);
    const __m128d closeb = _mm_cmplt_pd(_mm_add_pd(_mm_mul_pd(dxb, dxb), _mm_mul_pd(dyb, dyb)), d2);
    /* Each 64-bit mask lane is all ones or all zeros: one 32-bit half of
     * each packs four lanes into one movemask. */
    const __m128 in4 =
        _mm_shuffle_ps(_mm_castpd_ps(_mm_cmplt_pd(xa, lim)), _mm_castpd_ps(_mm_cmplt_pd(xb, lim)),
                       _MM_SHUFFLE(2, 0, 2, 0));
    const __m128 close4 =
        _mm_shuffle_ps(_mm_castpd_ps(closea), _mm_castpd_ps(closeb), _MM_SHUFFLE(2, 0, 2, 0));
    *inside = (unsigned)_mm_movemask_ps(in4);
    return (unsigned)_mm_movemask_ps(close4);
#else
    unsigned in = 0, close = 0;
    for (unsigned k = 0; k < 4; ++k) {
        const double dx = x[j + k] - xi, dy = y[j + k] - yi;
        in |= (unsigned)(x[j + k] < xlim) << k;
        close |= (unsigned)(dx * dx + dy * dy < d2max) << k;
    }
    *inside = in;
    return close;
#endif
}

/* Bit k says x[j+k] <= v, for k < 4 (x[j .. j+3] must be readable). */
static inline unsigned ds_at_most_four(const double *x, size_t j, double v)
{
#if defined(__SSE2__)
    const __m128d vv = _mm_set1_pd(v);
    const __m128 le = _mm_shuffle_ps(_mm_castpd_ps(_mm_cmple_pd(_mm_loadu_pd(x + j), vv)),
                                     _mm_castpd_ps(_mm_cmple_pd(_mm_loadu_pd(x + j + 2), vv)),
                                     _MM_SHUFFLE(2, 0, 2, 0));
    return (unsigned)_mm_movemask_ps(le);
#else
    unsigned m = 0;
    for (unsigned k = 0; k < 4; ++k)
        m |= (unsigned)(x[j + k] <= v) << k;
    return m;
#endif
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
