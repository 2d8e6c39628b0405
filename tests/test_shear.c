/* SPDX-License-Identifier: MIT */
/* Shear: Lees-Edwards boundaries (ds_sim_set_shear). What a user of a
 * sheared box relies on: the images move as the rate says (a free disk
 * flies straight in the unfolded plane), the heat the shear puts in is
 * its stress times the rate (an identity of the dynamics, exact to
 * rounding), no pair is missed across the moving edge (the cells
 * against brute force, and no overlap), the flow is the linear profile,
 * checkpoints continue to the bit, and what cannot be sheared is refused. */
#include "test_util.h"

#define SIDE 1000.0

/* n disks at area fraction eta on a lattice in a periodic 1000 x 1000
 * box, event-driven, the broad phase given, relaxed for `relax` steps. */
static ds_sim *fluid(size_t n, double eta, ds_broadphase bp, uint64_t relax)
{
    ds_params p =
        ds_params_default(n, sqrt(eta * SIDE * SIDE / ((double)n * 3.14159265358979323846)));
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.placement = DS_PLACEMENT_LATTICE;
    p.broadphase = bp;
    p.seed = 7;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    if (relax)
        assert_int_equal(ds_sim_run(sim, relax, NULL), DS_OK);
    return sim;
}

/* The kinetic energy of the peculiar velocities, vx less rate (y - H/2),
 * from the disks. */
static double peculiar_energy(const ds_sim *sim, double rate)
{
    const size_t n = ds_sim_get_count(sim);
    ds_disk *d = malloc(n * sizeof *d);
    assert_non_null(d);
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    const double middle = 0.5 * ds_sim_get_box_height(sim);
    double k = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double cx = d[i].vx - rate * (d[i].y - middle);
        k += 0.5 * (cx * cx + d[i].vy * d[i].vy);
    }
    free(d);
    return k;
}

/* With no heat bath the shear heats the gas at exactly -rate P_xy A: the
 * peculiar kinetic energy changes by -rate times the change of the
 * stress integral's xy component. The flights' part (dc_x/dt = -rate
 * v_y) and each collision's (the pair's peculiar frames differ by rate
 * times their separation along y) are exact, so the two sides agree up
 * to rounding: at most one rounding of the kinetic tensor (~2 K) per
 * event, events x DBL_EPSILON x 2 K. */
static void test_the_heat_a_shear_puts_in_is_its_stress_times_the_rate(void **state)
{
    (void)state;
    const double rate = 0.3; /* the images at 300 against a thermal speed of 100 */
    ds_sim *sim = fluid(400, 0.3, DS_BROADPHASE_AUTO, 2000);
    assert_int_equal(ds_sim_set_shear(sim, rate, NULL), DS_OK);
    double s0[3];
    assert_int_equal(ds_sim_get_stress_integral(sim, s0, NULL), DS_OK);
    const double k0 = peculiar_energy(sim, rate);
    const uint64_t c0 = ds_sim_get_collision_count(sim);
    for (int block = 0; block < 5; ++block) {
        assert_int_equal(ds_sim_run(sim, long_run(1000), NULL), DS_OK);
        double s[3];
        assert_int_equal(ds_sim_get_stress_integral(sim, s, NULL), DS_OK);
        const double k = peculiar_energy(sim, rate), heat = -rate * (s[2] - s0[2]);
        const double events = (double)(ds_sim_get_collision_count(sim) - c0) * 4.0 + 1e4;
        assert_true(heat > 0.0); /* shearing heats */
        assert_true(fabs((k - k0) - heat) <= events * DBL_EPSILON * 2.0 * k);
    }
    ds_sim_destroy(sim);
}

/* Unfolded, the periodic images tile the plane and a free disk flies
 * straight: its unwrapped centre (x + ix W + iy offset, y + iy H) is x0 +
 * v0 t, however often it crosses the moving top and bottom (each time
 * its velocity in the box changes by the images' speed, and x by their
 * shift). The rounding: one rounding of the flight per crossing and of
 * each sum, relative to the largest term (the offset grows as rate H t). */
