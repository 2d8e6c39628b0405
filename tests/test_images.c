/* SPDX-License-Identifier: MIT */
/* Periodic image counts and unwrapped centres, for both integrators and
 * every broad phase: a disk driven across the seam k times has image k;
 * a free disk's unwrapped centre is x0 + v t up to the rounding the header
 * states; no disk's unwrapped centre jumps in a step of a dense run
 * (which it would if a sort, merge or permutation dropped its counts);
 * ds_sim_set_disk keeps the counts, ds_sim_set_disks zeroes them, a checkpoint carries
 * them; the extended XYZ trajectory writes them, and ASE reads them back
 * as an (N, 2) integer array. */
#include "test_util.h"

#include <unistd.h>

static ds_sim *create_periodic(size_t n, double radius, double box, ds_integrator integ,
                               ds_broadphase bp, uint64_t seed)
{
    ds_params p = ds_params_default(n, radius);
    p.box = box;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = integ;
    p.broadphase = bp;
    p.seed = seed;
    p.speed = 1.0;
    p.dt = 0.01;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

/* Two disks: disk 0 flies with (vx, vy) from (x0, y0); disk 1, from
 * (5, 2.5), with (wx, wy), never meets it (at rest off disk 0's line, or
 * flying beside it with its velocity). */
static ds_sim *two_free_disks(ds_integrator integ, double x0, double y0, double vx, double vy,
                              double wx, double wy)
{
    ds_sim *sim = create_periodic(2, 0.5, 10.0, integ, DS_BROADPHASE_AUTO, 1);
    const ds_disk still = {5.0, 2.5, wx, wy}, moving = {x0, y0, vx, vy};
    const ds_disk both[2] = {moving, still};
    ds_error err;
    assert_int_equal(ds_sim_set_disks(sim, both, &err), DS_OK);
    return sim;
}

static void images_of(const ds_sim *sim, int32_t *image)
{
    assert_int_equal(ds_sim_get_images(sim, image, NULL), DS_OK);
}

static void driven_across_the_seam_k_times(ds_integrator integ)
{
    /* Disk 1 at rest is 3 / sqrt 5 > 2R from disk 0's line x + 2 y = 23
     * (mod the box). Box 10, speed 1 along x and -0.5 along y: x crosses the far edge
     * at t = 2, 12, 22, ...; y (from 7.5 down) crosses 0 at t = 15, 35. */
    ds_sim *sim = two_free_disks(integ, 8.0, 7.5, 1.0, -0.5, 0.0, 0.0);
    int32_t image[4];
    const uint64_t per_crossing = 1000; /* dt 0.01: 10 time units */
    ds_sim_run(sim, 300, NULL);         /* t = 3 */
    images_of(sim, image);
    assert_int_equal(image[0], 1);
    assert_int_equal(image[1], 0);
    for (int32_t k = 2; k <= 5; ++k) {
        ds_sim_run(sim, per_crossing, NULL); /* t = 3 + 10 (k - 1) */
        images_of(sim, image);
        assert_int_equal(image[0], k);
        assert_int_equal(image[1], -(int32_t)((3.0 + 10.0 * (k - 1) + 5.0) / 20.0));
        assert_int_equal(image[2], 0); /* the disk at rest */
        assert_int_equal(image[3], 0);
    }
    /* Back the other way, across the seam at x = 0, k times. */
    ds_disk d = ds_sim_get_disk(sim, 0);
    d.vx = -1.0;
    d.vy = 0.0;
    assert_int_equal(ds_sim_set_disk(sim, 0, d, NULL), DS_OK);
    images_of(sim, image);
    assert_int_equal(image[0], 5); /* ds_sim_set_disk keeps the counts */
    ds_sim_run(sim, 5 * per_crossing, NULL);
    images_of(sim, image);
    assert_int_equal(image[0], 0);
    ds_sim_run(sim, 150, NULL); /* across x = 0 once more */
    images_of(sim, image);
    assert_int_equal(image[0], -1);
    /* A new state starts in the box. */
    ds_disk d2[2];
    ds_error err;
    assert_int_equal(ds_sim_get_disks(sim, d2, NULL), DS_OK);
    assert_int_equal(ds_sim_set_disks(sim, d2, &err), DS_OK);
    images_of(sim, image);
    for (int k = 0; k < 4; ++k)
        assert_int_equal(image[k], 0);
    ds_sim_destroy(sim);
}

static void test_time_step_disk_driven_across_the_seam_k_times_has_image_k(void **state)
{
    (void)state;
    driven_across_the_seam_k_times(DS_INTEGRATOR_TIME_STEP);
}

static void test_event_disk_driven_across_the_seam_k_times_has_image_k(void **state)
{
    (void)state;
    driven_across_the_seam_k_times(DS_INTEGRATOR_EVENT_DRIVEN);
}

/* The bound of ds_sim_get_unwrapped's contract: (s + 2) eps (box + |u|). */
static void assert_unwrapped_is_free_flight(ds_integrator integ)
{
    const double x0 = 3.25, y0 = 7.5, vx = 0.7316, vy = -0.3041;
    ds_sim *sim = two_free_disks(integ, x0, y0, vx, vy, vx, vy);
    double xy[4];
    for (int round = 0; round < 10; ++round) {
        ds_sim_run(sim, long_run(5000), NULL);
        assert_int_equal(ds_sim_get_unwrapped(sim, xy, NULL), DS_OK);
        const double t = ds_sim_get_time(sim);
        const double ux = x0 + vx * t, uy = y0 + vy * t;
        /* The time step: one rounding a step; the event-driven one: one
         * a cell crossing (at most a few per unit length). */
        const double s =
            integ == DS_INTEGRATOR_TIME_STEP ? (double)ds_sim_get_steps(sim) : 10.0 * t;
        assert_true(fabs(xy[0] - ux) <= (s + 2.0) * DBL_EPSILON * (10.0 + fabs(ux)));
        assert_true(fabs(xy[1] - uy) <= (s + 2.0) * DBL_EPSILON * (10.0 + fabs(uy)));
        assert_true(fabs(ux) > 10.0 || round == 0 || quick_mode()); /* it has crossed */
    }
    ds_sim_destroy(sim);
}

static void test_time_step_unwrapped_free_disk_is_x0_plus_v_t(void **state)
{
    (void)state;
    assert_unwrapped_is_free_flight(DS_INTEGRATOR_TIME_STEP);
}

static void test_event_unwrapped_free_disk_is_x0_plus_v_t(void **state)
{
    (void)state;
    assert_unwrapped_is_free_flight(DS_INTEGRATOR_EVENT_DRIVEN);
}

/* In a step no disk's unwrapped centre moves further than the fastest
 * disk can (sqrt(2 K), unit masses) in dt, or than a step's chains carry
 * in all (n speed dt, event chains): a count lost or given to the wrong
 * disk by a sort, a merge or the cell permutation is a jump of a box. */
static void no_unwrapped_jump(ds_integrator integ, ds_broadphase bp, size_t n)
{
    ds_sim *sim = create_periodic(n, 0.5, 40.0, integ, bp, 7);
    const size_t m = ds_sim_get_count(sim);
    double *a = malloc(2 * m * sizeof *a), *b = malloc(2 * m * sizeof *b);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(ds_sim_get_unwrapped(sim, a, NULL), DS_OK);
    const double fastest = integ == DS_INTEGRATOR_EVENT_CHAIN
                               ? (double)m * 1.0 /* create_periodic's speed */
                               : sqrt(2.0 * ds_sim_get_kinetic_energy(sim));
    const double reach = fastest * ds_sim_get_dt(sim) * (1.0 + 1e-9) + 1e-9;
    int32_t *image = malloc(2 * m * sizeof *image);
    assert_non_null(image);
    int32_t most = 0;
    const int steps = quick_mode() ? 300 : 3000;
    for (int s = 0; s < steps; ++s) {
        ds_sim_step(sim, NULL);
        assert_int_equal(ds_sim_get_unwrapped(sim, b, NULL), DS_OK);
        for (size_t k = 0; k < 2 * m; k += 2)
            assert_true(hypot(b[k] - a[k], b[k + 1] - a[k + 1]) <= reach);
        double *t = a;
        a = b;
        b = t;
    }
    images_of(sim, image);
    for (size_t k = 0; k < 2 * m; ++k)
        most = image[k] > most ? image[k] : -image[k] > most ? -image[k] : most;
    assert_true(most >= 1); /* the run did cross the seams */
    free(image);
    free(a);
    free(b);
    ds_sim_destroy(sim);
}

/* Whether integrator integ takes broad phase bp (ds_params_check). */
static int takes(ds_integrator integ, ds_broadphase bp)
{
    ds_params p = ds_params_default(10, 0.5);
    p.integrator = integ;
    p.broadphase = bp;
    return ds_params_check(&p, NULL, NULL, NULL) == DS_OK;
}

static void test_every_broad_phase_keeps_the_counts_with_the_disks(void **state)
{
    (void)state;
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ)
        for (int bp = 0; bp < DS_BROADPHASE_COUNT; ++bp)
            if (bp != DS_BROADPHASE_AUTO && takes((ds_integrator)integ, (ds_broadphase)bp))
                no_unwrapped_jump((ds_integrator)integ, (ds_broadphase)bp,
                                  bp == DS_BROADPHASE_BRUTE ? 200 : 400); /* O(N^2) */
}

