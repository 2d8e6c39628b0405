/* SPDX-License-Identifier: MIT */
/* The box (src/core/box.h) and the boundary it makes possible beyond
 * walls and a periodic box: the channel, periodic along x with walls at
 * y = 0 and y = box_y.
 *
 * The box's operations are checked on cases worked by hand (every
 * number below is exact in binary). A channel run is then held to what
 * its physics promises: x momentum is conserved (nothing along x takes
 * it), y momentum goes to the walls, the event-driven energy stays to
 * rounding, image counts grow along x only, and its wall pressure is the
 * equation of state's, as both integrators measure it. */
#include "test_util.h"

#include "core/box.h"

static const double EPS = 2.220446049250313e-16;
#define PI 3.14159265358979323846

/* A box of 10 x 20 with each kind of boundary, as ds_params makes them. */
static ds_box box_of(ds_boundary b)
{
    return ds_box_make(10.0, 20.0, b == DS_BOUNDARY_WALLS ? DS_EDGE_WALLS : DS_EDGE_PERIODIC,
                       b == DS_BOUNDARY_PERIODIC ? DS_EDGE_PERIODIC : DS_EDGE_WALLS);
}

static void test_nearest_images_are_taken_along_the_periodic_axes_only(void **state)
{
    (void)state;
    const ds_box walls = box_of(DS_BOUNDARY_WALLS), periodic = box_of(DS_BOUNDARY_PERIODIC),
                 channel = box_of(DS_BOUNDARY_CHANNEL);
    double dx = 9.0, dy = 19.0;
    ds_box_nearest(&walls, &dx, &dy);
    assert_true(dx == 9.0 && dy == 19.0);
    dx = 9.0, dy = 19.0;
    ds_box_nearest(&periodic, &dx, &dy);
    assert_true(dx == -1.0 && dy == -1.0);
    dx = 9.0, dy = 19.0;
    ds_box_nearest(&channel, &dx, &dy);
    assert_true(dx == -1.0 && dy == 19.0);
    dx = -9.0, dy = 5.0; /* within half a side: as it is */
    ds_box_nearest(&channel, &dx, &dy);
    assert_true(dx == 1.0 && dy == 5.0);
    /* A sheared image (Lees-Edwards): the one above stands 3 further
     * along x, so a separation through it loses 3 in x as well. */
    ds_box sheared = periodic;
    sheared.shift = 3.0;
    dx = 1.0, dy = 19.0;
    ds_box_nearest(&sheared, &dx, &dy);
    assert_true(dx == -2.0 && dy == -1.0);
    dx = 0.0, dy = -19.0;
    ds_box_nearest(&sheared, &dx, &dy);
    assert_true(dx == 3.0 && dy == 1.0);
}

static void test_wrapping_counts_the_boxes_crossed(void **state)
{
    (void)state;
    const ds_box channel = box_of(DS_BOUNDARY_CHANNEL), periodic = box_of(DS_BOUNDARY_PERIODIC);
    double x = 10.5, y = 20.5;
    int32_t ix = 0, iy = 0;
    ds_box_wrap(&channel, &x, &y, &ix, &iy);
    assert_true(x == 0.5 && y == 20.5); /* y has walls: the integrator turns it */
    assert_int_equal(ix, 1);
    assert_int_equal(iy, 0);
    x = -0.25, y = -0.5;
    ds_box_wrap(&periodic, &x, &y, &ix, &iy);
    assert_true(x == 9.75 && y == 19.5);
    assert_int_equal(ix, 0);
    assert_int_equal(iy, -1);
    /* Far away (a caller's centre): several boxes at once. */
    x = 35.5, y = -41.0;
    ds_box_wrap(&periodic, &x, &y, &ix, &iy);
    assert_true(x == 5.5 && y == 19.0);
    assert_int_equal(ix, 3);
    assert_int_equal(iy, -4);
    x = 35.5, y = -41.0;
    ds_box_wrap_any(&channel, &x, &y);
    assert_true(x == 5.5 && y == -41.0);
}

/* Where a centre of radius 1 may be, the length of wall and the area it
 * reaches (the wall and virial pressures' denominators). */
