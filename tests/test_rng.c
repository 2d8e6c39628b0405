/* SPDX-License-Identifier: MIT */
/* The xorshift64* generator: reproducible, in range, uniform. */
#include "test_util.h"

static void test_same_seed_gives_same_stream(void **state)
{
    (void)state;
    ds_rng a, b;
    ds_rng_seed(&a, 42);
    ds_rng_seed(&b, 42);
    for (int k = 0; k < 1000; ++k)
        assert_true(ds_rng_next(&a) == ds_rng_next(&b));
}

static void test_nearby_seeds_give_different_streams(void **state)
{
    (void)state;
    ds_rng a, b;
    ds_rng_seed(&a, 0); /* 0 must be a valid seed too */
    ds_rng_seed(&b, 1);
    int equal = 0;
    for (int k = 0; k < 1000; ++k)
        equal += ds_rng_next(&a) == ds_rng_next(&b);
    assert_int_equal(equal, 0);
}

static void test_uniform_stays_in_half_open_interval(void **state)
{
    (void)state;
    ds_rng r;
    ds_rng_seed(&r, 7);
    for (int k = 0; k < 100000; ++k) {
        double u = ds_rng_uniform(&r, 5.0, 995.0);
        assert_true(u >= 5.0 && u < 995.0);
        double v = ds_rng_uniform(&r, 0.0, 1.0);
        assert_true(v >= 0.0 && v < 1.0);
    }
}

static void test_uniform_histogram_is_flat(void **state)
{
    (void)state;
    /* Pearson chi-square over 100 bins, 10^6 draws: 99 degrees of freedom,
     * mean 99, sd sqrt(198) = 14. 180 is ~5.8 sd above the mean, a
     * false-failure probability below 1e-6 for a correct generator. */
    enum { BINS = 100, DRAWS = 1000000 };
    static long count[BINS];
    memset(count, 0, sizeof count);
    ds_rng r;
    ds_rng_seed(&r, 2024);
    for (int k = 0; k < DRAWS; ++k)
        ++count[(int)ds_rng_uniform(&r, 0.0, (double)BINS)];
    double expected = (double)DRAWS / BINS, chi2 = 0.0;
    for (int b = 0; b < BINS; ++b)
        chi2 += (count[b] - expected) * (count[b] - expected) / expected;
    assert_true(chi2 < 180.0);
}

static void test_uniform_mean_and_variance_match(void **state)
{
    (void)state;
    /* U[0,1): mean 1/2, variance 1/12. With 10^6 draws the standard error
     * of the mean is sqrt(1/12/1e6) = 2.9e-4; 6 sd = 1.7e-3. */
    ds_rng r;
    ds_rng_seed(&r, 99);
    double s = 0.0, s2 = 0.0;
    const int n = 1000000;
    for (int k = 0; k < n; ++k) {
        double u = ds_rng_uniform(&r, 0.0, 1.0);
        s += u;
        s2 += u * u;
    }
    double mean = s / n, var = s2 / n - mean * mean;
    assert_true(fabs(mean - 0.5) < 1.7e-3);
    assert_true(fabs(var - 1.0 / 12.0) < 1.7e-3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_seed_gives_same_stream),
        cmocka_unit_test(test_nearby_seeds_give_different_streams),
        cmocka_unit_test(test_uniform_stays_in_half_open_interval),
        cmocka_unit_test(test_uniform_histogram_is_flat),
        cmocka_unit_test(test_uniform_mean_and_variance_match),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