static void checkpoint_carries_the_counts(ds_integrator integ)
{
    ds_sim *sim = create_periodic(300, 0.5, 40.0, integ, DS_BROADPHASE_AUTO, 3);
    ds_sim_run(sim, 2000, NULL);
    const size_t n = ds_sim_get_count(sim), len = ds_checkpoint_get_size(sim);
    void *buf = malloc(len);
    assert_non_null(buf);
    assert_int_equal(ds_checkpoint_format(sim, buf, len, NULL, NULL), DS_OK);
    ds_sim *back = NULL;
    ds_error err;
    const ds_status parsed = ds_checkpoint_parse(buf, len, &back, &err);
    if (parsed != DS_OK)
        printf("      %s\n", err.message);
    assert_int_equal(parsed, DS_OK);
    int32_t *a = malloc(2 * n * sizeof *a), *b = malloc(2 * n * sizeof *b);
    assert_non_null(a);
    assert_non_null(b);
    images_of(sim, a);
    images_of(back, b);
    assert_memory_equal(a, b, 2 * n * sizeof *a);
    /* Both go on to the same counts. */
    ds_sim_run(sim, 1000, NULL);
    ds_sim_run(back, 1000, NULL);
    images_of(sim, a);
    images_of(back, b);
    assert_memory_equal(a, b, 2 * n * sizeof *a);
    free(a);
    free(b);
    free(buf);
    ds_sim_destroy(back);
    ds_sim_destroy(sim);
}

