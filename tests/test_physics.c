/* SPDX-License-Identifier: MIT */
/* The physics a user checks statistical mechanics against: what is
 * conserved, what changes only at the walls, relaxation to the 2D
 * Maxwell-Boltzmann (Rayleigh) speed law, the ideal-gas pressure, and that
 * the fixed time step never lets disks stick or leak.
 *
 * Every tolerance below is derived in a comment (rounding bounds or
 * counting statistics), never fitted to a run. The runs are seeded, so each
 * test is deterministic; a statistical test is set so that a fresh seed
 * would fail it with a stated, tiny probability.
 *
 * DS_TEST_QUICK=1 (for the valgrind run in CI) shortens the long runs; the
 * tolerances that depend on run length are recomputed from the shorter run,
 * so the quick tests are weaker but still honest. */
#include "test_util.h"

#include "core/core.h"

static double max_speed(const ds_sim *sim)
{
    double m2 = 0.0;
    for (size_t k = 0; k < sim->world.n; ++k) {
        double v2 = sim->disks.vx[k] * sim->disks.vx[k] + sim->disks.vy[k] * sim->disks.vy[k];
        if (v2 > m2)
            m2 = v2;
    }
    return sqrt(m2);
}

static double mean_square_speed(const ds_sim *sim)
{
    return 2.0 * ds_sim_get_kinetic_energy(sim) / (double)sim->world.n;
}

/* ------------------------------------------------------------------ */
/* Observables on hand-made states                                      */
/* ------------------------------------------------------------------ */

static void test_observables_of_a_hand_placed_state_are_exact(void **state)
{
    (void)state;
    ds_sim *sim = test_create(2, 5.0, 1, DS_BROADPHASE_SAP);
    ds_disk a = {100.0, 100.0, 3.0, 4.0}, b = {500.0, 500.0, -1.0, 2.0};
    assert_int_equal(ds_sim_set_disk(sim, 0, a, NULL), DS_OK);
    assert_int_equal(ds_sim_set_disk(sim, 1, b, NULL), DS_OK);
    double px, py;
    ds_sim_get_momentum(sim, &px, &py);
    /* Small integers: every sum is exact in binary floating point. */
    assert_true(ds_sim_get_kinetic_energy(sim) == 0.5 * (25.0 + 5.0));
    assert_true(px == 2.0 && py == 6.0);
    assert_true(ds_sim_get_pressure(sim) == 0.0); /* no time has passed: defined as 0 */
    ds_sim_destroy(sim);
}

static void test_one_disk_bouncing_gives_the_ideal_gas_pressure_less_the_step_bias(void **state)
{
    (void)state;
    /* One disk flying along x, with dt = 1/1024 and v = 64 so that every
     * position is a multiple of 1/16 and exact. Centres reach [4, 996], a
     * span L = 992. The ideal gas of one disk has P = v^2 / 2 / L^2: one hit
     * of 2v per crossing time L/v over a perimeter 4L. Here the reflection
     * comes when x has passed the wall line, one step (1/16) beyond it, and
     * the disk needs another step to get back: each crossing takes 2 steps
     * longer than L/v = 15872 steps, so the measured pressure is exactly
     * 15872/15874 of the ideal value: the fixed-step bias, v dt / L. */
    const double r = 4.0, v = 64.0, span = 992.0;
    ds_params p = ds_params_default(1, r);
    p.dt = 1.0 / 1024.0;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_disk d = {500.0, 500.0, v, 0.0};
    assert_int_equal(ds_sim_set_disk(sim, 0, d, NULL), DS_OK);
    ds_sim_run(sim, 7937, NULL); /* to x = 996 + 1/16: the first reflection */
    assert_int_equal(ds_sim_get_wall_count(sim), 1);
    ds_sim_reset_observables(sim);
    ds_sim_run(sim, 20 * 15874, NULL); /* ten round trips */
    assert_int_equal(ds_sim_get_wall_count(sim), 20);
    assert_true(ds_sim_get_wall_impulse(sim) == 20 * 2.0 * v);
    const double ideal = v * v / 2.0 / (span * span);
    assert_true(fabs(ds_sim_get_pressure(sim) / ideal - 15872.0 / 15874.0) < 1e-12);
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* Conservation                                                        */
/* ------------------------------------------------------------------ */

static void test_kinetic_energy_is_conserved_over_50000_steps(void **state)
{
    (void)state;
    /* Walls flip a sign (exact). A pair exchanges the normal components:
     * exact in real arithmetic, a few roundings of the pair's energy in
     * floating point, ~1e-16 relative to the pair, so ~1e-16 / N relative to
     * the total. Even adding every collision's error in the same direction,
     * 10^4..10^5 collisions give < 1e-11, and the sum over N disks in
     * ds_sim_get_kinetic_energy adds N eps ~ 1e-13: 1e-9 has a margin of 100. */
    ds_sim *sim = test_create(400, 5.0, 7, DS_BROADPHASE_AUTO);
    const double e0 = ds_sim_get_kinetic_energy(sim);
    ds_sim_run(sim, long_run(50000), NULL);
    assert_true(ds_sim_get_collision_count(sim) > 1000); /* the gas did collide */
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) - e0) <= 1e-9 * e0);
    ds_sim_destroy(sim);
}

