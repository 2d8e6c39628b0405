/* SPDX-License-Identifier: MIT */
/* The public API contract: defaults, generation order, ds_sim_set_disk, time,
 * independence of simulations, NULL safety. */
#include "test_util.h"

static void test_default_params_are_the_exercise(void **state)
{
    (void)state;
    ds_params p = ds_params_default(400, 5.0);
    assert_int_equal(p.n, 400);
    assert_true(p.radius == 5.0);
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_true(ds_sim_get_box_width(sim) == 1000.0);
    assert_true(ds_sim_get_dt(sim) == 0.001);
    assert_true(ds_sim_get_radius(sim) == 5.0);
    assert_int_equal(ds_sim_get_count(sim), 400);
    assert_true(ds_sim_get_broadphase(sim) != DS_BROADPHASE_AUTO);
    assert_true(ds_sim_get_time(sim) == 0.0);
    ds_sim_destroy(sim);
}

static void test_time_is_steps_times_dt(void **state)
{
    (void)state;
    ds_sim *sim = test_create(10, 5.0, 1, DS_BROADPHASE_AUTO);
    ds_sim_run(sim, 12345, NULL);
    ds_sim_step(sim, NULL);
    assert_int_equal(ds_sim_get_steps(sim), 12346);
    assert_true(ds_sim_get_time(sim) == 12346 * 0.001);
    ds_sim_run(sim, 0, NULL); /* no-op */
    assert_int_equal(ds_sim_get_steps(sim), 12346);
    ds_sim_destroy(sim);
}

static void test_get_follows_each_disk_through_the_sort(void **state)
{
    (void)state;
    /* Free flight between collisions: where no collision happened, each
     * disk must be exactly where its own velocity took it, whatever order
     * the broad phase put the arrays in. Dilute gas, one step at a time. */
    const size_t n = 200;
    ds_sim *sim = test_create(n, 1.0, 4, DS_BROADPHASE_SAP);
    ds_disk before[200];
    for (int s = 0; s < 200; ++s) {
        for (size_t i = 0; i < n; ++i)
            before[i] = ds_sim_get_disk(sim, i);
        uint64_t walls = ds_sim_get_wall_count(sim), hits = ds_sim_get_collision_count(sim);
        ds_sim_step(sim, NULL);
        if (ds_sim_get_wall_count(sim) != walls || ds_sim_get_collision_count(sim) != hits)
            continue;
        for (size_t i = 0; i < n; ++i) {
            ds_disk d = ds_sim_get_disk(sim, i);
            assert_true(d.x == before[i].x + before[i].vx * 0.001);
            assert_true(d.vx == before[i].vx && d.vy == before[i].vy);
        }
    }
    ds_sim_destroy(sim);
}

/* The bulk copy is ds_sim_get_disk for every disk, in generation order,
 * whatever order each integrator and broad phase keeps its arrays in
 * (strips regroup them by strip every step, SAP sorts them by x, cells by
 * cell). */
static void test_get_all_copies_every_disk_in_generation_order(void **state)
{
    (void)state;
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ)
        for (int bp = 0; bp < DS_BROADPHASE_COUNT; ++bp) {
            ds_params p = ds_params_default(500, 3.0);
            p.seed = 11;
            p.integrator = (ds_integrator)integ;
            p.broadphase = (ds_broadphase)bp;
            ds_sim *sim = NULL;
            if (ds_params_check(&p, NULL, NULL, NULL) != DS_OK)
                continue; /* not one of this integrator's broad phases */
            assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
            ds_disk *got = malloc(500 * sizeof *got);
            assert_non_null(got);
            for (int round = 0; round < 3; ++round) {
                assert_int_equal(ds_sim_get_disks(sim, got, NULL), DS_OK);
                for (size_t i = 0; i < 500; ++i) {
                    ds_disk one = ds_sim_get_disk(sim, i);
                    assert_memory_equal(&got[i], &one, sizeof one);
                }
                ds_sim_run(sim, 200, NULL);
            }
            free(got);
            ds_sim_destroy(sim);
        }
}

