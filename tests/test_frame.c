/* SPDX-License-Identifier: MIT */
/* Frame files: exact formatting, round trip, and the parser's errors. */
#include "test_util.h"

#include "core/core.h"

/* Formats a one-disk frame with the disk at (x, y) and returns the x field. */
static void format_x(ds_sim *sim, double x, char *out, size_t cap)
{
    sim->disks.x[sim->disks.slot[0]] = x;
    char buf[256];
    size_t len = 0;
    assert_int_equal(ds_frame_format(sim, 0, buf, sizeof buf, &len, NULL), DS_OK);
    size_t field = strcspn(buf, " ");
    assert_true(field < cap);
    memcpy(out, buf, field);
    out[field] = '\0';
}

static void test_fixed_six_decimals_match_printf_exactly(void **state)
{
    (void)state;
    ds_sim *sim = test_create(1, 5.0, 1, DS_BROADPHASE_SAP);
    ds_rng r;
    ds_rng_seed(&r, 123);
    char mine[64], ref[64];
    /* Random values over the box and beyond, plus the hard cases: exact
     * ties k/128 (7812.5 millionths, printf rounds half to even), values
     * that round up into the next integer, tiny negatives, zero. */
    double special[] = {0.0,       -0.0,  0.0078125,  0.0234375, 1.0000005, 999.9999995,
                        0.9999999, -1e-9, -0.0000005, 5.0,       995.0,     123456789.123456789,
                        1e14 + 0.5};
    for (size_t k = 0; k < sizeof special / sizeof special[0]; ++k) {
        format_x(sim, special[k], mine, sizeof mine);
        snprintf(ref, sizeof ref, "%.6f", special[k]);
        assert_string_equal(mine, ref);
    }
    for (int k = 0; k < 200000; ++k) {
        double v = ds_rng_uniform(&r, -5.0, 1005.0);
        if (k % 4 == 0) /* multiples of 2^-7..2^-10 produce many exact ties */
            v = floor(v) + (double)(ds_rng_next(&r) % 1024) / 1024.0;
        format_x(sim, v, mine, sizeof mine);
        snprintf(ref, sizeof ref, "%.6f", v);
        assert_string_equal(mine, ref);
    }
    ds_sim_destroy(sim);
}

static void radius_text(double r, char *out, size_t cap)
{
    ds_sim *sim = test_create(1, r, 1, DS_BROADPHASE_SAP);
    char buf[256];
    size_t len = 0;
    assert_int_equal(ds_frame_format(sim, 0, buf, sizeof buf, &len, NULL), DS_OK);
    buf[len - 1] = '\0';
    snprintf(out, cap, "%s", strrchr(buf, ' ') + 1);
    ds_sim_destroy(sim);
}

static void test_radius_is_written_in_shortest_round_trip_form(void **state)
{
    (void)state;
    char text[64];
    radius_text(5.0, text, sizeof text);
    assert_string_equal(text, "5");
    radius_text(0.25, text, sizeof text);
    assert_string_equal(text, "0.25");
    radius_text(0.1, text, sizeof text);
    assert_string_equal(text, "0.1");
    radius_text(1.0 / 3.0, text, sizeof text);
    assert_true(strtod(text, NULL) == 1.0 / 3.0);
    /* Fewest digits is not shortest: one digit writes 10 as "1e+01". */
    radius_text(10.0, text, sizeof text);
    assert_string_equal(text, "10");
    radius_text(250.0, text, sizeof text);
    assert_string_equal(text, "250");
    radius_text(1e-7, text, sizeof text); /* here the exponent is shorter */
    assert_string_equal(text, "1e-07");
}

static void test_frame_round_trips_through_a_file(void **state)
{
    (void)state;
    ds_sim *sim = test_create(300, 4.0, 9, DS_BROADPHASE_SAP);
    ds_sim_run(sim, 500, NULL); /* slots permuted by the sort: output must not be */
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(ds_frame_write(sim, 1, f, NULL), DS_OK);
    long size = ftell(f);
    rewind(f);
    char *text = malloc((size_t)size);
    assert_int_equal(fread(text, 1, (size_t)size, f), (size_t)size);
    fclose(f);

    ds_frame frame;
    ds_error err;
    assert_int_equal(ds_frame_parse(text, (size_t)size, &frame, &err), DS_OK);
    assert_int_equal(frame.count, 300);
    assert_int_equal(frame.columns, 5);
    for (size_t i = 0; i < 300; ++i) {
        ds_disk d = ds_sim_get_disk(sim, i);
        /* Six decimals: the printed value is within half a millionth. */
        assert_true(fabs(frame.disks[i].x - d.x) <= 5e-7 + 1e-12);
        assert_true(fabs(frame.disks[i].y - d.y) <= 5e-7 + 1e-12);
        assert_true(fabs(frame.disks[i].vx - d.vx) <= 5e-7 + 1e-12);
        assert_true(frame.disks[i].r == 4.0);
    }
    ds_frame_free(&frame);
    free(text);
    ds_sim_destroy(sim);
}

