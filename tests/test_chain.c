/* SPDX-License-Identifier: MIT */
/* Event-chain Monte Carlo (DS_INTEGRATOR_EVENT_CHAIN): the ensemble it
 * samples and the pressure it measures, held to an exact result and to
 * the event-driven dynamics; what it promises about time, velocities and
 * temperature; its cells against brute force; and the cases that could
 * stall a chain. docs/physics.md ("Event-chain Monte Carlo") derives
 * what is measured. */
#include "test_util.h"

#include "chain/chain.h"

#define PI 3.14159265358979323846

static ds_sim *create(ds_params *p, const ds_mixture *mixture)
{
    ds_sim *sim = NULL;
    ds_error why;
    if (ds_sim_create(p, mixture, &sim, &why) != DS_OK)
        fail_msg("%s", why.message);
    return sim;
}

/* The standard error of the mean of n correlated values (x is
 * overwritten): neighbours averaged in pairs again and again
 * (Flyvbjerg and Petersen 1989), the largest error of the levels that
 * keep 16 values or more. Once the pairs are longer than the correlation
 * the error stops growing; the largest is the honest one, or a little
 * above it. */
static double blocked_error(double *x, int n)
{
    double most = 0.0;
    for (int m = n; m >= 16; m /= 2) {
        const double e = stats_of(x, m).error;
        most = e > most ? e : most;
        for (int i = 0; i < m / 2; ++i)
            x[i] = 0.5 * (x[2 * i] + x[2 * i + 1]);
    }
    return most;
}

/* Z over blocks of `block` steps after `relax`, its mean and blocked
 * error. */
static block_stats z_of(ds_sim *sim, uint64_t relax, int blocks, uint64_t block)
{
    double *z = malloc((size_t)blocks * sizeof *z);
    assert_non_null(z);
    ds_sim_run(sim, relax, NULL);
    for (int b = 0; b < blocks; ++b) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, block, NULL);
        z[b] = ds_sim_get_compressibility_factor(sim);
    }
    block_stats s = stats_of(z, blocks);
    s.error = blocked_error(z, blocks);
    free(z);
    return s;
}

/* Two disks in a periodic box: the configurational integral is A (A - pi
 * sigma^2) (tests/test_canonical.c derives it), so Z = (1 + A / (A - pi
 * sigma^2)) / 2. The chains sample that ensemble with no dynamics at
 * all: here Z is the liftings' alone. */
static void two_disks_give_the_exact_z(double radius)
{
    const double box = 10.0, sigma = 2.0 * radius, area = box * box;
    const double exact = 0.5 * (1.0 + area / (area - PI * sigma * sigma));
    ds_params p = ds_params_default(2, radius);
    p.box = box;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_CHAIN;
    p.speed = 1.0;
    p.dt = 0.1;
    ds_sim *sim = create(&p, NULL);
    /* A step carries 2 x 1 x 0.1 = 0.2 of displacement, a chain 2.5:
     * blocks of 20000 steps hold 1600 chains each (~1.2 liftings per unit
     * of displacement at R = 2), far more than the memory of two disks. */
    const block_stats s = z_of(sim, 1000, 64, long_run(20000));
    if (getenv("DS_TEST_VERBOSE"))
        printf("two disks, R = %g: Z = %.5f +- %.5f (exact %.5f)\n", radius, s.mean, s.error,
               exact);
    /* 5 standard errors: a correct run fails with probability 6e-7; the
     * error must be small enough to tell Z from 1 by far. */
    assert_true(s.error < 0.03 * (exact - 1.0));
    if (fabs(s.mean - exact) > 5.0 * s.error)
        fail_msg("two disks, R = %g: Z = %.5f +- %.5f, exact %.5f", radius, s.mean, s.error, exact);
    ds_sim_destroy(sim);
}

static void test_two_disks_give_the_exact_canonical_z(void **state)
{
    (void)state;
    two_disks_give_the_exact_z(2.0); /* pi sigma^2 / A = 0.50: Z = 1.506 */
    two_disks_give_the_exact_z(1.0); /* 0.13: Z = 1.072 */
}

/* N disks at area fraction eta in the default square periodic box, from
 * the lattice. */
static ds_params dense(size_t n, double eta, ds_integrator integrator, uint64_t seed)
{
    ds_params p = ds_params_default(n, sqrt(eta * 1e6 / ((double)n * PI)));
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.placement = DS_PLACEMENT_LATTICE;
    p.integrator = integrator;
    p.seed = seed;
    return p;
}

