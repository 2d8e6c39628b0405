/* SPDX-License-Identifier: MIT */
/* The names of the library's enumerations, its one table of each: every
 * value below _COUNT has a name that parses back to it, nothing past
 * _COUNT has one, and a name that is none of them is refused with every
 * name known, so that the command and Python keep no table of their own.
 * The defaults are 0. */
#include "test_util.h"

/* One enumeration through int-valued wrappers. */
typedef struct enumeration {
    const char *field; /* what the refusal names */
    int count;
    const char *(*name)(int value);
    ds_status (*parse)(const char *name, int *out, ds_error *err);
} enumeration;

#define WRAP(type)                                                                                 \
    static const char *type##_name_of(int v) { return type##_name((type)v); }                      \
    static ds_status type##_parse_of(const char *name, int *out, ds_error *err)                    \
    {                                                                                              \
        type v;                                                                                    \
        const ds_status st = type##_parse(name, out ? &v : NULL, err);                             \
        if (st == DS_OK)                                                                           \
            *out = (int)v;                                                                         \
        return st;                                                                                 \
    }
WRAP(ds_integrator)
WRAP(ds_boundary)
WRAP(ds_placement)
WRAP(ds_broadphase)
WRAP(ds_mass_rule)
WRAP(ds_growth_state)
WRAP(ds_format)

static const enumeration all[] = {
    {"integrator", DS_INTEGRATOR_COUNT, ds_integrator_name_of, ds_integrator_parse_of},
    {"boundary", DS_BOUNDARY_COUNT, ds_boundary_name_of, ds_boundary_parse_of},
    {"placement", DS_PLACEMENT_COUNT, ds_placement_name_of, ds_placement_parse_of},
    {"broadphase", DS_BROADPHASE_COUNT, ds_broadphase_name_of, ds_broadphase_parse_of},
    {"mass_rule", DS_MASS_RULE_COUNT, ds_mass_rule_name_of, ds_mass_rule_parse_of},
    {"growth_state", DS_GROWTH_STATE_COUNT, ds_growth_state_name_of, ds_growth_state_parse_of},
    {"format", DS_FORMAT_COUNT, ds_format_name_of, ds_format_parse_of},
};
#define ENUMERATIONS (sizeof all / sizeof all[0])

static void test_every_value_has_a_name_that_parses_back_to_it(void **state)
{
    (void)state;
    for (size_t e = 0; e < ENUMERATIONS; ++e) {
        assert_true(all[e].count >= 2);
        for (int v = 0; v < all[e].count; ++v) {
            const char *name = all[e].name(v);
            assert_string_not_equal(name, "unknown");
            for (int w = 0; w < v; ++w) /* each name once */
                assert_string_not_equal(name, all[e].name(w));
            int back = -1;
            ds_error err;
            assert_int_equal(all[e].parse(name, &back, &err), DS_OK);
            assert_int_equal(back, v);
            assert_int_equal(err.status, DS_OK);
            assert_string_equal(err.message, "");
        }
        assert_string_equal(all[e].name(all[e].count), "unknown");
        assert_string_equal(all[e].name(-1), "unknown");
    }
}

static void test_an_unknown_name_is_refused_with_every_name_known(void **state)
{
    (void)state;
    for (size_t e = 0; e < ENUMERATIONS; ++e) {
        int out = 12345;
        ds_error err;
        assert_int_equal(all[e].parse("no such thing", &out, &err), DS_ERR_ARG);
        assert_int_equal(out, 12345); /* untouched */
        assert_int_equal(err.status, DS_ERR_ARG);
        assert_string_equal(err.field, all[e].field);
        /* "integrator = 'no such thing' is not one of 'step', 'event'" */
        assert_true(strncmp(err.message, all[e].field, strlen(all[e].field)) == 0);
        assert_non_null(strstr(err.message, "'no such thing'"));
        for (int v = 0; v < all[e].count; ++v) {
            char quoted[64];
            snprintf(quoted, sizeof quoted, "'%s'", all[e].name(v));
            assert_non_null(strstr(err.message, quoted));
        }
        assert_int_equal(all[e].parse(NULL, &out, NULL), DS_ERR_ARG);
        assert_int_equal(all[e].parse(all[e].name(0), NULL, NULL), DS_ERR_ARG);
    }
}

/* The command's and Python's names, which 2.x spelt in three places. */
static void test_the_names_are_the_front_ends_names(void **state)
{
    (void)state;
    assert_string_equal(ds_integrator_name(DS_INTEGRATOR_TIME_STEP), "step");
    assert_string_equal(ds_integrator_name(DS_INTEGRATOR_EVENT_DRIVEN), "event");
    assert_string_equal(ds_boundary_name(DS_BOUNDARY_WALLS), "walls");
    assert_string_equal(ds_boundary_name(DS_BOUNDARY_PERIODIC), "periodic");
    assert_string_equal(ds_placement_name(DS_PLACEMENT_RANDOM), "random");
    assert_string_equal(ds_placement_name(DS_PLACEMENT_LATTICE), "lattice");
    assert_string_equal(ds_broadphase_name(DS_BROADPHASE_AUTO), "auto");
    assert_string_equal(ds_broadphase_name(DS_BROADPHASE_SAP), "sap");
    assert_string_equal(ds_broadphase_name(DS_BROADPHASE_STRIPS), "strips");
    assert_string_equal(ds_broadphase_name(DS_BROADPHASE_CELLS), "cells");
    assert_string_equal(ds_broadphase_name(DS_BROADPHASE_BRUTE), "brute");
    assert_string_equal(ds_mass_rule_name(DS_MASS_EQUAL), "equal");
    assert_string_equal(ds_mass_rule_name(DS_MASS_AREA), "area");
    assert_string_equal(ds_growth_state_name(DS_GROWTH_NONE), "none");
    assert_string_equal(ds_growth_state_name(DS_GROWTH_GROWING), "growing");
    assert_string_equal(ds_growth_state_name(DS_GROWTH_REACHED_ETA), "reached_eta");
    assert_string_equal(ds_growth_state_name(DS_GROWTH_JAMMED), "jammed");
    assert_string_equal(ds_format_name(DS_FORMAT_FRAME), "frame");
    assert_string_equal(ds_format_name(DS_FORMAT_XYZ), "xyz");
    assert_string_equal(ds_format_name(DS_FORMAT_GSD), "gsd");
}

/* Each default is 0, so a zeroed ds_params asks for every default. */
static void test_the_defaults_are_zero(void **state)
{
    (void)state;
    assert_int_equal(DS_INTEGRATOR_TIME_STEP, 0);
    assert_int_equal(DS_BOUNDARY_WALLS, 0);
    assert_int_equal(DS_PLACEMENT_RANDOM, 0);
    assert_int_equal(DS_BROADPHASE_AUTO, 0);
    assert_int_equal(DS_MASS_EQUAL, 0);
    assert_int_equal(DS_GROWTH_NONE, 0);
    assert_int_equal(DS_FORMAT_FRAME, 0);
    const ds_params p = ds_params_default(10, 1.0);
    assert_int_equal(p.broadphase, 0);
    assert_int_equal(p.integrator, 0);
    assert_true(p.box == 0.0 && p.box_y == 0.0 && p.speed == 0.0 && p.dt == 0.0);
    assert_int_equal(p.seed, DS_DEFAULT_SEED);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_value_has_a_name_that_parses_back_to_it),
        cmocka_unit_test(test_an_unknown_name_is_refused_with_every_name_known),
        cmocka_unit_test(test_the_names_are_the_front_ends_names),
        cmocka_unit_test(test_the_defaults_are_zero),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
