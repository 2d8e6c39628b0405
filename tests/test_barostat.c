/* SPDX-License-Identifier: MIT */
/* The barostat (ds_sim_set_barostat): Monte Carlo moves of ln A sample
 * the isobaric ensemble exactly, with either integrator: an ideal gas has
 * <A> = (N + 1) / (beta P) and <N / A> = beta P, with moves of the aspect
 * too; two disks, whose configurational integral is A (A - pi sigma^2),
 * have the mean area and area fraction of that weight; at the pressure a
 * canonical run measured, the isobaric run's mean area fraction is the
 * canonical one (0.50, and 0.70 with its finite-size shift); a move keeps
 * the scaled centres, the velocities and the image counts; a run is the
 * same to the bit however it is cut into calls and checkpoints; and what
 * cannot run is refused. */
#include "test_util.h"

#define PI 3.14159265358979323846

static ds_sim *create(size_t n, double radius, double box, ds_integrator integrator, double dt)
{
    ds_params p = ds_params_default(n, radius);
    p.integrator = integrator;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.box = box;
    p.dt = dt;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

static double area_of(const ds_sim *sim)
{
    return ds_sim_get_box_width(sim) * ds_sim_get_box_height(sim);
}

/* The mean area and the mean of 1 / A over a run of `steps` steps, a
 * move every `every`, in 50 blocks whose means are independent (each far
 * longer than the area's memory), with their standard errors. */
typedef struct area_stats {
    block_stats area, inverse;
} area_stats;

static area_stats sample_area(ds_sim *sim, int steps, int every)
{
    enum { BLOCKS = 50 };
    double a[BLOCKS], inv[BLOCKS];
    const int per = steps / every / BLOCKS;
    for (int b = 0; b < BLOCKS; ++b) {
        a[b] = inv[b] = 0.0;
        for (int m = 0; m < per; ++m) {
            ds_sim_run(sim, (uint64_t)every, NULL);
            a[b] += area_of(sim) / per;
            inv[b] += 1.0 / area_of(sim) / per;
        }
    }
    area_stats s = {stats_of(a, BLOCKS), stats_of(inv, BLOCKS)};
    return s;
}

/* Four disks of radius 1e-3 in a box about 1000 wide (an ideal gas: a
 * pair meets within 2e-3, one chance in 1e7 per move), beta P such that
 * (N + 1) / (beta P) = 10^6: the area is Gamma(5, 1 / (beta P)), mean
 * (N + 1) / (beta P), and <N / A> = beta P. Moves of ln A up to 0.5 (the
 * area's own spread in ln A is 1 / sqrt(5) = 0.45). A walk that forgot
 * the measure of ln A (N instead of N + 1) would give 0.8 of the mean.
 * (The aspect moves are tested with two disks: an ideal gas's aspect
 * walks without bound.) */
static void ideal_gas_area(ds_integrator integrator)
{
    const size_t n = 4;
    const double radius = 1e-3, sigma = 2.0 * radius, beta_p = 5e-6;
    ds_sim *sim = create(n, radius, 1000.0, integrator, 0.01);
    ds_error err;
    if (ds_sim_set_barostat(sim, beta_p * sigma * sigma, 1, 0.5, 0, &err) != DS_OK)
        fail_msg("%s", err.message);
    assert_true(ds_sim_get_barostat_pressure(sim) == beta_p * sigma * sigma);
    ds_sim_run(sim, 1000, NULL);
    const area_stats s = sample_area(sim, (int)long_run(50000), 1);
    const double want = (double)(n + 1) / beta_p;
    if (getenv("DS_TEST_VERBOSE"))
        printf("%s: <A> / ((N + 1) / beta P) = %.4f +- %.4f, <N / A> / beta P = %.4f +- %.4f, "
               "accepted %.3f\n",
               ds_integrator_name(integrator), s.area.mean / want, s.area.error / want,
               n * s.inverse.mean / beta_p, n * s.inverse.error / beta_p,
               ds_sim_get_barostat_acceptance(sim));
    /* 5 standard errors of 50 independent blocks: a correct run fails
     * with probability 6e-7; the errors must tell N + 1 from N (20%). */
    assert_true(s.area.error < 0.03 * want);
    if (fabs(s.area.mean - want) > 5.0 * s.area.error ||
        fabs(n * s.inverse.mean - beta_p) > 5.0 * n * s.inverse.error)
        fail_msg("%s: <A> = %g +- %g, not (N + 1) / (beta P) = %g; <N / A> = %g +- %g, not %g",
                 ds_integrator_name(integrator), s.area.mean, s.area.error, want,
                 n * s.inverse.mean, n * s.inverse.error, beta_p);
    ds_sim_destroy(sim);
}

static void test_an_ideal_gas_has_mean_area_n_plus_one_over_beta_p(void **state)
{
    (void)state;
    for (int i = 0; i < DS_INTEGRATOR_COUNT; ++i)
        ideal_gas_area((ds_integrator)i);
}

/* The integral of A^k exp(-b A) ln(A / a)^l from a to infinity: l = 0 in
 * closed form, exp(-a b) sum_j k! / j! a^j / b^(k + 1 - j); l = 1 by
 * Simpson's rule over 40 / b past a (exp(-40) of the rest left out),
 * 20000 intervals (its error below 1e-9 of the integral). */
static double area_moment(int k, int l, double a, double b)
{
    if (l == 0) {
        double sum = 0.0, term = 1.0 / b; /* j = k: a^k / b */
        for (int j = k; j >= 0; --j) {
            sum += term * pow(a, j);
            term *= (double)j / b;
        }
        return exp(-a * b) * sum;
    }
    const int m = 20000;
    const double h = 40.0 / b / m;
    double sum = 0.0;
    for (int i = 0; i <= m; ++i) {
        const double x = a + i * h, f = pow(x, k) * exp(-b * x) * log(x / a);
        sum += (i == 0 || i == m ? 1.0 : i % 2 ? 4.0 : 2.0) * f;
    }
    return sum * h / 3.0;
}

/* Two disks of radius 1 in a periodic box: their configurational
 * integral is A (A - pi sigma^2) in any box whose sides exceed 2 sigma
 * (the separation anywhere but inside the contact circle, which then
 * meets no image of itself), and the barostat keeps the sides above 4
 * radii = 2 sigma. The area's weight is exp(-beta P A) A (A - c), c = pi
 * sigma^2, for A > 4 sigma^2 (the square box's sides); the aspect moves
 * walk uniformly in ln(L_x / L_y) over the range the sides' limit leaves
 * at that area, whose length is ln(A / 4 sigma^2), a factor more. So <A>
 * = (I3 - c I2) / (I2 - c I1) and <1 / A> = (I1 - c I0) / (I2 - c I1), I_k
 * the integrals of A^k exp(-beta P A) above 4 sigma^2, times ln(A / 4
 * sigma^2) with aspect moves. At beta P = 0.1 (beta P sigma^2 = 0.4) the
 * disks cover a fifth of the box on average (0.188), their overlaps refuse
 * many compressions and the sides' limit some: <A> = 39.23, where without
 * the overlaps it would be 35.28 (30 without the limit either), and
 * aspect moves make it 47.17. A heat bath makes the pair forget its
 * motion quickly. The time step samples the same to within its overlaps
 * of v dt = 0.007 (at kT = 1, dt 0.005), a change of c by 0.1%, well
 * inside the errors. */
static void two_disks_area(ds_integrator integrator, int aspect)
{
    const double radius = 1.0, sigma = 2.0, beta_p = 0.1, c = PI * sigma * sigma;
    const double lowest = 4.0 * sigma * sigma;
    double in[4];
    for (int k = 0; k < 4; ++k)
        in[k] = area_moment(k, aspect, lowest, beta_p);
    const double want_a = (in[3] - c * in[2]) / (in[2] - c * in[1]);
    const double want_inv = (in[1] - c * in[0]) / (in[2] - c * in[1]);
    const int step = integrator == DS_INTEGRATOR_TIME_STEP;
    ds_sim *sim = create(2, radius, 7.0, integrator, step ? 0.005 : 0.05);
    /* Event chains sample the canonical ensemble without a bath (and
     * refuse one: they never change a velocity). */
    if (integrator != DS_INTEGRATOR_EVENT_CHAIN)
        assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, 1.0, 2.0, NULL), DS_OK);
    assert_int_equal(
        ds_sim_set_barostat(sim, beta_p * sigma * sigma, step ? 4 : 1, 0.3, aspect, NULL), DS_OK);
    ds_sim_run(sim, 1000, NULL);
    /* 50 blocks of 1200 moves: each many times the area's memory (a few
     * moves) and the pair's (a time unit: 20 event-driven moves, 50 time
     * step ones). */
    const area_stats s = sample_area(sim, (int)long_run(60000) * (step ? 4 : 1), step ? 4 : 1);
    if (getenv("DS_TEST_VERBOSE"))
        printf("two disks, %s%s: <A> = %.4f +- %.4f (exact %.4f), <1 / A> = %.6f +- %.6f (exact "
               "%.6f), accepted %.3f\n",
               ds_integrator_name(integrator), aspect ? " with aspect moves" : "", s.area.mean,
               s.area.error, want_a, s.inverse.mean, s.inverse.error, want_inv,
               ds_sim_get_barostat_acceptance(sim));
    /* 5 standard errors (a correct run fails with probability 6e-7), and
     * errors that tell the overlaps' effect (10%) from none (in the quick
     * run, a tenth as long, three times larger). */
    assert_true(s.area.error < (quick_mode() ? 0.06 : 0.02) * want_a);
    if (fabs(s.area.mean - want_a) > 5.0 * s.area.error ||
        fabs(s.inverse.mean - want_inv) > 5.0 * s.inverse.error)
        fail_msg("two disks, %s: <A> = %g +- %g (exact %g), <1 / A> = %g +- %g (exact %g)",
                 ds_integrator_name(integrator), s.area.mean, s.area.error, want_a, s.inverse.mean,
                 s.inverse.error, want_inv);
    ds_sim_destroy(sim);
}

