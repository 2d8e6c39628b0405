/* SPDX-License-Identifier: MIT */
/* The event-driven integrator, through the public API: exact analytic
 * cases (head-on, oblique, a wall, a corner, Newton's cradle) to the
 * 1e-9 the header promises, no overlap ever in a dense gas, energy and
 * momentum, relaxation to Maxwell-Boltzmann, the pressure against the
 * hard-disk virial series, ds_sim_set_disk between steps, and the same trajectory
 * however a run is cut into calls and whichever candidate search is used.
 *
 * Hand-made states live in a box 1e5 wide: the disks the test does not
 * use stay where random placement put them, on average ~1e3 apart, far
 * from the few the test places (and the seeds below are checked to keep
 * them out of the way). */
#include "test_util.h"

#define BIG_BOX 1e5

static ds_sim *create(size_t n, double radius, double box, uint64_t seed, ds_broadphase bp)
{
    ds_params p = ds_params_default(n, radius);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.box = box;
    p.seed = seed;
    p.broadphase = bp;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_get_integrator(sim), DS_INTEGRATOR_EVENT_DRIVEN);
    return sim;
}

static void assert_disk(const ds_sim *sim, size_t i, double x, double y, double vx, double vy)
{
    const ds_disk d = ds_sim_get_disk(sim, i);
    assert_close(d.x, x);
    assert_close(d.y, y);
    assert_close(d.vx, vx);
    assert_close(d.vy, vy);
}

/* ------------------------------------------------------------------ */
/* Exact cases                                                          */
/* ------------------------------------------------------------------ */

static void test_head_on_pair_collides_at_contact_and_swaps(void **state)
{
    (void)state;
    /* Centres 200 apart closing at 200: contact (10 apart) at t = 0.95.
     * At t = 1 each has come back 5: x = 490 and 510, velocities swapped. */
    ds_sim *sim = create(2, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 400.0, 500.0, 100.0, 0.0);
    place(sim, 1, 600.0, 500.0, -100.0, 0.0);
    ds_sim_run(sim, 1000, NULL);
    assert_disk(sim, 0, 490.0, 500.0, -100.0, 0.0);
    assert_disk(sim, 1, 510.0, 500.0, 100.0, 0.0);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    ds_sim_destroy(sim);
}

static void test_oblique_pair_exchanges_only_the_normal_components(void **state)
{
    (void)state;
    /* A at (400, 500) moving (100, 0) towards B at rest at (600, 506):
     * contact when the x gap is sqrt(10^2 - 6^2) = 8, at t = 1.92, with
     * the line of centres n = (0.8, 0.6). A's normal component 80 goes to
     * B: A leaves with (100, 0) - 80 n = (36, -48), B with (64, 48). */
    ds_sim *sim = create(2, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 400.0, 500.0, 100.0, 0.0);
    place(sim, 1, 600.0, 506.0, 0.0, 0.0);
    ds_sim_run(sim, 2000, NULL); /* t = 2, 0.08 after the collision */
    assert_disk(sim, 0, 592.0 + 36.0 * 0.08, 500.0 - 48.0 * 0.08, 36.0, -48.0);
    assert_disk(sim, 1, 600.0 + 64.0 * 0.08, 506.0 + 48.0 * 0.08, 64.0, 48.0);
    ds_sim_destroy(sim);
}

static void test_a_wall_turns_the_centre_at_exactly_R(void **state)
{
    (void)state;
    /* x = 100 moving at -100: the centre reaches x = R = 5 at t = 0.95. */
    ds_sim *sim = create(1, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 100.0, 5e4, -100.0, 30.0);
    ds_sim_run(sim, 949, NULL);
    assert_disk(sim, 0, 5.1, 5e4 + 28.47, -100.0, 30.0); /* not turned yet */
    ds_sim_run(sim, 51, NULL);
    assert_disk(sim, 0, 10.0, 5e4 + 30.0, 100.0, 30.0);
    assert_int_equal(ds_sim_get_wall_count(sim), 1);
    assert_close(ds_sim_get_wall_impulse(sim), 200.0);
    ds_sim_destroy(sim);
}

static void test_a_corner_turns_both_components(void **state)
{
    (void)state;
    /* Diagonally into the corner: both walls at t = 0.95, out along the
     * same diagonal. */
    ds_sim *sim = create(1, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 100.0, 100.0, -100.0, -100.0);
    ds_sim_run(sim, 1000, NULL);
    assert_disk(sim, 0, 10.0, 10.0, 100.0, 100.0);
    assert_int_equal(ds_sim_get_wall_count(sim), 2);
    ds_sim_destroy(sim);
}

