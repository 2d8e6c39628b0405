/* SPDX-License-Identifier: MIT */
/* DS_BROADPHASE_SAP, the seed's sweep and prune: the slots are kept sorted by x with
 * insertion sort (nearly linear, since the order barely changes between
 * steps) and a pair is tested only while their x distance is below 2R.
 * In a periodic box the seam pass (seam.c) follows, for the pairs that
 * touch across the box's edges. */
#include <math.h>

#include "timestep/broad_phase.h"
#include "timestep/sweep_block.h"

/* AVX and AVX-512 code is compiled with gcc/clang target attributes on
 * x86-64 whatever the build flags, and run only on a CPU that has it. */
#if defined(__GNUC__) && defined(__x86_64__)
#define HAVE_X86_VECTORS 1
#include <immintrin.h>
#endif

/* The last disks, whose blocks would run past the sentinel, one by one. */
static uint64_t sweep_rest(ds_disks *d, double diameter, size_t i, ds_pair_fn on_pair, void *ctx)
{
    uint64_t tested = 0;
    for (; i < d->n; ++i)
        tested +=
            ds_sweep_range(d, diameter, i, i + 1, d->n, d->x[i] + diameter, on_pair, ctx) - i - 1;
    return tested;
}

/* Blocks of BLOCK = 8 candidates per disk, tested without a data-dependent
 * branch (see sweep_block.h): the window after disk i holds ~ n 2R / box
 * disks (4 in the seed case), so only ~5% of windows fill the block and
 * continue past it. */
#define BLOCK 8
#define FULL_BLOCK ((1u << BLOCK) - 1u)

/* The block scans below run over CHUNK disks at a time and call nothing:
 * a disk whose block has a hit, or whose window continues past the block,
 * is only noted (an event: the disk, its hit bits, and bit BLOCK for
 * "continues"), and the events are handled after the scan, in order.
 * Without a call in the loop the compiler keeps every value in registers
 * (with the callback inside, it kept the running count and the limits on
 * the stack, and the seed case ran 15% slower). Events are rare (~5% of
 * disks in the seed case), so the branch that notes one predicts well. The
 * callback changes velocities only and the scan reads positions only, so
 * handling the events later reports the same pairs in the same order. */
#define CHUNK 256

typedef struct sweep_events {
    uint32_t disk[CHUNK];
    uint32_t bits[CHUNK];
    size_t count;
} sweep_events;

/* Scans the blocks of disks [begin, end) (end + BLOCK <= n), notes their
 * events and returns the tests made inside the blocks. */
typedef uint64_t (*block_scan_fn)(const double *x, const double *y, double diameter, size_t begin,
                                  size_t end, sweep_events *events);

static inline void note_event(sweep_events *events, size_t i, unsigned inside_bits, unsigned hit)
{
    const uint32_t bits = hit | (uint32_t)(inside_bits == FULL_BLOCK) << BLOCK;
    if (bits) {
        events->disk[events->count] = (uint32_t)i;
        events->bits[events->count++] = bits;
    }
}

/* Reports the pairs of the noted events and continues their windows past
 * the block; returns the tests made beyond the blocks. */
static uint64_t handle_events(ds_disks *d, double diameter, const sweep_events *events,
                              ds_pair_fn on_pair, void *ctx)
{
    uint64_t tested = 0;
    for (size_t e = 0; e < events->count; ++e) {
        const size_t i = events->disk[e];
        const uint32_t bits = events->bits[e];
        for (uint32_t hit = bits & FULL_BLOCK, j = 1; hit; ++j, hit >>= 1)
            if (hit & 1u)
                on_pair(d, i, i + j, ctx);
        if (bits >> BLOCK) {
            const size_t from = i + 1 + BLOCK;
            tested +=
                ds_sweep_range(d, diameter, i, from, d->n, d->x[i] + diameter, on_pair, ctx) - from;
        }
    }
    return tested;
}

static uint64_t scan_blocks_portable(const double *x, const double *y, double diameter,
                                     size_t begin, size_t end, sweep_events *events)
{
    const double d2max = diameter * diameter;
    uint64_t tested = 0;
    for (size_t i = begin; i < end; ++i) {
        const double xi = x[i], yi = y[i], xlim = xi + diameter;
        unsigned in_lo, in_hi;
        const unsigned close_lo = ds_test_four(x, y, i + 1, xi, yi, xlim, d2max, &in_lo);
        const unsigned close_hi = ds_test_four(x, y, i + 5, xi, yi, xlim, d2max, &in_hi);
        const unsigned inside_bits = in_lo | in_hi << 4;
        tested += ds_prefix_length(inside_bits);
        note_event(events, i, inside_bits, inside_bits & (close_lo | close_hi << 4));
    }
    return tested;
}

