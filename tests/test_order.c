/* SPDX-License-Identifier: MIT */
/* Bond-orientational order: psi6 per disk (ds_psi6_local) on arrangements
 * whose answer is known exactly, against an all-pairs reference, across a
 * periodic seam, and the global ds_sim_get_psi6 of a crystal and of a gas. */
#include "test_util.h"

#define PI 3.14159265358979323846

/* |a - b| <= tol, naming both values when it fails. */
#define assert_near(a, b, tol) near_or_fail((a), (b), (tol), #a, __FILE__, __LINE__)
static void near_or_fail(double a, double b, double tol, const char *what, const char *file,
                         int line)
{
    if (!(fabs(a - b) <= tol)) {
        print_error("%s:%d: %s = %.17g, want %.17g within %g\n", file, line, what, a, b, tol);
        fail();
    }
}

/* All pairs with atan2 and cos/sin: slow, obvious, and independent of the
 * cell grid and of the complex powers the library uses; the nearest image
 * along a periodic axis (a channel: along x only). */
static void reference_psi6(size_t n, const double *x, const double *y, double bx, double by,
                           int periodic_x, int periodic_y, double cutoff, double *re, double *im)
{
    for (size_t j = 0; j < n; ++j) {
        double sr = 0.0, si = 0.0;
        size_t bonds = 0;
        for (size_t k = 0; k < n; ++k) {
            double dx = x[k] - x[j], dy = y[k] - y[j];
            if (periodic_x)
                dx -= bx * round(dx / bx);
            if (periodic_y)
                dy -= by * round(dy / by);
            if (k == j || !(dx * dx + dy * dy < cutoff * cutoff))
                continue;
            const double theta = atan2(dy, dx);
            sr += cos(6.0 * theta);
            si += sin(6.0 * theta);
            ++bonds;
        }
        re[j] = bonds ? sr / (double)bonds : 0.0;
        im[j] = bonds ? si / (double)bonds : 0.0;
    }
}

/* A triangular lattice of rows x cols sites with spacing a, every site
 * moved by up to jitter in x and y (xorshift, seeded), offset by (x0, y0). */
static size_t jittered_lattice(size_t rows, size_t cols, double a, double jitter, double x0,
                               double y0, uint64_t seed, double *x, double *y)
{
    ds_rng rng;
    ds_rng_seed(&rng, seed);
    size_t n = 0;
    for (size_t r = 0; r < rows; ++r)
        for (size_t c = 0; c < cols; ++c, ++n) {
            x[n] = x0 + a * ((double)c + 0.5 * (double)(r % 2)) +
                   ds_rng_uniform(&rng, -jitter, jitter);
            y[n] = y0 + a * 0.8660254037844386 * (double)r + ds_rng_uniform(&rng, -jitter, jitter);
        }
    return n;
}

static void test_six_neighbours_at_sixty_degrees_give_one(void **state)
{
    (void)state;
    double x[7] = {50.0}, y[7] = {50.0}, re[7], im[7];
    const double tilt = 0.3; /* any orientation: |psi6| does not depend on it */
    for (int k = 0; k < 6; ++k) {
        x[k + 1] = 50.0 + cos(tilt + k * PI / 3.0);
        y[k + 1] = 50.0 + sin(tilt + k * PI / 3.0);
    }
    assert_int_equal(ds_psi6_local(7, x, y, 100.0, 100.0, DS_BOUNDARY_WALLS, 1.2, re, im, NULL),
                     DS_OK);
    /* Six unit vectors summed by a few products each: rounding only. */
    assert_near(hypot(re[0], im[0]), 1.0, 1e-14);
    assert_near(atan2(im[0], re[0]), 6.0 * tilt, 1e-13);
    /* Each ring disk sees the centre and its two ring neighbours, all on
     * the same hexagonal directions: the same order. */
    for (int k = 1; k < 7; ++k) {
        assert_near(re[k], re[0], 1e-13);
        assert_near(im[k], im[0], 1e-13);
    }
}

