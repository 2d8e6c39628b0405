/* SPDX-License-Identifier: MIT */
/* Frame I/O under bad input and failing files: every malformed frame is
 * refused with the line that is wrong, every failed write is reported, and
 * the library answers bad arguments with DS_ERR_ARG instead of crashing. */
#include "test_util.h"

#include <errno.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* AddressSanitizer reserves terabytes of shadow memory, so an address-space
 * limit cannot be used under it. */
#if defined(__SANITIZE_ADDRESS__)
#define DS_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DS_ASAN 1
#endif
#endif

/* Parses text and expects DS_ERR_FORMAT at the given line, with a message
 * containing want, and an empty frame left behind. */
static void expect_format_error(const char *text, size_t len, size_t line, const char *want)
{
    ds_frame frame = {(ds_frame_disk *)&frame, 99, 3}; /* garbage to be reset */
    ds_error err;
    assert_int_equal(ds_frame_parse(text, len, &frame, &err), DS_ERR_FORMAT);
    assert_int_equal(err.index, line);
    if (!strstr(err.message, want))
        fail_msg("message '%s' does not contain '%s'", err.message, want);
    assert_null(frame.disks);
    assert_int_equal(frame.count, 0);
}

static void expect_text_error(const char *text, size_t line, const char *want)
{
    expect_format_error(text, strlen(text), line, want);
}

static void test_a_nan_coordinate_is_refused_at_its_line(void **state)
{
    (void)state;
    expect_text_error("1 2 3\nnan 2 3\n", 2, "not finite");
}

static void test_an_infinite_coordinate_is_refused_at_its_line(void **state)
{
    (void)state;
    expect_text_error("1 2 3\n4 5 6\n1 inf 3\n", 3, "not finite");
    expect_text_error("1e400 2 3\n", 1, "not finite");
}

static void test_a_negative_or_zero_radius_is_refused(void **state)
{
    (void)state;
    expect_text_error("1 2 -3\n", 1, "radius must be positive");
    expect_text_error("1 2 3\n1 2 0\n", 2, "radius must be positive");
}

static void test_a_line_with_four_numbers_is_refused(void **state)
{
    (void)state;
    expect_text_error("1 2 3 4\n", 1, "expected 3 or 5 numbers");
    expect_text_error("1 2 3 4 5 6\n", 1, "expected 3 or 5 numbers");
}

static void test_a_frame_mixing_column_counts_is_refused(void **state)
{
    (void)state;
    expect_text_error("1 2 3\n1 2 3 4 5\n", 2, "expected 3 numbers like the first line");
}

static void test_trailing_garbage_after_a_number_is_refused(void **state)
{
    (void)state;
    expect_text_error("1 2 3x\n", 1, "not a number");
}

static void test_binary_garbage_is_refused_without_reading_past_the_buffer(void **state)
{
    (void)state;
    /* Not NUL-terminated on purpose: ASan catches any read past len. */
    char *bytes = malloc(7);
    assert_non_null(bytes);
    memcpy(bytes, "\x89PNG\r\n\x1a", 7);
    expect_format_error(bytes, 7, 1, "not a number");
    memcpy(bytes, "1 2 3\0\n", 7);
    expect_format_error(bytes, 7, 1, "NUL");
    memcpy(bytes, "1 2 3.5", 7); /* the last number runs up to the end */
    ds_frame frame;
    assert_int_equal(ds_frame_parse(bytes, 7, &frame, NULL), DS_OK);
    assert_int_equal(frame.count, 1);
    assert_true(frame.disks[0].r == 3.5);
    ds_frame_free(&frame);
    free(bytes);
}

static void test_an_overlong_line_is_refused(void **state)
{
    (void)state;
    char text[2048];
    memset(text, ' ', sizeof text);
    memcpy(text, "1 2 3", 5);
    expect_format_error(text, sizeof text, 1, "line too long");
}

static void test_an_empty_or_comment_only_frame_is_refused(void **state)
{
    (void)state;
    expect_text_error("", 0, "empty");
    expect_text_error("# only a comment\n\n   \n", 0, "empty");
}

static void test_a_missing_file_is_an_io_error(void **state)
{
    (void)state;
    ds_frame frame;
    ds_error err;
    assert_int_equal(ds_frame_read("/nonexistent/frame_0000.txt", &frame, &err), DS_ERR_IO);
    assert_non_null(strstr(err.message, strerror(ENOENT)));
    assert_null(frame.disks);
}

static void test_endless_binary_input_is_refused_without_reading_it_all(void **state)
{
    (void)state;
    ds_frame frame;
    ds_error err;
    /* /dev/zero never ends: the reader must stop at its first NUL byte. */
    assert_int_equal(ds_frame_read("/dev/zero", &frame, &err), DS_ERR_FORMAT);
    assert_int_equal(err.index, 1);
    assert_non_null(strstr(err.message, "NUL"));
    assert_null(frame.disks);
}

