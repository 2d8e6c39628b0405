/* SPDX-License-Identifier: MIT */
/* Thermostats (ds_sim_set_thermostat): Andersen's heat bath samples the
 * canonical ensemble, with either integrator, in any box: the kinetic
 * energy is Gamma(n, kT) distributed (the momentum is not conserved),
 * each kind of a mixture has kT per disk whatever its mass, a disk is
 * redrawn in a step with probability 1 - exp(-nu dt) (the time step's law
 * and the event-driven one's are the same), and two disks in a periodic
 * box have the exact canonical Z; the isokinetic thermostat holds the
 * kinetic temperature at kT; a thermostatted run is the same to the bit
 * however it is cut into calls and checkpoints; and what cannot run is
 * refused. */
#include "test_util.h"

#define PI 3.14159265358979323846

static ds_sim *create(size_t n, double radius, ds_integrator integrator, ds_boundary boundary,
                      double dt)
{
    ds_params p = ds_params_default(n, radius);
    p.integrator = integrator;
    p.boundary = boundary;
    p.dt = dt;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

/* The mean and the variance of the kinetic energy of 16 disks under
 * Andersen's bath at kT = 5000 (the default speed's), nu = 20: K is
 * Gamma(16, kT), mean 16 kT and variance 16 kT^2, in a periodic box as
 * with walls (the bath does not keep the momentum, so all 32 velocity
 * components are its). Samples every 0.25 time units, 5 / nu: a redraw
 * replaces a disk's energy, so K forgets itself as exp(-nu t), and the
 * samples are correlated by exp(-5) = 0.007 (their variances' error
 * grows by 1 + 2 x 0.007 / (1 - 0.007) = 1.014, within the slack below). */
static void kinetic_energy_is_gamma(ds_integrator integrator, ds_boundary boundary)
{
    const size_t n = 16;
    const double kt = 5000.0, nu = 20.0;
    ds_sim *sim = create(n, 5.0, integrator, boundary, 0.01);
    ds_error err;
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, kt, nu, &err), DS_OK);
    assert_int_equal(ds_sim_get_thermostat(sim), DS_THERMOSTAT_ANDERSEN);
    assert_true(ds_sim_get_thermostat_temperature(sim) == kt);
    ds_sim_run(sim, 100, NULL); /* 1 time unit: 20 redraws per disk, the start forgotten */
    const int samples = (int)long_run(8000);
    double sum = 0.0, sum2 = 0.0;
    for (int s = 0; s < samples; ++s) {
        ds_sim_run(sim, 25, NULL);
        const double k = ds_sim_get_kinetic_energy(sim) / kt;
        sum += k;
        sum2 += k * k;
    }
    const double mean = sum / samples, var = sum2 / samples - mean * mean;
    /* The standard errors of Gamma(k, 1)'s sample mean, sqrt(k / M), and
     * sample variance, k sqrt((2 + 6 / k) / M) (its fourth central moment
     * 3 k^2 + 6 k), times 1.02 for the samples' correlation: 5 of them,
     * so a correct run fails with probability 1e-6. At 8000 samples the
     * mean is held to 1.4% and the variance to 8.7%: a bath that kept the
     * momentum (Gamma(15)) misses the mean by 6%, a constant energy has no
     * variance at all. */
    const double k = (double)n, m = (double)samples;
    const double mean_error = 1.02 * sqrt(k / m), var_error = 1.02 * k * sqrt((2.0 + 6.0 / k) / m);
    if (getenv("DS_TEST_VERBOSE"))
        printf("%s %s: K / kT mean %.4f +- %.4f (16), variance %.3f +- %.3f (16)\n",
               ds_integrator_name(integrator), ds_boundary_name(boundary), mean, mean_error, var,
               var_error);
    if (fabs(mean - k) > 5.0 * mean_error || fabs(var - k) > 5.0 * var_error)
        fail_msg("%s %s: K / kT has mean %g (+- %g) and variance %g (+- %g), not 16 and 16",
                 ds_integrator_name(integrator), ds_boundary_name(boundary), mean, mean_error, var,
                 var_error);
    ds_sim_destroy(sim);
}

