/* SPDX-License-Identifier: MIT */
/* Replays tests/corpus/ (the fuzzer's seeds and every crash it ever found)
 * through the fuzz harness, so the ordinary suite, its sanitizer build and
 * valgrind keep guarding against them without clang or libFuzzer.
 * Files named ok-* must parse, bad-* must be refused; any other name (a
 * fuzzer find such as crash-<sha1>) must merely pass the harness's checks. */
#include "test_util.h"

#include <dirent.h>

#include "fuzz_frame.c"

static const char *corpus_dir(void)
{
    const char *dir = getenv("DS_CORPUS");
    return dir && *dir ? dir : "tests/corpus";
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    size_t cap = 1 << 16;
    char *buf = malloc(cap);
    assert_non_null(buf);
    *len = fread(buf, 1, cap, f);
    assert_int_equal(ferror(f), 0);
    fclose(f);
    return buf;
}

static void test_every_corpus_file_passes_the_harness_and_its_name(void **state)
{
    (void)state;
    DIR *d = opendir(corpus_dir());
    assert_non_null(d);
    struct dirent *e;
    int files = 0;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.')
            continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%.900s", corpus_dir(), e->d_name);
        size_t len = 0;
        char *bytes = slurp(path, &len);
        LLVMFuzzerTestOneInput((const uint8_t *)bytes, len);
        ds_frame frame;
        ds_error err;
        ds_status st = ds_frame_parse(bytes, len, &frame, &err);
        if (strncmp(e->d_name, "ok-", 3) == 0 && st != DS_OK)
            fail_msg("%s: refused: line %zu: %s", e->d_name, err.index, err.message);
        if (strncmp(e->d_name, "bad-", 4) == 0 && st != DS_ERR_FORMAT)
            fail_msg("%s: accepted, status %d", e->d_name, (int)st);
        ds_frame_free(&frame);
        free(bytes);
        ++files;
    }
    closedir(d);
    /* The seeds alone are 21 files: fewer means the wrong directory. */
    assert_true(files >= 21);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_corpus_file_passes_the_harness_and_its_name),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