#if defined(HAVE_X86_VECTORS)
/* The same block test with 256-bit AVX registers, four candidates per
 * instruction. Same arithmetic (no FMA), so the same pairs. */

__attribute__((target("avx"))) static uint64_t scan_blocks_avx(const double *x, const double *y,
                                                               double diameter, size_t begin,
                                                               size_t end, sweep_events *events)
{
    const __m256d d2max = _mm256_set1_pd(diameter * diameter);
    uint64_t tested = 0;
    for (size_t i = begin; i < end; ++i) {
        const __m256d xi = _mm256_set1_pd(x[i]), yi = _mm256_set1_pd(y[i]);
        const __m256d lim = _mm256_set1_pd(x[i] + diameter);
        const __m256d xa = _mm256_loadu_pd(x + i + 1), xb = _mm256_loadu_pd(x + i + 5);
        const __m256d dxa = _mm256_sub_pd(xa, xi), dxb = _mm256_sub_pd(xb, xi);
        const __m256d dya = _mm256_sub_pd(_mm256_loadu_pd(y + i + 1), yi);
        const __m256d dyb = _mm256_sub_pd(_mm256_loadu_pd(y + i + 5), yi);
        const __m256d d2a = _mm256_add_pd(_mm256_mul_pd(dxa, dxa), _mm256_mul_pd(dya, dya));
        const __m256d d2b = _mm256_add_pd(_mm256_mul_pd(dxb, dxb), _mm256_mul_pd(dyb, dyb));
        const unsigned inside_bits =
            (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(xa, lim, _CMP_LT_OQ)) |
            (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(xb, lim, _CMP_LT_OQ)) << 4;
        const unsigned close = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(d2a, d2max, _CMP_LT_OQ)) |
                               (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(d2b, d2max, _CMP_LT_OQ))
                                   << 4;
        tested += ds_prefix_length(inside_bits);
        note_event(events, i, inside_bits, inside_bits & close);
    }
    return tested;
}

/* With AVX-512 the whole block of eight is one register, and the
 * comparisons give bit masks directly. */

__attribute__((target("avx512f"))) static uint64_t
scan_blocks_avx512(const double *x, const double *y, double diameter, size_t begin, size_t end,
                   sweep_events *events)
{
    const __m512d d2max = _mm512_set1_pd(diameter * diameter);
    uint64_t tested = 0;
    for (size_t i = begin; i < end; ++i) {
        const __m512d xj = _mm512_loadu_pd(x + i + 1);
        const __m512d dx = _mm512_sub_pd(xj, _mm512_set1_pd(x[i]));
        const __m512d dy = _mm512_sub_pd(_mm512_loadu_pd(y + i + 1), _mm512_set1_pd(y[i]));
        const __m512d d2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
        const unsigned inside_bits =
            (unsigned)_mm512_cmp_pd_mask(xj, _mm512_set1_pd(x[i] + diameter), _CMP_LT_OQ);
        const unsigned hit = inside_bits & (unsigned)_mm512_cmp_pd_mask(d2, d2max, _CMP_LT_OQ);
        tested += ds_prefix_length(inside_bits);
        note_event(events, i, inside_bits, hit);
    }
    return tested;
}
#endif

ds_scan ds_bp_widest_scan(void)
{
#if defined(HAVE_X86_VECTORS)
    if (__builtin_cpu_supports("avx512f"))
        return DS_SCAN_AVX512;
    if (__builtin_cpu_supports("avx"))
        return DS_SCAN_AVX;
#endif
    return DS_SCAN_PORTABLE;
}

static block_scan_fn block_scan(ds_scan scan)
{
    switch (scan) {
#if defined(HAVE_X86_VECTORS)
    case DS_SCAN_AVX512:
        return scan_blocks_avx512;
    case DS_SCAN_AVX:
        return scan_blocks_avx;
#endif
    default:
        return scan_blocks_portable;
    }
}

uint64_t ds_sap_find_pairs(const ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx)
{
    ds_bp_insertion_sort(d, 0, d->n, bp->scan);
    const size_t n = d->n;
    const double diameter = bp->diameter;
    const block_scan_fn scan = block_scan(bp->scan);
    sweep_events events;
    uint64_t tested = 0;
    /* x[n] = +inf is a sentinel: no window runs past it. A block reads
     * x[i+1 .. i+BLOCK], so blocks need i + BLOCK <= n. */
    const size_t block_end = n >= BLOCK ? n - BLOCK + 1 : 0;
    for (size_t i = 0; i < block_end; i += CHUNK) {
        const size_t end = block_end - i > CHUNK ? i + CHUNK : block_end;
        events.count = 0;
        tested += scan(d->x, d->y, diameter, i, end, &events);
        tested += handle_events(d, diameter, &events, on_pair, ctx);
    }
    return tested + sweep_rest(d, diameter, block_end, on_pair, ctx);
}
