/* SPDX-License-Identifier: MIT */
/* Growth (Lubachevsky-Stillinger) and the contacts of a packing: two
 * growing disks meet when the analytic contact time says and leave at
 * twice the growth speed; a mixture compressed to 0.75 never overlaps,
 * keeps its radius ratio and stops at the target exactly; a compression
 * to jamming stops at Z, stable, near the jamming density of the 1:1.4
 * mixture with an isostatic contact number; a growing run saved and
 * loaded goes on bit for bit; contacts and rattlers of lattices and a
 * small cluster are counted exactly. */
#include "test_util.h"

#define PI 3.14159265358979323846

/* Two disks of radius 5, 30 apart in a periodic box 1000 wide, at rest
 * but for a common drift along y (growth needs motion; the pair's own
 * motion is nil), growing at rate 0.1: the contact distance 10 (1 + 0.1
 * t) reaches 30 at t = 20, and the pair then parts at twice the contact
 * distance's growth speed, a = 10 x 0.1 = 1 (each disk at 1, equal
 * masses): in the frame of the receding surfaces the pair arrives at -a
 * and leaves at +a; the drift stays. */
static void test_two_growing_disks_meet_on_time_and_part_at_twice_the_growth_speed(void **state)
{
    (void)state;
    ds_params p = ds_params_default(2, 5.0);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.dt = 0.25;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_disk d[2] = {{500.0, 500.0, 0.0, 1.0}, {530.0, 500.0, 0.0, 1.0}};
    assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.0, 0.0, NULL), DS_OK);
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_GROWING);
    ds_sim_run(sim, 79, NULL); /* t = 19.75: not yet */
    assert_int_equal(ds_sim_get_collision_count(sim), 0);
    assert_true(fabs(radius_of(sim, 0) - 5.0 * (1.0 + 0.1 * 19.75)) < 1e-12);
    ds_sim_run(sim, 2, NULL); /* t = 20.25 */
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    const ds_disk a = ds_sim_get_disk(sim, 0), b = ds_sim_get_disk(sim, 1);
    assert_true(fabs(a.vx + 1.0) < 1e-12 && fabs(b.vx - 1.0) < 1e-12);
    assert_true(fabs(a.vy - 1.0) < 1e-12 && fabs(b.vy - 1.0) < 1e-12);
    /* At t = 20.25 the centres are 30 + 2 x 0.25 apart, the contact
     * distance 10 (1 + 2.025) = 30.25: the gap opens at a. */
    assert_true(fabs((b.x - a.x) - 30.5) < 1e-9);
    ds_sim_destroy(sim);
}

static ds_sim *mixture(size_t n, double eta, uint64_t seed)
{
    const double r = sqrt(eta * 1e6 / (PI * (double)n * (1.0 + 1.96) / 2.0));
    ds_params p = ds_params_default(n, r);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.seed = seed;
    const ds_species kinds[2] = {{n / 2, r, 0.0, NULL}, {n - n / 2, 1.4 * r, 0.0, NULL}};
    ds_mixture mix = {2, kinds, NULL, NULL, DS_MASS_EQUAL};
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, &mix, &sim, NULL), DS_OK);
    return sim;
}

/* The closest pair relative to contact (brute force, nearest image). */
static double closest_gap(const ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    ds_disk *d = malloc(n * sizeof *d);
    double *r = malloc(n * sizeof *r);
    assert_non_null(d);
    assert_non_null(r);
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    assert_int_equal(ds_sim_get_radii(sim, r, NULL), DS_OK);
    double worst = INFINITY;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            double dx = d[j].x - d[i].x, dy = d[j].y - d[i].y;
            dx -= ds_sim_get_box_width(sim) * round(dx / ds_sim_get_box_width(sim));
            dy -= ds_sim_get_box_height(sim) * round(dy / ds_sim_get_box_height(sim));
            worst = fmin(worst, sqrt(dx * dx + dy * dy) / (r[i] + r[j]) - 1.0);
        }
    free(d);
    free(r);
    return worst;
}