static void test_three_column_frame_has_one_line_per_disk(void **state)
{
    (void)state;
    ds_sim *sim = test_create(50, 5.0, 2, DS_BROADPHASE_SAP);
    size_t cap = ds_frame_get_size(sim, 0), len = 0;
    char *buf = malloc(cap);
    assert_int_equal(ds_frame_format(sim, 0, buf, cap, &len, NULL), DS_OK);
    size_t lines = 0;
    for (size_t k = 0; k < len; ++k)
        lines += buf[k] == '\n';
    assert_int_equal(lines, 50);
    /* Too small a buffer is an error that still reports the size needed. */
    size_t need = 0;
    assert_int_equal(ds_frame_format(sim, 0, buf, len - 1, &need, NULL), DS_ERR_ARG);
    assert_int_equal(need, len);
    free(buf);
    ds_sim_destroy(sim);
}

static void expect_error(const char *text, size_t line, const char *message)
{
    ds_frame frame;
    ds_error err;
    assert_int_equal(ds_frame_parse(text, strlen(text), &frame, &err), DS_ERR_FORMAT);
    assert_int_equal(err.index, line);
    assert_string_equal(err.message, message);
    assert_null(frame.disks);
    assert_int_equal(frame.count, 0);
}

static void test_parser_names_the_bad_line(void **state)
{
    (void)state;
    expect_error("", 0, "empty frame: no disks");
    expect_error("1 2 3\n1 2\n", 2, "expected 3 or 5 numbers");
    expect_error("1 2 3 4 5 6\n", 1, "expected 3 or 5 numbers");
    expect_error("1 2 3\n1 2 3 4 5\n", 2, "expected 3 numbers like the first line");
    expect_error("1 2 x\n", 1, "not a number");
    expect_error("1 2 3x\n", 1, "not a number");
    expect_error("1 nan 3\n", 1, "number is not finite");
    expect_error("1 2 inf\n", 1, "number is not finite");
    expect_error("1 2 1e999\n", 1, "number is not finite");
    expect_error("1 2 -3\n", 1, "radius must be positive");
    expect_error("1 2 0\n", 1, "radius must be positive");
}

static void test_parser_accepts_comments_blank_lines_and_no_final_newline(void **state)
{
    (void)state;
    const char *text = "# a comment\n\n1.5 2.5 3\r\n  4 5 6";
    ds_frame frame;
    assert_int_equal(ds_frame_parse(text, strlen(text), &frame, NULL), DS_OK);
    assert_int_equal(frame.count, 2);
    assert_true(frame.disks[1].x == 4.0 && frame.disks[1].r == 6.0);
    ds_frame_free(&frame);
}

static void test_parser_rejects_binary_garbage(void **state)
{
    (void)state;
    const char garbage[] = {'1', ' ', '2', '\0', '3', '\n', (char)0xff, (char)0x80};
    ds_frame frame;
    ds_error err;
    assert_int_equal(ds_frame_parse(garbage, sizeof garbage, &frame, &err), DS_ERR_FORMAT);
    assert_int_equal(err.index, 1);
}

static void test_reading_a_missing_file_is_an_io_error(void **state)
{
    (void)state;
    ds_frame frame;
    ds_error err;
    assert_int_equal(ds_frame_read("/nonexistent/frame_0000.txt", &frame, &err), DS_ERR_IO);
    assert_non_null(strstr(err.message, "cannot open"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fixed_six_decimals_match_printf_exactly),
        cmocka_unit_test(test_radius_is_written_in_shortest_round_trip_form),
        cmocka_unit_test(test_frame_round_trips_through_a_file),
        cmocka_unit_test(test_three_column_frame_has_one_line_per_disk),
        cmocka_unit_test(test_parser_names_the_bad_line),
        cmocka_unit_test(test_parser_accepts_comments_blank_lines_and_no_final_newline),
        cmocka_unit_test(test_parser_rejects_binary_garbage),
        cmocka_unit_test(test_reading_a_missing_file_is_an_io_error),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