/* Both samplers at the same N, box and area fraction: the same canonical
 * Z. At 0.70 a small system sits at the liquid-hexatic transition and
 * its pressure relaxes slowly (integrated autocorrelation times of
 * 20-35 time units at N = 72 and 256, measured with 16384 blocks), so
 * the runs are thousands of time units and their errors blocked. In
 * quick mode (a tenth of the run, too short for blocking to see that
 * far) the difference is held to 20% of Z: four standard deviations of
 * the difference of two such short runs at N = 72. */
static void chains_and_dynamics_agree(size_t n, int blocks)
{
    ds_params pc = dense(n, 0.70, DS_INTEGRATOR_EVENT_CHAIN, 3);
    ds_params pe = dense(n, 0.70, DS_INTEGRATOR_EVENT_DRIVEN, 4);
    ds_sim *chain = create(&pc, NULL), *event = create(&pe, NULL);
    const uint64_t unit = 1000; /* steps of dt = 0.001 */
    const block_stats c = z_of(chain, 50 * unit, blocks, unit);
    const block_stats e = z_of(event, 50 * unit, blocks, unit);
    const double combined = hypot(c.error, e.error), apart = fabs(c.mean - e.mean);
    if (getenv("DS_TEST_VERBOSE"))
        printf("N = %zu at 0.70: chains Z = %.4f +- %.4f, dynamics %.4f +- %.4f (%.1f errors "
               "apart)\n",
               n, c.mean, c.error, e.mean, e.error, apart / combined);
    if (quick_mode()) {
        assert_true(apart < 0.2 * e.mean);
    } else {
        /* 4 combined errors: a correct pair fails with probability 6e-5;
         * the comparison must tell the two within 3%. */
        assert_true(combined < 0.01 * c.mean);
        if (apart > 4.0 * combined)
            fail_msg("N = %zu at 0.70: chains Z = %.4f +- %.4f, dynamics %.4f +- %.4f", n, c.mean,
                     c.error, e.mean, e.error);
    }
    ds_sim_destroy(chain);
    ds_sim_destroy(event);
}

static void test_chains_and_dynamics_give_the_same_dense_z(void **state)
{
    (void)state;
    chains_and_dynamics_agree(72, (int)long_run(8192));
    if (!quick_mode())
        chains_and_dynamics_agree(256, 2048);
}

/* The cell grid against brute force (every disk a candidate, through
 * the nearest image): the same liftings from the same start, so the same
 * count of them and the same centres up to rounding. Dilute (cells that
 * overflow), dense, each boundary, a mixture. Brute force computes each
 * separation as the cells do and stops the chains at the same cell
 * edges, so the centres agree to the bit unless two disks tie for the
 * nearest (which the two order differently) or a chain runs half a
 * periodic side without a lifting (where brute force looks again):
 * neither here, but the test allows rounding. */
static void cells_match_brute_force(size_t n, double radius, ds_boundary boundary, int mixed)
{
    const ds_species kinds[2] = {{n / 2, radius, 0.0, NULL}, {n - n / 2, 1.4 * radius, 0.0, NULL}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_EQUAL};
    ds_sim *sim[2];
    for (int k = 0; k < 2; ++k) {
        ds_params p = ds_params_default(n, radius);
        p.box = 200.0;
        p.boundary = boundary;
        p.integrator = DS_INTEGRATOR_EVENT_CHAIN;
        p.broadphase = k ? DS_BROADPHASE_BRUTE : DS_BROADPHASE_CELLS;
        p.speed = 1.0;
        p.dt = 1.0;
        p.seed = 11;
        sim[k] = create(&p, mixed ? &mixture : NULL);
    }
    while (ds_sim_get_collision_count(sim[0]) < 3000) {
        ds_sim_step(sim[0], NULL);
        ds_sim_step(sim[1], NULL);
    }
    assert_int_equal(ds_sim_get_collision_count(sim[1]), ds_sim_get_collision_count(sim[0]));
    assert_int_equal(ds_sim_get_wall_count(sim[1]), ds_sim_get_wall_count(sim[0]));
    ds_disk *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(ds_sim_get_disks(sim[0], a, NULL), DS_OK);
    assert_int_equal(ds_sim_get_disks(sim[1], b, NULL), DS_OK);
    for (size_t i = 0; i < n; ++i) {
        double dx = a[i].x - b[i].x, dy = a[i].y - b[i].y;
        /* The same centre may be shown at either edge of the seam. */
        if (boundary != DS_BOUNDARY_WALLS)
            dx -= 200.0 * nearbyint(dx / 200.0);
        if (boundary == DS_BOUNDARY_PERIODIC)
            dy -= 200.0 * nearbyint(dy / 200.0);
        if (!(hypot(dx, dy) < 1e-9 * 200.0))
            fail_msg("disk %zu: cells (%.17g, %.17g), brute force (%.17g, %.17g)", i, a[i].x,
                     a[i].y, b[i].x, b[i].y);
    }
    free(a);
    free(b);
    ds_sim_destroy(sim[0]);
    ds_sim_destroy(sim[1]);
}