static void test_newtons_cradle_passes_the_velocity_down_the_row(void **state)
{
    (void)state;
    /* Disks 1..4 touching in a row (centres exactly 2R apart), at rest;
     * disk 0 hits disk 1 at t = 1.9. Each collision hands the whole
     * velocity on, at once, down to disk 4: at t = 2 disks 0..3 stand at
     * 490, 500, 510, 520 and disk 4 has moved on by 10. */
    ds_sim *sim = create(5, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    for (size_t i = 1; i < 5; ++i)
        place(sim, i, 490.0 + 10.0 * (double)i, 500.0, 0.0, 0.0);
    place(sim, 0, 300.0, 500.0, 100.0, 0.0);
    ds_sim_run(sim, 2000, NULL);
    assert_disk(sim, 0, 490.0, 500.0, 0.0, 0.0);
    for (size_t i = 1; i < 4; ++i)
        assert_disk(sim, i, 490.0 + 10.0 * (double)i, 500.0, 0.0, 0.0);
    assert_disk(sim, 4, 540.0, 500.0, 100.0, 0.0);
    assert_int_equal(ds_sim_get_collision_count(sim), 4);
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* Dense gas                                                            */
/* ------------------------------------------------------------------ */

/* The smallest centre distance over all pairs, over 2R. */
static double closest_pair(const ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    ds_disk *d = malloc(n * sizeof *d);
    assert_non_null(d);
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    double m2 = INFINITY;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            const double dx = d[j].x - d[i].x, dy = d[j].y - d[i].y;
            if (dx * dx + dy * dy < m2)
                m2 = dx * dx + dy * dy;
        }
    free(d);
    return sqrt(m2) / (2.0 * ds_sim_get_radius(sim));
}

static void test_no_pair_ever_overlaps_in_a_dense_gas(void **state)
{
    (void)state;
    /* Area fraction 0.5, the densest random placement comfortably reaches,
     * checked after every step: ~14 collisions per disk per time unit,
     * ~3.5 per step in all. A
     * pair touches at 2R up to rounding, 1e-13 relative here; the header
     * promises 1e-9. */
    const size_t n = 500;
    const double r = sqrt(0.5 * 1e6 / (3.141592653589793 * (double)n));
    ds_sim *sim = create(n, r, 0.0, 7, DS_BROADPHASE_AUTO);
    const int steps = quick_mode() ? 100 : 1000;
    for (int s = 0; s < steps; ++s) {
        ds_sim_step(sim, NULL);
        assert_true(closest_pair(sim) >= 1.0 - 1e-9);
    }
    assert_true(ds_sim_get_collision_count(sim) > (uint64_t)(2 * steps));
    ds_sim_destroy(sim);
}

static void test_energy_is_conserved_to_rounding_over_a_million_collisions(void **state)
{
    (void)state;
    /* A wall turn flips a sign (exact); a collision adds and subtracts the
     * same computed impulse, changing v_i^2 + v_j^2 by a few rounding
     * errors, 1e-16 relative, in random directions: over 1e6 collisions
     * ~1e-13. The bound is 1e-12. (Quick mode: 1e5 collisions.) */
    const size_t n = 1000;
    const double r = sqrt(0.5 * 1e6 / (3.141592653589793 * (double)n));
    ds_sim *sim = create(n, r, 0.0, 8, DS_BROADPHASE_AUTO);
    const double e0 = ds_sim_get_kinetic_energy(sim);
    const uint64_t target = quick_mode() ? 100000 : 1000000;
    while (ds_sim_get_collision_count(sim) < target)
        ds_sim_run(sim, 1000, NULL);
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) / e0 - 1.0) < 1e-12);
    ds_sim_destroy(sim);
}

static void test_momentum_is_conserved_with_the_walls_out_of_reach(void **state)
{
    (void)state;
    /* As for the time step: 400 disks 12 apart (R = 5) in the middle of
     * the big box, random directions at 100. Every collision adds to one
     * disk what it takes from the other, so only rounding can change the
     * sum (momentum_rounding_bound, test_util.h). */
    const size_t side = 20, n = side * side;
    ds_sim *sim = create(n, 5.0, BIG_BOX, 3, DS_BROADPHASE_AUTO);
    ds_rng rng;
    ds_rng_seed(&rng, 11);
    for (size_t i = 0; i < n; ++i) {
        const double a = ds_rng_uniform(&rng, 0.0, 6.283185307179586);
        place(sim, i, 5e4 + 12.0 * (double)(i % side), 5e4 + 12.0 * (double)(i / side),
              100.0 * cos(a), 100.0 * sin(a));
    }
    double px0, py0, px, py;
    ds_sim_get_momentum(sim, &px0, &py0);
    const double vmax = sqrt(2.0 * ds_sim_get_kinetic_energy(sim));
    ds_sim_run(sim, long_run(5000), NULL);
    ds_sim_get_momentum(sim, &px, &py);
    assert_int_equal(ds_sim_get_wall_count(sim), 0);
    assert_true(ds_sim_get_collision_count(sim) > 100);
    const double bound = momentum_rounding_bound(ds_sim_get_collision_count(sim), vmax, n);
    assert_true(fabs(px - px0) <= bound);
    assert_true(fabs(py - py0) <= bound);
    ds_sim_destroy(sim);
}

