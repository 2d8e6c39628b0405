/* SPDX-License-Identifier: MIT */
/* The error model (disksim/base.h): every call that can fail returns a
 * ds_status and fills the optional ds_error with the same status, the
 * field at fault, the value and the limit it broke where they are
 * numbers, the disk at fault, and a sentence; a call that succeeds leaves
 * it empty. The command and Python print these instead of deriving the
 * library's rules again (2.x had three error structs, and growth, velocity
 * scaling and contacts refused with no reason at all). */
#include "test_util.h"

/* err as a refusal of field with value and limit (NaN: not a number). */
static void assert_refusal(const ds_error *err, ds_status status, const char *field, double value,
                           double limit)
{
    assert_int_equal(err->status, status);
    assert_string_equal(err->field, field);
    if (isnan(value))
        assert_true(isnan(err->value));
    else
        assert_true(err->value == value);
    if (isnan(limit))
        assert_true(isnan(err->limit));
    else
        assert_true(err->limit == limit);
    assert_true(strlen(err->message) > 0);
}

static void test_a_refused_request_names_the_field_its_value_and_the_limit(void **state)
{
    (void)state;
    ds_error err;
    ds_params p = ds_params_default(400, 600.0);
    assert_int_equal(ds_params_check(&p, NULL, NULL, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "radius", 600.0, 500.0);
    /* One sentence that begins with the field and names the value. */
    assert_true(strncmp(err.message, "radius = 600 ", 13) == 0);
    p = ds_params_default(0, 5.0);
    assert_int_equal(ds_sim_create(&p, NULL, &(ds_sim *){NULL}, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "n", 0.0, 1.0);
    p = ds_params_default(10, 5.0);
    p.box_y = 2e9;
    assert_int_equal(ds_params_memory(&p, NULL, &(size_t){0}, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "box_y", 2e9, 1e9);
    p = ds_params_default(10, 5.0);
    p.broadphase = (ds_broadphase)DS_BROADPHASE_COUNT;
    assert_int_equal(ds_params_check(&p, NULL, NULL, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "broadphase", (double)DS_BROADPHASE_COUNT,
                   (double)DS_BROADPHASE_COUNT);
}

/* A call that succeeds empties err, whatever a refusal left in it; a
 * warning is the one thing a success may carry. */
static void test_a_success_leaves_the_error_empty_but_for_a_warning(void **state)
{
    (void)state;
    ds_error err;
    ds_params p = ds_params_default(400, 600.0);
    assert_int_equal(ds_params_check(&p, NULL, NULL, &err), DS_ERR_ARG);
    p.radius = 5.0;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, &err), DS_OK);
    assert_int_equal(err.status, DS_OK);
    assert_string_equal(err.field, "");
    assert_string_equal(err.message, "");
    assert_true(isnan(err.value) && isnan(err.limit));
    assert_int_equal(err.index, 0);
    assert_int_equal(ds_sim_run(sim, 3, &err), DS_OK);
    assert_string_equal(err.message, "");
    ds_sim_destroy(sim);
    /* Tiny disks at the default speed: a pair can pass through each other. */
    p.radius = 0.01;
    unsigned warnings = 0;
    assert_int_equal(ds_params_check(&p, NULL, &warnings, &err), DS_OK);
    assert_int_equal(warnings, DS_WARN_TUNNELING);
    assert_string_equal(err.message, "");
    assert_true(strncmp(err.warning, "radius = 0.01 ", 14) == 0);
}

/* The refusals 2.x made without a word: growth, velocity scaling,
 * contacts, psi6 (NaN), a disk that is too fast. */
static void test_refusals_that_had_no_reason_have_one(void **state)
{
    (void)state;
    ds_error err;
    ds_params p = ds_params_default(20, 5.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    ds_sim *walls = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &walls, NULL), DS_OK);
    assert_int_equal(ds_sim_set_growth(walls, 0.01, 0.0, 0.0, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "boundary", NAN, NAN);
    p.boundary = DS_BOUNDARY_PERIODIC;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    /* Speeds 100, R = 5: at most 10 rms / (2 R) = 100 per unit time. */
    const double rms = sqrt(2.0 * ds_sim_get_kinetic_energy(sim) / 20.0);
    assert_int_equal(ds_sim_set_growth(sim, 200.0, 0.0, 0.0, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "rate", 200.0, 10.0 * rms / 10.0);
    assert_int_equal(ds_sim_set_growth(sim, 0.01, 1.5, 0.0, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "until_eta", 1.5, 1.0);
    const double eta = ds_sim_get_area_fraction(sim);
    assert_int_equal(ds_sim_set_growth(sim, 0.01, eta / 2.0, 0.0, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "until_eta", eta / 2.0, eta);
    assert_int_equal(ds_sim_set_growth(sim, 0.01, 0.0, 2e9, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "until_z", 2e9, 1e9);
    assert_int_equal(ds_sim_set_growth(sim, 0.01, 0.0, 0.0, &err), DS_OK);
    assert_string_equal(err.field, "");
    /* Every velocity component is at most 100: at most a factor 1e10. */
    double fastest = 0.0;
    for (size_t i = 0; i < 20; ++i) {
        const ds_disk d = ds_sim_get_disk(sim, i);
        fastest = fmax(fastest, fmax(fabs(d.vx), fabs(d.vy)));
    }
    assert_int_equal(ds_sim_scale_velocities(sim, 1e11, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "factor", 1e11, DS_VELOCITY_MAX / fastest);
    assert_int_equal(ds_sim_scale_velocities(sim, -1.0, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "factor", -1.0, 0.0);
    ds_contacts c;
    assert_int_equal(ds_sim_get_contacts(sim, 1.5, &c, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "gap", 1.5, 1.0);
    ds_disk d = ds_sim_get_disk(sim, 7);
    d.vx = 2e12;
    assert_int_equal(ds_sim_set_disk(sim, 7, d, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "disk", 2e12, DS_VELOCITY_MAX);
    assert_int_equal(err.index, 7);
    ds_sim_destroy(sim);
    ds_sim_destroy(walls);
}

/* A state of two overlapping disks names the pair (the first in err's
 * index), their distance and the contact distance it broke. */
static void test_an_overlap_names_the_pair_and_the_distances(void **state)
{
    (void)state;
    ds_sim *sim = test_create(3, 5.0, 1, DS_BROADPHASE_AUTO);
    ds_disk d[3] = {{100, 100, 1, 0}, {500, 500, 0, 1}, {506, 500, 1, 1}};
    ds_error err;
    assert_int_equal(ds_sim_set_disks(sim, d, &err), DS_ERR_OVERLAP);
    assert_refusal(&err, DS_ERR_OVERLAP, "disks", 6.0, 10.0);
    assert_int_equal(err.index, 1);
    assert_true(strncmp(err.message, "disks 1 and 2 overlap", 21) == 0);
    ds_sim_destroy(sim);
}

/* Every refusal of a NULL argument comes with a sentence naming it, and
 * err may be NULL everywhere. */
static void test_null_arguments_are_named(void **state)
{
    (void)state;
    ds_error err;
    assert_int_equal(ds_sim_run(NULL, 1, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "sim", NAN, NAN);
    assert_int_equal(ds_sim_step(NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_create(NULL, NULL, &(ds_sim *){NULL}, &err), DS_ERR_ARG);
    assert_int_equal(ds_sim_create(NULL, NULL, NULL, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "out", NAN, NAN);
    double psi6 = 0.0;
    assert_int_equal(ds_sim_get_psi6(NULL, &psi6, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "sim", NAN, NAN);
    assert_true(isnan(psi6));
    ds_sim *sim = test_create(3, 5.0, 1, DS_BROADPHASE_AUTO);
    assert_int_equal(ds_sim_get_radii(sim, NULL, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "radii", NAN, NAN);
    assert_int_equal(ds_sim_get_masses(sim, NULL, &err), DS_ERR_ARG);
    assert_refusal(&err, DS_ERR_ARG, "masses", NAN, NAN);
    assert_int_equal(ds_sim_run(sim, 0, &err), DS_OK); /* no steps: nothing to do */
    assert_int_equal(ds_sim_get_steps(sim), 0);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_refused_request_names_the_field_its_value_and_the_limit),
        cmocka_unit_test(test_a_success_leaves_the_error_empty_but_for_a_warning),
        cmocka_unit_test(test_refusals_that_had_no_reason_have_one),
        cmocka_unit_test(test_an_overlap_names_the_pair_and_the_distances),
        cmocka_unit_test(test_null_arguments_are_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
