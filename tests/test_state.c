/* SPDX-License-Identifier: MIT */
/* A whole state at once: ds_sim_set_disks takes every disk together where disk
 * by disk fails, refuses an overlapping or outside state naming the disks
 * and changing nothing, ends a growth keeping its radii, and the run goes
 * on from the new state. */
#include "test_util.h"

static ds_sim *dense_periodic(ds_integrator integrator)
{
    /* 1024 disks at area fraction 0.70 on a periodic lattice. */
    const size_t n = 1024;
    const double box_y = 1000.0 * sqrt(3.0) / 2.0;
    ds_params p =
        ds_params_default(n, sqrt(0.70 * 1000.0 * box_y / ((double)n * 3.14159265358979323846)));
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.placement = DS_PLACEMENT_LATTICE;
    p.box_y = box_y;
    p.integrator = integrator;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

/* Every disk takes the place of the next one (its velocity too): each
 * new place is held by a disk not yet moved, so ds_sim_set_disk refuses the first
 * move; the state as a whole is as good as the old one. */
static void test_set_all_moves_every_disk_where_one_by_one_fails(void **state)
{
    (void)state;
    ds_sim *sim = dense_periodic(DS_INTEGRATOR_EVENT_DRIVEN);
    ds_sim_run(sim, 20, NULL);
    const size_t n = ds_sim_get_count(sim);
    ds_disk *now = malloc(n * sizeof *now), *next = malloc(n * sizeof *next);
    assert_non_null(now);
    assert_non_null(next);
    assert_int_equal(ds_sim_get_disks(sim, now, NULL), DS_OK);
    for (size_t i = 0; i < n; ++i)
        next[i] = now[(i + 1) % n];
    assert_int_equal(ds_sim_set_disk(sim, 0, next[0], NULL), DS_ERR_OVERLAP);
    ds_error why;
    assert_int_equal(ds_sim_set_disks(sim, next, &why), DS_OK);
    assert_string_equal(why.message, "");
    ds_disk *got = malloc(n * sizeof *got);
    assert_non_null(got);
    assert_int_equal(ds_sim_get_disks(sim, got, NULL), DS_OK);
    for (size_t i = 0; i < n; ++i)
        assert_memory_equal(&got[i], &next[i], sizeof got[i]);
    free(now);
    free(next);
    free(got);
    ds_sim_destroy(sim);
}

/* The new state's disks must not overlap: the pair is named, and the old
 * state stays, to the bit. */
static void check_overlap_refused(ds_integrator integrator)
{
    ds_sim *sim = dense_periodic(integrator);
    ds_sim_run(sim, 5, NULL);
    const size_t n = ds_sim_get_count(sim);
    ds_disk *before = malloc(n * sizeof *before), *bad = malloc(n * sizeof *bad);
    assert_non_null(before);
    assert_non_null(bad);
    assert_int_equal(ds_sim_get_disks(sim, before, NULL), DS_OK);
    memcpy(bad, before, n * sizeof *bad);
    /* Disk 700 onto disk 300, a hair (1e-6 of a diameter) beside it. */
    bad[700] = bad[300];
    bad[700].x =
        fmod(bad[700].x + 2.0 * ds_sim_get_radius(sim) * (1.0 - 1e-6), ds_sim_get_box_width(sim));
    ds_error why;
    assert_int_equal(ds_sim_set_disks(sim, bad, &why), DS_ERR_OVERLAP);
    assert_non_null(strstr(why.message, "disks 300 and 700 overlap"));
    ds_disk *after = malloc(n * sizeof *after);
    assert_non_null(after);
    assert_int_equal(ds_sim_get_disks(sim, after, NULL), DS_OK);
    assert_memory_equal(after, before, n * sizeof *after);
    /* At contact up to DS_CONTACT_TOLERANCE it is no overlap. */
    bad[700].x =
        fmod(bad[300].x + 2.0 * ds_sim_get_radius(sim) * (1.0 - 0.5 * DS_CONTACT_TOLERANCE),
             ds_sim_get_box_width(sim));
    bad[700].y = bad[300].y;
    /* ... unless 700 now overlaps a neighbour of 300; then it names it. */
    ds_status st = ds_sim_set_disks(sim, bad, &why);
    assert_true(st == DS_OK || (st == DS_ERR_OVERLAP && !strstr(why.message, "disks 300 and")));
    free(before);
    free(bad);
    free(after);
    ds_sim_destroy(sim);
}

static void test_set_all_refuses_an_overlap_and_changes_nothing(void **state)
{
    (void)state;
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ)
        check_overlap_refused((ds_integrator)integ);
}

static void test_set_all_refuses_a_disk_outside_the_box_or_not_finite(void **state)
{
    (void)state;
    ds_sim *sim = test_create(50, 5.0, 1, DS_BROADPHASE_AUTO);
    ds_disk d[50];
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    ds_error why;
    ds_disk keep = d[7];
    d[7].x = 2.0; /* closer than R to the wall */
    assert_int_equal(ds_sim_set_disks(sim, d, &why), DS_ERR_ARG);
    assert_non_null(strstr(why.message, "disk 7 at (2,"));
    d[7] = keep;
    d[9].vy = NAN;
    assert_int_equal(ds_sim_set_disks(sim, d, &why), DS_ERR_ARG);
    assert_non_null(strstr(why.message, "disk 9"));
    d[9].vy = 1e13;
    assert_int_equal(ds_sim_set_disks(sim, d, &why), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_disks(NULL, d, &why), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_disks(sim, NULL, NULL), DS_ERR_ARG);
    ds_sim_destroy(sim);
}