static void test_two_disks_have_the_exact_isobaric_area(void **state)
{
    (void)state;
    for (int i = 0; i < DS_INTEGRATOR_COUNT; ++i)
        two_disks_area((ds_integrator)i, 0);
    two_disks_area(DS_INTEGRATOR_EVENT_DRIVEN, 1);
}

/* One move, set against the same step without a barostat: the box's
 * sides and every centre scaled by one factor, the velocities and the
 * image counts kept (a move is a change of units along each axis). */
static void test_a_move_scales_the_centres_and_keeps_velocities_and_images(void **state)
{
    (void)state;
    enum { N = 4 };
    for (int i = 0; i < DS_INTEGRATOR_COUNT; ++i) {
        ds_sim *sim = create(N, 1e-3, 1000.0, (ds_integrator)i, 0.01);
        ds_sim *twin = create(N, 1e-3, 1000.0, (ds_integrator)i, 0.01);
        assert_int_equal(ds_sim_set_barostat(sim, 2e-11, 1, 0.5, 0, NULL), DS_OK);
        int moved = 0;
        for (int s = 0; s < 20 && moved < 5; ++s) {
            ds_disk d[N], t[N];
            int32_t im[2 * N], it[2 * N];
            const double before = ds_sim_get_box_width(sim);
            ds_sim_step(sim, NULL);
            ds_sim_step(twin, NULL);
            const double f = ds_sim_get_box_width(sim) / before;
            assert_true(ds_sim_get_box_height(sim) / ds_sim_get_box_width(sim) == 1.0);
            assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
            assert_int_equal(ds_sim_get_disks(twin, t, NULL), DS_OK);
            assert_int_equal(ds_sim_get_images(sim, im, NULL), DS_OK);
            assert_int_equal(ds_sim_get_images(twin, it, NULL), DS_OK);
            assert_memory_equal(im, it, sizeof im);
            for (int k = 0; k < N; ++k) {
                assert_true(d[k].vx == t[k].vx && d[k].vy == t[k].vy);
                assert_true(fabs(d[k].x - f * t[k].x) <= 1e-12 * ds_sim_get_box_width(sim));
                assert_true(fabs(d[k].y - f * t[k].y) <= 1e-12 * ds_sim_get_box_width(sim));
            }
            moved += f != 1.0;
            /* The twin follows the box, so the next step starts alike. */
            ds_sim_destroy(twin);
            twin = NULL;
            const size_t len = ds_checkpoint_get_size(sim);
            uint8_t *buf = malloc(len);
            assert_non_null(buf);
            assert_int_equal(ds_checkpoint_format(sim, buf, len, NULL, NULL), DS_OK);
            assert_int_equal(ds_checkpoint_parse(buf, len, &twin, NULL), DS_OK);
            free(buf);
            assert_int_equal(ds_sim_set_barostat(twin, 0.0, 0, 0.0, 0, NULL), DS_OK);
        }
        assert_true(moved == 5); /* moves are accepted 78% of the time */
        ds_sim_destroy(sim);
        ds_sim_destroy(twin);
    }
}