static void test_momentum_is_conserved_when_the_walls_are_out_of_reach(void **state)
{
    (void)state;
    /* 400 disks in a 20 x 20 lattice (spacing 12 = 2R + 2) in the middle of
     * a box 1e5 wide, random directions at speed 100: they collide at once
     * and the cloud spreads. No disk can be faster than sqrt(2E) = 2000
     * (all the energy in one disk), so in 5 s none travels more than 1e4,
     * far from the walls 5e4 away: no wall can be involved. */
    const size_t side = 20, n = side * side;
    ds_params p = ds_params_default(n, 5.0);
    p.box = 1e5;
    p.seed = 3;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_rng rng;
    ds_rng_seed(&rng, 11);
    for (size_t i = 0; i < n; ++i) {
        double a = ds_rng_uniform(&rng, 0.0, DS_TWO_PI);
        ds_disk d = {5e4 + 12.0 * (double)(i % side), 5e4 + 12.0 * (double)(i / side),
                     100.0 * cos(a), 100.0 * sin(a)};
        assert_int_equal(ds_sim_set_disk(sim, i, d, NULL), DS_OK);
    }
    double px0, py0, px, py;
    ds_sim_get_momentum(sim, &px0, &py0);
    const double vmax = sqrt(2.0 * ds_sim_get_kinetic_energy(sim));
    ds_sim_run(sim, long_run(5000), NULL);
    ds_sim_get_momentum(sim, &px, &py);
    assert_int_equal(ds_sim_get_wall_count(sim), 0);
    assert_true(ds_sim_get_collision_count(sim) > 100);
    const double bound = momentum_rounding_bound(ds_sim_get_collision_count(sim), vmax, n);
    assert_true(fabs(px - px0) <= bound);
    assert_true(fabs(py - py0) <= bound);
    ds_sim_destroy(sim);
}