static void test_cells_find_the_liftings_brute_force_finds(void **state)
{
    (void)state;
    for (int boundary = 0; boundary < DS_BOUNDARY_COUNT; ++boundary) {
        cells_match_brute_force(40, 2.0, (ds_boundary)boundary, 0);  /* overflowing cells */
        cells_match_brute_force(230, 5.0, (ds_boundary)boundary, 0); /* area fraction 0.45 */
        cells_match_brute_force(200, 4.0, (ds_boundary)boundary, 1); /* a mixture, 0.37 */
    }
}

/* What the contract says a step of dt is: n speed dt of chain
 * displacement in all, along +x and +y only in a periodic box, so the
 * unwrapped centres advance by exactly that, up to rounding; the
 * velocities never change, and they give the temperature, kT = K / N,
 * and with Z the pressure, P A = Z N kT. */
static void test_a_step_carries_n_speed_dt_and_leaves_the_velocities(void **state)
{
    (void)state;
    enum { N = 100 };
    ds_params p = ds_params_default(N, 10.0);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_CHAIN;
    p.dt = 0.01;
    ds_sim *sim = create(&p, NULL);
    ds_disk before[N], after[N];
    double u0[2 * N], u1[2 * N];
    assert_int_equal(ds_sim_get_disks(sim, before, NULL), DS_OK);
    assert_int_equal(ds_sim_get_unwrapped(sim, u0, NULL), DS_OK);
    const uint64_t steps = 37;
    ds_sim_run(sim, steps, NULL);
    assert_int_equal(ds_sim_get_disks(sim, after, NULL), DS_OK);
    assert_int_equal(ds_sim_get_unwrapped(sim, u1, NULL), DS_OK);
    double moved = 0.0;
    for (size_t i = 0; i < N; ++i) {
        assert_true(after[i].vx == before[i].vx && after[i].vy == before[i].vy);
        const double dx = u1[2 * i] - u0[2 * i], dy = u1[2 * i + 1] - u0[2 * i + 1];
        assert_true(dx >= -1e-9 && dy >= -1e-9); /* up the axes only */
        moved += dx + dy;
    }
    const double carried = (double)steps * N * 100.0 * 0.01; /* n speed dt a step */
    assert_true(fabs(moved - carried) < 1e-9 * carried);
    assert_true(ds_sim_get_time(sim) == (double)steps * 0.01);
    const double kt = ds_sim_get_kinetic_energy(sim) / N;
    assert_true(ds_sim_get_temperature(sim) == kt);
    const double area = 1000.0 * 1000.0;
    assert_close(ds_sim_get_virial_pressure(sim),
                 ds_sim_get_compressibility_factor(sim) * N * kt / area);
    ds_sim_destroy(sim);
}

/* With walls the chains turn at them (and move up and down), and what
 * the turns tally is the wall pressure. In the dilute walled box and
 * channel of tests/test_box.c (area fraction 0.016), the wall pressure's
 * Z against Henderson's equation of state, Z = (1 + eta^2 / 8) / (1 -
 * eta)^2 (within 1e-5 of the virial series there; the box's own Z sits
 * 6e-4 below it, for the dynamics too, far inside the wall's error), and
 * against the liftings' Z of the same run; that Z against the dynamics'
 * in the same box. Each tolerance is four standard errors of ten
 * blocks, each of thousands of wall turns and liftings. */
static block_stats wall_and_z(ds_integrator integrator, ds_boundary boundary, block_stats *z)
{
    enum { N = 200, BLOCKS = 10 };
    const double r = 5.0;
    ds_params p = ds_params_default(N, r);
    p.boundary = boundary;
    p.integrator = integrator;
    p.dt = 0.1;
    p.seed = 17;
    ds_sim *sim = create(&p, NULL);
    ds_sim_run(sim, 200, NULL);
    const double width = boundary == DS_BOUNDARY_WALLS ? 1000.0 - 2.0 * r : 1000.0;
    const double area = width * (1000.0 - 2.0 * r);
    double wall[BLOCKS], zs[BLOCKS];
    for (int b = 0; b < BLOCKS; ++b) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, long_run(5000), NULL);
        wall[b] = ds_sim_get_pressure(sim) * area / (N * ds_sim_get_temperature(sim));
        zs[b] = ds_sim_get_compressibility_factor(sim);
    }
    ds_sim_destroy(sim);
    *z = stats_of(zs, BLOCKS);
    return stats_of(wall, BLOCKS);
}

