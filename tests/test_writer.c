/* SPDX-License-Identifier: MIT */
/* Writers (ds_writer): every trajectory format behind one interface. Each
 * frame a text writer writes is, byte for byte, what its format's own
 * function formats (ds_frame_format, ds_xyz_format), frames follow one
 * another in the file, and a write that fails is DS_ERR_IO. GSD, a binary
 * format with an index, has its own test (tests/test_gsd.c). */
#include "test_util.h"

/* The bytes of a memory stream after the writer of format wrote frames
 * frames of sim, one step apart; *len their length. */
static char *written(ds_format format, unsigned flags, ds_sim *sim, int frames, size_t *len)
{
    char *text = NULL;
    FILE *f = open_memstream(&text, len);
    assert_non_null(f);
    ds_writer *w = NULL;
    assert_int_equal(ds_writer_open(format, f, flags, &w, NULL), DS_OK);
    for (int k = 0; k < frames; ++k) {
        assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
        assert_int_equal(ds_sim_step(sim, NULL), DS_OK);
    }
    assert_int_equal(ds_writer_close(w, NULL), DS_OK);
    fclose(f);
    return text;
}

/* The text format's own function gives for sim now. */
static char *formatted(ds_format format, int velocities, const ds_sim *sim, size_t *len)
{
    const size_t cap =
        format == DS_FORMAT_XYZ ? ds_xyz_get_size(sim) : ds_frame_get_size(sim, velocities);
    char *buf = malloc(cap);
    assert_non_null(buf);
    const ds_status st = format == DS_FORMAT_XYZ
                             ? ds_xyz_format(sim, buf, cap, len, NULL)
                             : ds_frame_format(sim, velocities, buf, cap, len, NULL);
    assert_int_equal(st, DS_OK);
    return buf;
}

/* The formats written as text, a frame after another. */
static int is_text(int format) { return format == DS_FORMAT_FRAME || format == DS_FORMAT_XYZ; }

static void test_a_writer_writes_its_formats_frames_one_after_another(void **state)
{
    (void)state;
    for (int format = 0; format < DS_FORMAT_COUNT; ++format)
        for (unsigned flags = 0; flags <= DS_WRITE_VELOCITIES && is_text(format); ++flags) {
            ds_sim *a = test_create(50, 5.0, 3, DS_BROADPHASE_AUTO);
            ds_sim *b = test_create(50, 5.0, 3, DS_BROADPHASE_AUTO);
            size_t len = 0;
            char *text = written((ds_format)format, flags, a, 3, &len);
            /* The same frames from the format's function, concatenated. */
            size_t at = 0;
            for (int k = 0; k < 3; ++k) {
                size_t l = 0;
                char *want = formatted((ds_format)format, flags != 0, b, &l);
                assert_true(at + l <= len);
                assert_memory_equal(text + at, want, l);
                at += l;
                free(want);
                ds_sim_step(b, NULL);
            }
            assert_int_equal(at, len);
            free(text);
            ds_sim_destroy(a);
            ds_sim_destroy(b);
        }
}

static void test_a_writer_refuses_what_it_cannot_write(void **state)
{
    (void)state;
    ds_writer *w = (ds_writer *)&w;
    ds_error err;
    assert_int_equal(ds_writer_open(DS_FORMAT_COUNT, stdout, 0, &w, &err), DS_ERR_ARG);
    assert_null(w);
    assert_string_equal(err.field, "format");
    assert_int_equal(ds_writer_open(DS_FORMAT_FRAME, stdout, 0x80u, &w, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "flags");
    assert_int_equal(ds_writer_open(DS_FORMAT_FRAME, NULL, 0, &w, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "out");
    assert_int_equal(ds_writer_close(NULL, &err), DS_OK);
    /* A full device: the frame's flush fails (GSD's header's, at open). */
    FILE *full = fopen("/dev/full", "wb");
    if (!full) {
        print_message("skipped the write failure: no /dev/full\n");
        return;
    }
    ds_sim *sim = test_create(50, 5.0, 3, DS_BROADPHASE_AUTO);
    for (int format = 0; format < DS_FORMAT_COUNT; ++format) {
        if (!is_text(format)) {
            assert_int_equal(ds_writer_open((ds_format)format, full, 0, &w, &err), DS_ERR_IO);
            assert_string_equal(err.field, "out");
            clearerr(full);
            continue;
        }
        assert_int_equal(ds_writer_open((ds_format)format, full, 0, &w, &err), DS_OK);
        assert_int_equal(ds_writer_write(w, sim, &err), DS_ERR_IO);
        assert_int_equal(err.status, DS_ERR_IO);
        assert_string_equal(err.field, "out");
        assert_int_equal(ds_writer_write(w, NULL, &err), DS_ERR_ARG);
        ds_writer_close(w, NULL);
        clearerr(full);
    }
    fclose(full);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_writer_writes_its_formats_frames_one_after_another),
        cmocka_unit_test(test_a_writer_refuses_what_it_cannot_write),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
