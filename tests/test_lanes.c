/* SPDX-License-Identifier: MIT */
/* The two-lane wrapper (core/lanes.h): every operation of the SSE2 form
 * gives the same bits as its plain-C twin, on ordinary numbers and on
 * the edges of IEEE 754 (signed zeros, subnormals, infinities; a NaN for
 * a NaN, see assert_same), so
 * the hot loops written with it (the event-driven prediction, the sweep's
 * block test) give the same trajectories on every machine. Without SSE2
 * the two forms are one, and the checks of what each operation means
 * still hold. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "core/lanes.h"

static const double values[] = {0.0,       -0.0,       1.0,     -1.0,     0.5,   3.0e-310,
                                -4.9e-324, DBL_MIN,    DBL_MAX, -DBL_MAX, 1e300, 1e-300,
                                INFINITY,  -INFINITY,  NAN,     -NAN,     2.0,   7.25,
                                -1e-17,    123456.789, 6.02e23, -0.125};
#define COUNT (sizeof values / sizeof values[0])

static uint64_t bits(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

/* Lane k of the SSE2 form and of the plain form, as bits. A NaN is a
 * NaN: IEEE 754 leaves the sign and payload of a NaN an operation makes to
 * the machine (SSE2's square root of -1 is the "indefinite" -NaN, the C
 * library's +NaN), and the hot loops never let one decide (a NaN lag is
 * clipped to 0, a NaN time discarded by its mask). */
static void assert_same(ds_x2 fast, ds_p2 plain)
{
    double lanes[2];
    memcpy(lanes, &fast, sizeof lanes);
    for (int k = 0; k < 2; ++k)
        if (bits(lanes[k]) != bits(plain.v[k]) && !(isnan(lanes[k]) && isnan(plain.v[k])))
            fail_msg("lane %d: %a (%016llx) against the plain %a (%016llx)", k, lanes[k],
                     (unsigned long long)bits(lanes[k]), plain.v[k],
                     (unsigned long long)bits(plain.v[k]));
}

static void test_arithmetic_gives_the_plain_bits(void **state)
{
    (void)state;
    for (size_t i = 0; i < COUNT; ++i)
        for (size_t j = 0; j < COUNT; ++j) {
            const double a0 = values[i], a1 = values[j], b0 = values[j],
                         b1 = values[(i + j) % COUNT];
            const ds_x2 a = ds_x2_make(a0, a1), b = ds_x2_make(b0, b1);
            const ds_p2 pa = ds_p2_make(a0, a1), pb = ds_p2_make(b0, b1);
            assert_same(ds_x2_add(a, b), ds_p2_add(pa, pb));
            assert_same(ds_x2_sub(a, b), ds_p2_sub(pa, pb));
            assert_same(ds_x2_mul(a, b), ds_p2_mul(pa, pb));
            assert_same(ds_x2_div(a, b), ds_p2_div(pa, pb));
            assert_same(ds_x2_sqrt(a), ds_p2_sqrt(pa));
            assert_same(ds_x2_max(a, b), ds_p2_max(pa, pb));
            assert_same(ds_x2_min(a, b), ds_p2_min(pa, pb));
        }
}