static void assert_same_run(const ds_sim *a, const ds_sim *b)
{
    const size_t n = ds_sim_get_count(a);
    ds_disk *da = malloc(n * sizeof *da), *db = malloc(n * sizeof *db);
    assert_true(da && db);
    assert_int_equal(ds_sim_get_disks(a, da, NULL), DS_OK);
    assert_int_equal(ds_sim_get_disks(b, db, NULL), DS_OK);
    assert_memory_equal(da, db, n * sizeof *da);
    assert_true(ds_sim_get_box_width(a) == ds_sim_get_box_width(b));
    assert_true(ds_sim_get_box_height(a) == ds_sim_get_box_height(b));
    assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(b));
    assert_true(ds_sim_get_barostat_acceptance(a) == ds_sim_get_barostat_acceptance(b));
    free(da);
    free(db);
}

/* 200 disks at area fraction 0.5 under a heat bath and a barostat with
 * aspect moves: a run cut into single steps, or saved and loaded in the
 * middle (the box, the moves' stream, the bath's), is the run of one
 * call, to the bit, with either integrator; the box has moved. */
static void test_an_isobaric_run_is_the_same_however_it_is_cut(void **state)
{
    (void)state;
    const double radius = sqrt(0.5e6 / (200.0 * PI));
    for (int i = 0; i < DS_INTEGRATOR_COUNT; ++i) {
        ds_sim *a = create(200, radius, 1000.0, (ds_integrator)i, 0.001);
        ds_sim *b = create(200, radius, 1000.0, (ds_integrator)i, 0.001);
        for (int k = 0; k < 2; ++k) {
            ds_sim *s = k ? b : a;
            if (i != DS_INTEGRATOR_EVENT_CHAIN) /* canonical without a bath */
                assert_int_equal(
                    ds_sim_set_thermostat(s, DS_THERMOSTAT_ANDERSEN, 5000.0, 0.0, NULL), DS_OK);
            assert_int_equal(ds_sim_set_barostat(s, 2.6, 5, 0.0, 1, NULL), DS_OK);
        }
        ds_sim_run(a, 300, NULL);
        for (int s = 0; s < 300; ++s)
            ds_sim_step(b, NULL);
        assert_same_run(a, b);
        assert_true(ds_sim_get_box_width(a) != 1000.0 && ds_sim_get_box_height(a) != 1000.0);
        ds_sim *c = through_checkpoint(a);
        ds_sim_run(a, 12000, NULL); /* past a move of the event-driven origin */
        ds_sim_run(c, 12000, NULL);
        assert_same_run(a, c);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
        ds_sim_destroy(c);
    }
}

