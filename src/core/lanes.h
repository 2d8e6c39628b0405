/* SPDX-License-Identifier: MIT */
/* Two lanes of doubles (and four of 32-bit integers) behind one small
 * type, as Box2D's b2FloatW: the hot loops that decide without branches
 * (the event-driven prediction, the sweep's block test) are written once
 * with these operations. On x86-64 each is one SSE2 instruction; the
 * plain-C twin of each does the same IEEE 754 arithmetic lane by lane, with
 * masks as all-ones or all-zeros bit patterns as SSE2 makes them, so both
 * give the same bits (tests/test_lanes.c checks every operation on both,
 * NaNs, infinities, signed zeros and subnormals included).
 *
 * The plain twins are always compiled (ds_p2_*, ds_p4_*); ds_x2_* and
 * ds_u4_* are the SSE2 ones where the compiler targets SSE2, else the
 * plain ones. Not installed. */
#ifndef DS_LANES_H
#define DS_LANES_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* ------------------------------------------------------------------ */
/* The plain-C twins                                                    */
/* ------------------------------------------------------------------ */

typedef struct ds_p2 {
    double v[2]; /* lane 0, lane 1 */
} ds_p2;

static inline uint64_t ds_p2_bits_of(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

static inline double ds_p2_double_of(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

static inline double ds_p2_mask_of(int yes) { return ds_p2_double_of(yes ? ~(uint64_t)0 : 0); }

static inline ds_p2 ds_p2_make(double lane0, double lane1)
{
    ds_p2 r = {{lane0, lane1}};
    return r;
}
static inline ds_p2 ds_p2_set1(double a) { return ds_p2_make(a, a); }
static inline ds_p2 ds_p2_load(const double *p) { return ds_p2_make(p[0], p[1]); }
static inline ds_p2 ds_p2_load_pair(const double *a, const double *b) { return ds_p2_make(*a, *b); }
static inline ds_p2 ds_p2_add(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(a.v[0] + b.v[0], a.v[1] + b.v[1]);
}
static inline ds_p2 ds_p2_sub(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(a.v[0] - b.v[0], a.v[1] - b.v[1]);
}
static inline ds_p2 ds_p2_mul(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(a.v[0] * b.v[0], a.v[1] * b.v[1]);
}
static inline ds_p2 ds_p2_div(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(a.v[0] / b.v[0], a.v[1] / b.v[1]);
}
static inline ds_p2 ds_p2_sqrt(ds_p2 a) { return ds_p2_make(sqrt(a.v[0]), sqrt(a.v[1])); }
/* SSE2's maximum: the second operand unless the first is greater (so a
 * NaN in either lane, or two zeros, give the second). */
static inline ds_p2 ds_p2_max(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(a.v[0] > b.v[0] ? a.v[0] : b.v[0], a.v[1] > b.v[1] ? a.v[1] : b.v[1]);
}
/* And its minimum: the second operand unless the first is less. */
static inline ds_p2 ds_p2_min(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(a.v[0] < b.v[0] ? a.v[0] : b.v[0], a.v[1] < b.v[1] ? a.v[1] : b.v[1]);
}
static inline ds_p2 ds_p2_lt(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(ds_p2_mask_of(a.v[0] < b.v[0]), ds_p2_mask_of(a.v[1] < b.v[1]));
}
static inline ds_p2 ds_p2_le(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(ds_p2_mask_of(a.v[0] <= b.v[0]), ds_p2_mask_of(a.v[1] <= b.v[1]));
}
static inline ds_p2 ds_p2_gt(ds_p2 a, ds_p2 b) { return ds_p2_lt(b, a); }
static inline ds_p2 ds_p2_eq(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(ds_p2_mask_of(a.v[0] == b.v[0]), ds_p2_mask_of(a.v[1] == b.v[1]));
}
static inline ds_p2 ds_p2_ne(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(ds_p2_mask_of(!(a.v[0] == b.v[0])), ds_p2_mask_of(!(a.v[1] == b.v[1])));
}
static inline ds_p2 ds_p2_and(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(ds_p2_double_of(ds_p2_bits_of(a.v[0]) & ds_p2_bits_of(b.v[0])),
                      ds_p2_double_of(ds_p2_bits_of(a.v[1]) & ds_p2_bits_of(b.v[1])));
}
/* ~a & b, bit by bit */
static inline ds_p2 ds_p2_andnot(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(ds_p2_double_of(~ds_p2_bits_of(a.v[0]) & ds_p2_bits_of(b.v[0])),
                      ds_p2_double_of(~ds_p2_bits_of(a.v[1]) & ds_p2_bits_of(b.v[1])));
}
static inline ds_p2 ds_p2_or(ds_p2 a, ds_p2 b)
{
    return ds_p2_make(ds_p2_double_of(ds_p2_bits_of(a.v[0]) | ds_p2_bits_of(b.v[0])),
                      ds_p2_double_of(ds_p2_bits_of(a.v[1]) | ds_p2_bits_of(b.v[1])));
}
/* Lane by lane: yes where mask is all ones, no where it is zero. */
static inline ds_p2 ds_p2_select(ds_p2 mask, ds_p2 yes, ds_p2 no)
{
    return ds_p2_or(ds_p2_and(mask, yes), ds_p2_andnot(mask, no));
}
/* Bit k: the sign bit of lane k (a mask's lane is set). */
static inline unsigned ds_p2_bits(ds_p2 a)
{
    return (unsigned)(ds_p2_bits_of(a.v[0]) >> 63) | (unsigned)(ds_p2_bits_of(a.v[1]) >> 63) << 1;
}
/* The bits of two masks at once: lo's lanes in bits 0 and 1, hi's in 2
 * and 3 (a block of four). */
static inline unsigned ds_p2_bits_pair(ds_p2 lo, ds_p2 hi)
{
    return ds_p2_bits(lo) | ds_p2_bits(hi) << 2;
}
static inline double ds_p2_first(ds_p2 a) { return a.v[0]; }
/* Lane 1 in both lanes. */
static inline ds_p2 ds_p2_high(ds_p2 a) { return ds_p2_make(a.v[1], a.v[1]); }

/* Four lanes of 32-bit integers: a cell's four slots. */
typedef struct ds_p4 {
    uint32_t v[4];
} ds_p4;

static inline ds_p4 ds_p4_load(const uint32_t *p)
{
    ds_p4 r = {{p[0], p[1], p[2], p[3]}};
    return r;
}
static inline void ds_p4_store(uint32_t *p, ds_p4 a) { memcpy(p, a.v, sizeof a.v); }
/* Bit k: lane k equals u. */
static inline unsigned ds_p4_equal_bits(ds_p4 a, uint32_t u)
{
    return (unsigned)(a.v[0] == u) | (unsigned)(a.v[1] == u) << 1 | (unsigned)(a.v[2] == u) << 2 |
           (unsigned)(a.v[3] == u) << 3;
}

/* ------------------------------------------------------------------ */
/* The SSE2 forms                                                       */
/* ------------------------------------------------------------------ */

#if defined(__SSE2__)
#include <emmintrin.h>

typedef __m128d ds_x2;

static inline ds_x2 ds_x2_make(double lane0, double lane1) { return _mm_set_pd(lane1, lane0); }
static inline ds_x2 ds_x2_set1(double a) { return _mm_set1_pd(a); }
static inline ds_x2 ds_x2_load(const double *p) { return _mm_loadu_pd(p); }
static inline ds_x2 ds_x2_load_pair(const double *a, const double *b)
{
    return _mm_loadh_pd(_mm_load_sd(a), b);
}
static inline ds_x2 ds_x2_add(ds_x2 a, ds_x2 b) { return _mm_add_pd(a, b); }
static inline ds_x2 ds_x2_sub(ds_x2 a, ds_x2 b) { return _mm_sub_pd(a, b); }
static inline ds_x2 ds_x2_mul(ds_x2 a, ds_x2 b) { return _mm_mul_pd(a, b); }
static inline ds_x2 ds_x2_div(ds_x2 a, ds_x2 b) { return _mm_div_pd(a, b); }
static inline ds_x2 ds_x2_sqrt(ds_x2 a) { return _mm_sqrt_pd(a); }
static inline ds_x2 ds_x2_max(ds_x2 a, ds_x2 b) { return _mm_max_pd(a, b); }
static inline ds_x2 ds_x2_min(ds_x2 a, ds_x2 b) { return _mm_min_pd(a, b); }
static inline ds_x2 ds_x2_lt(ds_x2 a, ds_x2 b) { return _mm_cmplt_pd(a, b); }
static inline ds_x2 ds_x2_le(ds_x2 a, ds_x2 b) { return _mm_cmple_pd(a, b); }
static inline ds_x2 ds_x2_gt(ds_x2 a, ds_x2 b) { return _mm_cmpgt_pd(a, b); }
static inline ds_x2 ds_x2_eq(ds_x2 a, ds_x2 b) { return _mm_cmpeq_pd(a, b); }
static inline ds_x2 ds_x2_ne(ds_x2 a, ds_x2 b) { return _mm_cmpneq_pd(a, b); }
static inline ds_x2 ds_x2_and(ds_x2 a, ds_x2 b) { return _mm_and_pd(a, b); }
static inline ds_x2 ds_x2_andnot(ds_x2 a, ds_x2 b) { return _mm_andnot_pd(a, b); }
static inline ds_x2 ds_x2_or(ds_x2 a, ds_x2 b) { return _mm_or_pd(a, b); }
static inline ds_x2 ds_x2_select(ds_x2 mask, ds_x2 yes, ds_x2 no)
{
    return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}
static inline unsigned ds_x2_bits(ds_x2 a) { return (unsigned)_mm_movemask_pd(a); }
/* Each 64-bit mask lane is all ones or all zeros: one 32-bit half of
 * each packs the four lanes into one movemask. */
static inline unsigned ds_x2_bits_pair(ds_x2 lo, ds_x2 hi)
{
    return (unsigned)_mm_movemask_ps(
        _mm_shuffle_ps(_mm_castpd_ps(lo), _mm_castpd_ps(hi), _MM_SHUFFLE(2, 0, 2, 0)));
}
static inline double ds_x2_first(ds_x2 a) { return _mm_cvtsd_f64(a); }
static inline ds_x2 ds_x2_high(ds_x2 a) { return _mm_unpackhi_pd(a, a); }

typedef __m128i ds_u4;

static inline ds_u4 ds_u4_load(const uint32_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}
static inline void ds_u4_store(uint32_t *p, ds_u4 a) { _mm_storeu_si128((__m128i *)(void *)p, a); }
static inline unsigned ds_u4_equal_bits(ds_u4 a, uint32_t u)
{
    return (unsigned)_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(a, _mm_set1_epi32((int)u))));
}