static void test_speeds_relax_to_rayleigh(void **state)
{
    (void)state;
    /* The time step's test (test_physics.c), exactly: N = 2000, R = 3,
     * ~60 collisions per disk by t = 20 (quick mode: 500 disks of R = 6). */
    const size_t n = quick_mode() ? 500 : 2000;
    const double r = quick_mode() ? 6.0 : 3.0;
    ds_sim *sim = create(n, r, 0.0, 2, DS_BROADPHASE_AUTO);
    assert_true(ks_distance_to_rayleigh(sim) > ks_critical_1_percent(n));
    ds_sim_run(sim, 20000, NULL);
    assert_true(ks_distance_to_rayleigh(sim) < ks_critical_1_percent(n));
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* Pressure                                                             */
/* ------------------------------------------------------------------ */

static void test_the_series_reproduces_the_published_values(void **state)
{
    (void)state;
    assert_true(fabs(virial_series(0.1) - 1.23614) < 5e-6);
    assert_true(fabs(virial_series(0.3) - 2.06316) < 5e-6);
    assert_true(fabs(virial_series(0.5) - 4.0827) < 5e-5);
}

/* Z = P A / E from the walls, A = (box - 2R)^2, in `blocks` blocks of one
 * time unit after 5 of relaxation: its mean and the standard error of the
 * mean from the scatter of the blocks. One time unit is hundreds of
 * collision times, so the blocks are independent. */
typedef struct z_estimate {
    double mean, error, virial_mean;
} z_estimate;

static z_estimate wall_z(size_t n, double eta, int blocks, uint64_t seed)
{
    const double r = sqrt(eta * 1e6 / (3.141592653589793 * (double)n));
    ds_sim *sim = create(n, r, 0.0, seed, DS_BROADPHASE_AUTO);
    ds_sim_run(sim, 5000, NULL);
    const double area = (1000.0 - 2.0 * r) * (1000.0 - 2.0 * r);
    double sum = 0.0, sum2 = 0.0, virial = 0.0;
    for (int b = 0; b < blocks; ++b) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, 1000, NULL);
        const double z = ds_sim_get_pressure(sim) * area / ds_sim_get_kinetic_energy(sim);
        sum += z;
        sum2 += z * z;
        virial += ds_sim_get_virial_pressure(sim) * area / ds_sim_get_kinetic_energy(sim);
    }
    ds_sim_destroy(sim);
    z_estimate est;
    est.mean = sum / blocks;
    est.error = sqrt((sum2 / blocks - est.mean * est.mean) / (blocks - 1));
    est.virial_mean = virial / blocks;
    return est;
}

static void test_wall_pressure_follows_the_virial_series(void **state)
{
    (void)state;
    /* N = 10^4 with walls at area fraction 0.1 and 0.3 (eta = N pi R^2 /
     * box^2): Z within 3 standard errors of the series (a fresh seed would
     * fail with probability 0.3% each). The walls themselves shift Z by a
     * term ~ R / box that the virial pressure resolves: +0.24% at 0.3 and
     * +0.07% at 0.1 for this N (+0.8% at N = 1000), below the 0.4% the
     * wall pressure can see in 20 time units. The virial pressure must
     * agree with the wall pressure (the virial theorem) to the same 3
     * standard errors. Quick mode: 4 blocks, the error from their
     * scatter. */
    const int blocks = quick_mode() ? 4 : 20;
    const double etas[] = {0.1, 0.3};
    for (int k = 0; k < 2; ++k) {
        const z_estimate z = wall_z(10000, etas[k], blocks, 5);
        const double series = virial_series(etas[k]);
        print_message("eta %.1f: Z = %.5f +- %.5f (walls), %.5f (virial), series %.5f\n", etas[k],
                      z.mean, z.error, z.virial_mean, series);
        assert_true(fabs(z.mean - series) < 3.0 * z.error);
        assert_true(fabs(z.virial_mean - z.mean) < 3.0 * z.error);
        assert_true(z.mean > 1.0 + 2.0 * etas[k]); /* above the second virial term */
    }
}

/* Z = P A / E from the collision virial (A = (box - 2R)^2), mean and
 * standard error over `blocks` blocks of one time unit after 5 of
 * relaxation, for either integrator at time step dt. */
static z_estimate virial_z(size_t n, double eta, ds_integrator integrator, double dt, int blocks)
{
    ds_params p = ds_params_default(n, sqrt(eta * 1e6 / (3.141592653589793 * (double)n)));
    p.integrator = integrator;
    p.dt = dt;
    p.seed = 3;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    const uint64_t per_unit = (uint64_t)llround(1.0 / dt);
    ds_sim_run(sim, 5 * per_unit, NULL);
    const double span = 1000.0 - 2.0 * p.radius;
    double sum = 0.0, sum2 = 0.0;
    for (int b = 0; b < blocks; ++b) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, per_unit, NULL);
        const double z =
            ds_sim_get_virial_pressure(sim) * span * span / ds_sim_get_kinetic_energy(sim);
        sum += z;
        sum2 += z * z;
    }
    ds_sim_destroy(sim);
    z_estimate est;
    est.mean = sum / blocks;
    est.error = sqrt((sum2 / blocks - est.mean * est.mean) / (blocks - 1));
    est.virial_mean = est.mean;
    return est;
}

