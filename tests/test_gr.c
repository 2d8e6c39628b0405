/* SPDX-License-Identifier: MIT */
/* tools/gr: g(r) of a frame file. A square lattice gives the exact
 * neighbour counts over the ideal-gas ones; a dilute random gas gives 0
 * inside contact and 1 beyond a few diameters; bad input gets one line on
 * stderr and the documented exit status.
 *
 * DS_GR in the environment overrides the path the Makefile compiled in. */
#define _XOPEN_SOURCE 700
#include "test_util.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef DS_TEST_GR
#define DS_TEST_GR "tools/gr"
#endif

#define PI 3.14159265358979323846
#define MAX_BINS 4096

static char gr_path[4096], dir[64];

typedef struct result {
    int status;
    size_t bins;
    double r[MAX_BINS], g[MAX_BINS];
    char err[1024];
    int err_lines;
} result;

static void path_in_dir(char *out, size_t cap, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
}

/* Runs gr with args (a shell word list) and reads its output. */
static void run_gr(const char *args, result *res)
{
    char out[128], err[128], cmd[8192];
    path_in_dir(out, sizeof out, "out.txt");
    path_in_dir(err, sizeof err, "err.txt");
    snprintf(cmd, sizeof cmd, "'%s' %s > '%s' 2> '%s'", gr_path, args, out, err);
    const int rc = system(cmd);
    assert_true(rc != -1 && WIFEXITED(rc));
    res->status = WEXITSTATUS(rc);
    FILE *f = fopen(out, "r");
    assert_non_null(f);
    char line[256];
    res->bins = 0;
    while (fgets(line, sizeof line, f))
        if (line[0] != '#' && res->bins < MAX_BINS &&
            sscanf(line, "%lf %lf", &res->r[res->bins], &res->g[res->bins]) == 2)
            ++res->bins;
    fclose(f);
    f = fopen(err, "r");
    assert_non_null(f);
    const size_t len = fread(res->err, 1, sizeof res->err - 1, f);
    res->err[len] = '\0';
    fclose(f);
    res->err_lines = 0;
    for (size_t i = 0; i < len; ++i)
        res->err_lines += res->err[i] == '\n';
}

