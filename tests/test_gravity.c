/* SPDX-License-Identifier: MIT */
/* A uniform field: a falling disk's parabola and its bounces against
 * hand-computed ones, the energy of an elastic gas in a field conserved
 * to rounding, the barometric profile of a dilute gas, a disk resting on
 * the floor, the stress integral of falling disks, and the refusals. */
#include "test_util.h"

/* One disk of radius 5 in a box of side 1000 with walls. */
static ds_sim *one_disk(ds_integrator integrator, ds_disk d, double g)
{
    ds_params p = ds_params_default(1, 5.0);
    p.integrator = integrator;
    p.dt = 1.0 / 64.0; /* exact in binary: the step boundaries are exact times */
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_disks(sim, &d, NULL), DS_OK);
    assert_int_equal(ds_sim_set_gravity(sim, 0.0, -g, NULL), DS_OK);
    return sim;
}

/* A disk dropped from rest at height 505 falls y = 505 - g t^2 / 2, meets
 * the floor (y = 5) at t = 10 (g = 10), comes back up elastically and
 * is at rest at 505 again at t = 20: the event-driven integrator's
 * parabola at every step boundary, to rounding (a few ulps of 1000). */
static void test_a_falling_disk_flies_a_parabola_and_bounces(void **state)
{
    (void)state;
    const double g = 10.0;
    ds_sim *sim = one_disk(DS_INTEGRATOR_EVENT_DRIVEN, (ds_disk){300.0, 505.0, 2.0, 0.0}, g);
    for (int s = 1; s <= 20 * 64; ++s) {
        ds_sim_step(sim, NULL);
        const double t = (double)s / 64.0, fall = t <= 10.0 ? t : 20.0 - t;
        const ds_disk d = ds_sim_get_disk(sim, 0);
        assert_true(fabs(d.y - (505.0 - 0.5 * g * fall * fall)) < 1e-11);
        assert_true(fabs(d.vy - (t <= 10.0 ? -g * t : g * (20.0 - t))) < 1e-11);
        assert_true(d.vx == 2.0 && fabs(d.x - (300.0 + 2.0 * t)) < 1e-11);
    }
    assert_int_equal(ds_sim_get_wall_count(sim), 1);
    double gx = 1.0, gy = 1.0;
    ds_sim_get_gravity(sim, &gx, &gy);
    assert_true(gx == 0.0 && gy == -g);
    ds_sim_destroy(sim);
}

/* The time step adds g dt to the velocity at the start of each step and
 * then moves the disk at it (semi-implicit Euler). */
static void test_the_time_step_adds_g_dt_each_step(void **state)
{
    (void)state;
    const double g = 16.0, dt = 1.0 / 64.0;
    ds_sim *sim = one_disk(DS_INTEGRATOR_TIME_STEP, (ds_disk){300.0, 505.0, 0.0, 0.0}, g);
    double y = 505.0, vy = 0.0;
    for (int s = 0; s < 64; ++s) {
        ds_sim_step(sim, NULL);
        vy -= g * dt;
        y += vy * dt;
        const ds_disk d = ds_sim_get_disk(sim, 0);
        assert_true(d.vy == vy && d.y == y);
    }
    ds_sim_destroy(sim);
}

/* An elastic gas in a field, with walls and in a channel: the kinetic
 * plus the potential energy stays what it was to rounding over thousands
 * of collisions and wall turns, while energy moves between the two. The
 * bound: each event rounds the energies it touches, so a few DBL_EPSILON
 * of the total per event at most (they add as a random walk, far
 * inside). */
static void test_an_elastic_gas_in_a_field_keeps_its_energy(void **state)
{
    (void)state;
    for (int boundary = 0; boundary < 3; boundary += 2) {
        ds_params p = ds_params_default(300, 5.0);
        p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
        p.boundary = (ds_boundary)boundary;
        p.box = 400.0;
        p.dt = 0.01;
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        assert_int_equal(ds_sim_set_gravity(sim, 0.0, -50.0, NULL), DS_OK);
        const double u0 = ds_sim_get_potential_energy(sim);
        const double e0 = ds_sim_get_kinetic_energy(sim) + u0;
        ds_sim_run(sim, long_run(2000), NULL);
        const double u = ds_sim_get_potential_energy(sim);
        const double e = ds_sim_get_kinetic_energy(sim) + u;
        const double events =
            (double)(ds_sim_get_collision_count(sim) + ds_sim_get_wall_count(sim));
        assert_true(ds_sim_get_collision_count(sim) > 1000);
        assert_true(fabs(u - u0) > 0.01 * e0); /* the field did work */
        if (!(fabs(e - e0) <= 4.0 * DBL_EPSILON * e0 * (events + 300.0)))
            fail_msg("%s: (E - E0) / E0 = %g after %g events", ds_boundary_name(p.boundary),
                     (e - e0) / e0, events);
        assert_true(ds_sim_get_energy_lost(sim) == 0.0);
        ds_sim_destroy(sim);
    }
}