static void test_time_step_pressure_approaches_the_exact_one_linearly_in_dt(void **state)
{
    (void)state;
    /* The time step sees each collision up to one step late, a little
     * inside 2R: its Z is low by a bias proportional to dt (measured
     * dZ/dt = -23 from dt = 0.008 down to 0.0005 at this density). Fit
     * Z(dt) = Z0 + a dt to dt = 0.004, 0.002, 0.001, weighted by their
     * block errors: the line must fit (chi-square with 1 degree of freedom
     * below 10.8, p = 0.001), lead to the event-driven Z (intercept within
     * 3 combined standard errors) and have a slope far from zero (the bias
     * is real, > 5 of its standard errors). N = 4000 at area fraction 0.3,
     * 20 blocks (quick mode: 1000 disks, 6 blocks, and a slope > 3 of its
     * larger standard errors). */
    const size_t n = quick_mode() ? 1000 : 4000;
    const int blocks = quick_mode() ? 6 : 20;
    const z_estimate exact = virial_z(n, 0.3, DS_INTEGRATOR_EVENT_DRIVEN, 0.001, blocks);
    const double dts[] = {0.004, 0.002, 0.001};
    double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, y[3], w[3];
    for (int k = 0; k < 3; ++k) {
        const z_estimate z = virial_z(n, 0.3, DS_INTEGRATOR_TIME_STEP, dts[k], blocks);
        print_message("dt %.3f: Z = %.5f +- %.5f (event-driven %.5f +- %.5f)\n", dts[k], z.mean,
                      z.error, exact.mean, exact.error);
        y[k] = z.mean;
        w[k] = 1.0 / (z.error * z.error);
        sw += w[k];
        sx += w[k] * dts[k];
        sy += w[k] * y[k];
        sxx += w[k] * dts[k] * dts[k];
        sxy += w[k] * dts[k] * y[k];
    }
    const double det = sw * sxx - sx * sx;
    const double slope = (sw * sxy - sx * sy) / det, intercept = (sxx * sy - sx * sxy) / det;
    const double slope_error = sqrt(sw / det), intercept_error = sqrt(sxx / det);
    double chi2 = 0.0;
    for (int k = 0; k < 3; ++k)
        chi2 += w[k] * (y[k] - intercept - slope * dts[k]) * (y[k] - intercept - slope * dts[k]);
    print_message("Z(dt) = %.5f + %.2f dt (+- %.5f, %.2f), chi2 %.2f\n", intercept, slope,
                  intercept_error, slope_error, chi2);
    assert_true(chi2 < 10.8);
    assert_true(fabs(intercept - exact.mean) <
                3.0 * sqrt(intercept_error * intercept_error + exact.error * exact.error));
    assert_true(slope < -(quick_mode() ? 3.0 : 5.0) * slope_error);
}

/* ------------------------------------------------------------------ */
/* The API around it                                                    */
/* ------------------------------------------------------------------ */

static void test_set_refuses_an_overlap_and_keeps_the_state(void **state)
{
    (void)state;
    ds_sim *sim = create(2, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 400.0, 500.0, 100.0, 0.0);
    place(sim, 1, 600.0, 500.0, -100.0, 0.0);
    const ds_disk inside = {405.0, 503.0, 0.0, 0.0}; /* 5.8 from disk 0 */
    assert_int_equal(ds_sim_set_disk(sim, 1, inside, NULL), DS_ERR_OVERLAP);
    assert_disk(sim, 1, 600.0, 500.0, -100.0, 0.0);
    /* Touching exactly is contact, not overlap; approaching, the pair
     * collides at once, and then separates. */
    const ds_disk touching = {410.0, 500.0, -100.0, 0.0};
    assert_int_equal(ds_sim_set_disk(sim, 1, touching, NULL), DS_OK);
    ds_sim_run(sim, 100, NULL);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    assert_disk(sim, 0, 400.0 - 10.0, 500.0, -100.0, 0.0);
    assert_disk(sim, 1, 410.0 + 10.0, 500.0, 100.0, 0.0);
    ds_sim_destroy(sim);
}

/* The header's tolerance, on both sides: closer than 2R by a relative
 * DS_CONTACT_TOLERANCE is an overlap, by less it is contact. */