/* From 0.5 to 0.75 at rate 0.02 (about 0.005 of a diameter per time
 * unit at the speed of 100), the heat taken out as the run goes: after
 * every step no pair is closer than contact (rounding: 1e-12 of a
 * diameter), the time only goes forward, the radii grow linearly in time,
 * r0 (1 + rate t), through every window's restart and every new state
 * (rounding: 1e-16 per restart, a few thousand of them), keep their
 * ratio, and the growth stops at 0.75 to rounding. */
static void test_a_mixture_grows_to_its_target_without_overlap(void **state)
{
    (void)state;
    const size_t n = quick_mode() ? 64 : 256;
    ds_sim *sim = mixture(n, 0.5, 3);
    const double e0 = ds_sim_get_kinetic_energy(sim), r0 = radius_of(sim, 0);
    const double rate = 0.02 * 100.0 / (2.0 * ds_sim_get_radius(sim));
    assert_int_equal(ds_sim_set_growth(sim, rate, 0.75, 0.0, NULL), DS_OK);
    double t = 0.0;
    int steps = 0;
    while (ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING && steps < 200000) {
        ds_sim_step(sim, NULL);
        ++steps;
        assert_true(ds_sim_get_time(sim) > t);
        t = ds_sim_get_time(sim);
        assert_true(closest_gap(sim) > -1e-12);
        if (ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING)
            assert_true(fabs(radius_of(sim, 0) / (r0 * (1.0 + rate * t)) - 1.0) < 1e-12);
    }
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_REACHED_ETA);
    assert_true(fabs(ds_sim_get_area_fraction(sim) - 0.75) < 1e-12);
    assert_true(fabs(radius_of(sim, n - 1) / radius_of(sim, 0) - 1.4) < 1e-12);
    /* The heat out when it stopped: the kinetic energy of the start, to
     * rounding (one scaling of n velocities, 1e-16 each). */
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) / e0 - 1.0) < 1e-12);
    /* Then it runs as any mixture, without overlap. */
    ds_sim_run(sim, 100, NULL);
    assert_true(closest_gap(sim) > -1e-12);
    ds_sim_destroy(sim);
}

/* Grows sim at rate (relative) to until_eta step by step, and checks the
 * stop against the target's time t*, when the area fraction eta0 of now
 * grows to until_eta as eta0 (1 + rate (t - t0))^2: every step that ends
 * before t* ends growing and below the target, and the step that holds
 * t* (its end included) ends at the target, reached. "At the target" is
 * to rounding, u = DBL_EPSILON / 2, relative: the stop time comes from
 * the area fraction at growth's last restart (n squares summed, the
 * constant, the box's area: (n + 4) u), a quotient and a square root (3 u
 * in its square); the factor from the stop time has five roundings of
 * numbers no larger than itself and those of the integrator's times
 * (the stop time's sum, and the shifts when the epoch moves), u rate |t|
 * each with |t| below two rebase periods (box / speed = 10) and rate at
 * most 0.05 here (rate |t| <= 1): below 8 u, 16 u in its square; and the
 * area fraction shown sums n squares of the radii times the factor again
 * ((n + 6) u). In all below (2 n + 29) u < (n + 16) DBL_EPSILON. */
static void assert_growth_stops_in_the_step_of_its_target(ds_sim *sim, double rate,
                                                          double until_eta)
{
    const double n = (double)ds_sim_get_count(sim), dt = ds_sim_get_dt(sim);
    const double t0 = ds_sim_get_time(sim), eta0 = ds_sim_get_area_fraction(sim);
    const double t_star = t0 + (sqrt(until_eta / eta0) - 1.0) / rate;
    const double k_star = ceil(t_star / dt); /* the step that holds t* ends at k_star dt */
    /* Not within rounding of a step's end, where the step would be moot. */
    assert_true(fabs(t_star / dt - round(t_star / dt)) > 1e-6);
    const double slack = (n + 16.0) * DBL_EPSILON;
    assert_int_equal(ds_sim_set_growth(sim, rate, until_eta, 0.0, NULL), DS_OK);
    while ((double)ds_sim_get_steps(sim) < k_star - 0.5) {
        ds_sim_step(sim, NULL);
        if ((double)ds_sim_get_steps(sim) < k_star - 0.5) {
            assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_GROWING);
            assert_true(ds_sim_get_area_fraction(sim) <= until_eta * (1.0 + slack));
        }
    }
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_REACHED_ETA);
    if (!(fabs(ds_sim_get_area_fraction(sim) / until_eta - 1.0) <= slack))
        fail_msg("stopped at t = %.6f (t* = %.6f) at area fraction %.17g, not %.17g",
                 ds_sim_get_time(sim), t_star, ds_sim_get_area_fraction(sim), until_eta);
    /* And stays there. */
    ds_sim_run(sim, 10, NULL);
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_REACHED_ETA);
    assert_true(fabs(ds_sim_get_area_fraction(sim) / until_eta - 1.0) <= slack);
}