static void test_a_free_disk_flies_straight_through_the_moving_images(void **state)
{
    (void)state;
    ds_params p = ds_params_default(1, 5.0);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.box_y = 700.0;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_disk(sim, 0, (ds_disk){123.0, 456.0, 37.0, 411.0}, NULL), DS_OK);
    const double rate = -0.7;
    assert_int_equal(ds_sim_set_shear(sim, rate, NULL), DS_OK);
    ds_disk d0;
    assert_int_equal(ds_sim_get_disks(sim, &d0, NULL), DS_OK);
    assert_true(d0.vx == 37.0 + rate * (456.0 - 350.0)); /* the profile added */
    const double t0 = ds_sim_get_time(sim);
    for (int k = 0; k < 20; ++k) {
        assert_int_equal(ds_sim_run(sim, 997, NULL), DS_OK);
        const double t = ds_sim_get_time(sim) - t0;
        double xy[2];
        int32_t image[2];
        assert_int_equal(ds_sim_get_unwrapped(sim, xy, NULL), DS_OK);
        assert_int_equal(ds_sim_get_images(sim, image, NULL), DS_OK);
        const double scale =
            SIDE + fabs(d0.x + d0.vx * t) + fabs((double)image[1] * ds_sim_get_shear_offset(sim));
        const double crossings = fabs((double)image[0]) + fabs((double)image[1]) + 2.0;
        assert_true(fabs(xy[0] - (d0.x + d0.vx * t)) <= 4.0 * crossings * DBL_EPSILON * scale);
        assert_true(fabs(xy[1] - (d0.y + d0.vy * t)) <=
                    4.0 * crossings * DBL_EPSILON * (700.0 + fabs(d0.y + d0.vy * t)));
        assert_true(image[1] > 0); /* it went up through the top, again and again */
    }
    assert_true(fabs(ds_sim_get_shear_offset(sim) - rate * 700.0 * (ds_sim_get_time(sim) - t0)) <=
                1e-9 * fabs(ds_sim_get_shear_offset(sim)));
    ds_sim_destroy(sim);
}

/* Whether any two disks overlap, the separation taken to the nearest
 * sheared image by hand. */
static int any_overlap(const ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    ds_disk *d = malloc(n * sizeof *d);
    assert_non_null(d);
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    const double w = ds_sim_get_box_width(sim), h = ds_sim_get_box_height(sim);
    const double shift = ds_sim_get_shear_shift(sim), sigma = 2.0 * ds_sim_get_radius(sim);
    int found = 0;
    for (size_t i = 0; i < n && !found; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            double dx = d[j].x - d[i].x, dy = d[j].y - d[i].y;
            if (dy > 0.5 * h) {
                dy -= h;
                dx -= shift;
            } else if (dy < -0.5 * h) {
                dy += h;
                dx += shift;
            }
            dx -= w * floor(dx / w + 0.5);
            if (dx * dx + dy * dy < sigma * sigma * (1.0 - 2.0 * DS_CONTACT_TOLERANCE))
                found = 1;
        }
    free(d);
    return found;
}

/* The cells reach across the moving edge through a stencil that follows
 * the images; brute force (one cell: every disk everyone's candidate,
 * through every image) misses nothing by construction. The two runs are
 * the same collisions in the same order: a pair one missed would send
 * them apart at once (by a diameter). They agree to the growth of
 * rounding over a few collisions per disk (chaos: about e per collision,
 * from 1e-13: far below 1e-6), and no pair overlaps. */
static void test_the_cells_meet_every_pair_brute_force_meets(void **state)
{
    (void)state;
    ds_sim *cells = fluid(300, 0.5, DS_BROADPHASE_CELLS, 500);
    ds_sim *brute = fluid(300, 0.5, DS_BROADPHASE_BRUTE, 500);
    const double rate = 0.8; /* the images pass a cell width in ~0.03 */
    assert_int_equal(ds_sim_set_shear(cells, rate, NULL), DS_OK);
    assert_int_equal(ds_sim_set_shear(brute, rate, NULL), DS_OK);
    /* Both start where the unsheared runs left them, whose candidates
     * came in different orders: the same to rounding. */
    for (int block = 0; block < 4; ++block) {
        assert_int_equal(ds_sim_run(cells, 25, NULL), DS_OK);
        assert_int_equal(ds_sim_run(brute, 25, NULL), DS_OK);
        ds_disk a[300], b[300];
        assert_int_equal(ds_sim_get_disks(cells, a, NULL), DS_OK);
        assert_int_equal(ds_sim_get_disks(brute, b, NULL), DS_OK);
        for (size_t i = 0; i < 300; ++i) {
            assert_true(fabs(a[i].x - b[i].x) < 1e-6 && fabs(a[i].y - b[i].y) < 1e-6);
            assert_true(fabs(a[i].vx - b[i].vx) < 1e-6 && fabs(a[i].vy - b[i].vy) < 1e-6);
        }
        assert_false(any_overlap(cells));
    }
    /* Long after: still no overlap anywhere, at a shift of many widths. */
    assert_int_equal(ds_sim_run(cells, long_run(20000), NULL), DS_OK);
    assert_false(any_overlap(cells));
    assert_true(ds_sim_get_shear_offset(cells) > 5.0 * SIDE * (quick_mode() ? 0.1 : 1.0));
    ds_sim_destroy(cells);
    ds_sim_destroy(brute);
}