/* Henderson's equation of state (1975), Z = (1 + eta^2 / 8) / (1 -
 * eta)^2, for the slope d ln(beta P) / d ln eta = 1 + eta Z' / Z that
 * turns a pressure's error into an area fraction's. */
static double henderson_slope(double eta)
{
    const double z = (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
    const double dz = (eta / 4.0) / ((1.0 - eta) * (1.0 - eta)) + 2.0 * z / (1.0 - eta);
    return 1.0 + eta * dz / z;
}

/* The mean of n samples of a correlated series and its standard error
 * corrected for the correlation (Flyvbjerg and Petersen 1989): the
 * samples averaged in pairs again and again, the naive error of each
 * level's blocks grows until the blocks are longer than the series'
 * memory, then stays; the largest over the levels that keep 32 blocks or
 * more. x is overwritten. */
static block_stats blocked(double *x, int n)
{
    block_stats s = stats_of(x, n);
    for (; n >= 32; n /= 2) {
        const block_stats level = stats_of(x, n);
        s.error = fmax(s.error, level.error);
        for (int i = 0; i < n / 2; ++i)
            x[i] = 0.5 * (x[2 * i] + x[2 * i + 1]);
    }
    return s;
}

/* 64 disks at area fraction eta on a lattice in a periodic box, melted,
 * under Andersen's bath: Z measured canonically, then the barostat at the
 * reduced pressure that gives, its area fraction and its virial pressure
 * (each stretch between two moves at its own area) averaged. The
 * isobaric run's mean of the canonical pressure of the areas it visits
 * is the pressure set, exactly at any N (its weight exp(-beta P A) Q(A)
 * has <d ln Q / dA> = beta P). Its mean area fraction is the canonical
 * one up to the ensembles' difference at finite N, -rho Pi'' / (2 N
 * Pi'^2) relative (Pi = beta P as a function of rho), 1e-3 of eta at 0.50
 * by Henderson's equation of state, below the errors here; near 0.70 a
 * system of 64 disks has a flat canonical pressure (the liquid-hexatic
 * transition: beta P sigma^2 = 8.104 +- 0.018 at 0.68, 8.126 +- 0.023 at
 * 0.69 and 8.115 +- 0.023 at 0.70), where the isobaric area fraction
 * spreads over the whole flat part and its mean is not the canonical one
 * (0.6888 +- 0.0006 over 10^7 steps; docs/physics.md). The blocked
 * errors take the area's long memory into account. */
static void isobaric_meets_canonical(double eta, int compare_eta)
{
    const size_t n = 64;
    const double height = 1000.0 * sqrt(3.0) / 2.0;
    const double radius = sqrt(eta * 1000.0 * height / ((double)n * PI)), sigma = 2.0 * radius;
    ds_params p = ds_params_default(n, radius);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.placement = DS_PLACEMENT_LATTICE;
    p.box_y = height;
    p.dt = 0.01;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, 5000.0, 0.0, NULL), DS_OK);
    ds_sim_run(sim, 2000, NULL); /* 20 time units: the lattice melts */
    /* The canonical Z over samples of 100 steps (a time unit, five
     * collisions per disk), 2^10 of them; then a move every other step,
     * the area forgetting itself over some 600 moves (the configuration
     * must follow it), and 2^16 samples, each of a step between two
     * moves, whose collisions see the area of the sample: a move's new
     * area is not the one its step's collisions saw. */
    const int samples = 65536, every = 2;
    double *x = malloc((size_t)samples * sizeof *x), *y = malloc((size_t)samples * sizeof *y);
    assert_true(x && y);
    for (int s = 0; s < samples / 64; ++s) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, 100, NULL);
        x[s] = ds_sim_get_compressibility_factor(sim);
    }
    const block_stats canonical = blocked(x, samples / 64);
    const double beta_p = canonical.mean * (double)n * sigma * sigma / (1000.0 * height);
    assert_int_equal(ds_sim_set_barostat(sim, beta_p, (uint64_t)every, 0.0, 0, NULL), DS_OK);
    ds_sim_run(sim, 20000, NULL);
    assert_true(ds_sim_get_steps(sim) % 2 == 0); /* the moves come at the even steps' ends */
    for (int s = 0; s < samples; ++s) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, 1, NULL);
        x[s] = ds_sim_get_area_fraction(sim);
        y[s] = ds_sim_get_virial_pressure(sim) / 5000.0 * sigma * sigma;
        ds_sim_run(sim, 1, NULL);
    }
    const block_stats isobaric = blocked(x, samples), virial = blocked(y, samples);
    free(x);
    free(y);
    /* The canonical pressure's error as one of the area fraction. */
    const double eta_error = eta * canonical.error / canonical.mean / henderson_slope(eta);
    const double error = sqrt(isobaric.error * isobaric.error + eta_error * eta_error);
    if (getenv("DS_TEST_VERBOSE"))
        printf("eta %.2f: Z = %.4f +- %.4f, beta P sigma^2 = %.4f; isobaric eta %.5f +- %.5f "
               "(%.5f with the pressure's), its virial beta P sigma^2 %.4f +- %.4f, accepted "
               "%.3f\n",
               eta, canonical.mean, canonical.error, beta_p, isobaric.mean, isobaric.error, error,
               virial.mean, virial.error, ds_sim_get_barostat_acceptance(sim));
    /* 5 standard errors each: a correct run fails with probability 1e-6. */
    const double k = 5.0;
    if (fabs(virial.mean - beta_p) > k * virial.error)
        fail_msg("eta %g: the isobaric run's virial beta P sigma^2 = %g +- %g, set %g", eta,
                 virial.mean, virial.error, beta_p);
    if (compare_eta && fabs(isobaric.mean - eta) > k * error)
        fail_msg("eta %g: the isobaric run's area fraction is %g +- %g", eta, isobaric.mean, error);
    ds_sim_destroy(sim);
}