static void test_set_refuses_overlap_exactly_at_the_documented_tolerance(void **state)
{
    (void)state;
    ds_sim *sim = create(2, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 400.0, 500.0, 0.0, 0.0);
    place(sim, 1, 600.0, 500.0, 0.0, 0.0);
    const ds_disk over = {400.0 + 10.0 * (1.0 - 2.0 * DS_CONTACT_TOLERANCE), 500.0, 1.0, 0.0};
    const ds_disk contact = {400.0 + 10.0 * (1.0 - 0.5 * DS_CONTACT_TOLERANCE), 500.0, 1.0, 0.0};
    assert_int_equal(ds_sim_set_disk(sim, 1, over, NULL), DS_ERR_OVERLAP);
    assert_int_equal(ds_sim_set_disk(sim, 1, contact, NULL), DS_OK);
    /* A velocity component beyond 1e12, as the header says. */
    const ds_disk fast = {700.0, 500.0, 1e13, 0.0};
    assert_int_equal(ds_sim_set_disk(sim, 1, fast, NULL), DS_ERR_ARG);
    ds_sim_destroy(sim);
}

/* Found by a client of the library: at exact close packing (100 disks of
 * R = 50 on the 10 x 10 lattice of a periodic box of aspect sqrt(3)/2)
 * every disk touches six others and the first step never returned (5
 * million collisions, the time still 0). Refused now, for the event-driven
 * integrator only; with DS_ROOM_TO_MOVE to spare a step ends. */
static void test_a_lattice_at_close_packing_is_refused_and_one_with_room_runs(void **state)
{
    (void)state;
    ds_params p = ds_params_default(100, 50.0);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.placement = DS_PLACEMENT_LATTICE;
    p.box_y = 1000.0 * sqrt(3.0) / 2.0;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    ds_error why;
    assert_int_equal(ds_params_check(&p, NULL, NULL, &why), DS_ERR_PLACEMENT);
    assert_non_null(strstr(why.message, "close packing"));
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_ERR_PLACEMENT);
    p.integrator = DS_INTEGRATOR_TIME_STEP; /* a fixed amount of work per step */
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_OK);
    /* 1e-4 of a diameter of room: ~v dt / gap = 0.1 / 0.01 = 10 collisions
     * per disk per step. */
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.radius = 50.0 * (1.0 - 1e-4);
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_sim_run(sim, 3, NULL);
    assert_int_equal(ds_sim_get_steps(sim), 3);
    assert_true(ds_sim_get_collision_count(sim) > 100);
    ds_sim_destroy(sim);
}

/* Found by a client too: one disk of R = nextafter(500, 0) in the default
 * box has a band of 2e-13 between the walls, and one step would have
 * taken ~10^12 wall turns (hours). The event-driven integrator refuses a
 * band under DS_ROOM_TO_MOVE of a diameter; the time step takes it. */
static void test_a_band_a_rounding_error_wide_is_refused(void **state)
{
    (void)state;
    ds_params p = ds_params_default(1, nextafter(500.0, 0.0));
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    ds_error why;
    assert_int_equal(ds_params_check(&p, NULL, NULL, &why), DS_ERR_ARG);
    assert_string_equal(why.field, "radius");
    assert_non_null(strstr(why.message, "band"));
    p.radius = 500.0 * (1.0 - 2.0 * DS_ROOM_TO_MOVE); /* a band of 2e-3, 1e-3 = room * 2R */
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_sim_run(sim, 2, NULL); /* ~100 turns a step */
    assert_true(ds_sim_get_wall_count(sim) > 50);
    ds_sim_destroy(sim);
    p.radius = nextafter(500.0, 0.0);
    p.integrator = DS_INTEGRATOR_TIME_STEP;
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_OK);
}

static void test_a_pair_a_hair_inside_contact_is_never_stuck(void **state)
{
    (void)state;
    /* Centres 2R (1 - 1e-11) apart, inside contact by rounding, which
     * ds_sim_set_disk accepts (up to 1e-9). Separating, they are left alone and fly
     * apart; approaching, they collide at once, then separate: time never
     * runs backwards, and no pair collides over and over. */
    const double gap = 10.0 * (1.0 - 1e-11);
    ds_sim *sim = create(4, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 400.0, 500.0, -100.0, 0.0);
    place(sim, 1, 400.0 + gap, 500.0, 100.0, 0.0); /* separating */
    place(sim, 2, 400.0, 900.0, 100.0, 0.0);
    place(sim, 3, 400.0 + gap, 900.0, -100.0, 0.0); /* approaching */
    ds_sim_run(sim, 1000, NULL);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    assert_disk(sim, 0, 300.0, 500.0, -100.0, 0.0);
    assert_disk(sim, 1, 500.0 + gap, 500.0, 100.0, 0.0);
    assert_disk(sim, 2, 300.0, 900.0, -100.0, 0.0);
    assert_disk(sim, 3, 500.0 + gap, 900.0, 100.0, 0.0);
    ds_sim_destroy(sim);
}