/* The mean height of n(y) ~ exp(-lambda y) on [a, b]. */
static double truncated_mean(double lambda, double a, double b)
{
    const double d = b - a, q = exp(-lambda * d);
    return a + 1.0 / lambda - d * q / (1.0 - q);
}

/* A dilute elastic gas in a box with walls under a field g has the
 * barometric profile n(y) ~ exp(-m g y / kT), kT = K / N averaged over
 * the run. The profile's rate lambda is fitted to the mean height of the
 * centres over the run (the maximum-likelihood fit of an exponential on
 * the band [R, box - R] the centres reach) and must be m g / kT within
 * 2%. Area fraction 0.002, where the excluded area changes the local
 * pressure by 2 eta < 1% at the floor; about 4e4 independent heights
 * (400 disks, 100 flights up and down) give lambda to 0.5%. */
static void test_a_dilute_gas_in_a_field_has_the_barometric_profile(void **state)
{
    (void)state;
    const size_t n = 400;
    const double box = 400.0, r = 0.5, g = 30.0;
    ds_params p = ds_params_default(n, r);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.box = box;
    p.dt = 0.25;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_gravity(sim, 0.0, -g, NULL), DS_OK);
    ds_sim_run(sim, 200, NULL); /* 50 time units: ten flights up and down */
    const int frames = quick_mode() ? 200 : 2000;
    double height = 0.0, kt = 0.0;
    ds_disk *d = malloc(n * sizeof *d);
    assert_non_null(d);
    for (int f = 0; f < frames; ++f) {
        ds_sim_step(sim, NULL);
        assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
        for (size_t k = 0; k < n; ++k)
            height += d[k].y;
        kt += ds_sim_get_kinetic_energy(sim) / (double)n;
    }
    free(d);
    height /= (double)frames * (double)n;
    kt /= frames;
    const double want = g / kt;
    /* The rate whose truncated mean is the mean height (it falls with
     * lambda): bisection in the rate. */
    double lo = 1e-6 / box, hi = 100.0 / box;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (truncated_mean(mid, r, box - r) > height)
            lo = mid;
        else
            hi = mid;
    }
    const double fitted = 0.5 * (lo + hi), tolerance = quick_mode() ? 0.05 : 0.02;
    if (!(fabs(fitted / want - 1.0) < tolerance))
        fail_msg("lambda = %g, m g / kT = %g (ratio %.4f)", fitted, want, fitted / want);
    ds_sim_destroy(sim);
}

/* A disk at rest on the floor, which hard disks cannot hold still: the
 * field's floor sends it off at g t_c / 2, so it hops once per contact
 * time, and every step ends. Elastic walls, so the hops are all the
 * energy it gains: its height stays within g t_c^2 / 8 of the floor. */
static void test_a_disk_at_rest_on_the_floor_hops_and_every_step_ends(void **state)
{
    (void)state;
    const double g = 100.0;
    ds_sim *sim = one_disk(DS_INTEGRATOR_EVENT_DRIVEN, (ds_disk){300.0, 5.0, 0.0, 0.0}, g);
    const double tc = 1e-3;
    assert_int_equal(ds_sim_set_contact_time(sim, tc, NULL), DS_OK);
    ds_sim_run(sim, 64, NULL); /* one time unit: 1000 hops */
    const ds_disk d = ds_sim_get_disk(sim, 0);
    assert_true(d.y >= 5.0 && d.y <= 5.0 + g * tc * tc / 8.0 * (1.0 + 1e-9));
    assert_true(ds_sim_get_wall_count(sim) >= 999 && ds_sim_get_wall_count(sim) <= 1001);
    ds_sim_destroy(sim);
}

/* A field set in the middle of a run bends the flights from then on: a
 * disk moving sideways at 10 under g = 4 from t = 1 has fallen g (t -
 * 1)^2 / 2 at t = 3, and the field off again it flies straight. */
static void test_a_field_set_in_a_run_bends_the_flights_from_then_on(void **state)
{
    (void)state;
    FOR_EACH_DYNAMIC_INTEGRATOR(integrator)
    {
        ds_sim *sim = one_disk((ds_integrator)integrator, (ds_disk){100.0, 500.0, 10.0, 0.0}, 0.0);
        ds_sim_run(sim, 64, NULL);
        assert_int_equal(ds_sim_set_gravity(sim, 0.0, -4.0, NULL), DS_OK);
        ds_sim_run(sim, 128, NULL);
        ds_disk d = ds_sim_get_disk(sim, 0);
        /* The time step's Euler steps fall g dt t / 2 further. */
        const double slack = integrator == DS_INTEGRATOR_TIME_STEP ? 4.0 * 2.0 / 64.0 : 1e-11;
        assert_true(fabs(d.y - (500.0 - 8.0)) <= slack && fabs(d.vy + 8.0) < 1e-11);
        assert_true(fabs(d.x - 130.0) < 1e-11);
        assert_int_equal(ds_sim_set_gravity(sim, 0.0, 0.0, NULL), DS_OK);
        const double y = d.y;
        ds_sim_run(sim, 64, NULL);
        d = ds_sim_get_disk(sim, 0);
        assert_true(fabs(d.y - (y - 8.0)) < 1e-11 && fabs(d.vy + 8.0) < 1e-11);
        ds_sim_destroy(sim);
    }
}

