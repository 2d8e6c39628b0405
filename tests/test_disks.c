/* SPDX-License-Identifier: MIT */
/* End to end: the built ./disks command and the gnuplot animation script.
 * Run from the repository root (as `make test` does). */
#include "test_util.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

static char workdir[256];

static int setup(void **state)
{
    (void)state;
    snprintf(workdir, sizeof workdir, "/tmp/ds_test_disks_XXXXXX");
    return mkdtemp(workdir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", workdir);
    return system(cmd) == 0 ? 0 : -1;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    rewind(f);
    char *buf = malloc((size_t)size + 1);
    *len = fread(buf, 1, (size_t)size, f);
    buf[*len] = '\0';
    fclose(f);
    return buf;
}

static int run(const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "./disks %s >%s/stdout.txt 2>%s/stderr.txt", args, workdir, workdir);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static size_t count_entries(const char *dir, const char *prefix)
{
    DIR *d = opendir(dir);
    size_t n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    if (d)
        closedir(d);
    return n;
}

static void test_small_run_writes_every_frame_with_n_lines(void **state)
{
    (void)state;
    char args[512], path[512];
    snprintf(args, sizeof args, "50 5 --frames 4 --steps-per-frame 10 --out %s/run", workdir);
    assert_int_equal(run(args), 0);
    snprintf(path, sizeof path, "%s/run", workdir);
    assert_int_equal(count_entries(path, "frame_"), 4);
    assert_int_equal(count_entries(path, ".frame_"), 0); /* no temporaries left */
    for (int k = 0; k < 4; ++k) {
        size_t len = 0;
        snprintf(path, sizeof path, "%s/run/frame_%04d.txt", workdir, k);
        char *text = slurp(path, &len);
        assert_non_null(text);
        ds_frame frame;
        assert_int_equal(ds_frame_parse(text, len, &frame, NULL), DS_OK);
        assert_int_equal(frame.count, 50);
        assert_int_equal(frame.columns, 3);
        /* "x y R": six decimals, then the radius exactly as "5". */
        char *first_nl = strchr(text, '\n');
        assert_true(first_nl - text > 4 && strncmp(first_nl - 2, " 5", 2) == 0);
        assert_true(*(first_nl - 9) == '.'); /* 6 digits after the point */
        ds_frame_free(&frame);
        free(text);
    }
    size_t len = 0;
    snprintf(path, sizeof path, "%s/stdout.txt", workdir);
    char *out = slurp(path, &len);
    assert_non_null(strstr(out, "collision processing time:"));
    assert_non_null(strstr(out, "disk-disk collisions:"));
    free(out);
}

static void test_frame_zero_is_the_library_initial_state(void **state)
{
    (void)state;
    char args[512], path[512];
    snprintf(args, sizeof args, "30 5 --seed 99 --frames 1 --quiet --out %s/f0", workdir);
    assert_int_equal(run(args), 0);
    snprintf(path, sizeof path, "%s/f0/frame_0000.txt", workdir);
    ds_frame frame;
    assert_int_equal(ds_frame_read(path, &frame, NULL), DS_OK);
    ds_sim *sim = test_create(30, 5.0, 99, DS_BROADPHASE_AUTO);
    for (size_t i = 0; i < 30; ++i) { /* line i is disk i */
        ds_disk d = ds_sim_get_disk(sim, i);
        assert_true(fabs(frame.disks[i].x - d.x) <= 5e-7 + 1e-12);
        assert_true(fabs(frame.disks[i].y - d.y) <= 5e-7 + 1e-12);
    }
    ds_sim_destroy(sim);
    ds_frame_free(&frame);
    snprintf(path, sizeof path, "%s/stdout.txt", workdir);
    size_t len = 0;
    char *out = slurp(path, &len);
    assert_int_equal(len, 0); /* --quiet */
    free(out);
}

static void test_same_seed_gives_identical_frames(void **state)
{
    (void)state;
    char args[512], a[512], b[512];
    for (int k = 0; k < 2; ++k) {
        snprintf(args, sizeof args, "100 5 --frames 2 --quiet --out %s/same%d", workdir, k);
        assert_int_equal(run(args), 0);
    }
    size_t la = 0, lb = 0;
    snprintf(a, sizeof a, "%s/same0/frame_0001.txt", workdir);
    snprintf(b, sizeof b, "%s/same1/frame_0001.txt", workdir);
    char *ta = slurp(a, &la), *tb = slurp(b, &lb);
    assert_int_equal(la, lb);
    assert_memory_equal(ta, tb, la);
    free(ta);
    free(tb);
}

static void test_bad_argument_gives_one_line_and_usage_status(void **state)
{
    (void)state;
    assert_int_equal(run("400 abc"), 2);
    char path[512];
    snprintf(path, sizeof path, "%s/stderr.txt", workdir);
    size_t len = 0;
    char *err = slurp(path, &len);
    assert_non_null(strstr(err, "'abc'"));
    assert_true(len > 0 && strchr(err, '\n') == err + len - 1); /* exactly one line */
    free(err);
}

static void test_gnuplot_script_makes_one_gif_image_per_frame(void **state)
{
    (void)state;
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        printf("      skipped: gnuplot is not installed\n");
        skip();
    }
    char args[512], cmd[2048], path[512];
    snprintf(args, sizeof args, "40 8 --frames 6 --steps-per-frame 20 --quiet --out %s/gif",
             workdir);
    assert_int_equal(run(args), 0);
    char cwd[512];
    assert_non_null(getcwd(cwd, sizeof cwd));
    snprintf(cmd, sizeof cmd, "cd %s/gif && gnuplot %s/animate_disk.plt >/dev/null 2>&1", workdir,
             cwd);
    assert_int_equal(system(cmd), 0);
    snprintf(path, sizeof path, "%s/gif/animation.gif", workdir);
    size_t len = 0;
    unsigned char *gif = (unsigned char *)slurp(path, &len);
    assert_non_null(gif);
    assert_memory_equal(gif, "GIF89a", 6);
    /* Each animation image carries a Graphic Control Extension block,
     * 0x21 0xF9 0x04: count them. */
    size_t images = 0;
    for (size_t k = 0; k + 3 < len; ++k)
        images += gif[k] == 0x21 && gif[k + 1] == 0xF9 && gif[k + 2] == 0x04;
    assert_int_equal(images, 6);
    free(gif);
}

int main(void)
{
    if (access("./disks", X_OK) != 0) {
        fprintf(stderr, "test_disks: run from the repository root after `make`\n");
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_small_run_writes_every_frame_with_n_lines),
        cmocka_unit_test(test_frame_zero_is_the_library_initial_state),
        cmocka_unit_test(test_same_seed_gives_identical_frames),
        cmocka_unit_test(test_bad_argument_gives_one_line_and_usage_status),
        cmocka_unit_test(test_gnuplot_script_makes_one_gif_image_per_frame),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