/* A shear of rate 0 set before the first step is the periodic box: the
 * stencils reach four columns across the edge where they reached three,
 * the images stand still, and the run is the same to the bit. */
static void test_a_shear_of_rate_zero_is_the_periodic_box(void **state)
{
    (void)state;
    ds_sim *plain = fluid(256, 0.6, DS_BROADPHASE_AUTO, 0);
    ds_sim *sheared = fluid(256, 0.6, DS_BROADPHASE_AUTO, 0);
    assert_int_equal(ds_sim_set_shear(sheared, 0.0, NULL), DS_OK);
    assert_int_equal(ds_sim_run(plain, long_run(3000), NULL), DS_OK);
    assert_int_equal(ds_sim_run(sheared, long_run(3000), NULL), DS_OK);
    ds_disk a[256], b[256];
    assert_int_equal(ds_sim_get_disks(plain, a, NULL), DS_OK);
    assert_int_equal(ds_sim_get_disks(sheared, b, NULL), DS_OK);
    assert_memory_equal(a, b, sizeof a);
    assert_true(ds_sim_get_collision_count(plain) == ds_sim_get_collision_count(sheared));
    ds_sim_destroy(plain);
    ds_sim_destroy(sheared);
}

/* A sheared run under the isokinetic bath goes on from a checkpoint to
 * the bit: disks, images, the images' offset and the stress integral. */
static void test_a_sheared_run_continues_from_a_checkpoint_to_the_bit(void **state)
{
    (void)state;
    ds_sim *a = fluid(200, 0.4, DS_BROADPHASE_AUTO, 200);
    assert_int_equal(ds_sim_set_shear(a, 0.5, NULL), DS_OK);
    assert_int_equal(ds_sim_set_thermostat(a, DS_THERMOSTAT_ISOKINETIC, 5000.0, 0.0, NULL), DS_OK);
    assert_int_equal(ds_sim_run(a, 777, NULL), DS_OK);
    ds_sim *b = through_checkpoint(a);
    assert_true(ds_sim_get_shear(b) == 0.5);
    assert_int_equal(ds_sim_run(a, 1500, NULL), DS_OK);
    assert_int_equal(ds_sim_run(b, 1500, NULL), DS_OK);
    ds_disk da[200], db[200];
    int32_t ia[400], ib[400];
    double sa[3], sb[3];
    assert_int_equal(ds_sim_get_disks(a, da, NULL), DS_OK);
    assert_int_equal(ds_sim_get_disks(b, db, NULL), DS_OK);
    assert_int_equal(ds_sim_get_images(a, ia, NULL), DS_OK);
    assert_int_equal(ds_sim_get_images(b, ib, NULL), DS_OK);
    assert_int_equal(ds_sim_get_stress_integral(a, sa, NULL), DS_OK);
    assert_int_equal(ds_sim_get_stress_integral(b, sb, NULL), DS_OK);
    assert_memory_equal(da, db, sizeof da);
    assert_memory_equal(ia, ib, sizeof ia);
    assert_memory_equal(sa, sb, sizeof sa);
    assert_true(ds_sim_get_shear_offset(a) == ds_sim_get_shear_offset(b));
    assert_true(ds_sim_get_temperature(a) == ds_sim_get_temperature(b));
    ds_sim_destroy(a);
    ds_sim_destroy(b);
}

/* In the steady state under the isokinetic bath the mean velocity along
 * x is the profile rate (y - H/2): the slope of the bins' means, fitted
 * in each of `blocks` blocks, has the rate within 4 standard errors of
 * the blocks' mean (a false alarm about once in 16,000 runs), and the
 * temperature is the bath's. */