static ds_sim *sparse(size_t n, uint64_t seed)
{
    ds_params p = ds_params_default(n, 5.0);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.seed = seed;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

/* A sparse system's next event may be steps after the target's time (two
 * disks in a box 1000 wide: about one collision in 3000 time units): the
 * growth stops at that time all the same, not at the next event, and
 * never overshoots; so with 20 disks, and a mixture of 200. */
static void test_growth_stops_at_its_target_even_with_no_event_near(void **state)
{
    (void)state;
    ds_sim *sim = sparse(2, 4);
    ds_sim_run(sim, 5, NULL);
    assert_growth_stops_in_the_step_of_its_target(sim, 0.05, 0.001); /* t* = 30.4677 */
    ds_sim_destroy(sim);
    sim = sparse(20, 4);
    ds_sim_run(sim, 5, NULL);
    assert_growth_stops_in_the_step_of_its_target(sim, 0.05, 0.005);
    ds_sim_destroy(sim);
    sim = mixture(200, 0.05, 4);
    ds_sim_run(sim, 5, NULL);
    assert_growth_stops_in_the_step_of_its_target(sim, 0.05, 0.06);
    ds_sim_destroy(sim);
}

/* Compressed to jamming (Z past 10^6): the growth stops, the packing
 * holds (no overlap), its area fraction is that of the 1:1.4 mixture's
 * jamming (O'Hern et al. 2003: 0.84; 0.80 to 0.87 for one small packing),
 * and its contact number, rattlers removed, is isostatic: 2 d = 4 less
 * O(1/N), within 5%. */
static void test_a_compression_to_jamming_stops_with_an_isostatic_packing(void **state)
{
    (void)state;
    if (quick_mode())
        skip(); /* millions of collisions: not under valgrind */
    ds_sim *sim = mixture(256, 0.5, 7);
    assert_int_equal(
        ds_sim_set_growth(sim, 0.01 * 100.0 / (2.0 * ds_sim_get_radius(sim)), 0.0, 1e6, NULL),
        DS_OK);
    int steps = 0;
    while (ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING && steps < 1000000) {
        ds_sim_run(sim, 10, NULL);
        steps += 10;
    }
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_JAMMED);
    assert_true(ds_sim_get_growth_z(sim) >= 1e6); /* the window that stopped it */
    const double eta = ds_sim_get_area_fraction(sim);
    assert_true(eta > 0.80 && eta < 0.87);
    assert_true(closest_gap(sim) > -1e-12);
    ds_contacts c;
    assert_int_equal(ds_sim_get_contacts(sim, 1e-4, &c, NULL), DS_OK);
    print_message("jammed at %.5f, %zu rattlers, %.4f contacts per disk\n", eta, c.rattlers,
                  c.per_disk);
    assert_true(fabs(c.per_disk - 4.0) < 0.2);
    assert_true(c.rattler_fraction < 0.2);
    ds_sim_destroy(sim);
}

/* A growing run saved and loaded goes on to the bit, the thermostat's
 * windows and the growth's clock and all. */
