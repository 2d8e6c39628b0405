/* SPDX-License-Identifier: MIT */
/* Collision response: walls and pairs, against hand-computed results, and
 * the two traps of the exercise's literal rules. */
#include "test_util.h"

#include "core/core.h"

static const double R = 5.0, DT = 0.001;

/* Puts disk i at an exact state, bypassing ds_sim_set_disk's inside-the-band check
 * so a test can start a disk in the wall band. */
static void put(ds_sim *sim, size_t i, double x, double y, double vx, double vy)
{
    size_t k = sim->disks.slot[i];
    sim->disks.x[k] = x;
    sim->disks.y[k] = y;
    sim->disks.vx[k] = vx;
    sim->disks.vy[k] = vy;
}

/* A simulation of n disks whose positions the test then sets: the disks
 * not used by the test are parked far apart in the box's lower row. */
static ds_sim *make(size_t n)
{
    ds_sim *sim = test_create(n, R, 1, DS_BROADPHASE_SAP);
    for (size_t i = 0; i < n; ++i)
        put(sim, i, 100.0 + 30.0 * (double)i, 100.0, 0.0, 0.0);
    return sim;
}

static void test_disk_crossing_left_wall_reverses_vx_only(void **state)
{
    (void)state;
    ds_sim *sim = make(1);
    put(sim, 0, R + 0.05, 500.0, -100.0, 30.0);
    ds_sim_step(sim, NULL); /* moves to x = R - 0.05: outside, moving out */
    ds_disk d = ds_sim_get_disk(sim, 0);
    assert_true(d.vx == 100.0);
    assert_true(d.vy == 30.0);
    assert_true(fabs(d.x - (R - 0.05)) < 1e-12); /* position not changed */
    assert_int_equal(ds_sim_get_wall_count(sim), 1);
    assert_true(ds_sim_get_wall_impulse(sim) == 200.0);
    ds_sim_destroy(sim);
}

static void test_disk_crossing_top_wall_reverses_vy_only(void **state)
{
    (void)state;
    ds_sim *sim = make(1);
    put(sim, 0, 500.0, 1000.0 - R - 0.05, 10.0, 100.0);
    ds_sim_step(sim, NULL);
    ds_disk d = ds_sim_get_disk(sim, 0);
    assert_true(d.vx == 10.0);
    assert_true(d.vy == -100.0);
    ds_sim_destroy(sim);
}

static void test_disk_outside_but_returning_is_not_inverted_again(void **state)
{
    (void)state;
    /* Outside the band but already moving back in (as right after a
     * reflection, or after a collision slowed it): it must keep going in. */
    ds_sim *sim = make(1);
    put(sim, 0, R - 0.09, 500.0, 10.0, 0.0);
    for (int s = 0; s < 20; ++s) {
        ds_sim_step(sim, NULL);
        assert_true(ds_sim_get_disk(sim, 0).vx == 10.0);
    }
    assert_true(ds_sim_get_disk(sim, 0).x > R);
    assert_int_equal(ds_sim_get_wall_count(sim), 0);
    ds_sim_destroy(sim);
}

/* The exercise's literal wall rule: invert whenever outside [R, 1000-R]. */
static void literal_wall_step(double *x, double *vx)
{
    *x += *vx * DT;
    if (*x < R || *x > 1000.0 - R)
        *vx = -*vx;
}

static void test_literal_wall_rule_traps_a_slow_disk_in_the_wall(void **state)
{
    (void)state;
    /* Same start as above: with the literal rule the disk flips every step
     * and never gets back inside; with ours it is inside after 10 steps. */
    double x = R - 0.09, vx = 10.0;
    for (int s = 0; s < 1000; ++s)
        literal_wall_step(&x, &vx);
    assert_true(x < R); /* trapped */

    ds_sim *sim = make(1);
    put(sim, 0, R - 0.09, 500.0, 10.0, 0.0);
    ds_sim_run(sim, 1000, NULL);
    assert_true(ds_sim_get_disk(sim, 0).x > R); /* free */
    ds_sim_destroy(sim);
}

static void test_head_on_collision_swaps_velocities(void **state)
{
    (void)state;
    ds_sim *sim = make(2);
    /* 10.08 apart; one step later 9.88 apart and approaching. */
    put(sim, 0, 494.96, 500.0, 100.0, 0.0);
    put(sim, 1, 505.04, 500.0, -100.0, 0.0);
    ds_sim_step(sim, NULL);
    ds_disk a = ds_sim_get_disk(sim, 0), b = ds_sim_get_disk(sim, 1);
    assert_true(a.vx == -100.0 && a.vy == 0.0);
    assert_true(b.vx == 100.0 && b.vy == 0.0);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    ds_sim_destroy(sim);
}