static void test_andersen_kinetic_energy_is_gamma_n_kt(void **state)
{
    (void)state;
    FOR_EACH_DYNAMIC_INTEGRATOR(i)
    {
        kinetic_energy_is_gamma((ds_integrator)i, DS_BOUNDARY_WALLS);
        kinetic_energy_is_gamma((ds_integrator)i, DS_BOUNDARY_PERIODIC);
    }
}

/* A mixture of 8 disks of mass 1 and 8 of mass 4 (radius 5 and 10, mass
 * by area): each disk's mean kinetic energy is kT whatever its mass, since
 * each is redrawn with its own (with mass 1 for all, the heavy ones would
 * have 4 kT). */
static void test_andersen_gives_each_kind_kt_per_disk(void **state)
{
    (void)state;
    const double kt = 5000.0;
    FOR_EACH_DYNAMIC_INTEGRATOR(i)
    {
        ds_params p = ds_params_default(16, 5.0);
        p.integrator = (ds_integrator)i;
        p.dt = 0.01;
        const ds_species kinds[2] = {{8, 5.0, 0.0, NULL}, {8, 10.0, 0.0, NULL}};
        const ds_mixture mix = {2, kinds, NULL, NULL, DS_MASS_AREA};
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, &mix, &sim, NULL), DS_OK);
        assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, kt, 20.0, NULL), DS_OK);
        ds_sim_run(sim, 100, NULL);
        const int samples = (int)long_run(4000);
        double light = 0.0, heavy = 0.0, masses[16];
        ds_disk d[16];
        assert_int_equal(ds_sim_get_masses(sim, masses, NULL), DS_OK);
        assert_true(masses[0] == 1.0 && masses[15] == 4.0);
        for (int s = 0; s < samples; ++s) {
            ds_sim_run(sim, 25, NULL);
            assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
            for (int k = 0; k < 16; ++k) {
                const double e = 0.5 * masses[k] * (d[k].vx * d[k].vx + d[k].vy * d[k].vy) / kt;
                *(k < 8 ? &light : &heavy) += e / 8.0;
            }
        }
        light /= samples;
        heavy /= samples;
        /* Each kind's energy per disk is Gamma(8, 1) / 8 per sample: a
         * standard error of sqrt(8) / 8 / sqrt(M) (1.02 for correlation),
         * 5 of them: 2.8% at 4000 samples. */
        const double error = 1.02 * sqrt(8.0) / 8.0 / sqrt((double)samples);
        if (fabs(light - 1.0) > 5.0 * error || fabs(heavy - 1.0) > 5.0 * error)
            fail_msg("%s: kinetic energy per disk %g (mass 1) and %g (mass 4) of kT, +- %g",
                     ds_integrator_name((ds_integrator)i), light, heavy, error);
        ds_sim_destroy(sim);
    }
}

/* One disk, far from the walls of a wide box, nothing to collide with:
 * its velocity changes in a step only when the bath redraws it, which
 * happens at least once with probability 1 - exp(-nu dt) = 0.3935 at nu dt
 * = 0.5, with the time step (applied at the end of the step it falls in)
 * as with the event-driven integrator (at its exact time): the same law. A
 * redraw per step with probability nu dt would give 0.5. */
static void test_a_disk_is_redrawn_in_a_step_with_probability_one_minus_exp(void **state)
{
    (void)state;
    const double nu = 50.0, dt = 0.01, want = 1.0 - exp(-nu * dt);
    FOR_EACH_DYNAMIC_INTEGRATOR(i)
    {
        ds_sim *sim = create(1, 1.0, (ds_integrator)i, DS_BOUNDARY_PERIODIC, dt);
        /* kT = 1e-6: the disk moves less than 1e-2 in a run of 40000 steps. */
        assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, 1e-6, nu, NULL), DS_OK);
        const int steps = (int)long_run(40000);
        int changed = 0;
        ds_disk before = ds_sim_get_disk(sim, 0);
        for (int s = 0; s < steps; ++s) {
            ds_sim_step(sim, NULL);
            const ds_disk after = ds_sim_get_disk(sim, 0);
            changed += after.vx != before.vx || after.vy != before.vy;
            before = after;
        }
        const double p = (double)changed / steps, error = sqrt(want * (1.0 - want) / steps);
        /* 5 binomial standard errors: 0.012 at 40000 steps, against the
         * 0.106 between the right law and the wrong one. */
        if (fabs(p - want) > 5.0 * error)
            fail_msg("%s: redrawn in %g of the steps, not %g (+- %g)",
                     ds_integrator_name((ds_integrator)i), p, want, error);
        ds_sim_destroy(sim);
    }
}