#else /* no SSE2: the plain twins under the same names */

typedef ds_p2 ds_x2;
#define ds_x2_make ds_p2_make
#define ds_x2_set1 ds_p2_set1
#define ds_x2_load ds_p2_load
#define ds_x2_load_pair ds_p2_load_pair
#define ds_x2_add ds_p2_add
#define ds_x2_sub ds_p2_sub
#define ds_x2_mul ds_p2_mul
#define ds_x2_div ds_p2_div
#define ds_x2_sqrt ds_p2_sqrt
#define ds_x2_max ds_p2_max
#define ds_x2_min ds_p2_min
#define ds_x2_lt ds_p2_lt
#define ds_x2_le ds_p2_le
#define ds_x2_gt ds_p2_gt
#define ds_x2_eq ds_p2_eq
#define ds_x2_ne ds_p2_ne
#define ds_x2_and ds_p2_and
#define ds_x2_andnot ds_p2_andnot
#define ds_x2_or ds_p2_or
#define ds_x2_select ds_p2_select
#define ds_x2_bits ds_p2_bits
#define ds_x2_bits_pair ds_p2_bits_pair
#define ds_x2_first ds_p2_first
#define ds_x2_high ds_p2_high

typedef ds_p4 ds_u4;
#define ds_u4_load ds_p4_load
#define ds_u4_store ds_p4_store
#define ds_u4_equal_bits ds_p4_equal_bits

#endif

#endif