/* a and b, run on by the same steps, are the same to the bit. */
static void assert_same_run(ds_sim *a, ds_sim *b, uint64_t steps)
{
    ds_sim_run(a, steps, NULL);
    ds_sim_run(b, steps, NULL);
    const size_t n = ds_sim_get_count(a);
    assert_int_equal(ds_sim_get_count(b), n);
    ds_disk *da = malloc(n * sizeof *da), *db = malloc(n * sizeof *db);
    double *ra = malloc(n * sizeof *ra), *rb = malloc(n * sizeof *rb);
    assert_true(da && db && ra && rb);
    assert_int_equal(ds_sim_get_disks(a, da, NULL), DS_OK);
    assert_int_equal(ds_sim_get_disks(b, db, NULL), DS_OK);
    assert_int_equal(ds_sim_get_radii(a, ra, NULL), DS_OK);
    assert_int_equal(ds_sim_get_radii(b, rb, NULL), DS_OK);
    assert_memory_equal(da, db, n * sizeof *da);
    assert_memory_equal(ra, rb, n * sizeof *ra);
    free(da);
    free(db);
    free(ra);
    free(rb);
    assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(b));
    assert_int_equal(ds_sim_get_growth_state(a), ds_sim_get_growth_state(b));
}

/* Saved while growing, and after the growth stopped (its cells are then
 * those it built for radii 5% past its last rebuild, coarser than the
 * radii of now would choose), a run loads and goes on bit for bit. */
static void test_a_growing_run_saved_and_loaded_goes_on_bit_for_bit(void **state)
{
    (void)state;
    ds_sim *a = mixture(200, 0.5, 5);
    assert_int_equal(ds_sim_set_growth(a, 0.5, 0.7, 0.0, NULL), DS_OK);
    ds_sim_run(a, 30, NULL);
    ds_sim *b = through_checkpoint(a);
    assert_same_run(a, b, 300);
    ds_sim_destroy(b);
    ds_sim_destroy(a);
    /* 600 disks to 0.75: a grid of about 20 cells a side, where the one
     * built for 5% larger radii has a cell fewer than the radii of now
     * would choose. */
    a = mixture(600, 0.5, 5);
    assert_int_equal(ds_sim_set_growth(a, 0.5, 0.75, 0.0, NULL), DS_OK);
    while (ds_sim_get_growth_state(a) == DS_GROWTH_GROWING)
        ds_sim_step(a, NULL);
    assert_int_equal(ds_sim_get_growth_state(a), DS_GROWTH_REACHED_ETA);
    b = through_checkpoint(a);
    assert_same_run(a, b, 50);
    ds_sim_destroy(a);
    ds_sim_destroy(b);
}

static void test_growth_is_refused_where_it_cannot_run(void **state)
{
    (void)state;
    ds_sim *walls = test_create(10, 5.0, 1, DS_BROADPHASE_AUTO); /* the time step, walls */
    assert_int_equal(ds_sim_set_growth(walls, 0.1, 0.0, 0.0, NULL), DS_ERR_ARG);
    ds_sim_destroy(walls);
    ds_params p = ds_params_default(10, 5.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.0, 0.0, NULL), DS_ERR_ARG); /* walls */
    ds_sim_destroy(sim);
    p.boundary = DS_BOUNDARY_PERIODIC;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_growth(sim, -1.0, 0.0, 0.0, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_growth(sim, NAN, 0.0, 0.0, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 1.5, 0.0, NULL), DS_ERR_ARG);
    /* A target already passed: the growth would have to run backwards. */
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.5 * ds_sim_get_area_fraction(sim), 0.0, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, ds_sim_get_area_fraction(sim), 0.0, NULL),
                     DS_ERR_ARG);
    assert_int_equal(ds_sim_set_growth(sim, 0.1, 0.0, 0.5, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_growth(NULL, 0.1, 0.0, 0.0, NULL), DS_ERR_ARG);
    /* Faster than the disks move: 10 disks of R = 5 at the speed of 100
     * take a rate up to 10 x 100 / (2 x 5) = 100. */
    assert_int_equal(ds_sim_set_growth(sim, 100.5, 0.0, 0.0, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_NONE);
    /* Disks at rest take no growth at all. */
    ds_sim *rest = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &rest, NULL), DS_OK);
    ds_disk still[10];
    assert_int_equal(ds_sim_get_disks(rest, still, NULL), DS_OK);
    for (int k = 0; k < 10; ++k)
        still[k].vx = still[k].vy = 0.0;
    assert_int_equal(ds_sim_set_disks(rest, still, NULL), DS_OK);
    assert_int_equal(ds_sim_set_growth(rest, 1e-3, 0.0, 0.0, NULL), DS_ERR_ARG);
    ds_sim_destroy(rest);
    assert_int_equal(ds_sim_scale_velocities(sim, 0.0, NULL), DS_ERR_ARG);
    /* Past ds_sim_set_disk's 1e12 a velocity is refused, and nothing changes:
     * every component is at most the speed, 100. */
    const double e = ds_sim_get_kinetic_energy(sim);
    assert_int_equal(ds_sim_scale_velocities(sim, 1e11, NULL), DS_ERR_ARG);
    assert_true(ds_sim_get_kinetic_energy(sim) == e);
    assert_int_equal(ds_sim_scale_velocities(sim, 2.0, NULL), DS_OK);
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) / (4.0 * e) - 1.0) < 1e-14);
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_NONE);
    assert_true(ds_sim_get_growth_z(sim) == 0.0);
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* Contacts                                                             */
/* ------------------------------------------------------------------ */