/* Two disks in a periodic box: the canonical Z = (1 + A / (A - pi
 * sigma^2)) / 2 (tests/test_canonical.c derives it), here with the bath's
 * kT, which the observables take while a thermostat is set: with two
 * disks the kinetic temperature of an instant, K_int / (N - 1), is an
 * exponential variable, and 1 over it has no mean at all. */
static void two_disks_under_a_bath_give_the_exact_z(double radius)
{
    const double box = 10.0, sigma = 2.0 * radius, area = box * box;
    const double exact = 0.5 * (1.0 + area / (area - PI * sigma * sigma));
    ds_params p = ds_params_default(2, radius);
    p.box = box;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.speed = 1.0;
    p.dt = 0.1;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    /* kT 0.5 (the start's), a redraw per disk per 2 time units. */
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, 0.5, 0.5, NULL), DS_OK);
    assert_true(ds_sim_get_temperature(sim) == 0.5);
    enum { BLOCKS = 40 };
    double z[BLOCKS];
    ds_sim_run(sim, 200, NULL);
    /* Blocks of 1000 time units, 500 redraws per disk each and hundreds of
     * collisions (test_canonical.c counts them): far longer than the
     * pressure's memory, so the blocks are independent. */
    for (int b = 0; b < BLOCKS; ++b) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, long_run(10000), NULL);
        z[b] = ds_sim_get_compressibility_factor(sim);
    }
    const block_stats s = stats_of(z, BLOCKS);
    if (getenv("DS_TEST_VERBOSE"))
        printf("two disks under Andersen, R = %g: Z = %.5f +- %.5f (exact %.5f)\n", radius, s.mean,
               s.error, exact);
    /* 5 standard errors of 40 independent blocks (a correct run fails
     * with probability 6e-7), the error small enough to mean something. */
    assert_true(s.error < (quick_mode() ? 0.1 : 0.03) * (exact - 1.0));
    if (fabs(s.mean - exact) > 5.0 * s.error)
        fail_msg("two disks under Andersen, R = %g: Z = %.5f +- %.5f, exact %.5f", radius, s.mean,
                 s.error, exact);
    ds_sim_destroy(sim);
}

static void test_two_disks_under_andersen_have_the_exact_canonical_z(void **state)
{
    (void)state;
    two_disks_under_a_bath_give_the_exact_z(2.0); /* Z = 1.506 */
    two_disks_under_a_bath_give_the_exact_z(1.0); /* Z = 1.072 */
}

/* The kinetic temperature of the disks' velocities, by the rule of
 * ds_sim_get_temperature without a bath (which now answers the bath's). */
static double kinetic_temperature(const ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    double px = 0.0, py = 0.0, *m = malloc(n * sizeof *m), mass = 0.0;
    assert_non_null(m);
    assert_int_equal(ds_sim_get_masses(sim, m, NULL), DS_OK);
    for (size_t k = 0; k < n; ++k)
        mass += m[k];
    free(m);
    ds_sim_get_momentum(sim, &px, &py);
    const double k = ds_sim_get_kinetic_energy(sim);
    return ds_sim_get_boundary(sim) == DS_BOUNDARY_WALLS
               ? k / (double)n
               : (k - (px * px + py * py) / (2.0 * mass)) / ((double)n - 1.0);
}

/* The isokinetic thermostat scales every velocity at each step's end to
 * the kinetic temperature kT: after the first step every velocity is its
 * twin's without a thermostat times one factor (positions the same: the
 * step was taken before), and after every step the kinetic temperature is
 * kT to rounding, in a periodic box whose momentum is not zero too. */