static void test_a_directory_is_an_io_error(void **state)
{
    (void)state;
    ds_frame frame;
    ds_error err;
    /* fopen succeeds on a directory under Linux; the read then fails. */
    assert_int_equal(ds_frame_read("/", &frame, &err), DS_ERR_IO);
    assert_null(frame.disks);
}

static void test_writing_a_frame_to_a_full_disk_reports_io_error(void **state)
{
    (void)state;
    FILE *full = fopen("/dev/full", "w");
    if (!full)
        skip(); /* not Linux: no /dev/full */
    ds_sim *sim = test_create(50, 5.0, 1, DS_BROADPHASE_SAP);
    /* 50 lines fit in stdio's buffer: only the flush can see ENOSPC. */
    assert_int_equal(ds_frame_write(sim, 0, full, NULL), DS_ERR_IO);
    clearerr(full);
    assert_int_equal(ds_frame_write(sim, 1, full, NULL), DS_ERR_IO);
    fclose(full);
    ds_sim_destroy(sim);
}

static void test_a_written_frame_reads_back_exactly(void **state)
{
    (void)state;
    ds_sim *sim = test_create(30, 4.0, 7, DS_BROADPHASE_SAP);
    char path[] = "/tmp/ds_frame_errors_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "w");
    assert_non_null(f);
    assert_int_equal(ds_frame_write(sim, 1, f, NULL), DS_OK);
    assert_int_equal(fclose(f), 0);
    ds_frame frame;
    assert_int_equal(ds_frame_read(path, &frame, NULL), DS_OK);
    unlink(path);
    assert_int_equal(frame.count, 30);
    assert_int_equal(frame.columns, 5);
    for (size_t i = 0; i < frame.count; ++i) {
        ds_disk d = ds_sim_get_disk(sim, i);
        /* Six decimals are written: the round trip is exact to 5e-7. */
        assert_true(fabs(frame.disks[i].x - d.x) <= 5e-7);
        assert_true(fabs(frame.disks[i].vy - d.vy) <= 5e-7);
        assert_true(frame.disks[i].r == 4.0);
    }
    ds_frame_free(&frame);
    ds_sim_destroy(sim);
}

static void test_null_arguments_are_refused_not_dereferenced(void **state)
{
    (void)state;
    ds_frame frame;
    assert_int_equal(ds_frame_parse(NULL, 5, &frame, NULL), DS_ERR_ARG);
    assert_int_equal(ds_frame_parse("1 2 3", 5, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_frame_read(NULL, &frame, NULL), DS_ERR_ARG);
    assert_int_equal(ds_frame_write(NULL, 0, stdout, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_create(NULL, NULL, NULL, NULL), DS_ERR_ARG);
    ds_frame_free(NULL);
    ds_sim_destroy(NULL);
}

/* The header promises "On error *frame is left empty": a caller may free it
 * after any failure, so a frame holding garbage before the call must come
 * out empty whatever the error, an argument error included. */
static void test_a_failed_read_leaves_the_frame_empty_even_for_bad_arguments(void **state)
{
    (void)state;
    ds_frame_disk junk;
    ds_frame frame = {&junk, 99, 5};
    assert_int_equal(ds_frame_parse(NULL, 5, &frame, NULL), DS_ERR_ARG);
    assert_null(frame.disks);
    assert_int_equal(frame.count, 0);
    assert_int_equal(frame.columns, 0);
    frame = (ds_frame){&junk, 99, 5};
    assert_int_equal(ds_frame_read(NULL, &frame, NULL), DS_ERR_ARG);
    assert_null(frame.disks);
    assert_int_equal(frame.count, 0);
    assert_int_equal(frame.columns, 0);
    ds_frame_free(&frame); /* what a careful caller does: must be harmless */
}

/* A caller with no buffer yet asks for the size: *len is the exact size the
 * frame takes, the same a full format reports. */
static void test_formatting_into_no_buffer_reports_the_bytes_needed(void **state)
{
    (void)state;
    ds_sim *sim = test_create(40, 5.0, 2, DS_BROADPHASE_SAP);
    for (int velocities = 0; velocities <= 1; ++velocities) {
        size_t need = 12345;
        assert_int_equal(ds_frame_format(sim, velocities, NULL, 0, &need, NULL), DS_ERR_ARG);
        size_t cap = ds_frame_get_size(sim, velocities), len = 0;
        char *buf = malloc(cap);
        assert_non_null(buf);
        assert_int_equal(ds_frame_format(sim, velocities, buf, cap, &len, NULL), DS_OK);
        assert_int_equal(need, len);
        free(buf);
    }
    /* A NULL buffer that claims a capacity is still refused, and says 0. */
    size_t need = 12345;
    assert_int_equal(ds_frame_format(sim, 0, NULL, 10, &need, NULL), DS_ERR_ARG);
    assert_int_equal(ds_frame_format(NULL, 0, NULL, 0, &need, NULL), DS_ERR_ARG);
    assert_int_equal(need, 0);
    ds_sim_destroy(sim);
}

static void test_memory_needed_refuses_a_null_result_pointer(void **state)
{
    (void)state;
    ds_params p = ds_params_default(400, 5.0);
    assert_int_equal(ds_params_memory(&p, NULL, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_params_memory(NULL, NULL, NULL, NULL), DS_ERR_ARG);
    size_t bytes = 0;
    assert_int_equal(ds_params_memory(NULL, NULL, &bytes, NULL), DS_ERR_ARG);
    assert_int_equal(ds_params_memory(&p, NULL, &bytes, NULL), DS_OK);
    assert_true(bytes >= 400 * 4 * sizeof(double)); /* x, y, vx, vy at least */
}

static void test_bad_parameters_are_refused_with_arg_error(void **state)
{
    (void)state;
    ds_sim *sim = NULL;
    ds_params p = ds_params_default(10, 5.0);
    p.radius = NAN;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_ERR_ARG);
    p.radius = 500.0; /* a disk as wide as the box has nowhere to go */
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_ERR_ARG);
    p = ds_params_default(0, 5.0);
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_ERR_ARG);
    p = ds_params_default(100000, 50.0);
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_ERR_PLACEMENT);
    assert_null(sim);
}