static void test_isobaric_and_canonical_runs_agree(void **state)
{
    (void)state;
    /* The area's memory is hundreds of moves, and at 0.70 the run visits
     * both sides of the loop slowly: a tenth of the run (the valgrind
     * run's) holds neither the canonical Z nor the isobaric means to its
     * errors, so it checks nothing here (the other tests run the same
     * code under valgrind). */
    if (quick_mode())
        skip();
    isobaric_meets_canonical(0.50, 1);
    isobaric_meets_canonical(0.70, 0);
}

static void test_what_a_barostat_cannot_do_is_refused(void **state)
{
    (void)state;
    ds_error err;
    ds_params p = ds_params_default(10, 5.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
        if (b == DS_BOUNDARY_PERIODIC)
            continue;
        p.boundary = (ds_boundary)b;
        ds_sim *walls = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &walls, NULL), DS_OK);
        assert_int_equal(ds_sim_set_barostat(walls, 1.0, 0, 0.0, 0, &err), DS_ERR_ARG);
        assert_string_equal(err.field, "boundary");
        assert_non_null(strstr(err.message, "periodic box only"));
        ds_sim_destroy(walls);
    }
    ds_sim *sim = create(10, 5.0, 1000.0, DS_INTEGRATOR_EVENT_DRIVEN, 0.001);
    assert_int_equal(ds_sim_set_barostat(NULL, 1.0, 0, 0.0, 0, &err), DS_ERR_ARG);
    const double bad[] = {-1.0, NAN, INFINITY, 2e9};
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(ds_sim_set_barostat(sim, bad[k], 0, 0.0, 0, &err), DS_ERR_ARG);
        assert_string_equal(err.field, "pressure");
        assert_int_equal(ds_sim_set_barostat(sim, 1.0, 0, bad[k], 0, &err), DS_ERR_ARG);
        assert_string_equal(err.field, "max_step");
    }
    assert_true(ds_sim_get_barostat_pressure(sim) == 0.0);
    /* The defaults, and 0 removes it. */
    assert_int_equal(ds_sim_set_barostat(sim, 1.0, 0, 0.0, 0, &err), DS_OK);
    assert_true(ds_sim_get_barostat_pressure(sim) == 1.0);
    assert_true(ds_sim_get_barostat_acceptance(sim) == 0.0);
    ds_sim_run(sim, 100, NULL); /* ten moves */
    assert_true(ds_sim_get_barostat_acceptance(sim) > 0.0);
    /* A growth moves the radii in a box of its own: neither while the
     * other is on. */
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.0, 0.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "rate");
    assert_int_equal(ds_sim_set_barostat(sim, 0.0, 0, 0.0, 0, &err), DS_OK);
    assert_true(ds_sim_get_barostat_pressure(sim) == 0.0);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.0, 0.0, &err), DS_OK);
    assert_int_equal(ds_sim_set_barostat(sim, 1.0, 0, 0.0, 0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "pressure");
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_an_ideal_gas_has_mean_area_n_plus_one_over_beta_p),
        cmocka_unit_test(test_two_disks_have_the_exact_isobaric_area),
        cmocka_unit_test(test_a_move_scales_the_centres_and_keeps_velocities_and_images),
        cmocka_unit_test(test_an_isobaric_run_is_the_same_however_it_is_cut),
        cmocka_unit_test(test_isobaric_and_canonical_runs_agree),
        cmocka_unit_test(test_what_a_barostat_cannot_do_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