static void test_the_flow_is_the_linear_profile_of_the_rate(void **state)
{
    (void)state;
    const double rate = 0.2;
    ds_sim *sim = fluid(400, 0.3, DS_BROADPHASE_AUTO, 1000);
    assert_int_equal(ds_sim_set_shear(sim, rate, NULL), DS_OK);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ISOKINETIC, 5000.0, 0.0, NULL),
                     DS_OK);
    assert_int_equal(ds_sim_run(sim, 2000, NULL), DS_OK);
    enum { BINS = 8, BLOCKS = 10 };
    const int frames = quick_mode() ? 10 : 40;
    double slope[BLOCKS];
    ds_disk d[400];
    for (int b = 0; b < BLOCKS; ++b) {
        double sum[BINS] = {0}, count[BINS] = {0};
        for (int f = 0; f < frames; ++f) {
            assert_int_equal(ds_sim_run(sim, 50, NULL), DS_OK);
            assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
            for (size_t i = 0; i < 400; ++i) {
                const int k = (int)(d[i].y / SIDE * BINS);
                sum[k < BINS ? k : BINS - 1] += d[i].vx;
                count[k < BINS ? k : BINS - 1] += 1.0;
            }
        }
        double sy = 0.0, syy = 0.0, su = 0.0, syu = 0.0;
        for (int k = 0; k < BINS; ++k) {
            const double y = (k + 0.5) * SIDE / BINS, u = sum[k] / count[k];
            sy += y;
            syy += y * y;
            su += u;
            syu += y * u;
        }
        slope[b] = (BINS * syu - sy * su) / (BINS * syy - sy * sy);
        assert_true(fabs(ds_sim_get_temperature(sim) / 5000.0 - 1.0) < 1e-9);
    }
    const block_stats s = stats_of(slope, BLOCKS);
    assert_true(fabs(s.mean - rate) < 4.0 * s.error);
    assert_true(s.error < 0.1 * rate); /* the test can tell */
    ds_sim_destroy(sim);
}

/* What cannot be sheared is refused, naming the field, and changes
 * nothing. */
static void test_what_cannot_be_sheared_is_refused(void **state)
{
    (void)state;
    ds_error err;
    ds_sim *sim = fluid(100, 0.3, DS_BROADPHASE_AUTO, 0);
    const double bad[] = {NAN, INFINITY, -INFINITY, 2000.0 /* 2 per step at dt 0.001 */};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        assert_int_equal(ds_sim_set_shear(sim, bad[k], &err), DS_ERR_ARG);
        assert_string_equal(err.field, "rate");
        assert_true(ds_sim_get_shear(sim) == 0.0);
    }
    assert_int_equal(ds_sim_set_shear(NULL, 1.0, NULL), DS_ERR_ARG);
    assert_true(ds_sim_get_shear(NULL) == 0.0);
    /* Andersen's draws know no profile; a barostat's box moves. */
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, 0.0, 0.0, NULL), DS_OK);
    assert_int_equal(ds_sim_set_shear(sim, 0.1, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "thermostat");
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_NONE, 0.0, 0.0, NULL), DS_OK);
    assert_int_equal(ds_sim_set_barostat(sim, 2.0, 0, 0.0, 0, NULL), DS_OK);
    assert_int_equal(ds_sim_set_shear(sim, 0.1, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "barostat");
    assert_int_equal(ds_sim_set_barostat(sim, 0.0, 0, 0.0, 0, NULL), DS_OK);
    /* Sheared, the others refuse in turn. */
    assert_int_equal(ds_sim_set_shear(sim, 0.1, NULL), DS_OK);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, 0.0, 0.0, &err),
                     DS_ERR_ARG);
    assert_string_equal(err.field, "thermostat");
    assert_int_equal(ds_sim_set_barostat(sim, 2.0, 0, 0.0, 0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "shear");
    assert_int_equal(ds_sim_set_growth(sim, 0.01, 0.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "shear");
    assert_true(ds_sim_get_shear(sim) == 0.1);
    ds_sim_destroy(sim);
    /* Walls, a channel (walls along y), and integrators without a sheared
     * box. */
    for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
        if (b == DS_BOUNDARY_PERIODIC)
            continue;
        ds_params p = ds_params_default(50, 5.0);
        p.boundary = (ds_boundary)b;
        p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        assert_int_equal(ds_sim_set_shear(sim, 0.1, &err), DS_ERR_ARG);
        assert_string_equal(err.field, "boundary");
        ds_sim_destroy(sim);
    }
    for (int i = 0; i < DS_INTEGRATOR_COUNT; ++i) {
        if (i == DS_INTEGRATOR_EVENT_DRIVEN)
            continue;
        ds_params p = ds_params_default(50, 5.0);
        p.boundary = DS_BOUNDARY_PERIODIC;
        p.integrator = (ds_integrator)i;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        assert_int_equal(ds_sim_set_shear(sim, 0.1, &err), DS_ERR_ARG);
        assert_string_equal(err.field, "integrator");
        ds_sim_destroy(sim);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_the_heat_a_shear_puts_in_is_its_stress_times_the_rate),
        cmocka_unit_test(test_a_free_disk_flies_straight_through_the_moving_images),
        cmocka_unit_test(test_the_cells_meet_every_pair_brute_force_meets),
        cmocka_unit_test(test_a_shear_of_rate_zero_is_the_periodic_box),
        cmocka_unit_test(test_a_sheared_run_continues_from_a_checkpoint_to_the_bit),
        cmocka_unit_test(test_the_flow_is_the_linear_profile_of_the_rate),
        cmocka_unit_test(test_what_cannot_be_sheared_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