/* 64 disks on the 8 x 8 triangular lattice of a periodic box of aspect
 * sqrt(3)/2, their diameter 1e-6 short of the spacing: six contacts each
 * within a gap of 1e-5, none within 1e-7. */
static void test_a_lattice_has_its_coordination_number(void **state)
{
    (void)state;
    const double spacing = 1000.0 / 8.0;
    ds_params p = ds_params_default(64, 0.5 * spacing / (1.0 + 1e-6));
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.placement = DS_PLACEMENT_LATTICE;
    p.box_y = 1000.0 * sqrt(3.0) / 2.0;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_contacts c;
    assert_int_equal(ds_sim_get_contacts(sim, 1e-5, &c, NULL), DS_OK);
    assert_int_equal(c.pairs, 3 * 64);
    assert_int_equal(c.rattlers, 0);
    assert_true(c.per_disk == 6.0);
    assert_int_equal(ds_sim_get_contacts(sim, 1e-7, &c, NULL), DS_OK);
    assert_int_equal(c.pairs, 0);
    assert_int_equal(c.rattlers, 64);
    assert_true(c.rattler_fraction == 1.0);
    assert_int_equal(ds_sim_get_contacts(sim, 1.5, &c, NULL), DS_ERR_ARG);
    assert_int_equal(ds_sim_get_contacts(NULL, 0.1, &c, NULL), DS_ERR_ARG);
    ds_sim_destroy(sim);
}

/* A rhombus of four touching disks, two triangles on one edge: the tips
 * have two contacts each, the edge's disks three. Taking the tips away
 * leaves the edge's disks with two: they go too, and nothing is left. */
static void test_rattlers_are_removed_until_none_is_left(void **state)
{
    (void)state;
    ds_params p = ds_params_default(4, 10.0);
    p.boundary = DS_BOUNDARY_PERIODIC;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    /* Centres 20 = 2R apart along every edge: in contact. */
    const double h = 10.0 * sqrt(3.0);
    const ds_disk d[4] = {{500.0, 500.0 - h, 0.0, 0.0},
                          {490.0, 500.0, 0.0, 0.0},
                          {510.0, 500.0, 0.0, 0.0},
                          {500.0, 500.0 + h, 0.0, 0.0}};
    for (int k = 0; k < 4; ++k)
        assert_int_equal(ds_sim_set_disk(sim, (size_t)k, d[k], NULL), DS_OK);
    ds_contacts c;
    assert_int_equal(ds_sim_get_contacts(sim, 1e-6, &c, NULL), DS_OK);
    assert_int_equal(c.rattlers, 4);
    assert_int_equal(c.pairs, 0);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_two_growing_disks_meet_on_time_and_part_at_twice_the_growth_speed),
        cmocka_unit_test(test_a_mixture_grows_to_its_target_without_overlap),
        cmocka_unit_test(test_growth_stops_at_its_target_even_with_no_event_near),
        cmocka_unit_test(test_a_compression_to_jamming_stops_with_an_isostatic_packing),
        cmocka_unit_test(test_a_growing_run_saved_and_loaded_goes_on_bit_for_bit),
        cmocka_unit_test(test_growth_is_refused_where_it_cannot_run),
        cmocka_unit_test(test_a_lattice_has_its_coordination_number),
        cmocka_unit_test(test_rattlers_are_removed_until_none_is_left),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