static void test_the_turns_at_walls_give_the_wall_pressure(void **state)
{
    (void)state;
    const double r = 5.0;
    for (int boundary = 0; boundary < DS_BOUNDARY_COUNT; boundary += 2) { /* walls, channel */
        block_stats z, ze;
        const block_stats w = wall_and_z(DS_INTEGRATOR_EVENT_CHAIN, (ds_boundary)boundary, &z);
        (void)wall_and_z(DS_INTEGRATOR_EVENT_DRIVEN, (ds_boundary)boundary, &ze);
        const double width = boundary == DS_BOUNDARY_WALLS ? 1000.0 - 2.0 * r : 1000.0;
        const double eta = 200 * PI * r * r / (width * (1000.0 - 2.0 * r));
        const double henderson = (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
        if (getenv("DS_TEST_VERBOSE"))
            printf("%s: wall Z %.4f +- %.4f, liftings' Z %.5f +- %.5f, dynamics %.5f +- "
                   "%.5f, Henderson %.5f\n",
                   ds_boundary_name((ds_boundary)boundary), w.mean, w.error, z.mean, z.error,
                   ze.mean, ze.error, henderson);
        assert_true(fabs(w.mean - henderson) < 4.0 * w.error);
        assert_true(fabs(w.mean - z.mean) < 4.0 * hypot(w.error, z.error));
        assert_true(fabs(z.mean - ze.mean) < 4.0 * hypot(z.error, ze.error));
        /* The test has teeth: the ideal gas is 2 eta = 3% away. */
        assert_true(w.error < 0.25 * (henderson - 1.0) || quick_mode());
    }
}

/* A mixture: both samplers give the same Z (a binary mixture of radius
 * ratio 1.4 at area fraction 0.5, periodic; blocks of 20 time units,
 * hundreds of liftings or collisions per disk, about independent). */
static void test_a_mixture_has_the_same_z_with_chains_and_dynamics(void **state)
{
    (void)state;
    enum { N = 200 };
    const ds_species kinds[2] = {{N / 2, 1.0, 0.0, NULL}, {N / 2, 1.4, 0.0, NULL}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    /* Radii 1 and 1.4 times R at area fraction 0.5 of the box. */
    const double radius = sqrt(0.5 * 1e6 / (PI * (N / 2) * (1.0 + 1.4 * 1.4)));
    const ds_species sized[2] = {{N / 2, radius, 0.0, NULL}, {N / 2, 1.4 * radius, 0.0, NULL}};
    const ds_mixture scaled = {2, sized, NULL, NULL, DS_MASS_AREA};
    (void)mixture;
    block_stats s[2];
    for (int k = 0; k < 2; ++k) {
        ds_params p = ds_params_default(N, radius);
        p.boundary = DS_BOUNDARY_PERIODIC;
        p.placement = DS_PLACEMENT_LATTICE;
        p.integrator = k ? DS_INTEGRATOR_EVENT_DRIVEN : DS_INTEGRATOR_EVENT_CHAIN;
        p.seed = 5;
        ds_sim *sim = create(&p, &scaled);
        s[k] = z_of(sim, 20000, (int)long_run(256), 1000);
        ds_sim_destroy(sim);
    }
    if (getenv("DS_TEST_VERBOSE"))
        printf("mixture at 0.5: chains Z = %.4f +- %.4f, dynamics %.4f +- %.4f\n", s[0].mean,
               s[0].error, s[1].mean, s[1].error);
    const double combined = hypot(s[0].error, s[1].error);
    assert_true(combined < 0.01 * s[1].mean || quick_mode());
    assert_true(fabs(s[0].mean - s[1].mean) < 4.0 * combined);
}

/* Disks touching all the way across the box pass every chain along
 * their line round and round without moving (each lifting moves
 * nothing): a row round a periodic box, and a row between walls, which
 * the chain also turns at. The step ends all the same, nothing having
 * moved (the first chain is along x); later a chain across the row moves
 * a disk off the line, and the row comes apart. */
static void touching_row_stalls_no_step(ds_boundary boundary)
{
    ds_params p = ds_params_default(3, 2.0);
    p.box = 12.0;
    p.boundary = boundary;
    p.integrator = DS_INTEGRATOR_EVENT_CHAIN;
    p.speed = 1.0;
    p.dt = 0.1;
    ds_sim *sim = create(&p, NULL);
    const double x0 = boundary == DS_BOUNDARY_WALLS ? 2.0 : 0.0;
    const ds_disk row[3] = {
        {x0, 6.0, 1.0, 0.0}, {x0 + 4.0, 6.0, 0.0, 1.0}, {x0 + 8.0, 6.0, -1.0, 0.0}};
    ds_error why;
    assert_int_equal(ds_sim_set_disks(sim, row, &why), DS_OK);
    ds_disk d[3];
    ds_sim_run(sim, 1, NULL);
    assert_true(ds_sim_get_collision_count(sim) > 3); /* it went round */
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    assert_memory_equal(d, row, sizeof row);
    ds_sim_run(sim, 100, NULL); /* 30 of displacement: chains across */
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    assert_true(d[0].y != 6.0 || d[1].y != 6.0 || d[2].y != 6.0);
    ds_sim_destroy(sim);
}

static void test_disks_touching_across_the_box_stall_no_step(void **state)
{
    (void)state;
    touching_row_stalls_no_step(DS_BOUNDARY_PERIODIC);
    touching_row_stalls_no_step(DS_BOUNDARY_WALLS);
}

/* What the chains cannot do is refused with a reason: growth (no
 * growing radii), and a disk set onto another. */
static void test_growth_and_overlaps_are_refused(void **state)
{
    (void)state;
    ds_params p = ds_params_default(50, 5.0);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_CHAIN;
    ds_sim *sim = create(&p, NULL);
    ds_error why;
    assert_int_equal(ds_sim_set_growth(sim, 0.01, 0.0, 0.0, &why), DS_ERR_ARG);
    assert_string_equal(why.field, "integrator");
    assert_non_null(strstr(why.message, "chain"));
    const ds_disk other = ds_sim_get_disk(sim, 1), on = {other.x + 3.0, other.y, 0.0, 0.0};
    const ds_disk was = ds_sim_get_disk(sim, 0);
    assert_int_equal(ds_sim_set_disk(sim, 0, on, NULL), DS_ERR_OVERLAP);
    const ds_disk still = ds_sim_get_disk(sim, 0);
    assert_memory_equal(&still, &was, sizeof was);
    ds_sim_destroy(sim);
}

/* Any chain length samples the same ensemble (the default only decides
 * how fast): chains a tenth and four times as long give the same Z as
 * the default's, each over blocks of tens of chains. */
static void test_the_chain_length_does_not_change_z(void **state)
{
    (void)state;
    static const double lengths[3] = {0.1, DS_CHAIN_LENGTH_OF_BOX, 4.0};
    block_stats s[3];
    for (int k = 0; k < 3; ++k) {
        ds_params p = dense(200, 0.5, DS_INTEGRATOR_EVENT_CHAIN, 21);
        ds_sim *sim = create(&p, NULL);
        assert_true(ds_chain_length(sim) == DS_CHAIN_LENGTH_OF_BOX * 1000.0);
        ds_chain_set_length(sim, lengths[k] * 1000.0);
        s[k] = z_of(sim, 20000, (int)long_run(256), 1000);
        ds_sim_destroy(sim);
    }
    if (getenv("DS_TEST_VERBOSE"))
        printf("chains of 0.1, %g, 4 box sides: Z = %.4f +- %.4f, %.4f +- %.4f, %.4f +- %.4f\n",
               DS_CHAIN_LENGTH_OF_BOX, s[0].mean, s[0].error, s[1].mean, s[1].error, s[2].mean,
               s[2].error);
    assert_true(fabs(s[0].mean - s[1].mean) < 4.0 * hypot(s[0].error, s[1].error));
    assert_true(fabs(s[2].mean - s[1].mean) < 4.0 * hypot(s[2].error, s[1].error));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_two_disks_give_the_exact_canonical_z),
        cmocka_unit_test(test_chains_and_dynamics_give_the_same_dense_z),
        cmocka_unit_test(test_cells_find_the_liftings_brute_force_finds),
        cmocka_unit_test(test_a_step_carries_n_speed_dt_and_leaves_the_velocities),
        cmocka_unit_test(test_the_turns_at_walls_give_the_wall_pressure),
        cmocka_unit_test(test_a_mixture_has_the_same_z_with_chains_and_dynamics),
        cmocka_unit_test(test_disks_touching_across_the_box_stall_no_step),
        cmocka_unit_test(test_growth_and_overlaps_are_refused),
        cmocka_unit_test(test_the_chain_length_does_not_change_z),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
