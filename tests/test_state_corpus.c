/* SPDX-License-Identifier: MIT */
/* Replays tests/corpus-state/ (every checkpoint the fuzzer of the loader
 * ever found to crash, hang or exhaust memory) through its harness, so the
 * ordinary suite, its sanitizer build and valgrind keep guarding against
 * them without clang or libFuzzer. Each must merely pass the harness:
 * refused with a reason, or loaded and run. */
#include "test_util.h"

#include <dirent.h>

#include "fuzz_state.c"

static const char *corpus_dir(void)
{
    const char *dir = getenv("DS_STATE_CORPUS");
    return dir && *dir ? dir : "tests/corpus-state";
}

static void test_every_found_checkpoint_passes_the_harness(void **state)
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
        FILE *f = fopen(path, "rb");
        assert_non_null(f);
        static uint8_t bytes[1 << 16];
        const size_t len = fread(bytes, 1, sizeof bytes, f);
        fclose(f);
        LLVMFuzzerTestOneInput(bytes, len);
        ++files;
    }
    closedir(d);
    assert_true(files >= 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_found_checkpoint_passes_the_harness),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