static void test_isokinetic_holds_the_kinetic_temperature(void **state)
{
    (void)state;
    enum { N = 100 };
    FOR_EACH_DYNAMIC_INTEGRATOR(i)
    for (int periodic = 0; periodic < 2; ++periodic) {
        const ds_boundary boundary = periodic ? DS_BOUNDARY_PERIODIC : DS_BOUNDARY_WALLS;
        ds_sim *sim = create(N, 5.0, (ds_integrator)i, boundary, 0.001);
        ds_sim *twin = create(N, 5.0, (ds_integrator)i, boundary, 0.001);
        ds_disk d[N], t[N];
        assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
        for (int k = 0; k < N; ++k)
            d[k].vx += 30.0; /* a drift: the momentum is not zero */
        assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK);
        assert_int_equal(ds_sim_set_disks(twin, d, NULL), DS_OK);
        const double kt = 0.5 * kinetic_temperature(sim);
        assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ISOKINETIC, kt, 0.0, NULL),
                         DS_OK);
        assert_true(ds_sim_get_temperature(sim) == kt);
        ds_sim_step(sim, NULL);
        ds_sim_step(twin, NULL);
        assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
        assert_int_equal(ds_sim_get_disks(twin, t, NULL), DS_OK);
        const double f = d[0].vx / t[0].vx;
        for (int k = 0; k < N; ++k) {
            assert_true(d[k].x == t[k].x && d[k].y == t[k].y);
            assert_true(fabs(d[k].vx - f * t[k].vx) <= 1e-14 * fabs(t[k].vx) + 1e-12 &&
                        fabs(d[k].vy - f * t[k].vy) <= 1e-14 * fabs(t[k].vy) + 1e-12);
        }
        for (int s = 0; s < 50; ++s) {
            if (fabs(kinetic_temperature(sim) / kt - 1.0) > 1e-11)
                fail_msg("%s: kinetic temperature %.17g after step %d, not %.17g",
                         ds_integrator_name((ds_integrator)i), kinetic_temperature(sim), s, kt);
            ds_sim_step(sim, NULL);
        }
        ds_sim_destroy(sim);
        ds_sim_destroy(twin);
    }
}

static void assert_same_disks(const ds_sim *a, const ds_sim *b)
{
    const size_t n = ds_sim_get_count(a);
    ds_disk *da = malloc(n * sizeof *da), *db = malloc(n * sizeof *db);
    assert_true(da && db);
    assert_int_equal(ds_sim_get_disks(a, da, NULL), DS_OK);
    assert_int_equal(ds_sim_get_disks(b, db, NULL), DS_OK);
    assert_memory_equal(da, db, n * sizeof *da);
    assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(b));
    free(da);
    free(db);
}

/* A thermostatted run, cut into single steps, or saved and loaded in the
 * middle (its redraws' stream and the next redraw's time with it), is the
 * run of one call, to the bit: both kinds, both integrators, a periodic
 * box whose event-driven clock moves its origin on the way. */
static void test_a_thermostatted_run_is_the_same_however_it_is_cut(void **state)
{
    (void)state;
    FOR_EACH_DYNAMIC_INTEGRATOR(i)
    for (int kind = DS_THERMOSTAT_ANDERSEN; kind < DS_THERMOSTAT_COUNT; ++kind) {
        const ds_integrator integrator = (ds_integrator)i;
        ds_sim *a = create(200, 10.0, integrator, DS_BOUNDARY_PERIODIC, 0.001);
        ds_sim *b = create(200, 10.0, integrator, DS_BOUNDARY_PERIODIC, 0.001);
        const double rate = kind == DS_THERMOSTAT_ANDERSEN ? 50.0 : 0.0;
        assert_int_equal(ds_sim_set_thermostat(a, (ds_thermostat)kind, 3000.0, rate, NULL), DS_OK);
        assert_int_equal(ds_sim_set_thermostat(b, (ds_thermostat)kind, 3000.0, rate, NULL), DS_OK);
        ds_sim_run(a, 400, NULL);
        for (int s = 0; s < 400; ++s)
            ds_sim_step(b, NULL);
        assert_same_disks(a, b);
        ds_sim *c = through_checkpoint(a);
        assert_int_equal(ds_sim_get_thermostat(c), (ds_thermostat)kind);
        ds_sim_run(a, 12000, NULL); /* past a few moves of the event-driven origin */
        ds_sim_run(c, 12000, NULL);
        assert_same_disks(a, c);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
        ds_sim_destroy(c);
    }
}

