/* SPDX-License-Identifier: MIT */
/* The canonical pressure at any N (docs/physics.md, "The canonical
 * pressure at any N"), held by two exact results:
 *
 * - Two disks in a periodic box: the configurational integral is A (A -
 *   pi sigma^2) (the centre of mass anywhere, the separation anywhere but
 *   inside the contact circle, sigma = 2R < half the side), so beta P =
 *   1/A + 1/(A - pi sigma^2) and the canonical Z = beta P A / 2 = (1 + A /
 *   (A - pi sigma^2)) / 2. The relative motion is a Sinai billiard, which
 *   is ergodic, so the event-driven run's ds_sim_get_compressibility_factor converges to
 *   it; P A / K, with kT = K / N, does not.
 * - The collision rate against the pressure: both come from the contact
 *   value g(sigma), the rate through the mean normal relative speed and
 *   the virial through its mean square, so Z - 1 = (nu sigma / 4) sqrt(pi
 *   m / kT) c_D, nu the collisions per disk per unit time, where c_D = 1
 *   for Maxwell's velocities and, at finite N, corrects for the velocities
 *   lying on a sphere of D = 2 (N - 1) dimensions (see rate_factor). */
#include "test_util.h"

#define PI 3.14159265358979323846

static void two_disks_give_the_exact_canonical_z(double radius)
{
    const double box = 10.0, sigma = 2.0 * radius, area = box * box;
    const double exact = 0.5 * (1.0 + area / (area - PI * sigma * sigma));
    ds_params p = ds_params_default(2, radius);
    p.box = box;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.speed = 1.0;
    p.dt = 0.1;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    /* A total momentum that is not 0, so kT = K_int / (N - 1) differs from
     * K / N for a reason other than N alone. */
    const ds_disk start[2] = {{2.0, 5.0, 1.3, 0.4}, {8.0, 5.0, -0.5, -0.3}};
    ds_error err;
    assert_int_equal(ds_sim_set_disks(sim, start, &err), DS_OK);
    /* Blocks of 2000 time units, ~600 (R = 2) and ~180 (R = 1) collisions
     * each (mean free path of the relative motion pi (A - pi sigma^2) /
     * (2 pi sigma), relative speed 1.93): the blocks are far longer than the billiard's memory,
     * so their means are independent, and the standard error of their mean
     * is honest; the horizon is infinite (corridors between the images),
     * whose long free flights the long blocks average over. */
    /* The whole test takes well under a second, so DS_TEST_QUICK (the
     * valgrind run) runs it in full. */
    enum { BLOCKS = 40 };
    const int blocks = BLOCKS;
    double z[BLOCKS], naive[BLOCKS];
    ds_sim_run(sim, 2000, NULL);
    for (int b = 0; b < blocks; ++b) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, 20000, NULL);
        z[b] = ds_sim_get_compressibility_factor(sim);
        naive[b] = ds_sim_get_virial_pressure(sim) * area / ds_sim_get_kinetic_energy(sim);
    }
    const block_stats s = stats_of(z, blocks), wrong = stats_of(naive, blocks);
    if (getenv("DS_TEST_VERBOSE"))
        printf("two disks, R = %g: Z = %.5f +- %.5f (exact %.5f), P A / K = %.5f +- %.5f\n", radius,
               s.mean, s.error, exact, wrong.mean, wrong.error);
    /* 5 standard errors: a correct run fails with probability 6e-7; the
     * error itself must be small enough to mean something. */
    assert_true(s.error < 0.02 * (exact - 1.0));
    if (fabs(s.mean - exact) > 5.0 * s.error)
        fail_msg("two disks, R = %g: Z = %.5f +- %.5f, exact %.5f", radius, s.mean, s.error, exact);
    /* P A / K takes the virial part over K instead of N kT = 2 K_int:
     * here K = 1.095 and K_int = K - P^2 / 4 = 0.9325, so its Z - 1 comes
     * out 2 K_int / K = 1.70 times the canonical one, far off. */
    assert_true(fabs(wrong.mean - exact) > 20.0 * wrong.error);
    ds_sim_destroy(sim);
}

static void test_two_disks_exact_z(void **state)
{
    (void)state;
    two_disks_give_the_exact_canonical_z(2.0); /* pi sigma^2 / A = 0.50: Z = 1.506 */
    two_disks_give_the_exact_canonical_z(1.0); /* 0.13: Z = 1.072 */
}