static void test_comparisons_and_masks_give_the_plain_bits(void **state)
{
    (void)state;
    for (size_t i = 0; i < COUNT; ++i)
        for (size_t j = 0; j < COUNT; ++j) {
            const double a0 = values[i], a1 = values[j], b0 = values[j], b1 = values[i];
            const ds_x2 a = ds_x2_make(a0, a1), b = ds_x2_make(b0, b1);
            const ds_p2 pa = ds_p2_make(a0, a1), pb = ds_p2_make(b0, b1);
            const ds_x2 m[] = {ds_x2_lt(a, b), ds_x2_le(a, b), ds_x2_gt(a, b), ds_x2_eq(a, b),
                               ds_x2_ne(a, b)};
            const ds_p2 pm[] = {ds_p2_lt(pa, pb), ds_p2_le(pa, pb), ds_p2_gt(pa, pb),
                                ds_p2_eq(pa, pb), ds_p2_ne(pa, pb)};
            for (size_t c = 0; c < sizeof m / sizeof m[0]; ++c) {
                assert_same(m[c], pm[c]);
                assert_int_equal(ds_x2_bits(m[c]), ds_p2_bits(pm[c]));
                assert_same(ds_x2_select(m[c], a, b), ds_p2_select(pm[c], pa, pb));
                assert_same(ds_x2_and(m[c], a), ds_p2_and(pm[c], pa));
                assert_same(ds_x2_andnot(m[c], a), ds_p2_andnot(pm[c], pa));
                assert_same(ds_x2_or(m[c], b), ds_p2_or(pm[c], pb));
                assert_int_equal(ds_x2_bits_pair(m[c], m[(c + 1) % 5]),
                                 ds_p2_bits_pair(pm[c], pm[(c + 1) % 5]));
            }
            assert_same(ds_x2_high(a), ds_p2_high(pa));
            assert_true(bits(ds_x2_first(a)) == bits(ds_p2_first(pa)));
            const double pair[2] = {a0, a1};
            assert_same(ds_x2_load(pair), ds_p2_load(pair));
            assert_same(ds_x2_load_pair(&values[i], &values[j]),
                        ds_p2_load_pair(&values[i], &values[j]));
            assert_same(ds_x2_set1(a0), ds_p2_set1(a0));
        }
}

/* What the operations mean, as the hot loops use them: SSE2's maximum
 * takes the second operand unless the first is greater (a NaN gives the
 * second: the prediction's max(lag, 0) turns a NaN into 0); a mask selects
 * lane by lane; the bits of a mask are its lanes in order. */
static void test_the_operations_mean_what_the_hot_loops_take(void **state)
{
    (void)state;
    const ds_x2 lag = ds_x2_make(NAN, -3.0), zero = ds_x2_set1(0.0);
    const ds_x2 clipped = ds_x2_max(lag, zero);
    assert_true(ds_x2_first(clipped) == 0.0);
    assert_true(ds_x2_first(ds_x2_high(clipped)) == 0.0);
    const ds_x2 m = ds_x2_lt(ds_x2_make(1.0, 5.0), ds_x2_make(2.0, 4.0));
    assert_int_equal(ds_x2_bits(m), 1u);
    const ds_x2 s = ds_x2_select(m, ds_x2_make(10.0, 20.0), ds_x2_make(30.0, 40.0));
    assert_true(ds_x2_first(s) == 10.0 && ds_x2_first(ds_x2_high(s)) == 40.0);
    assert_int_equal(ds_x2_bits_pair(m, ds_x2_eq(zero, zero)), 0xDu);
    /* |b| as andnot(-0.0, b): the sign bit cleared. */
    const ds_x2 b = ds_x2_andnot(ds_x2_set1(-0.0), ds_x2_make(-2.5, 3.0));
    assert_true(ds_x2_first(b) == 2.5 && ds_x2_first(ds_x2_high(b)) == 3.0);
}

/* Four slots of 32-bit disk numbers: loaded, stored, and which are
 * empty, as the gathering of a cell's disks reads them. */
static void test_four_slots_say_which_are_empty(void **state)
{
    (void)state;
    const uint32_t empty = 1000u;
    const uint32_t slots[][4] = {
        {1, 2, 3, 4}, {1, 2, empty, empty}, {empty, empty, empty, empty}, {7, empty, 9, empty}};
    const unsigned expected[] = {0x0u, 0xCu, 0xFu, 0xAu};
    for (size_t c = 0; c < 4; ++c) {
        const ds_u4 v = ds_u4_load(slots[c]);
        assert_int_equal(ds_u4_equal_bits(v, empty), expected[c]);
        assert_int_equal(ds_p4_equal_bits(ds_p4_load(slots[c]), empty), expected[c]);
        uint32_t out[4];
        ds_u4_store(out, v);
        assert_memory_equal(out, slots[c], sizeof out);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arithmetic_gives_the_plain_bits),
        cmocka_unit_test(test_comparisons_and_masks_give_the_plain_bits),
        cmocka_unit_test(test_the_operations_mean_what_the_hot_loops_take),
        cmocka_unit_test(test_four_slots_say_which_are_empty),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
