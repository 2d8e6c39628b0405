/* SPDX-License-Identifier: MIT */
/* ds_pair_histogram: the pair counts behind g(r). A periodic square
 * lattice gives exact shell counts; random centres give exactly the counts
 * of testing every pair (walls and periodic, centres wrapped or not); bad
 * arguments are refused. */
#include "test_util.h"

/* Every pair, the reference: nearest image by rounding, as a caller might. */
static void brute_force(size_t n, const double *x, const double *y, double bx, double by,
                        int periodic, double dr, size_t bins, uint64_t *counts)
{
    memset(counts, 0, bins * sizeof *counts);
    for (size_t j = 0; j < n; ++j)
        for (size_t k = j + 1; k < n; ++k) {
            double dx = x[k] - x[j], dy = y[k] - y[j];
            if (periodic) {
                dx -= bx * round(dx / bx);
                dy -= by * round(dy / by);
            }
            const double r = sqrt(dx * dx + dy * dy);
            if (r < (double)bins * dr)
                ++counts[(size_t)(r / dr) < bins ? (size_t)(r / dr) : bins - 1];
        }
}

/* m x m sites of spacing a in a periodic square of side m a: each site
 * has 4 neighbours at a, 4 at a sqrt 2, 4 at 2 a, so the pairs at those
 * distances number 2 m^2 each (each pair counted once). */
static void test_a_square_lattice_gives_exact_shell_counts(void **state)
{
    (void)state;
    enum { M = 20, N = M * M, BINS = 50 };
    const double a = 10.0, side = M * a, dr = 0.05 * a;
    static double x[N], y[N];
    for (size_t k = 0; k < N; ++k) {
        x[k] = a * (double)(k % M) + 0.5 * a;
        y[k] = a * (double)(k / M) + 0.5 * a;
    }
    uint64_t counts[BINS];
    assert_int_equal(
        ds_pair_histogram(N, x, y, side, side, DS_BOUNDARY_PERIODIC, dr, BINS, counts, NULL),
        DS_OK);
    /* The bins that hold a, a sqrt 2 and 2 a, up to rounding either way. */
    uint64_t at_a = 0, at_diagonal = 0, at_2a = 0, total = 0;
    for (size_t b = 0; b < BINS; ++b) {
        const double lo = (double)b * dr, hi = lo + dr;
        total += counts[b];
        if (lo <= a + 1e-9 && hi > a - 1e-9)
            at_a += counts[b];
        else if (lo <= sqrt(2.0) * a + 1e-9 && hi > sqrt(2.0) * a - 1e-9)
            at_diagonal += counts[b];
        else if (lo <= 2.0 * a + 1e-9 && hi > 2.0 * a - 1e-9)
            at_2a += counts[b];
    }
    assert_int_equal(at_a, 2 * N);
    assert_int_equal(at_diagonal, 2 * N);
    assert_int_equal(at_2a, 2 * N);
    /* Up to 2.5 a: those three shells and the 8 sites at a sqrt 5. */
    assert_int_equal(total, 2 * N + 2 * N + 2 * N + 4 * N);
}

static void check_against_brute_force(int periodic, double shift)
{
    enum { N = 700, BINS = 97 };
    const double bx = 300.0, by = 170.0, dr = 0.83;
    static double x[N], y[N];
    ds_rng rng;
    ds_rng_seed(&rng, 77 + (uint64_t)periodic);
    for (size_t k = 0; k < N; ++k) {
        /* Some on a coarse grid: equal coordinates, pairs on bin edges. */
        const int coarse = ds_rng_next(&rng) & 1u;
        x[k] = coarse ? 5.0 * floor(ds_rng_uniform(&rng, 0.0, bx) / 5.0)
                      : ds_rng_uniform(&rng, 0.0, bx);
        y[k] = coarse ? 5.0 * floor(ds_rng_uniform(&rng, 0.0, by) / 5.0)
                      : ds_rng_uniform(&rng, 0.0, by);
        /* Periodic centres given a few boxes away: the same pairs. */
        x[k] += shift * bx * (double)(k % 3);
        y[k] -= shift * by * (double)(k % 5);
    }
    uint64_t got[BINS], want[BINS];
    brute_force(N, x, y, bx, by, periodic, dr, BINS, want);
    assert_int_equal(ds_pair_histogram(N, x, y, bx, by,
                                       periodic ? DS_BOUNDARY_PERIODIC : DS_BOUNDARY_WALLS, dr,
                                       BINS, got, NULL),
                     DS_OK);
    uint64_t pairs = 0;
    for (size_t b = 0; b < BINS; ++b) {
        assert_int_equal(got[b], want[b]);
        pairs += got[b];
    }
    assert_true(pairs > 1000); /* not an empty case */
}

static void test_walls_count_exactly_the_pairs_of_brute_force(void **state)
{
    (void)state;
    check_against_brute_force(0, 0.0);
}

static void test_periodic_counts_are_nearest_images_wherever_the_centres_are(void **state)
{
    (void)state;
    check_against_brute_force(1, 0.0);
    check_against_brute_force(1, 1.0);
}

static void test_bad_arguments_are_refused(void **state)
{
    (void)state;
    double x[2] = {1.0, 2.0}, y[2] = {1.0, 1.0};
    uint64_t c[4];
    assert_int_equal(ds_pair_histogram(2, NULL, y, 10, 10, DS_BOUNDARY_WALLS, 1, 4, c, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_pair_histogram(2, x, y, 10, 10, DS_BOUNDARY_WALLS, 1, 4, NULL, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_pair_histogram(2, x, y, 10, 10, DS_BOUNDARY_WALLS, 1, 0, c, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_pair_histogram(2, x, y, 10, 10, DS_BOUNDARY_WALLS, NAN, 4, c, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_pair_histogram(2, x, y, -1, 10, DS_BOUNDARY_WALLS, 1, 4, c, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_pair_histogram(2, x, y, 10, 10, (ds_boundary)5, 1, 4, c, NULL), DS_ERR_ARG);
    /* A periodic range past half the shorter side, named with its limit. */
    ds_error err;
    assert_int_equal(ds_pair_histogram(2, x, y, 10, 6, DS_BOUNDARY_PERIODIC, 1, 4, c, &err),
                     DS_ERR_ARG);
    assert_int_equal(err.status, DS_ERR_ARG);
    assert_string_equal(err.field, "dr");
    assert_true(err.value == 4.0 && err.limit == 3.0);
    x[1] = INFINITY;
    assert_int_equal(ds_pair_histogram(2, x, y, 10, 10, DS_BOUNDARY_WALLS, 1, 4, c, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_pair_histogram(0, NULL, NULL, 10, 10, DS_BOUNDARY_WALLS, 1, 4, c, NULL),
                     DS_OK);
    for (int b = 0; b < 4; ++b)
        assert_int_equal(c[b], 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_square_lattice_gives_exact_shell_counts),
        cmocka_unit_test(test_walls_count_exactly_the_pairs_of_brute_force),
        cmocka_unit_test(test_periodic_counts_are_nearest_images_wherever_the_centres_are),
        cmocka_unit_test(test_bad_arguments_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