/* The ratio of the mean |u| of one component u of a vector uniform on the
 * sphere in D dimensions to Maxwell's at the same mean square: <|u|> =
 * Gamma(D/2) / (sqrt(pi) Gamma((D + 1)/2)) on the unit sphere, <u^2> =
 * 1/D, and Maxwell's <|u|> / sqrt(<u^2>) = sqrt(2 / pi). A pair's normal
 * relative velocity is such a component (in mass-weighted coordinates the
 * velocities are uniform on a sphere in the 2 (N - 1) dimensions the
 * conserved momentum leaves), and the virial takes its mean square, the
 * collision rate its mean modulus: Z - 1 = (nu sigma / 4) sqrt(pi m / kT)
 * / ratio. It is 1 + 1 / (4 D) + O(1 / D^2). */
static double sphere_over_maxwell(double dims)
{
    const double mean_abs = exp(lgamma(dims / 2) - lgamma((dims + 1) / 2)) / sqrt(PI);
    return mean_abs * sqrt(dims) / sqrt(2.0 / PI);
}

static void collision_rate_gives_the_pressure(double eta)
{
    const size_t n = 256;
    const double height = 1000.0 * sqrt(3.0) / 2.0;
    const double radius = sqrt(eta * 1000.0 * height / ((double)n * PI)), sigma = 2.0 * radius;
    ds_params p = ds_params_default(n, radius);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.placement = DS_PLACEMENT_LATTICE;
    p.box_y = height;
    p.seed = 7;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_sim_run(sim, 5000, NULL); /* 5 time units, ~20 collisions per disk: the lattice melts */
    enum { BLOCKS = 100 };
    const int blocks = BLOCKS;
    const uint64_t steps = 5000;
    const double kt = ds_sim_get_temperature(sim),
                 ratio = sphere_over_maxwell(2.0 * (double)(n - 1));
    double r[BLOCKS];
    for (int b = 0; b < blocks; ++b) {
        const uint64_t before = ds_sim_get_collision_count(sim);
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, steps, NULL);
        const double nu = 2.0 * (double)(ds_sim_get_collision_count(sim) - before) /
                          ((double)n * (double)steps * ds_sim_get_dt(sim));
        /* The measured Z - 1 over what the rate predicts: 1 in expectation */
        r[b] = (ds_sim_get_compressibility_factor(sim) - 1.0) /
               (nu * sigma / 4.0 * sqrt(PI / kt) / ratio);
    }
    /* The temperature is the run's own: energy and momentum are conserved
     * to rounding, so kT of the last block is kT of the first. */
    assert_true(fabs(ds_sim_get_temperature(sim) - kt) < 1e-9 * kt);
    const block_stats s = stats_of(r, blocks);
    if (getenv("DS_TEST_VERBOSE"))
        printf("eta %g: (Z - 1) over the rate's prediction %.5f +- %.5f (sphere factor %.6f)\n",
               eta, s.mean, s.error, ratio);
    /* 100 blocks of 5 time units (seeds 7, 8, 9 gave 0.9976 +- 0.0011,
     * 1.0000 +- 0.0013, 0.9994 +- 0.0012 at eta 0.2 and 1.0003, 1.0000,
     * 0.9985 +- 0.0008 at 0.5), each holding thousands of
     * collisions, far longer than the pressure's correlation time
     * (collision times), so the 5-standard-error bound is honest (a good
     * run fails with probability 6e-7); the error must be small enough
     * to tell the identity from a 2% miss. */
    assert_true(s.error < 0.004);
    if (fabs(s.mean - 1.0) > 5.0 * s.error)
        fail_msg("eta %g: (Z - 1) over the rate's prediction = %.5f +- %.5f", eta, s.mean, s.error);
    ds_sim_destroy(sim);
}

static void test_collision_rate_vs_pressure(void **state)
{
    (void)state;
    collision_rate_gives_the_pressure(0.2);
    collision_rate_gives_the_pressure(0.5);
}

static void test_the_sphere_factor(void **state)
{
    (void)state;
    /* D = 3: a component of a uniform unit vector is uniform on [-1, 1],
     * <|u|> = 1/2, <u^2> = 1/3: ratio (1/2) sqrt 3 / sqrt(2/pi). */
    assert_true(fabs(sphere_over_maxwell(3.0) - 0.5 * sqrt(3.0) / sqrt(2.0 / PI)) < 1e-12);
    /* Large D: 1 + 1 / (4 D) to O(1 / D^2). */
    assert_true(fabs(sphere_over_maxwell(510.0) - (1.0 + 1.0 / 2040.0)) < 1e-5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_the_sphere_factor),
        cmocka_unit_test(test_two_disks_exact_z),
        cmocka_unit_test(test_collision_rate_vs_pressure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