/* The stress integral's kinetic part follows the kinetic tensor as the
 * disks fall between events: small disks (hardly a collision, so hardly
 * a virial part) with a field and walls, run in one call (each run sums
 * the tensor afresh at its start), against the same disks stepped one
 * step at a time and the tensor they show summed by the trapezoid rule.
 * Elastic wall turns leave xx and yy; between them yy is quadratic in
 * time, whose trapezoid sums err by M g^2 dt^2 t / 6, 1e-4 of the
 * integral here; without the field's terms the tally had 2% of it. */
static void test_the_stress_integral_follows_falling_disks(void **state)
{
    (void)state;
    const size_t n = 50;
    ds_params p = ds_params_default(n, 0.1);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.box = 400.0;
    p.dt = 1.0 / 1024.0;
    p.speed = 20.0;
    ds_sim *sim[2] = {NULL, NULL};
    for (int k = 0; k < 2; ++k) {
        assert_int_equal(ds_sim_create(&p, NULL, &sim[k], NULL), DS_OK);
        assert_int_equal(ds_sim_set_gravity(sim[k], 0.0, -100.0, NULL), DS_OK);
    }
    double sum[3] = {0.0, 0.0, 0.0}, before[3] = {0.0, 0.0, 0.0}, s[3];
    ds_disk d[50];
    for (int step = 0; step <= 2048; ++step) {
        assert_int_equal(ds_sim_get_disks(sim[0], d, NULL), DS_OK);
        double k[3] = {0.0, 0.0, 0.0};
        for (size_t i = 0; i < n; ++i) {
            k[0] += d[i].vx * d[i].vx;
            k[1] += d[i].vy * d[i].vy;
            k[2] += d[i].vx * d[i].vy;
        }
        for (int c = 0; step > 0 && c < 3; ++c)
            sum[c] += 0.5 * (k[c] + before[c]) * p.dt;
        memcpy(before, k, sizeof k);
        if (step < 2048)
            ds_sim_step(sim[0], NULL);
    }
    ds_sim_run(sim[1], 2048, NULL);
    assert_int_equal(ds_sim_get_stress_integral(sim[1], s, NULL), DS_OK);
    /* A pair may meet near the floor: its virial, an impulse times 0.2,
     * is 1e-5 of the integral. */
    assert_true(ds_sim_get_collision_count(sim[1]) < 10);
    assert_true(ds_sim_get_wall_count(sim[1]) > 5); /* some hit the floor */
    for (int c = 0; c < 2; ++c)
        if (!(fabs(s[c] - sum[c]) < 1e-3 * sum[c]))
            fail_msg("component %d: the tally %.9g, the frames %.9g", c, s[c], sum[c]);
    ds_sim_destroy(sim[0]);
    ds_sim_destroy(sim[1]);
}

/* Refusals name the component and the limit, and change nothing: a
 * field along a periodic axis (the disks would fall for ever), not a
 * number, beyond DS_GRAVITY_MAX. */
static void test_a_field_that_cannot_be_is_refused(void **state)
{
    (void)state;
    ds_params p = ds_params_default(10, 5.0);
    p.boundary = DS_BOUNDARY_CHANNEL;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_error err;
    assert_int_equal(ds_sim_set_gravity(sim, 1.0, -10.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "gx");
    assert_int_equal(ds_sim_set_gravity(sim, 0.0, NAN, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "gy");
    assert_int_equal(ds_sim_set_gravity(sim, 0.0, -2e12, &err), DS_ERR_ARG);
    assert_true(err.limit == DS_GRAVITY_MAX);
    double gx = 1.0, gy = 1.0;
    ds_sim_get_gravity(sim, &gx, &gy);
    assert_true(gx == 0.0 && gy == 0.0);
    assert_int_equal(ds_sim_set_gravity(sim, 0.0, -10.0, NULL), DS_OK);
    assert_true(ds_sim_get_potential_energy(sim) > 0.0);
    ds_sim_destroy(sim);
    p.boundary = DS_BOUNDARY_PERIODIC;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_gravity(sim, 0.0, -10.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "gy");
    assert_true(ds_sim_get_potential_energy(sim) == 0.0);
    ds_sim_destroy(sim);
    assert_int_equal(ds_sim_set_gravity(NULL, 0.0, -1.0, NULL), DS_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_falling_disk_flies_a_parabola_and_bounces),
        cmocka_unit_test(test_the_time_step_adds_g_dt_each_step),
        cmocka_unit_test(test_an_elastic_gas_in_a_field_keeps_its_energy),
        cmocka_unit_test(test_a_dilute_gas_in_a_field_has_the_barometric_profile),
        cmocka_unit_test(test_a_disk_at_rest_on_the_floor_hops_and_every_step_ends),
        cmocka_unit_test(test_a_field_set_in_a_run_bends_the_flights_from_then_on),
        cmocka_unit_test(test_the_stress_integral_follows_falling_disks),
        cmocka_unit_test(test_a_field_that_cannot_be_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