static void test_set_between_steps_changes_the_course(void **state)
{
    (void)state;
    /* Both flying apart; after 1 time unit disk 1 is turned round and
     * aimed at disk 0: they meet where the new courses cross. */
    ds_sim *sim = create(2, 5.0, BIG_BOX, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 400.0, 500.0, -100.0, 0.0);
    place(sim, 1, 600.0, 500.0, 100.0, 0.0);
    ds_sim_run(sim, 1000, NULL); /* 300 and 700 */
    place(sim, 1, 700.0, 500.0, -100.0, 0.0);
    place(sim, 0, 300.0, 500.0, 100.0, 0.0);
    ds_sim_run(sim, 2000, NULL); /* contact at t = 1 + 1.95, then 0.05 back */
    assert_disk(sim, 0, 490.0, 500.0, -100.0, 0.0);
    assert_disk(sim, 1, 510.0, 500.0, 100.0, 0.0);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    ds_sim_destroy(sim);
}

static void test_a_run_cut_into_steps_gives_the_same_trajectory(void **state)
{
    (void)state;
    /* The integrator advances from event to event; ds_sim_run only says up to
     * when. Stopping at every step (and showing the disks) must not change
     * a single bit, across the moves of the integrator's clock epoch
     * (every 10 time units here). */
    const uint64_t steps = quick_mode() ? 2000 : 25000;
    ds_sim *a = create(300, 8.0, 0.0, 4, DS_BROADPHASE_AUTO),
           *b = create(300, 8.0, 0.0, 4, DS_BROADPHASE_AUTO);
    ds_sim_run(a, steps, NULL);
    for (uint64_t s = 0; s < steps; ++s)
        ds_sim_step(b, NULL);
    for (size_t i = 0; i < 300; ++i) {
        const ds_disk da = ds_sim_get_disk(a, i), db = ds_sim_get_disk(b, i);
        assert_memory_equal(&da, &db, sizeof da);
    }
    assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(b));
    ds_sim_destroy(a);
    ds_sim_destroy(b);
}

static void test_brute_force_and_cells_follow_the_same_trajectory(void **state)
{
    (void)state;
    /* Brute force: one cell, every disk every disk's candidate. The same
     * collisions at the same times; positions differ only by rounding
     * (cell crossings re-base a disk's position), which collisions then
     * amplify, so the run stops at about 3 collisions per disk. */
    ds_sim *cells = create(200, 15.0, 0.0, 6, DS_BROADPHASE_CELLS);
    ds_sim *brute = create(200, 15.0, 0.0, 6, DS_BROADPHASE_BRUTE);
    assert_int_equal(ds_sim_get_broadphase(cells), DS_BROADPHASE_CELLS);
    assert_int_equal(ds_sim_get_broadphase(brute), DS_BROADPHASE_BRUTE);
    while (ds_sim_get_collision_count(cells) < 300) {
        ds_sim_step(cells, NULL);
        ds_sim_step(brute, NULL);
        assert_int_equal(ds_sim_get_collision_count(cells), ds_sim_get_collision_count(brute));
    }
    for (size_t i = 0; i < 200; ++i) {
        const ds_disk c = ds_sim_get_disk(cells, i), b = ds_sim_get_disk(brute, i);
        assert_true(fabs(c.x - b.x) < 1e-6 && fabs(c.y - b.y) < 1e-6);
        assert_true(fabs(c.vx - b.vx) < 1e-6 && fabs(c.vy - b.vy) < 1e-6);
    }
    ds_sim_destroy(cells);
    ds_sim_destroy(brute);
}

static void test_a_crowded_cell_of_a_dilute_gas_matches_brute_force(void **state)
{
    (void)state;
    /* A dilute gas gets large cells (a few per disk at most), and one of
     * them can hold more disks than its four slots: the rest wait in its
     * overflow list, which every prediction around it reads, the crowd's
     * own disks included. 40 disks of R = 1 get 14 x 14 cells ~71 wide;
     * 16 of them start in a 4 x 4 square of spacing 3 inside one cell
     * away from the grid's edges, in all directions at speed 100, the
     * others in three rows far below. Brute force (one cell, every disk
     * every disk's candidate) must find the same collisions at the same
     * times, up to the rounding that ends the brute-force test above. */
    ds_sim *sim[2] = {create(40, 1.0, 1000.0, 3, DS_BROADPHASE_CELLS),
                      create(40, 1.0, 1000.0, 3, DS_BROADPHASE_BRUTE)};
    for (int s = 0; s < 2; ++s)
        for (size_t k = 0; k < 40; ++k) {
            const double angle = 2.4 * (double)k, vx = 100.0 * cos(angle), vy = 100.0 * sin(angle);
            if (k < 16)
                place(sim[s], k, 520.0 + 3.0 * (double)(k % 4), 520.0 + 3.0 * (double)(k / 4), vx,
                      vy);
            else
                place(sim[s], k, 60.0 + 110.0 * (double)((k - 16) % 8),
                      100.0 + 150.0 * (double)((k - 16) / 8), vx, vy);
        }
    /* The crowd spreads out within 0.1 time units, after some 17
     * collisions; the gas is then too dilute for more within the run. */
    for (int step = 0; step < 200; ++step) {
        ds_sim_step(sim[0], NULL);
        ds_sim_step(sim[1], NULL);
        assert_int_equal(ds_sim_get_collision_count(sim[0]), ds_sim_get_collision_count(sim[1]));
    }
    assert_true(ds_sim_get_collision_count(sim[0]) >= 12);
    double worst = 0.0;
    for (size_t i = 0; i < 40; ++i) {
        const ds_disk c = ds_sim_get_disk(sim[0], i), b = ds_sim_get_disk(sim[1], i);
        worst = fmax(worst, fmax(fabs(c.x - b.x), fabs(c.y - b.y)));
    }
    assert_true(worst < 1e-9); /* rounding apart: 3e-14 measured */
    ds_sim_destroy(sim[0]);
    ds_sim_destroy(sim[1]);
}

