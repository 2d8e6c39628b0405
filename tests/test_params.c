/* SPDX-License-Identifier: MIT */
/* Parameters: ds_params_check gives ds_params_check's answer and says
 * why, naming the field at fault and its value, for every refusal; and it
 * explains a warning. */
#include "test_util.h"

/* One request and what the library must say of it. */
typedef struct refusal {
    ds_params params;
    ds_status status;
    const char *field;
    const char *value; /* text the message must contain (the value at fault) */
} refusal;

static ds_params with(size_t n, double radius)
{
    ds_params p = ds_params_default(n, radius);
    return p;
}

static void assert_explained(const refusal *r)
{
    unsigned warnings = 123;
    ds_error why;
    memset(&why, 'x', sizeof why); /* every byte must be written */
    const ds_status st = ds_params_check(&r->params, NULL, &warnings, &why);
    assert_int_equal(st, r->status);
    assert_int_equal(ds_params_check(&r->params, NULL, NULL, NULL), r->status);
    assert_int_equal(warnings, 0u);
    assert_string_equal(why.field, r->field);
    /* The sentence begins with the field's name, then its value. */
    const size_t flen = strlen(r->field);
    assert_memory_equal(why.message, r->field, flen);
    assert_memory_equal(why.message + flen, " = ", 3);
    if (!strstr(why.message, r->value))
        fail_msg("\"%s\" does not name \"%s\"", why.message, r->value);
    assert_string_equal(why.warning, "");
}

static void test_each_refusal_names_its_field_and_value(void **state)
{
    (void)state;
    refusal cases[20];
    size_t count = 0;
    cases[count++] = (refusal){with(0, 5.0), DS_ERR_ARG, "n", "n = 0"};
    cases[count++] = (refusal){with(10, NAN), DS_ERR_ARG, "radius", "nan"};
    cases[count++] = (refusal){with(10, -1.0), DS_ERR_ARG, "radius", "-1"};
    cases[count++] = (refusal){with(10, 500.0), DS_ERR_ARG, "radius", "500"};
    refusal r = {with(2, 300.0), DS_ERR_ARG, "radius", "300"};
    r.params.boundary = DS_BOUNDARY_PERIODIC;
    cases[count++] = r;
    r = (refusal){with(1, 60.0), DS_ERR_ARG, "radius", "60"};
    r.params.box_y = 100.0;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "box", "-3"};
    r.params.box = -3.0;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "box_y", "2e+09"};
    r.params.box_y = 2e9;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "speed", "inf"};
    r.params.speed = INFINITY;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "dt", "2"};
    r.params.dt = 2.0;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "integrator", "7"};
    r.params.integrator = (ds_integrator)7;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "boundary", "9"};
    r.params.boundary = (ds_boundary)9;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "placement", "9"};
    r.params.placement = (ds_placement)9;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "broadphase", "sap"};
    r.params.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    r.params.broadphase = DS_BROADPHASE_SAP;
    cases[count++] = r;
    r = (refusal){with(10, 5.0), DS_ERR_ARG, "broadphase", "cells"};
    r.params.broadphase = DS_BROADPHASE_CELLS;
    cases[count++] = r;
    cases[count++] = (refusal){with((size_t)1e12, 1.0), DS_ERR_NOMEM, "n", "1000000000000"};
    cases[count++] = (refusal){with(100000, 50.0), DS_ERR_PLACEMENT, "n", "100000"};
    cases[count++] = (refusal){with(2000, 9.5), DS_ERR_PLACEMENT, "n", "0.567"};
    r = (refusal){with(4096, 8.5), DS_ERR_PLACEMENT, "n", "0.930"};
    r.params.placement = DS_PLACEMENT_LATTICE;
    cases[count++] = r;
    for (size_t k = 0; k < count; ++k)
        assert_explained(&cases[k]);
}

/* A zeroed ds_params with n and radius set is a valid request for every
 * integrator, boundary and placement: each choice's default is its 0
 * (2.x's 0 was the broad phase SAP, which the event-driven integrator
 * refused). A broad phase that does not serve the integrator is refused,
 * and the reason names the broad phase. */
static void test_a_zeroed_request_is_valid_for_every_choice(void **state)
{
    (void)state;
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ)
        for (int b = 0; b < DS_BOUNDARY_COUNT; ++b)
            for (int pl = 0; pl < DS_PLACEMENT_COUNT; ++pl) {
                ds_params p;
                memset(&p, 0, sizeof p);
                p.n = 10;
                p.radius = 5.0;
                p.integrator = (ds_integrator)integ;
                p.boundary = (ds_boundary)b;
                p.placement = (ds_placement)pl;
                ds_error why;
                assert_int_equal(ds_params_check(&p, NULL, NULL, &why), DS_OK);
                assert_int_equal(why.status, DS_OK);
                ds_sim *sim = NULL;
                assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
                assert_int_not_equal(ds_sim_get_broadphase(sim), DS_BROADPHASE_AUTO);
                ds_sim_destroy(sim);
            }
    ds_params p;
    memset(&p, 0, sizeof p);
    p.n = 10;
    p.radius = 5.0;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.broadphase = DS_BROADPHASE_SAP;
    ds_error why;
    assert_int_equal(ds_params_check(&p, NULL, NULL, &why), DS_ERR_ARG);
    assert_string_equal(why.field, "broadphase");
    assert_non_null(strstr(why.message, "sap"));
}

static void test_an_accepted_request_has_no_message(void **state)
{
    (void)state;
    ds_error why;
    unsigned warnings = 1;
    ds_params p = ds_params_default(400, 5.0);
    assert_int_equal(ds_params_check(&p, NULL, &warnings, &why), DS_OK);
    assert_int_equal(warnings, 0u);
    assert_string_equal(why.field, "");
    assert_string_equal(why.message, "");
    assert_string_equal(why.warning, "");
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_OK);
}

/* A disk small for its speed and dt runs, with the warning explained in
 * the values of the request (speed and dt as resolved). */
static void test_a_warning_is_explained_with_the_resolved_values(void **state)
{
    (void)state;
    ds_error why;
    unsigned warnings = 0;
    ds_params p = ds_params_default(400, 0.1);
    p.speed = 250.0;
    assert_int_equal(ds_params_check(&p, NULL, &warnings, &why), DS_OK);
    assert_true(warnings & DS_WARN_TUNNELING);
    assert_string_equal(why.message, "");
    assert_non_null(strstr(why.warning, "radius = 0.1"));
    assert_non_null(strstr(why.warning, "250"));
    assert_non_null(strstr(why.warning, "0.001"));
    /* The event-driven integrator has no step to tunnel through. */
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    assert_int_equal(ds_params_check(&p, NULL, &warnings, &why), DS_OK);
    assert_int_equal(warnings, 0u);
    assert_string_equal(why.warning, "");
}

static void test_null_params_are_refused_with_a_reason(void **state)
{
    (void)state;
    ds_error why;
    assert_int_equal(ds_params_check(NULL, NULL, NULL, &why), DS_ERR_ARG);
    assert_string_equal(why.field, "");
    assert_true(strlen(why.message) > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_each_refusal_names_its_field_and_value),
        cmocka_unit_test(test_a_zeroed_request_is_valid_for_every_choice),
        cmocka_unit_test(test_an_accepted_request_has_no_message),
        cmocka_unit_test(test_a_warning_is_explained_with_the_resolved_values),
        cmocka_unit_test(test_null_params_are_refused_with_a_reason),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
