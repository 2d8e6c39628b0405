/* SPDX-License-Identifier: MIT */
/* The kinds of disk (a mixture's species): each disk knows its kind, the
 * kinds their names, through every broad phase's reordering of the slots,
 * a checkpoint and ds_sim_set_disks; bad names are refused. The kind is
 * one row of the disk columns' table (core/disk_arrays.h): that it moves
 * with its disk through every sort, merge and permutation is what the
 * table promises. */
#include "test_util.h"

enum { N = 300 };

/* 300 disks of three species (100 of radius 3 named "small", 120 of 4
 * unnamed, 80 of 5 named "big") in a box where they collide a lot. */
static ds_sim *make(ds_integrator integrator, ds_boundary boundary, ds_broadphase bp)
{
    static const ds_species kinds[3] = {
        {100, 3.0, 0.0, "small"}, {120, 4.0, 0.0, NULL}, {80, 5.0, 0.0, "big"}};
    const ds_mixture mixture = {3, kinds, NULL, NULL, DS_MASS_AREA};
    ds_params p = ds_params_default(N, 4.0);
    p.box = 220.0;
    p.integrator = integrator;
    p.boundary = boundary;
    p.broadphase = bp;
    p.seed = 11;
    ds_sim *sim = NULL;
    if (ds_params_check(&p, &mixture, NULL, NULL) != DS_OK)
        return NULL; /* a broad phase this integrator does not take */
    assert_int_equal(ds_sim_create(&p, &mixture, &sim, NULL), DS_OK);
    return sim;
}

/* Disk i's kind is its species, and its radius that species' radius: the
 * kind moved with its disk, whatever order the slots took. */
static void assert_kinds(const ds_sim *sim)
{
    uint32_t kind[N];
    double radius[N];
    assert_int_equal(ds_sim_get_kinds(sim, kind, NULL), DS_OK);
    assert_int_equal(ds_sim_get_radii(sim, radius, NULL), DS_OK);
    for (size_t i = 0; i < N; ++i) {
        const uint32_t want = i < 100 ? 0u : i < 220 ? 1u : 2u;
        assert_int_equal(kind[i], want);
        assert_true(radius[i] == 3.0 + (double)want);
    }
    assert_int_equal(ds_sim_get_kind_count(sim), 3);
    assert_string_equal(ds_sim_get_kind_name(sim, 0), "small");
    assert_string_equal(ds_sim_get_kind_name(sim, 1), "B");
    assert_string_equal(ds_sim_get_kind_name(sim, 2), "big");
    assert_null(ds_sim_get_kind_name(sim, 3));
}

static void test_each_disk_keeps_its_kind_as_the_slots_move(void **state)
{
    (void)state;
    for (int in = 0; in < DS_INTEGRATOR_COUNT; ++in)
        for (int b = 0; b < DS_BOUNDARY_COUNT; ++b)
            for (int bp = 0; bp < DS_BROADPHASE_COUNT; ++bp) {
                ds_sim *sim = make((ds_integrator)in, (ds_boundary)b, (ds_broadphase)bp);
                if (!sim)
                    continue;
                assert_kinds(sim);
                /* The placed state (the time step's later ones may
                 * overlap, which ds_sim_set_disks refuses). */
                ds_disk placed[N];
                assert_int_equal(ds_sim_get_disks(sim, placed, NULL), DS_OK);
                assert_int_equal(ds_sim_run(sim, 400, NULL), DS_OK);
                assert_kinds(sim);
                /* A checkpoint carries them, and a new state keeps them. */
                const size_t len = ds_checkpoint_get_size(sim);
                char *buf = malloc(len);
                assert_non_null(buf);
                assert_int_equal(ds_checkpoint_format(sim, buf, len, NULL, NULL), DS_OK);
                ds_sim *back = NULL;
                assert_int_equal(ds_checkpoint_parse(buf, len, &back, NULL), DS_OK);
                assert_kinds(back);
                assert_int_equal(ds_sim_set_disks(back, placed, NULL), DS_OK);
                assert_int_equal(ds_sim_run(back, 50, NULL), DS_OK);
                assert_kinds(back);
                free(buf);
                ds_sim_destroy(back);
                ds_sim_destroy(sim);
            }
}

static void test_without_species_there_is_one_kind(void **state)
{
    (void)state;
    ds_sim *sim = test_create(50, 5.0, 3, DS_BROADPHASE_AUTO);
    uint32_t kind[50];
    assert_int_equal(ds_sim_get_kinds(sim, kind, NULL), DS_OK);
    for (size_t i = 0; i < 50; ++i)
        assert_int_equal(kind[i], 0u);
    assert_int_equal(ds_sim_get_kind_count(sim), 1);
    assert_string_equal(ds_sim_get_kind_name(sim, 0), "A");
    assert_int_equal(ds_sim_get_kinds(sim, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_kind_count(NULL), 0);
    assert_null(ds_sim_get_kind_name(NULL, 0));
    ds_sim_destroy(sim);
}

static void test_bad_names_are_refused(void **state)
{
    (void)state;
    ds_params p = ds_params_default(20, 3.0);
    const char *const bad[] = {"", "a b", "sixteen-letters!", "tab\there"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        const ds_species kinds[2] = {{10, 3.0, 0.0, bad[k]}, {10, 4.0, 0.0, NULL}};
        const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_EQUAL};
        ds_error err;
        assert_int_equal(ds_params_check(&p, &mixture, NULL, &err), DS_ERR_ARG);
        assert_string_equal(err.field, "mixture");
        assert_non_null(strstr(err.message, "species 0's name"));
    }
    /* Two kinds of one name: "B" given to the first, the second's default. */
    const ds_species twice[2] = {{10, 3.0, 0.0, "B"}, {10, 4.0, 0.0, NULL}};
    const ds_mixture mixture = {2, twice, NULL, NULL, DS_MASS_EQUAL};
    ds_error err;
    assert_int_equal(ds_params_check(&p, &mixture, NULL, &err), DS_ERR_ARG);
    assert_non_null(strstr(err.message, "both named \"B\""));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_each_disk_keeps_its_kind_as_the_slots_move),
        cmocka_unit_test(test_without_species_there_is_one_kind),
        cmocka_unit_test(test_bad_names_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