static int by_x(const void *a, const void *b)
{
    const double xa = ((const ds_disk *)a)->x, xb = ((const ds_disk *)b)->x;
    return (xa > xb) - (xa < xb);
}

/* The closest centres over 2R, by a sweep along x: in a box with walls,
 * or in a periodic box (y by the nearest image, the disks near x = 0
 * appended again one box further). */
static double closest_swept(const ds_sim *sim, int periodic)
{
    const size_t n = ds_sim_get_count(sim);
    const double box = ds_sim_get_box_width(sim), box_y = ds_sim_get_box_height(sim),
                 d = 2.0 * ds_sim_get_radius(sim);
    ds_disk *all = malloc(2 * n * sizeof *all);
    assert_non_null(all);
    assert_int_equal(ds_sim_get_disks(sim, all, NULL), DS_OK);
    qsort(all, n, sizeof *all, by_x);
    size_t m = n;
    for (size_t k = 0; periodic && k < n && all[k].x < d; ++k) {
        all[m] = all[k];
        all[m++].x += box;
    }
    double m2 = INFINITY;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < m && all[j].x - all[i].x < d; ++j) {
            const double dx = all[j].x - all[i].x, dy_wall = all[j].y - all[i].y;
            const double dy = periodic ? remainder(dy_wall, box_y) : dy_wall;
            m2 = fmin(m2, dx * dx + dy * dy);
        }
    free(all);
    return sqrt(m2) / d;
}

static void test_a_long_channel_caps_its_grid_and_keeps_its_disks_apart(void **state)
{
    (void)state;
    /* 5,000 disks of R = 0.5 in a periodic channel 1e6 x 4: the grid is
     * capped at 65,535 columns of 15.3 (test_cells; a disk's column is 16
     * bits). One disk is sent across the seam from the last column to the
     * first. After 10 units of travel: it has wrapped, every centre is in
     * the box, no pair is closer than 2R (up to the header's 1e-9), energy
     * holds to rounding and momentum to the rounding of its terms. */
    ds_params p = ds_params_default(5000, 0.5);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.box = 1e6;
    p.box_y = 4.0;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    /* Area fraction 0.001: the first free height will do. */
    double y = 0.5;
    while (ds_sim_set_disk(sim, 0, (ds_disk){p.box - 1.0, y, 100.0, 0.0}, NULL) != DS_OK)
        y += 1.0;
    const double e0 = ds_sim_get_kinetic_energy(sim);
    double px0, py0;
    ds_sim_get_momentum(sim, &px0, &py0);
    ds_sim_run(sim, 100, NULL);
    const ds_disk crossed = ds_sim_get_disk(sim, 0);
    assert_true(crossed.x >= 0.0 && crossed.x < 10.0); /* 9.0 unless it met a disk */
    for (size_t i = 0; i < ds_sim_get_count(sim); ++i) {
        const ds_disk d = ds_sim_get_disk(sim, i);
        assert_true(d.x >= 0.0 && d.x < p.box && d.y >= 0.0 && d.y < p.box_y);
    }
    assert_true(ds_sim_get_collision_count(sim) > 0);
    assert_true(closest_swept(sim, 1) >= 1.0 - 1e-9);
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) / e0 - 1.0) < 1e-12);
    double px, py;
    ds_sim_get_momentum(sim, &px, &py);
    /* Momenta of 5,000 disks of speed 100 summed: rounding ~1e-10. */
    assert_true(fabs(px - px0) < 1e-8 && fabs(py - py0) < 1e-8);
    ds_sim_destroy(sim);
}

static void test_a_system_larger_than_the_caches_keeps_its_disks_apart(void **state)
{
    (void)state;
    /* 50,000 disks at area fraction 0.4 with walls: 9.3 MiB of integrator
     * state, above the 8 MiB from which it fetches memory ahead of its
     * events (FETCH_AHEAD_BYTES), so this runs that path too, under CI's
     * sanitizers and valgrind. Fetching only reads: a mistake there is a
     * read out of bounds, which those catch. About 2,000 collisions per
     * step: after 20 steps (5 in quick mode) no pair is closer than 2R (up
     * to the header's 1e-9) and energy holds to rounding. */
    const size_t n = 50000;
    const double r = sqrt(0.4 * 1e6 / (3.141592653589793 * (double)n));
    ds_sim *sim = create(n, r, 0.0, 9, DS_BROADPHASE_AUTO);
    const double e0 = ds_sim_get_kinetic_energy(sim);
    const uint64_t steps = quick_mode() ? 5 : 20;
    ds_sim_run(sim, steps, NULL);
    assert_true(ds_sim_get_collision_count(sim) > 500 * steps);
    assert_true(closest_swept(sim, 0) >= 1.0 - 1e-9);
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) / e0 - 1.0) < 1e-12);
    ds_sim_destroy(sim);
}