static void test_an_allocation_failure_is_reported_not_fatal(void **state)
{
    (void)state;
#ifdef DS_ASAN
    skip();
#endif
    const char *preload = getenv("LD_PRELOAD");
    if (preload && strstr(preload, "vgpreload"))
        skip(); /* valgrind replaces malloc and ignores the limit */
    /* In a child limited to 256 MiB of address space, 20 million disks
     * (~900 MB of arrays) cannot be allocated: ds_sim_create must say so. */
    fflush(NULL);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        struct rlimit rl = {(rlim_t)256 << 20, (rlim_t)256 << 20};
        if (setrlimit(RLIMIT_AS, &rl) != 0)
            _exit(2);
        ds_params p = ds_params_default(20000000, 0.01);
        ds_sim *sim = NULL;
        ds_status st = ds_sim_create(&p, NULL, &sim, NULL);
        _exit(st == DS_ERR_NOMEM && sim == NULL ? 0 : 1);
    }
    int ws = 0;
    assert_int_equal(waitpid(pid, &ws, 0), pid);
    assert_true(WIFEXITED(ws));
    assert_int_equal(WEXITSTATUS(ws), 0);
}

static void test_two_simulations_in_one_process_do_not_interfere(void **state)
{
    (void)state;
    /* Same seed: a and c must stay identical while b, stepped in between,
     * must not disturb them (no hidden shared state). */
    ds_sim *a = test_create(100, 5.0, 3, DS_BROADPHASE_SAP);
    ds_sim *b = test_create(200, 3.0, 4, DS_BROADPHASE_BRUTE);
    ds_sim *c = test_create(100, 5.0, 3, DS_BROADPHASE_SAP);
    for (int k = 0; k < 50; ++k) {
        ds_sim_step(a, NULL);
        ds_sim_run(b, 3, NULL);
        ds_sim_step(c, NULL);
    }
    for (size_t i = 0; i < 100; ++i) {
        ds_disk da = ds_sim_get_disk(a, i), dc = ds_sim_get_disk(c, i);
        assert_true(da.x == dc.x && da.y == dc.y && da.vx == dc.vx && da.vy == dc.vy);
    }
    ds_sim_destroy(a);
    ds_sim_destroy(b);
    ds_sim_destroy(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_nan_coordinate_is_refused_at_its_line),
        cmocka_unit_test(test_an_infinite_coordinate_is_refused_at_its_line),
        cmocka_unit_test(test_a_negative_or_zero_radius_is_refused),
        cmocka_unit_test(test_a_line_with_four_numbers_is_refused),
        cmocka_unit_test(test_a_frame_mixing_column_counts_is_refused),
        cmocka_unit_test(test_trailing_garbage_after_a_number_is_refused),
        cmocka_unit_test(test_binary_garbage_is_refused_without_reading_past_the_buffer),
        cmocka_unit_test(test_an_overlong_line_is_refused),
        cmocka_unit_test(test_an_empty_or_comment_only_frame_is_refused),
        cmocka_unit_test(test_a_missing_file_is_an_io_error),
        cmocka_unit_test(test_endless_binary_input_is_refused_without_reading_it_all),
        cmocka_unit_test(test_a_directory_is_an_io_error),
        cmocka_unit_test(test_writing_a_frame_to_a_full_disk_reports_io_error),
        cmocka_unit_test(test_a_written_frame_reads_back_exactly),
        cmocka_unit_test(test_null_arguments_are_refused_not_dereferenced),
        cmocka_unit_test(test_a_failed_read_leaves_the_frame_empty_even_for_bad_arguments),
        cmocka_unit_test(test_formatting_into_no_buffer_reports_the_bytes_needed),
        cmocka_unit_test(test_memory_needed_refuses_a_null_result_pointer),
        cmocka_unit_test(test_bad_parameters_are_refused_with_arg_error),
        cmocka_unit_test(test_an_allocation_failure_is_reported_not_fatal),
        cmocka_unit_test(test_two_simulations_in_one_process_do_not_interfere),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