static void test_a_checkpoint_carries_the_counts(void **state)
{
    (void)state;
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ)
        checkpoint_carries_the_counts((ds_integrator)integ);
}

static void test_walls_have_no_images(void **state)
{
    (void)state;
    ds_sim *sim = test_create(20, 5.0, 1, DS_BROADPHASE_AUTO);
    ds_sim_run(sim, 100, NULL);
    int32_t image[40];
    double xy[40];
    images_of(sim, image);
    assert_int_equal(ds_sim_get_unwrapped(sim, xy, NULL), DS_OK);
    for (size_t i = 0; i < 20; ++i) {
        const ds_disk d = ds_sim_get_disk(sim, i);
        assert_int_equal(image[2 * i], 0);
        assert_int_equal(image[2 * i + 1], 0);
        assert_true(xy[2 * i] == d.x && xy[2 * i + 1] == d.y);
    }
    size_t len = 0;
    const size_t cap = ds_xyz_get_size(sim);
    char *text = malloc(cap + 1); /* the frame is not NUL-terminated */
    assert_non_null(text);
    assert_int_equal(ds_xyz_format(sim, text, cap, &len, NULL), DS_OK);
    assert_true(len <= cap);
    text[len] = '\0';
    assert_null(strstr(text, "map_shift"));
    free(text);
    assert_int_equal(ds_sim_get_images(NULL, image, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_images(sim, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_unwrapped(NULL, xy, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_unwrapped(sim, NULL, NULL), DS_ERR_ARG);
    ds_sim_destroy(sim);
}

/* The trajectory's image column (map_shift, OVITO's Periodic Image) is
 * the counts and 0 along z; ASE (Debian's python3, if it has ase) reads
 * it as an (N, 3) integer array, and pos + image cell is the unwrapped
 * centre. */
static void test_xyz_image_column_reads_back_in_ase(void **state)
{
    (void)state;
    ds_sim *sim = two_free_disks(DS_INTEGRATOR_EVENT_DRIVEN, 8.0, 7.5, 1.0, -0.5, 0.0, 0.0);
    ds_sim_run(sim, 4000, NULL); /* t = 40: x crossed 4 times, y twice */
    char path[] = "/tmp/ds_images_XXXXXX";
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    assert_non_null(out);
    assert_int_equal(ds_xyz_write(sim, out, NULL), DS_OK);
    fclose(out);
    FILE *in = fopen(path, "r");
    char text[1024];
    size_t len = fread(text, 1, sizeof text - 1, in);
    fclose(in);
    text[len] = '\0';
    assert_non_null(strstr(text, ":masses:R:1:map_shift:I:3 "));
    assert_non_null(strstr(text, " 4 -2 0\n"));
    ds_sim_destroy(sim);
    if (system("/usr/bin/python3 -c 'import ase.io' >/dev/null 2>&1") != 0) {
        unlink(path);
        printf("      skipped: /usr/bin/python3 has no ase\n");
        skip();
    }
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "/usr/bin/python3 -c \"import ase.io, numpy as np; a = ase.io.read('%s'); "
             "i = a.arrays['map_shift']; "
             "assert i.shape == (2, 3) and i.dtype.kind == 'i', (i.shape, i.dtype); "
             "assert i.tolist() == [[4, -2, 0], [0, 0, 0]], i; "
             "u = a.positions[:, :2] + i[:, :2] * np.diag(a.cell)[:2]; "
             "assert abs(u[0, 0] - 48.0) < 1e-5 and abs(u[0, 1] - (-12.5)) < 1e-5, u\"",
             path);
    const int rc = system(cmd);
    unlink(path);
    assert_int_equal(rc, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_time_step_disk_driven_across_the_seam_k_times_has_image_k),
        cmocka_unit_test(test_event_disk_driven_across_the_seam_k_times_has_image_k),
        cmocka_unit_test(test_time_step_unwrapped_free_disk_is_x0_plus_v_t),
        cmocka_unit_test(test_event_unwrapped_free_disk_is_x0_plus_v_t),
        cmocka_unit_test(test_every_broad_phase_keeps_the_counts_with_the_disks),
        cmocka_unit_test(test_a_checkpoint_carries_the_counts),
        cmocka_unit_test(test_walls_have_no_images),
        cmocka_unit_test(test_xyz_image_column_reads_back_in_ase),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