static void test_disks_at_rest_are_no_trouble(void **state)
{
    (void)state;
    /* Nothing will ever happen: steps still pass, nothing moves. */
    ds_sim *sim = create(2, 5.0, 1000.0, 1, DS_BROADPHASE_AUTO);
    place(sim, 0, 400.0, 500.0, 0.0, 0.0);
    place(sim, 1, 600.0, 500.0, 0.0, 0.0);
    ds_sim_run(sim, 100000, NULL);
    assert_disk(sim, 0, 400.0, 500.0, 0.0, 0.0);
    assert_true(ds_sim_get_time(sim) == 100000 * 0.001);
    /* Woken up, it moves again. */
    place(sim, 1, 600.0, 500.0, -100.0, 0.0);
    ds_sim_run(sim, 2000, NULL);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    ds_sim_destroy(sim);
}

static void test_the_integrator_and_its_grid_are_named(void **state)
{
    (void)state;
    ds_params p = ds_params_default(10, 5.0);
    assert_int_equal(p.integrator, DS_INTEGRATOR_TIME_STEP);
    assert_string_equal(ds_integrator_name(DS_INTEGRATOR_TIME_STEP), "step");
    assert_string_equal(ds_integrator_name(DS_INTEGRATOR_EVENT_DRIVEN), "event");
    assert_string_equal(ds_broadphase_name(DS_BROADPHASE_CELLS), "cells");
    /* The sweeps belong to the time step, the cells to events. */
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.broadphase = DS_BROADPHASE_SAP;
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_ERR_ARG);
    p.broadphase = DS_BROADPHASE_CELLS;
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_OK);
    p.integrator = DS_INTEGRATOR_TIME_STEP;
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_ERR_ARG);
    p.integrator = (ds_integrator)7;
    p.broadphase = DS_BROADPHASE_AUTO;
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_integrator(NULL), DS_INTEGRATOR_TIME_STEP);
    /* No tunnelling warning: nothing is stepped over. */
    unsigned warnings = 0;
    p = ds_params_default(10, 0.01);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    assert_int_equal(ds_params_check(&p, NULL, &warnings, NULL), DS_OK);
    assert_int_equal(warnings, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_head_on_pair_collides_at_contact_and_swaps),
        cmocka_unit_test(test_oblique_pair_exchanges_only_the_normal_components),
        cmocka_unit_test(test_a_wall_turns_the_centre_at_exactly_R),
        cmocka_unit_test(test_a_corner_turns_both_components),
        cmocka_unit_test(test_newtons_cradle_passes_the_velocity_down_the_row),
        cmocka_unit_test(test_a_long_channel_caps_its_grid_and_keeps_its_disks_apart),
        cmocka_unit_test(test_no_pair_ever_overlaps_in_a_dense_gas),
        cmocka_unit_test(test_energy_is_conserved_to_rounding_over_a_million_collisions),
        cmocka_unit_test(test_momentum_is_conserved_with_the_walls_out_of_reach),
        cmocka_unit_test(test_speeds_relax_to_rayleigh),
        cmocka_unit_test(test_the_series_reproduces_the_published_values),
        cmocka_unit_test(test_wall_pressure_follows_the_virial_series),
        cmocka_unit_test(test_time_step_pressure_approaches_the_exact_one_linearly_in_dt),
        cmocka_unit_test(test_set_refuses_an_overlap_and_keeps_the_state),
        cmocka_unit_test(test_set_refuses_overlap_exactly_at_the_documented_tolerance),
        cmocka_unit_test(test_a_lattice_at_close_packing_is_refused_and_one_with_room_runs),
        cmocka_unit_test(test_a_band_a_rounding_error_wide_is_refused),
        cmocka_unit_test(test_a_pair_a_hair_inside_contact_is_never_stuck),
        cmocka_unit_test(test_set_between_steps_changes_the_course),
        cmocka_unit_test(test_a_run_cut_into_steps_gives_the_same_trajectory),
        cmocka_unit_test(test_brute_force_and_cells_follow_the_same_trajectory),
        cmocka_unit_test(test_a_crowded_cell_of_a_dilute_gas_matches_brute_force),
        cmocka_unit_test(test_a_system_larger_than_the_caches_keeps_its_disks_apart),
        cmocka_unit_test(test_disks_at_rest_are_no_trouble),
        cmocka_unit_test(test_the_integrator_and_its_grid_are_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