static void test_momentum_changes_only_on_steps_with_wall_reflections(void **state)
{
    (void)state;
    /* In the ordinary box, step by step: a step without a wall reflection
     * keeps the momentum within the rounding bound above, and the walls do
     * change it (by 2|v_n| each, so by far more than rounding). */
    ds_sim *sim = test_create(400, 5.0, 5, DS_BROADPHASE_AUTO);
    const double vmax = sqrt(2.0 * ds_sim_get_kinetic_energy(sim));
    uint64_t quiet_steps_with_collisions = 0, wall_steps = 0;
    double px0, py0;
    ds_sim_get_momentum(sim, &px0, &py0);
    for (int s = 0; s < (int)long_run(5000); ++s) {
        uint64_t walls = ds_sim_get_wall_count(sim), pairs = ds_sim_get_collision_count(sim);
        ds_sim_step(sim, NULL);
        double px, py;
        ds_sim_get_momentum(sim, &px, &py);
        double change = fabs(px - px0) + fabs(py - py0);
        if (ds_sim_get_wall_count(sim) == walls) {
            uint64_t collided = ds_sim_get_collision_count(sim) - pairs;
            quiet_steps_with_collisions += collided > 0;
            assert_true(change <= momentum_rounding_bound(collided, vmax, 400));
        } else {
            ++wall_steps;
        }
        px0 = px;
        py0 = py;
    }
    /* Both kinds of step happened, so both branches were exercised. */
    assert_true(quiet_steps_with_collisions > 10);
    assert_true(wall_steps > 10);
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* Relaxation to Maxwell-Boltzmann                                      */
/* ------------------------------------------------------------------ */

static void test_speeds_start_equal_and_fail_the_rayleigh_ks_test(void **state)
{
    (void)state;
    /* Every speed is 100 = sqrt(<v^2>): the empirical CDF jumps from 0 to 1
     * where Rayleigh is 1 - 1/e, so D = 1 - 1/e = 0.632 exactly. */
    ds_sim *sim = test_create(2000, 3.0, 2, DS_BROADPHASE_AUTO);
    double d = ks_distance_to_rayleigh(sim);
    assert_true(fabs(d - (1.0 - exp(-1.0))) < 1e-9);
    assert_true(d > ks_critical_1_percent(2000));
    ds_sim_destroy(sim);
}

static void test_speeds_relax_to_rayleigh_within_20_time_units(void **state)
{
    (void)state;
    /* N = 2000, R = 3: two disks meet when their centres pass within 2R,
     * a target 4R wide, so the mean free path is 1 / (sqrt2 n 4R) ~ 29 at
     * mean speed ~ 89: ~3.4 collisions per disk per time unit (the run
     * counts 3.3), ~60 by t = 20, many times the few a speed needs to
     * forget its start. Quick mode keeps the area fraction and the 20 time
     * units with 500 disks of R = 6 (mean free path 59, still ~30). */
    const size_t n = quick_mode() ? 500 : 2000;
    const double r = quick_mode() ? 6.0 : 3.0;
    ds_sim *sim = test_create(n, r, 2, DS_BROADPHASE_AUTO);
    ds_sim_run(sim, 20000, NULL);
    double d = ks_distance_to_rayleigh(sim);
    assert_true(d < ks_critical_1_percent(n));
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* Pressure                                                            */
/* ------------------------------------------------------------------ */

/* Measured pressure over the ideal-gas value N <v^2> / 2 / A, A = (box-2R)^2,
 * after `relax` steps and over `measure` steps; *hits gets the wall hits. */
static double pressure_over_ideal(size_t n, double r, uint64_t relax, uint64_t measure,
                                  uint64_t *hits)
{
    ds_sim *sim = test_create(n, r, 9, DS_BROADPHASE_AUTO);
    ds_sim_run(sim, relax, NULL);
    ds_sim_reset_observables(sim);
    ds_sim_run(sim, measure, NULL);
    double span = ds_sim_get_box_width(sim) - 2.0 * r;
    double ideal = (double)n * mean_square_speed(sim) / 2.0 / (span * span);
    double ratio = ds_sim_get_pressure(sim) / ideal;
    *hits = ds_sim_get_wall_count(sim);
    ds_sim_destroy(sim);
    return ratio;
}

/* Relative standard deviation of a pressure built from `hits` wall hits,
 * treating hits as a Poisson process: the impulse 2 v_n of one hit has the
 * flux-weighted law v_n exp(-v_n^2 / 2 s^2), whose relative variance is
 * 4/pi - 1, so a compound Poisson sum has relative variance (4/pi) / hits.
 * This overestimates the real scatter: a disk's bounces between opposite
 * walls are regular, not Poisson, and their impulse adds up to its v^2,
 * which total energy fixes. */
static double pressure_relative_sigma(uint64_t hits)
{
    return sqrt(8.0 / DS_TWO_PI / (double)hits);
}

static void test_dilute_gas_pressure_matches_the_ideal_gas_law(void **state)
{
    (void)state;
    /* N = 200, R = 1: area fraction 6e-4, second virial correction 2 eta
     * ~ 1e-3. A late reflection lengthens each crossing by ~v dt, 1e-4 of
     * the 998-unit span. Both are far below the statistical tolerance, 4
     * sigma of the hit count (a fresh seed fails with probability < 1e-4). */
    uint64_t hits = 0;
    double ratio = pressure_over_ideal(200, 1.0, 20000, long_run(500000), &hits);
    double tol = 4.0 * pressure_relative_sigma(hits);
    assert_true(hits > 1000);
    assert_true(fabs(ratio - 1.0) < tol);
}

static void test_dense_gas_pressure_is_above_the_ideal_gas_law(void **state)
{
    (void)state;
    /* 1000 disks of R = 8, area fraction eta = 0.20: the excluded area
     * raises P A / N kT to ~ (1 + eta^2/8) / (1 - eta)^2 = 1.57 (Henderson's
     * equation of state), and at least by the second virial term 2 eta =
     * 0.40. Assert the excess is more than 4 sigma of its own statistics,
     * and that it follows Henderson within 4 sigma plus 1% for the model:
     * Henderson's own error is < 0.5% at this density, and the step bias
     * (pairs collide ~0.06 inside 2R, see README) lowers P by ~0.4%. */
    const double r = 8.0, eta = 1000.0 * (DS_TWO_PI / 2.0) * r * r / 1e6;
    const double henderson = (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
    uint64_t hits = 0;
    double ratio = pressure_over_ideal(1000, r, 10000, long_run(20000), &hits);
    double sigma = pressure_relative_sigma(hits);
    assert_true(ratio - 1.0 > 4.0 * sigma);
    assert_true(fabs(ratio / henderson - 1.0) < 4.0 * sigma + 0.01);
}

/* ------------------------------------------------------------------ */
/* The fixed time step never lets disks stick or leak                   */
/* ------------------------------------------------------------------ */

static void test_no_disks_stick_or_leak_over_50000_steps(void **state)
{
    (void)state;
    /* A pair is resolved the first step its centres are closer than 2R, and
     * before that step they were apart, so they overlap by at most their
     * closing speed times dt <= 2 vmax dt; once resolved they separate. A
     * wall is crossed by at most |v| dt before the reflection. vmax is the
     * largest speed seen during the run (checked after every step). */
    const double r = 5.0, dt = 0.001, box = 1000.0;
    ds_sim *sim = test_create(400, r, 13, DS_BROADPHASE_AUTO);
    double vmax = max_speed(sim), worst_overlap = 0.0, worst_leak = 0.0;
    const uint64_t steps = long_run(50000);
    for (uint64_t s = 1; s <= steps; ++s) {
        ds_sim_step(sim, NULL);
        double v = max_speed(sim);
        if (v > vmax)
            vmax = v;
        for (size_t k = 0; k < sim->world.n; ++k) {
            double out = fmax(fmax(r - sim->disks.x[k], sim->disks.x[k] - (box - r)),
                              fmax(r - sim->disks.y[k], sim->disks.y[k] - (box - r)));
            worst_leak = fmax(worst_leak, out);
        }
        /* All pairs every 100 steps and at the end: O(N^2) is the point
         * (no broad phase to trust), so not every step. */
        if (s % 100 == 0 || s == steps)
            for (size_t a = 0; a < sim->world.n; ++a)
                for (size_t b = a + 1; b < sim->world.n; ++b) {
                    double dx = sim->disks.x[b] - sim->disks.x[a],
                           dy = sim->disks.y[b] - sim->disks.y[a];
                    worst_overlap = fmax(worst_overlap, 2.0 * r - sqrt(dx * dx + dy * dy));
                }
    }
    assert_true(worst_overlap <= 2.0 * vmax * dt);
    assert_true(worst_leak <= vmax * dt);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_observables_of_a_hand_placed_state_are_exact),
        cmocka_unit_test(test_one_disk_bouncing_gives_the_ideal_gas_pressure_less_the_step_bias),
        cmocka_unit_test(test_kinetic_energy_is_conserved_over_50000_steps),
        cmocka_unit_test(test_momentum_is_conserved_when_the_walls_are_out_of_reach),
        cmocka_unit_test(test_momentum_changes_only_on_steps_with_wall_reflections),
        cmocka_unit_test(test_speeds_start_equal_and_fail_the_rayleigh_ks_test),
        cmocka_unit_test(test_speeds_relax_to_rayleigh_within_20_time_units),
        cmocka_unit_test(test_dilute_gas_pressure_matches_the_ideal_gas_law),
        cmocka_unit_test(test_dense_gas_pressure_is_above_the_ideal_gas_law),
        cmocka_unit_test(test_no_disks_stick_or_leak_over_50000_steps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