static void write_frame(const char *name, size_t n, const double *x, const double *y, double r)
{
    char path[128];
    path_in_dir(path, sizeof path, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (size_t j = 0; j < n; ++j)
        fprintf(f, "%.6f %.6f %.6f\n", x[j], y[j], r);
    assert_int_equal(fclose(f), 0);
}

enum { SIDE = 20, N = SIDE * SIDE };
#define SPACING 10.0

/* A square lattice of spacing SPACING filling a SIDE SPACING periodic box. */
static void write_square_lattice(const char *name)
{
    static double x[N], y[N];
    for (size_t j = 0; j < N; ++j) {
        x[j] = 5.0 + SPACING * (double)(j % SIDE);
        y[j] = 5.0 + SPACING * (double)(j / SIDE);
    }
    write_frame(name, N, x, y, 2.0);
}

/* g(r) of that lattice, bins of 0.3 up to 25. */
static void assert_square_lattice_shells(const result *res)
{
    const double a = SPACING, box = SIDE * a;
    assert_int_equal(res->status, 0);
    assert_int_equal(res->bins, 83); /* whole bins of 0.3 up to 25 */
    /* Every disk has 4 neighbours at a, 4 at a sqrt 2, 4 at 2a, 8 at a
     * sqrt 5: unordered pairs 2N, 2N, 2N, 4N. Over the ideal gas's
     * N (N - 1) / 2 pi (r1^2 - r0^2) / A pairs in the bin. */
    const double shells[][2] = {
        {a, 4.0}, {a * sqrt(2.0), 4.0}, {2.0 * a, 4.0}, {a * sqrt(5.0), 8.0}};
    for (size_t b = 0; b < res->bins; ++b) {
        const double r0 = 0.3 * (double)b, r1 = r0 + 0.3;
        double want = 0.0;
        for (size_t s = 0; s < 4; ++s)
            if (shells[s][0] >= r0 && shells[s][0] < r1)
                want = shells[s][1] * box * box / ((N - 1.0) * PI * (r1 * r1 - r0 * r0));
        /* Printed with 9 significant digits. */
        assert_true(fabs(res->g[b] - want) <= 1e-8 * want);
        assert_true(fabs(res->r[b] - (r0 + 0.15)) < 1e-9);
    }
}

static void test_a_square_lattice_has_its_exact_neighbour_shells(void **state)
{
    (void)state;
    write_square_lattice("square.txt");
    static result res;
    char args[256];
    snprintf(args, sizeof args, "--periodic --box %g --dr 0.3 --rmax 25 '%s/square.txt'",
             SIDE * SPACING, dir);
    run_gr(args, &res);
    assert_square_lattice_shells(&res);
}

/* Without options the box and boundary are the run's, from the
 * frames.json disks writes beside its frames: the lattice above in a
 * directory whose frames.json says 200 x 200 periodic has the same exact
 * shells. Options still win, and the contradiction is said. */
static void test_the_box_comes_from_the_runs_frames_json(void **state)
{
    (void)state;
    char path[128], args[256];
    path_in_dir(path, sizeof path, "run");
    assert_int_equal(mkdir(path, 0755), 0);
    write_square_lattice("run/frame_0000.txt");
    path_in_dir(path, sizeof path, "run/frames.json");
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("{\n  \"disksim_frames\": 1,\n  \"n\": 400,\n  \"box\": [200, 200],\n"
          "  \"boundary\": \"periodic\",\n  \"future_key\": {\"a\": [1, \"b\"]}\n}\n",
          f);
    assert_int_equal(fclose(f), 0);
    static result res;
    snprintf(args, sizeof args, "--dr 0.3 --rmax 25 '%s/run/frame_0000.txt'", dir);
    run_gr(args, &res);
    assert_int_equal(res.err_lines, 0);
    assert_square_lattice_shells(&res);
    snprintf(args, sizeof args, "--boundary walls --dr 0.3 --rmax 25 '%s/run/frame_0000.txt'", dir);
    run_gr(args, &res);
    assert_int_equal(res.status, 0);
    if (res.err_lines != 1 || !strstr(res.err, "gives the boundary periodic; taken walls"))
        fail_msg("stderr: %s", res.err);
}

static void test_a_dilute_random_gas_is_empty_inside_contact_and_ideal_beyond(void **state)
{
    (void)state;
    /* N disks at area fraction 0.05 placed at random without overlap (in
     * a periodic box, minimum image), by rejection, here and not by the
     * library, so the test needs no periodic simulation. */
    enum { N = 1000 };
    const double radius = 5.0, box = sqrt(N * PI * radius * radius / 0.05);
    static double x[N], y[N];
    ds_rng rng;
    ds_rng_seed(&rng, 99);
    for (size_t j = 0; j < N;) {
        x[j] = ds_rng_uniform(&rng, 0.0, box);
        y[j] = ds_rng_uniform(&rng, 0.0, box);
        int free_spot = 1;
        for (size_t k = 0; k < j && free_spot; ++k) {
            double dx = x[k] - x[j], dy = y[k] - y[j];
            dx -= box * round(dx / box);
            dy -= box * round(dy / box);
            /* A margin over 2R: the frame rounds to 6 decimals. */
            free_spot = dx * dx + dy * dy >= (2.0 * radius + 1e-5) * (2.0 * radius + 1e-5);
        }
        j += (size_t)free_spot;
    }
    write_frame("gas.txt", N, x, y, radius);
    static result res;
    char args[256];
    snprintf(args, sizeof args, "--periodic --box %.9g --dr 5 --rmax 200 '%s/gas.txt'", box, dir);
    run_gr(args, &res);
    assert_int_equal(res.status, 0);
    assert_int_equal(res.bins, 40);
    /* No pair closer than 2R = 10: the two bins below are exactly empty. */
    assert_true(res.g[0] == 0.0 && res.g[1] == 0.0);
    /* Beyond 3 diameters the gas is ideal. The pooled bins from 30 to 200
     * hold ~39000 ideal-gas pairs, so a relative counting error of
     * 1/sqrt(39000) = 0.5%: 3% is six of them. */
    double pairs = 0.0, ideal = 0.0;
    for (size_t b = 6; b < res.bins; ++b) {
        const double r0 = 5.0 * (double)b, r1 = r0 + 5.0;
        const double expected = 0.5 * N * (N - 1.0) * PI * (r1 * r1 - r0 * r0) / (box * box);
        pairs += res.g[b] * expected;
        ideal += expected;
    }
    print_message("pooled g(r) over [30, 200): %.4f from %.0f pairs\n", pairs / ideal, pairs);
    assert_true(fabs(pairs / ideal - 1.0) < 0.03);
}

static void test_a_walled_frame_from_the_library_has_nothing_inside_contact(void **state)
{
    (void)state;
    ds_sim *sim = test_create(500, 8.0, 3, DS_BROADPHASE_AUTO);
    ds_sim_run(sim, 50, NULL);
    char path[128];
    path_in_dir(path, sizeof path, "walls.txt");
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    assert_int_equal(ds_frame_write(sim, 0, f, NULL), DS_OK);
    assert_int_equal(fclose(f), 0);
    ds_sim_destroy(sim);
    static result res;
    char args[256];
    snprintf(args, sizeof args, "--dr 1 '%s'", path);
    run_gr(args, &res);
    assert_int_equal(res.status, 0);
    /* Default rmax 10 d = 160, bins of 1. The time step lets pairs overlap
     * a little between steps (a fraction of v dt = 0.1): the bins wholly
     * below 2R - 1 = 15 are empty. */
    assert_int_equal(res.bins, 160);
    for (size_t b = 0; b < 15; ++b)
        assert_true(res.g[b] == 0.0);
    /* Walls: the normalisation ignores them, so g stays below 1 far out. */
    assert_true(res.g[150] > 0.5 && res.g[150] < 1.0);
}

static void test_bad_input_gets_one_line_and_the_documented_status(void **state)
{
    (void)state;
    const double x[2] = {10.0, 20.0}, y[2] = {10.0, 10.0};
    write_frame("two.txt", 2, x, y, 1.0);
    const struct {
        const char *args;
        int status;
        const char *expect;
    } cases[] = {
        {"", 2, "no frame file"},
        {"--bogus two.txt", 2, "'--bogus'"},
        {"--dr abc two.txt", 2, "'abc'"},
        {"--dr -1 two.txt", 2, "'-1'"},
        {"--rmax nan two.txt", 2, "'nan'"},
        {"--box", 2, "--box needs a value"},
        {"two.txt two.txt", 2, "one frame file only"},
        {"--periodic --box 100 --rmax 60 two.txt", 2, "half the shorter side"},
        {"--dr 5 --rmax 1 two.txt", 2, "--dr"},
        {"missing.txt", 1, "missing.txt"},
        {"--box 15 two.txt", 1, "outside the 15 x 15 box"},
        {"--boundary ring two.txt", 2, "'ring'"},
        {"--boundary channel --box 100 --rmax 60 two.txt", 2, "half the width (50)"},
        {"bad/two.txt", 1, "bad/frames.json:3: \"box\" must be [width, height]"},
    };
    if (chdir(dir) != 0)
        fail_msg("cannot enter %s", dir);
    assert_int_equal(mkdir("bad", 0755), 0);
    write_frame("bad/two.txt", 2, x, y, 1.0);
    FILE *f = fopen("bad/frames.json", "w");
    assert_non_null(f);
    fputs("{\n  \"n\": 2,\n  \"box\": [1000],\n}\n", f);
    assert_int_equal(fclose(f), 0);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        static result res;
        run_gr(cases[i].args, &res);
        if (res.status != cases[i].status || res.err_lines != 1 ||
            !strstr(res.err, cases[i].expect))
            fail_msg("gr %s: status %d, stderr \"%s\"", cases[i].args, res.status, res.err);
    }
}

int main(void)
{
    const char *p = getenv("DS_GR");
    if (!realpath(p && *p ? p : DS_TEST_GR, gr_path)) {
        fprintf(stderr, "test_gr: no %s (run make)\n", p && *p ? p : DS_TEST_GR);
        return 1;
    }
    snprintf(dir, sizeof dir, "/tmp/test_gr.XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_square_lattice_has_its_exact_neighbour_shells),
        cmocka_unit_test(test_the_box_comes_from_the_runs_frames_json),
        cmocka_unit_test(test_a_dilute_random_gas_is_empty_inside_contact_and_ideal_beyond),
        cmocka_unit_test(test_a_walled_frame_from_the_library_has_nothing_inside_contact),
        cmocka_unit_test(test_bad_input_gets_one_line_and_the_documented_status),
    };
    const int failed = cmocka_run_group_tests(tests, NULL, NULL);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "test_gr: could not remove %s\n", dir);
    return failed;
}