static void test_oblique_collision_swaps_only_normal_components(void **state)
{
    (void)state;
    /* After the move A is at (500,500) moving (100,0) and B, at rest, at
     * (507,507): the line of centres is 45 degrees. A's normal component
     * (50,50) goes to B; A keeps its tangential part (50,-50). */
    ds_sim *sim = make(2);
    put(sim, 0, 499.9, 500.0, 100.0, 0.0);
    put(sim, 1, 507.0, 507.0, 0.0, 0.0);
    ds_sim_step(sim, NULL);
    ds_disk a = ds_sim_get_disk(sim, 0), b = ds_sim_get_disk(sim, 1);
    const double eps = 1e-12 * 100.0; /* a few ulps of the speeds */
    assert_true(fabs(a.vx - 50.0) < eps && fabs(a.vy + 50.0) < eps);
    assert_true(fabs(b.vx - 50.0) < eps && fabs(b.vy - 50.0) < eps);
    ds_sim_destroy(sim);
}

static void test_collision_conserves_energy_and_momentum(void **state)
{
    (void)state;
    ds_sim *sim = make(2);
    put(sim, 0, 500.0, 500.0, 73.0, -21.0);
    put(sim, 1, 508.0, 503.0, -40.0, 55.0);
    double e0 = ds_sim_get_kinetic_energy(sim), px0, py0, px1, py1;
    ds_sim_get_momentum(sim, &px0, &py0);
    ds_sim_step(sim, NULL);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    ds_sim_get_momentum(sim, &px1, &py1);
    /* Rounding only: a few ulps of the magnitudes involved. */
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) - e0) < 1e-12 * e0);
    assert_true(fabs(px1 - px0) < 1e-12 && fabs(py1 - py0) < 1e-12);
    ds_sim_destroy(sim);
}

static void test_separating_overlapped_pair_is_left_alone(void **state)
{
    (void)state;
    ds_sim *sim = make(2);
    put(sim, 0, 500.0, 500.0, -100.0, 10.0);
    put(sim, 1, 508.0, 500.0, 100.0, 10.0);
    ds_sim_step(sim, NULL);
    ds_disk a = ds_sim_get_disk(sim, 0), b = ds_sim_get_disk(sim, 1);
    assert_true(a.vx == -100.0 && a.vy == 10.0);
    assert_true(b.vx == 100.0 && b.vy == 10.0);
    assert_int_equal(ds_sim_get_collision_count(sim), 0);
    ds_sim_destroy(sim);
}

/* The exercise's literal pair rule: swap whenever the centres are closer
 * than 2R, approaching or not (1D version, along x). */
static void literal_pair_step(double x[2], double v[2])
{
    x[0] += v[0] * DT;
    x[1] += v[1] * DT;
    if (fabs(x[1] - x[0]) < 2.0 * R) {
        double t = v[0];
        v[0] = v[1];
        v[1] = t;
    }
}

static void test_literal_pair_rule_glues_disks_and_ours_does_not(void **state)
{
    (void)state;
    /* A deep overlap with a slow approach: after one swap the pair is
     * still overlapping; the literal rule swaps it back, forever. */
    double x[2] = {500.0, 509.5}, v[2] = {10.0, -10.0};
    for (int s = 0; s < 1000; ++s)
        literal_pair_step(x, v);
    assert_true(x[1] - x[0] < 2.0 * R); /* glued */

    ds_sim *sim = make(2);
    put(sim, 0, 500.0, 500.0, 10.0, 0.0);
    put(sim, 1, 509.5, 500.0, -10.0, 0.0);
    ds_sim_run(sim, 1000, NULL);
    ds_disk a = ds_sim_get_disk(sim, 0), b = ds_sim_get_disk(sim, 1);
    assert_true(b.x - a.x >= 2.0 * R); /* separated */
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_disk_crossing_left_wall_reverses_vx_only),
        cmocka_unit_test(test_disk_crossing_top_wall_reverses_vy_only),
        cmocka_unit_test(test_disk_outside_but_returning_is_not_inverted_again),
        cmocka_unit_test(test_literal_wall_rule_traps_a_slow_disk_in_the_wall),
        cmocka_unit_test(test_head_on_collision_swaps_velocities),
        cmocka_unit_test(test_oblique_collision_swaps_only_normal_components),
        cmocka_unit_test(test_collision_conserves_energy_and_momentum),
        cmocka_unit_test(test_separating_overlapped_pair_is_left_alone),
        cmocka_unit_test(test_literal_pair_rule_glues_disks_and_ours_does_not),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