static void test_rotating_the_disks_turns_psi6_by_six_times_the_angle(void **state)
{
    (void)state;
    enum { ROWS = 12, COLS = 12, N = ROWS * COLS };
    double x[N], y[N], rx[N], ry[N], re[N], im[N], rre[N], rim[N];
    jittered_lattice(ROWS, COLS, 1.0, 0.1, 40.0, 40.0, 7, x, y);
    const double a = 0.37, c = cos(a), s = sin(a);
    for (size_t j = 0; j < N; ++j) {
        rx[j] = 50.0 + c * (x[j] - 50.0) - s * (y[j] - 50.0);
        ry[j] = 50.0 + s * (x[j] - 50.0) + c * (y[j] - 50.0);
    }
    assert_int_equal(ds_psi6_local(N, x, y, 100.0, 100.0, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_OK);
    assert_int_equal(ds_psi6_local(N, rx, ry, 100.0, 100.0, DS_BOUNDARY_WALLS, 1.4, rre, rim, NULL),
                     DS_OK);
    const double turn_re = cos(6.0 * a), turn_im = sin(6.0 * a);
    for (size_t j = 0; j < N; ++j) {
        /* The jittered neighbours are 0.72 to 1.28 apart or beyond 1.45:
         * no bond is near the cutoff, so rotation keeps every bond. */
        assert_near(rre[j], re[j] * turn_re - im[j] * turn_im, 1e-12);
        assert_near(rim[j], re[j] * turn_im + im[j] * turn_re, 1e-12);
    }
}

static void test_a_square_lattice_has_no_sixfold_order(void **state)
{
    (void)state;
    enum { SIDE = 10, N = SIDE * SIDE };
    double x[N], y[N], re[N], im[N];
    for (size_t j = 0; j < N; ++j) {
        x[j] = 0.5 + (double)(j % SIDE);
        y[j] = 0.5 + (double)(j / SIDE);
    }
    /* Periodic, so every disk has its four neighbours at 90 degrees:
     * exp(6 i k pi/2) = (-1)^k sums to 0. The diagonals (1.41) are out. */
    assert_int_equal(ds_psi6_local(N, x, y, SIDE, SIDE, DS_BOUNDARY_PERIODIC, 1.2, re, im, NULL),
                     DS_OK);
    for (size_t j = 0; j < N; ++j) {
        assert_near(re[j], 0.0, 1e-14);
        assert_near(im[j], 0.0, 1e-14);
    }
}

static void test_neighbours_across_the_periodic_seam_count_as_interior_ones(void **state)
{
    (void)state;
    /* 16 rows of 14 at spacing 1 tile a 14 x 8 sqrt(3) box exactly. */
    enum { ROWS = 16, COLS = 14, N = ROWS * COLS };
    const double bx = COLS, by = ROWS * 0.8660254037844386;
    double x[N], y[N], sx[N], sy[N], re[N], im[N], sre[N], sim[N];
    jittered_lattice(ROWS, COLS, 1.0, 0.1, 0.3, 0.2, 11, x, y);
    for (size_t j = 0; j < N; ++j) {
        x[j] -= bx * floor(x[j] / bx);
        y[j] -= by * floor(y[j] / by);
    }
    /* Shift by a periodic translation and wrap: disks that were in the
     * middle now straddle the seams, and the reverse. */
    for (size_t j = 0; j < N; ++j) {
        sx[j] = x[j] + 6.3;
        sy[j] = y[j] + 5.1;
        sx[j] -= bx * floor(sx[j] / bx);
        sy[j] -= by * floor(sy[j] / by);
    }
    assert_int_equal(ds_psi6_local(N, x, y, bx, by, DS_BOUNDARY_PERIODIC, 1.4, re, im, NULL),
                     DS_OK);
    assert_int_equal(ds_psi6_local(N, sx, sy, bx, by, DS_BOUNDARY_PERIODIC, 1.4, sre, sim, NULL),
                     DS_OK);
    double least = 1.0;
    for (size_t j = 0; j < N; ++j) {
        assert_near(sre[j], re[j], 1e-12);
        assert_near(sim[j], im[j], 1e-12);
        least = fmin(least, hypot(re[j], im[j]));
    }
    /* Every disk kept its six neighbours, the seam disks included. */
    assert_true(least > 0.5);
}

static void test_the_cell_grid_finds_the_same_neighbours_as_all_pairs(void **state)
{
    (void)state;
    enum { N = 400 };
    double x[N], y[N], re[N], im[N], want_re[N], want_im[N];
    ds_rng rng;
    ds_rng_seed(&rng, 5);
    /* Boxes of 1 to 9 cutoffs across: one and two cells per side are the
     * periodic grid's special cases (the cells left and right coincide). */
    const double sides[][2] = {{2.5, 2.5}, {4.1, 2.9}, {9.0, 30.0}, {25.0, 25.0}};
    for (int boundary = 0; boundary < DS_BOUNDARY_COUNT; ++boundary)
        for (size_t b = 0; b < sizeof sides / sizeof sides[0]; ++b) {
            const int px = boundary != DS_BOUNDARY_WALLS, py = boundary == DS_BOUNDARY_PERIODIC;
            const double bx = sides[b][0], by = sides[b][1], cutoff = 1.2;
            const size_t n = bx * by < 50.0 ? 40 : N;
            for (size_t j = 0; j < n; ++j) {
                x[j] = ds_rng_uniform(&rng, 0.0, bx);
                y[j] = ds_rng_uniform(&rng, 0.0, by);
            }
            assert_int_equal(
                ds_psi6_local(n, x, y, bx, by, (ds_boundary)boundary, cutoff, re, im, NULL), DS_OK);
            reference_psi6(n, x, y, bx, by, px, py, cutoff, want_re, want_im);
            for (size_t j = 0; j < n; ++j) {
                /* Powers against cos/sin of atan2: a few roundings each. */
                assert_near(re[j], want_re[j], 1e-12);
                assert_near(im[j], want_im[j], 1e-12);
            }
        }
}

static void test_a_disk_without_neighbours_has_zero_order(void **state)
{
    (void)state;
    double x[3] = {10.0, 10.9, 80.0}, y[3] = {10.0, 10.0, 80.0}, re[3], im[3];
    assert_int_equal(ds_psi6_local(3, x, y, 100.0, 100.0, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_OK);
    assert_true(re[2] == 0.0 && im[2] == 0.0);
    /* A lone pair: one bond, |psi6| = 1 for both, the same phase (the
     * bond seen from either end differs by pi, and 6 pi is a full turn). */
    assert_near(re[0], 1.0, 1e-15);
    assert_near(re[1], 1.0, 1e-15);
}

static void test_a_tiny_cutoff_in_a_huge_box_allocates_a_bounded_grid(void **state)
{
    (void)state;
    /* 10^18 cells of side 1e-9 would be wanted; the grid is capped at a
     * few per disk and still finds the one bond. */
    double x[2] = {1.0, 1.0 + 5e-10}, y[2] = {3.0, 3.0}, re[2], im[2];
    assert_int_equal(ds_psi6_local(2, x, y, 1e9, 1e9, DS_BOUNDARY_WALLS, 1e-9, re, im, NULL),
                     DS_OK);
    assert_near(re[0], 1.0, 1e-6);
    assert_near(re[1], 1.0, 1e-6);
}

static void test_bad_arguments_are_refused(void **state)
{
    (void)state;
    double x[2] = {1.0, 2.0}, y[2] = {1.0, 1.0}, re[2], im[2];
    assert_int_equal(ds_psi6_local(2, NULL, y, 10, 10, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, NULL, 10, 10, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, 10, DS_BOUNDARY_WALLS, 1.4, NULL, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, 10, DS_BOUNDARY_WALLS, 1.4, re, NULL, NULL),
                     DS_ERR_ARG);
    /* No disks: DS_OK, nothing read or written, as the header says. */
    assert_int_equal(ds_psi6_local(0, NULL, NULL, 10, 10, DS_BOUNDARY_WALLS, 1.4, NULL, NULL, NULL),
                     DS_OK);
    assert_int_equal(ds_psi6_local(2, x, y, 0, 10, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, -1, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, INFINITY, 10, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, NAN, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, 10, DS_BOUNDARY_WALLS, 0.0, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, 10, DS_BOUNDARY_WALLS, NAN, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, 10, DS_BOUNDARY_WALLS, INFINITY, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, 10, (ds_boundary)7, 1.4, re, im, NULL), DS_ERR_ARG);
    /* Periodic: the minimum image is unique only below half the shorter side. */
    assert_int_equal(ds_psi6_local(2, x, y, 10, 4, DS_BOUNDARY_PERIODIC, 2.0, re, im, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_psi6_local(2, x, y, 10, 4, DS_BOUNDARY_PERIODIC, 1.99, re, im, NULL),
                     DS_OK);
    /* The same cutoff is fine with walls, where there are no images. */
    assert_int_equal(ds_psi6_local(2, x, y, 10, 4, DS_BOUNDARY_WALLS, 5.0, re, im, NULL), DS_OK);
    x[1] = NAN;
    assert_int_equal(ds_psi6_local(2, x, y, 10, 10, DS_BOUNDARY_WALLS, 1.4, re, im, NULL),
                     DS_ERR_ARG);
    /* No disks: nothing to do, nothing written. */
    assert_int_equal(ds_psi6_local(0, x, y, 10, 10, DS_BOUNDARY_WALLS, 1.4, re, im, NULL), DS_OK);
    double psi6 = 0.0;
    assert_int_equal(ds_sim_get_psi6(NULL, &psi6, NULL), DS_ERR_ARG);
    assert_true(isnan(psi6));
}

static ds_sim *sim_at(size_t n, double eta, ds_placement placement, ds_integrator integrator)
{
    /* eta = N pi R^2 / box^2 in the default 1000 x 1000 box. */
    ds_params p = ds_params_default(n, sqrt(eta * 1e6 / (PI * (double)n)));
    p.placement = placement;
    p.integrator = integrator;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

static void test_a_dense_lattice_is_ordered(void **state)
{
    (void)state;
    /* The target: the lattice at area fraction 0.85 with walls,
     * before and after it has moved a little, with either integrator. */
    for (int e = 0; e < DS_INTEGRATOR_COUNT; ++e) {
        ds_sim *sim = sim_at(4096, 0.85, DS_PLACEMENT_LATTICE, (ds_integrator)e);
        const double start = psi6_of(sim);
        print_message("lattice at 0.85 (%s): psi6 = %.6f\n", ds_integrator_name((ds_integrator)e),
                      start);
        assert_true(start > 0.99);
        /* A short run: the crystal vibrates but keeps its orientation. */
        ds_sim_run(sim, 20, NULL);
        assert_true(psi6_of(sim) > 0.9);
        ds_sim_destroy(sim);
    }
}

static void test_a_periodic_lattice_is_ordered_and_a_tiny_periodic_box_has_no_psi6(void **state)
{
    (void)state;
    ds_params p = ds_params_default(4096, sqrt(0.85 * 1e6 / (PI * 4096.0)));
    p.placement = DS_PLACEMENT_LATTICE;
    p.boundary = DS_BOUNDARY_PERIODIC;
    ds_sim *sim = NULL;
    if (ds_sim_create(&p, NULL, &sim, NULL) == DS_ERR_ARG) {
        print_message("skipped: this build has no periodic boxes\n");
        skip();
    }
    assert_non_null(sim);
    /* The bonds across the seams count: as ordered as with walls. */
    assert_true(psi6_of(sim) > 0.99);
    ds_sim_destroy(sim);
    /* A box 50 wide holds one disk of R = 10, but the cutoff 1.4 d = 28 is
     * more than half of it: no unique nearest image, a refusal that names
     * the box and the least it may be (2 cutoffs), psi6 NaN. */
    p = ds_params_default(1, 10.0);
    p.box = 50.0;
    p.boundary = DS_BOUNDARY_PERIODIC;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    double psi6 = 0.0;
    ds_error err;
    assert_int_equal(ds_sim_get_psi6(sim, &psi6, &err), DS_ERR_ARG);
    assert_true(isnan(psi6));
    assert_string_equal(err.field, "box");
    assert_true(err.value == 50.0 && err.limit == 2.0 * 28.0);
    ds_sim_destroy(sim);
}

static void test_a_dilute_gas_has_no_global_order(void **state)
{
    (void)state;
    const size_t n = 1000;
    ds_sim *sim = sim_at(n, 0.05, DS_PLACEMENT_RANDOM, DS_INTEGRATOR_TIME_STEP);
    const double psi6 = psi6_of(sim);
    print_message("random gas at 0.05: psi6 = %.4f, bound %.4f\n", psi6, 5.0 / sqrt((double)n));
    /* The phases of the disks with a neighbour (about a sixth of them at
     * this density) are uniform on the circle, so the sum of N terms of
     * modulus <= 1 is a random walk: |mean| ~ sqrt(N_bonded) / N, at most
     * a few times 1/sqrt(N) even counting the correlation of a bonded pair
     * (whose two disks share the bond's phase). 5 / sqrt(N) is beyond five
     * standard deviations of the worst case. */
    assert_true(psi6 >= 0.0);
    assert_true(psi6 < 5.0 / sqrt((double)n));
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_six_neighbours_at_sixty_degrees_give_one),
        cmocka_unit_test(test_rotating_the_disks_turns_psi6_by_six_times_the_angle),
        cmocka_unit_test(test_a_square_lattice_has_no_sixfold_order),
        cmocka_unit_test(test_neighbours_across_the_periodic_seam_count_as_interior_ones),
        cmocka_unit_test(test_the_cell_grid_finds_the_same_neighbours_as_all_pairs),
        cmocka_unit_test(test_a_disk_without_neighbours_has_zero_order),
        cmocka_unit_test(test_a_tiny_cutoff_in_a_huge_box_allocates_a_bounded_grid),
        cmocka_unit_test(test_bad_arguments_are_refused),
        cmocka_unit_test(test_a_dense_lattice_is_ordered),
        cmocka_unit_test(test_a_periodic_lattice_is_ordered_and_a_tiny_periodic_box_has_no_psi6),
        cmocka_unit_test(test_a_dilute_gas_has_no_global_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