static void test_what_a_thermostat_cannot_do_is_refused(void **state)
{
    (void)state;
    ds_sim *sim = create(10, 5.0, DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC, 0.001);
    ds_error err;
    const ds_thermostat andersen = DS_THERMOSTAT_ANDERSEN;
    assert_int_equal(ds_sim_set_thermostat(NULL, andersen, 1.0, 0.0, &err), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_COUNT, 1.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "thermostat");
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, -1.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "kt");
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, NAN, 0.0, &err), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, INFINITY, 0.0, &err), DS_ERR_ARG);
    /* Past the speed limit: 8.58 sqrt(kT) > 1e12 for kT past 1.36e22. */
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 1.4e22, 0.0, &err), DS_ERR_ARG);
    assert_true(err.limit < 1.4e22 && err.limit > 1.3e22);
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 1.0, -1.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "collision_rate");
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 1.0, INFINITY, &err), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ISOKINETIC, 1.0, 2.0, &err),
                     DS_ERR_ARG);
    assert_string_equal(err.field, "collision_rate");
    assert_int_equal(ds_sim_get_thermostat(sim), DS_THERMOSTAT_NONE);
    /* kt 0: the temperature of now (ds_sim_get_temperature's, without a
     * bath), with the default rate. */
    const double now = ds_sim_get_temperature(sim);
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 0.0, 0.0, &err), DS_OK);
    assert_true(ds_sim_get_thermostat_temperature(sim) == now);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_NONE, 0.0, 0.0, &err), DS_OK);
    assert_int_equal(ds_sim_get_thermostat(sim), DS_THERMOSTAT_NONE);
    assert_true(ds_sim_get_thermostat_temperature(sim) == 0.0);
    /* Disks at rest have no temperature of now. */
    ds_disk d[10];
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    for (int k = 0; k < 10; ++k)
        d[k].vx = d[k].vy = 0.0;
    assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK);
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 0.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "kt");
    /* A growth takes out its own heat: neither while the other is on. */
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 100.0, 100.0, &err), DS_OK);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "rate");
    ds_sim_run(sim, 100, NULL); /* the bath sets them moving: 10 redraws a disk */
    assert_true(ds_sim_get_kinetic_energy(sim) > 0.0);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_NONE, 0.0, 0.0, &err), DS_OK);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.0, 0.0, &err), DS_OK);
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 100.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "thermostat");
    ds_sim_destroy(sim);
    /* Event chains never change a velocity (they sample the canonical
     * ensemble at kT = K / N without a bath): a heat bath is refused. */
    sim = create(10, 5.0, DS_INTEGRATOR_EVENT_CHAIN, DS_BOUNDARY_PERIODIC, 0.001);
    assert_int_equal(ds_sim_set_thermostat(sim, andersen, 1.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "integrator");
    assert_int_equal(ds_sim_get_thermostat(sim), DS_THERMOSTAT_NONE);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_andersen_kinetic_energy_is_gamma_n_kt),
        cmocka_unit_test(test_andersen_gives_each_kind_kt_per_disk),
        cmocka_unit_test(test_a_disk_is_redrawn_in_a_step_with_probability_one_minus_exp),
        cmocka_unit_test(test_two_disks_under_andersen_have_the_exact_canonical_z),
        cmocka_unit_test(test_isokinetic_holds_the_kinetic_temperature),
        cmocka_unit_test(test_a_thermostatted_run_is_the_same_however_it_is_cut),
        cmocka_unit_test(test_what_a_thermostat_cannot_do_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