static void test_reach_walls_and_areas_follow_each_axis(void **state)
{
    (void)state;
    const ds_box walls = box_of(DS_BOUNDARY_WALLS), periodic = box_of(DS_BOUNDARY_PERIODIC),
                 channel = box_of(DS_BOUNDARY_CHANNEL);
    assert_true(ds_box_wall_reached(&walls, 1.0) == 2.0 * 18.0 + 2.0 * 8.0);
    assert_true(ds_box_wall_reached(&channel, 1.0) == 2.0 * 10.0);
    assert_true(ds_box_wall_reached(&periodic, 1.0) == 0.0);
    assert_true(ds_box_area_reached(&walls, 1.0) == 8.0 * 18.0);
    assert_true(ds_box_area_reached(&channel, 1.0) == 10.0 * 18.0);
    assert_true(ds_box_area_reached(&periodic, 1.0) == 200.0);
    /* A channel holds x in [0, 10) and y in [1, 19]. */
    assert_true(ds_box_holds(&channel, 0.0, 1.0, 1.0, 0.0));
    assert_true(ds_box_holds(&channel, 9.5, 19.0, 1.0, 0.0));
    assert_false(ds_box_holds(&channel, 10.0, 5.0, 1.0, 0.0));
    assert_false(ds_box_holds(&channel, 5.0, 0.5, 1.0, 0.0));
    assert_true(ds_box_holds(&channel, 5.0, 0.5, 1.0, 0.5)); /* within the slack */
    assert_false(ds_box_holds(&walls, 0.5, 5.0, 1.0, 0.0));
    /* A cell grid of 5 x 4: past the left edge is the right end's image
     * one side away along x, past the bottom a wall. */
    double shift = 1.0;
    assert_int_equal(ds_box_cell_along(&channel, 0, -1, 5, &shift), 4);
    assert_true(shift == -10.0);
    assert_int_equal(ds_box_cell_along(&channel, 0, 5, 5, &shift), 0);
    assert_true(shift == 10.0);
    assert_int_equal(ds_box_cell_along(&channel, 1, -1, 4, &shift), -1);
    assert_int_equal(ds_box_cell_along(&channel, 1, 2, 4, &shift), 2);
    assert_true(shift == 0.0);
}

static ds_sim *channel(size_t n, double r, double box_y, ds_integrator integrator, double dt,
                       uint64_t seed)
{
    ds_params p = ds_params_default(n, r);
    p.boundary = DS_BOUNDARY_CHANNEL;
    p.box_y = box_y;
    p.integrator = integrator;
    p.dt = dt;
    p.seed = seed;
    ds_sim *sim = NULL;
    ds_error why;
    if (ds_sim_create(&p, NULL, &sim, &why) != DS_OK)
        fail_msg("%s", why.message);
    return sim;
}

/* x momentum is the channel's conserved quantity, y momentum the walls'
 * to take; disks cross the periodic sides (image counts along x) and
 * never the walls (none along y); the event-driven dynamics keeps every
 * centre in [r, box_y - r] and the energy to rounding. Event chains move
 * the disks without velocities: they keep every velocity as it was. */
static void test_a_channel_conserves_x_momentum_and_turns_disks_at_its_walls(void **state)
{
    (void)state;
    enum { N = 800 };
    const double r = 6.0, box_y = 500.0;
    for (int in = 0; in < DS_INTEGRATOR_COUNT; ++in) {
        ds_sim *sim = channel(N, r, box_y, (ds_integrator)in, 0.001, 9);
        double px0, py0, px, py;
        ds_sim_get_momentum(sim, &px0, &py0);
        const double e0 = ds_sim_get_kinetic_energy(sim), vmax = sqrt(2.0 * e0);
        /* A random start along a periodic axis: no net momentum (both
         * components are taken out), up to n terms' rounding. */
        assert_true(fabs(px0) < 1e-9 * 100.0 * N);
        ds_sim_run(sim, long_run(20000), NULL);
        ds_sim_get_momentum(sim, &px, &py);
        const uint64_t collisions = ds_sim_get_collision_count(sim);
        assert_true(collisions > 1000);
        assert_true(ds_sim_get_wall_count(sim) > 100);
        /* Each collision moves momentum between two disks, off by ~eps
         * vmax; the sum of n terms adds ~eps vmax sqrt(n) per term (as in
         * test_periodic.c). */
        const double bound = EPS * vmax * ((double)collisions + 2.0 * N * sqrt((double)N));
        assert_true(fabs(px - px0) <= bound);
        /* The walls took y momentum: far more than rounding. */
        if (in == DS_INTEGRATOR_EVENT_CHAIN)
            assert_true(px == px0 && py == py0);
        else
            assert_true(fabs(py - py0) > 1e3 * bound);
        int32_t image[2 * N];
        assert_int_equal(ds_sim_get_images(sim, image, NULL), DS_OK);
        int crossed = 0;
        for (size_t i = 0; i < N; ++i) {
            assert_int_equal(image[2 * i + 1], 0);
            crossed += image[2 * i] != 0;
        }
        assert_true(crossed > 0);
        ds_disk d[N];
        assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
        for (size_t i = 0; i < N; ++i) {
            assert_true(d[i].x >= 0.0 && d[i].x < 1000.0);
            /* The time step turns a disk once it is past its wall, by
             * at most one step's travel, speed dt. */
            const double slack = in == DS_INTEGRATOR_TIME_STEP ? vmax * 0.001 : 1e-9 * box_y;
            assert_true(d[i].y >= r - slack && d[i].y <= box_y - r + slack);
        }
        if (in == DS_INTEGRATOR_EVENT_DRIVEN) {
            /* 1e-16 relative per collision, random signs: 1e-12 is wide. */
            assert_true(fabs(ds_sim_get_kinetic_energy(sim) - e0) <= 1e-12 * e0);
        }
        ds_sim_destroy(sim);
    }
}