/* After ds_sim_set_disks the run goes on from the new state: the clock and step
 * count continue, energy is what the new state has (exactly conserved by
 * the event-driven dynamics to rounding: 1e-12 relative over these few
 * thousand collisions, each exchange exact to a few ulps), and no pair
 * overlaps. */
static void test_the_run_goes_on_from_the_new_state(void **state)
{
    (void)state;
    for (int integrator = 0; integrator < DS_INTEGRATOR_COUNT; ++integrator) {
        ds_sim *sim = dense_periodic((ds_integrator)integrator);
        ds_sim_run(sim, 10, NULL);
        const size_t n = ds_sim_get_count(sim);
        ds_disk *d = malloc(n * sizeof *d);
        assert_non_null(d);
        assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
        /* Reverse every velocity and double it: a different state. */
        for (size_t i = 0; i < n; ++i) {
            d[i].vx *= -2.0;
            d[i].vy *= -2.0;
        }
        assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK);
        const double e0 = ds_sim_get_kinetic_energy(sim), t0 = ds_sim_get_time(sim);
        assert_int_equal(ds_sim_get_steps(sim), 10);
        ds_sim_run(sim, 30, NULL);
        assert_int_equal(ds_sim_get_steps(sim), 40);
        assert_true(ds_sim_get_time(sim) > t0);
        const double e1 = ds_sim_get_kinetic_energy(sim);
        if (integrator == DS_INTEGRATOR_EVENT_DRIVEN)
            assert_true(fabs(e1 - e0) <= 1e-12 * e0);
        else
            assert_true(fabs(e1 - e0) <= 1e-9 * e0); /* equal-mass swaps: exact up to rounding */
        assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
        if (integrator == DS_INTEGRATOR_EVENT_DRIVEN)
            assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK); /* no overlap after the run */
        free(d);
        ds_sim_destroy(sim);
    }
}

/* ds_sim_set_disks ends a growth, as its contract says: the radii stay as grown
 * (to the bit, and for the rest of the run), the state says no growth and
 * no Z, the velocities are the ones given; and a growth that had reached
 * its target is forgotten too. */
static void test_set_all_ends_a_growth_keeping_the_grown_radii(void **state)
{
    (void)state;
    enum { N = 30 };
    for (int reached = 0; reached < 2; ++reached) {
        ds_params p = ds_params_default(N, 5.0);
        p.boundary = DS_BOUNDARY_PERIODIC;
        p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
        p.seed = 3;
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        ds_sim_run(sim, 10, NULL);
        const double eta0 = ds_sim_get_area_fraction(sim);
        if (reached) {
            assert_int_equal(ds_sim_set_growth(sim, 0.5, 0.03, 0.0, NULL), DS_OK);
            for (int k = 0; k < 100000 && ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING; ++k)
                ds_sim_run(sim, 1, NULL);
            assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_REACHED_ETA);
        } else {
            assert_int_equal(ds_sim_set_growth(sim, 0.05, 0.0, 0.0, NULL), DS_OK);
            ds_sim_run(sim, 100000, NULL); /* t = 100: radii 6x, windows of 2 N collisions done */
            assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_GROWING);
            assert_true(ds_sim_get_growth_z(sim) > 0.0);
        }
        const double eta = ds_sim_get_area_fraction(sim);
        assert_true(eta > 2.0 * eta0);
        double grown[N], after[N];
        assert_int_equal(ds_sim_get_radii(sim, grown, NULL), DS_OK);
        ds_disk d[N], got[N];
        assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
        for (size_t i = 0; i < N; ++i) { /* another kinetic energy than growth's */
            d[i].vx *= 0.5;
            d[i].vy *= 0.5;
        }
        assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK);
        assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_NONE);
        assert_true(ds_sim_get_growth_z(sim) == 0.0);
        assert_int_equal(ds_sim_get_disks(sim, got, NULL), DS_OK);
        assert_memory_equal(got, d, sizeof d); /* as given, not scaled */
        for (int k = 0; k < 2; ++k) {
            assert_int_equal(ds_sim_get_radii(sim, after, NULL), DS_OK);
            assert_memory_equal(after, grown, sizeof grown);
            assert_true(ds_sim_get_area_fraction(sim) == eta);
            ds_sim_run(sim, 2000, NULL); /* and they do not grow on */
        }
        assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_NONE);
        ds_sim_destroy(sim);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_set_all_moves_every_disk_where_one_by_one_fails),
        cmocka_unit_test(test_set_all_refuses_an_overlap_and_changes_nothing),
        cmocka_unit_test(test_set_all_refuses_a_disk_outside_the_box_or_not_finite),
        cmocka_unit_test(test_set_all_ends_a_growth_keeping_the_grown_radii),
        cmocka_unit_test(test_the_run_goes_on_from_the_new_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