static void test_get_all_refuses_null_arguments(void **state)
{
    (void)state;
    ds_sim *sim = test_create(3, 5.0, 1, DS_BROADPHASE_SAP);
    ds_disk out[3];
    assert_int_equal(ds_sim_get_disks(sim, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_disks(NULL, out, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_disks(sim, out, NULL), DS_OK);
    ds_sim_destroy(sim);
}

static void test_set_replaces_one_disk_and_checks_bounds(void **state)
{
    (void)state;
    ds_sim *sim = test_create(20, 5.0, 1, DS_BROADPHASE_SAP);
    ds_sim_run(sim, 10, NULL);
    ds_disk d = {5.0, 995.0, -3.0, 4.0}; /* on the band's corner: allowed */
    assert_int_equal(ds_sim_set_disk(sim, 7, d, NULL), DS_OK);
    ds_disk got = ds_sim_get_disk(sim, 7);
    assert_memory_equal(&got, &d, sizeof d);

    ds_disk outside = {4.9, 500.0, 0.0, 0.0};
    assert_int_equal(ds_sim_set_disk(sim, 7, outside, NULL), DS_ERR_ARG);
    ds_disk nan_v = {500.0, 500.0, NAN, 0.0};
    assert_int_equal(ds_sim_set_disk(sim, 7, nan_v, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_disk(sim, 20, d, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_disk(NULL, 0, d, NULL), DS_ERR_ARG);
    got = ds_sim_get_disk(sim, 7);
    assert_memory_equal(&got, &d, sizeof d); /* failed sets changed nothing */

    ds_disk zero = ds_sim_get_disk(sim, 20); /* out of range reads as zeros */
    assert_true(zero.x == 0.0 && zero.vx == 0.0);
    ds_sim_destroy(sim);
}

static void test_two_simulations_do_not_interfere(void **state)
{
    (void)state;
    /* Stepping two simulations interleaved gives the same result as
     * stepping each alone: no shared state. */
    ds_sim *a = test_create(300, 5.0, 8, DS_BROADPHASE_SAP);
    ds_sim *b = test_create(300, 5.0, 9, DS_BROADPHASE_SAP);
    ds_sim *ref = test_create(300, 5.0, 8, DS_BROADPHASE_SAP);
    for (int s = 0; s < 50; ++s) {
        ds_sim_run(a, 20, NULL);
        ds_sim_run(b, 20, NULL);
    }
    ds_sim_run(ref, 1000, NULL);
    for (size_t i = 0; i < 300; ++i) {
        ds_disk da = ds_sim_get_disk(a, i), dr = ds_sim_get_disk(ref, i);
        assert_memory_equal(&da, &dr, sizeof da);
    }
    assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(ref));
    ds_sim_destroy(a);
    ds_sim_destroy(b);
    ds_sim_destroy(ref);
}

static void test_collision_timer_and_counters_advance(void **state)
{
    (void)state;
    ds_sim *sim = test_create(400, 5.0, 1, DS_BROADPHASE_SAP);
    assert_true(ds_sim_get_collision_seconds(sim) == 0.0);
    ds_sim_run(sim, 5000, NULL);
    assert_true(ds_sim_get_collision_seconds(sim) > 0.0);
    assert_true(ds_sim_get_collision_count(sim) > 0);
    assert_true(ds_sim_get_pairs_tested(sim) > 0);
    ds_sim_destroy(sim);
}

static void test_null_simulation_is_harmless(void **state)
{
    (void)state;
    ds_sim_destroy(NULL);
    ds_sim_step(NULL, NULL);
    ds_sim_run(NULL, 10, NULL);
    assert_int_equal(ds_sim_get_count(NULL), 0);
    assert_true(ds_sim_get_time(NULL) == 0.0);
    assert_int_equal(ds_frame_write(NULL, 0, stdout, NULL), DS_ERR_ARG);
    double px = 1.0, py = 1.0;
    ds_sim_get_momentum(NULL, &px, &py);
    assert_true(px == 0.0 && py == 0.0);
}

static void test_every_status_has_a_description(void **state)
{
    (void)state;
    for (int s = 0; s < DS_STATUS_COUNT; ++s) {
        const char *text = ds_status_name((ds_status)s);
        assert_non_null(text);
        assert_true(strlen(text) > 0);
        assert_string_not_equal(text, "unknown status");
    }
    assert_string_equal(ds_status_name(DS_STATUS_COUNT), "unknown status");
    assert_string_equal(ds_version(), DS_VERSION_STRING);
}

/* DS_ERR_FORMAT comes back for a malformed frame and for a malformed
 * checkpoint: its description, which a caller prints when there is no
 * reason in the error struct, names both. */
static void test_the_format_status_describes_frames_and_checkpoints(void **state)
{
    (void)state;
    static const char not_a_checkpoint[] = "DSIMSTAX and then nothing of a checkpoint";
    ds_sim *sim = NULL;
    const ds_status from_state =
        ds_checkpoint_parse(not_a_checkpoint, sizeof not_a_checkpoint, &sim, NULL);
    assert_int_equal(from_state, DS_ERR_FORMAT);
    assert_null(sim);
    ds_frame frame;
    const ds_status from_frame = ds_frame_parse("1 2 x\n", 6, &frame, NULL);
    assert_int_equal(from_frame, DS_ERR_FORMAT);
    assert_non_null(strstr(ds_status_name(from_state), "checkpoint"));
    assert_non_null(strstr(ds_status_name(from_frame), "frame"));
}

static void test_tunneling_warning_for_tiny_radius(void **state)
{
    (void)state;
    /* Head-on at 3x the initial speed the gap closes by 2*300*dt = 0.6 per
     * step; the overlap band is 4R wide, so R below 0.15 can be skipped. */
    unsigned w = 0;
    ds_params p = ds_params_default(100, 0.1);
    assert_int_equal(ds_params_check(&p, NULL, &w, NULL), DS_OK);
    assert_true(w & DS_WARN_TUNNELING);
    p.radius = 5.0;
    assert_int_equal(ds_params_check(&p, NULL, &w, NULL), DS_OK);
    assert_int_equal(w, 0);
}

/* A run does not depend on how it is cut into calls (disksim/sim.h):
 * 300 steps in one call, in calls of one step, or in calls of 7, 93 and
 * 200 give the same disks to the bit, for every integrator and boundary,
 * and each call returns DS_OK. */
static void test_a_run_cut_into_calls_gives_the_same_disks(void **state)
{
    (void)state;
    static const uint64_t cuts[][3] = {{300, 0, 0}, {7, 93, 200}};
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ)
        for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
            ds_params p = ds_params_default(300, 8.0);
            p.integrator = (ds_integrator)integ;
            p.boundary = (ds_boundary)b;
            ds_disk want[300], got[300];
            ds_sim *one = NULL;
            assert_int_equal(ds_sim_create(&p, NULL, &one, NULL), DS_OK);
            for (int s = 0; s < 300; ++s)
                assert_int_equal(ds_sim_step(one, NULL), DS_OK);
            assert_int_equal(ds_sim_get_disks(one, want, NULL), DS_OK);
            for (size_t c = 0; c < sizeof cuts / sizeof cuts[0]; ++c) {
                ds_sim *sim = NULL;
                assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
                for (int k = 0; k < 3; ++k)
                    assert_int_equal(ds_sim_run(sim, cuts[c][k], NULL), DS_OK);
                assert_int_equal(ds_sim_get_steps(sim), 300);
                assert_int_equal(ds_sim_get_disks(sim, got, NULL), DS_OK);
                assert_memory_equal(got, want, sizeof want);
                assert_int_equal(ds_sim_get_collision_count(sim), ds_sim_get_collision_count(one));
                ds_sim_destroy(sim);
            }
            ds_sim_destroy(one);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_run_cut_into_calls_gives_the_same_disks),
        cmocka_unit_test(test_default_params_are_the_exercise),
        cmocka_unit_test(test_time_is_steps_times_dt),
        cmocka_unit_test(test_get_follows_each_disk_through_the_sort),
        cmocka_unit_test(test_get_all_copies_every_disk_in_generation_order),
        cmocka_unit_test(test_get_all_refuses_null_arguments),
        cmocka_unit_test(test_set_replaces_one_disk_and_checks_bounds),
        cmocka_unit_test(test_two_simulations_do_not_interfere),
        cmocka_unit_test(test_collision_timer_and_counters_advance),
        cmocka_unit_test(test_null_simulation_is_harmless),
        cmocka_unit_test(test_every_status_has_a_description),
        cmocka_unit_test(test_the_format_status_describes_frames_and_checkpoints),
        cmocka_unit_test(test_tunneling_warning_for_tiny_radius),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