/* The wall pressure of a dilute hard-disk fluid in a channel, measured by
 * both integrators, against each other, against the virial pressure of
 * the same run, and against the equation of state of Henderson (Mol.
 * Phys. 30, 971 (1975)), Z = (1 + eta^2 / 8) / (1 - eta)^2, which at
 * this area fraction (0.0157) is within 1e-5 of the exact virial series.
 * The walls' extra density near contact changes the bulk density by
 * about (Z - 1) R / box_y = 2e-4, below the run's error. Each tolerance is
 * four standard errors of the difference, from ten blocks of the run. */
static block_stats wall_pressure(ds_integrator integrator, double *virial, double *z_eos)
{
    enum { N = 200, BLOCKS = 10 };
    const double r = 5.0;
    /* The event-driven integrator is exact for any dt: a long one costs
     * nothing. The time step needs its 0.001. */
    const double dt = integrator == DS_INTEGRATOR_EVENT_DRIVEN ? 0.1 : 0.001;
    ds_sim *sim = channel(N, r, 1000.0, integrator, dt, 17);
    ds_sim_run(sim, (uint64_t)(20.0 / dt), NULL); /* a few wall crossings: equilibrium */
    const uint64_t block = long_run((uint64_t)(100.0 / dt));
    double p[BLOCKS], v[BLOCKS];
    for (int b = 0; b < BLOCKS; ++b) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, block, NULL);
        /* P A / (N kT): the pressures in units of the ideal gas's. */
        const double ideal =
            N * ds_sim_get_temperature(sim) / ((1000.0 - 2.0 * r) * 1000.0); /* A reached */
        p[b] = ds_sim_get_pressure(sim) / ideal;
        v[b] = ds_sim_get_virial_pressure(sim) / ideal;
    }
    const double eta = N * PI * r * r / (1000.0 * (1000.0 - 2.0 * r));
    *z_eos = (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
    *virial = stats_of(v, BLOCKS).mean;
    ds_sim_destroy(sim);
    return stats_of(p, BLOCKS);
}

static void test_a_channels_wall_pressure_is_the_equation_of_states(void **state)
{
    (void)state;
    double virial_ed, virial_ts, z;
    const block_stats ed = wall_pressure(DS_INTEGRATOR_EVENT_DRIVEN, &virial_ed, &z);
    const block_stats ts = wall_pressure(DS_INTEGRATOR_TIME_STEP, &virial_ts, &z);
    print_message("channel Z: event %.4f +- %.4f (virial %.4f), step %.4f +- %.4f, "
                  "Henderson %.4f\n",
                  ed.mean, ed.error, virial_ed, ts.mean, ts.error, z);
    assert_true(fabs(ed.mean - z) < 4.0 * ed.error);
    assert_true(fabs(ts.mean - z) < 4.0 * ts.error);
    assert_true(fabs(ed.mean - ts.mean) < 4.0 * hypot(ed.error, ts.error));
    /* The virial pressure of the same run carries less noise (the
     * kinetic part is exact); the wall's error bounds the difference. */
    assert_true(fabs(ed.mean - virial_ed) < 4.0 * ed.error);
    /* The test has teeth: the ideal gas (Z = 1) is 2 eta = 3% away,
     * several errors at this run's length. */
    assert_true(ed.error < 0.25 * (z - 1.0) || quick_mode());
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nearest_images_are_taken_along_the_periodic_axes_only),
        cmocka_unit_test(test_wrapping_counts_the_boxes_crossed),
        cmocka_unit_test(test_reach_walls_and_areas_follow_each_axis),
        cmocka_unit_test(test_a_channel_conserves_x_momentum_and_turns_disks_at_its_walls),
        cmocka_unit_test(test_a_channels_wall_pressure_is_the_equation_of_states),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
