/* SPDX-License-Identifier: MIT */
/* Inelastic collisions: the coefficients of restitution of pairs and
 * walls against hand-computed results, e = 1 as the elastic collision to
 * the bit, the energy books, the TC model, the inelastic collapse it
 * prevents, and Haff's law of a freely cooling gas. */
#include "test_util.h"

static const double PI = 3.14159265358979323846;

/* A simulation of n disks of radius r in a box of side box, with the
 * integrator and boundary asked; the test then sets the disks. */
static ds_sim *make(ds_integrator integrator, ds_boundary boundary, size_t n, double r, double box)
{
    ds_params p = ds_params_default(n, r);
    p.integrator = integrator;
    p.boundary = boundary;
    p.box = box;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

/* Two disks on a line, a at x = 40 moving right at 10, b at x = 60 at
 * rest, radius 5: they meet at t = 1 (gap 10) head on. */
static ds_sim *head_on(ds_integrator integrator, const ds_mixture *mixture)
{
    ds_params p = ds_params_default(2, 5.0);
    p.integrator = integrator;
    p.box = 200.0;
    p.dt = integrator == DS_INTEGRATOR_EVENT_DRIVEN ? 0.5 : 1.0 / 1024.0;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, mixture, &sim, NULL), DS_OK);
    const ds_disk d[2] = {{40.0, 100.0, 10.0, 0.0}, {60.0, 100.0, 0.0, 0.0}};
    assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK);
    return sim;
}

/* A head-on collision leaves the relative velocity -e times what it was,
 * keeps the momentum, and the energy lost is (1 - e^2) mu u^2 / 2, with
 * both integrators, for equal and unequal masses. The time step's
 * collision comes a step late, so its positions differ; its velocities
 * are those of the same rule. */
static void test_a_head_on_collision_keeps_e_of_the_relative_velocity(void **state)
{
    (void)state;
    const double e = 0.6;
    const ds_species kinds[2] = {{1, 5.0, 1.0, NULL}, {1, 5.0, 3.0, NULL}};
    const ds_mixture unequal = {2, kinds, NULL, NULL, DS_MASS_EQUAL};
    FOR_EACH_DYNAMIC_INTEGRATOR(integrator)
    for (int masses = 0; masses < 2; ++masses) {
        ds_sim *sim = head_on((ds_integrator)integrator, masses ? &unequal : NULL);
        assert_int_equal(ds_sim_set_restitution(sim, e, 1.0, NULL), DS_OK);
        const uint64_t steps = (uint64_t)(2.0 / ds_sim_get_dt(sim));
        ds_sim_run(sim, steps, NULL);
        assert_int_equal(ds_sim_get_collision_count(sim), 1);
        const double ma = 1.0, mb = masses ? 3.0 : 1.0, mu = ma * mb / (ma + mb);
        const ds_disk a = ds_sim_get_disk(sim, 0), b = ds_sim_get_disk(sim, 1);
        /* One rounding of each product and sum: 1e-14 relative. */
        assert_true(fabs((b.vx - a.vx) - e * 10.0) < 1e-13);
        assert_true(fabs(ma * a.vx + mb * b.vx - 10.0) < 1e-13);
        assert_true(fabs(ds_sim_get_energy_lost(sim) - 0.5 * (1.0 - e * e) * mu * 100.0) < 1e-12);
        /* The books: the kinetic energy is what it was less the loss. */
        assert_true(fabs(ds_sim_get_kinetic_energy(sim) + ds_sim_get_energy_lost(sim) - 50.0) <
                    1e-12);
        ds_sim_destroy(sim);
    }
}

/* At a wall the normal velocity comes back -e times itself, the tangential
 * one stays, the wall receives (1 + e) m |v_n| and the energy lost is (1 -
 * e^2) m v_n^2 / 2: both integrators. */
static void test_a_wall_turn_keeps_e_of_the_normal_velocity(void **state)
{
    (void)state;
    const double e = 0.5;
    FOR_EACH_DYNAMIC_INTEGRATOR(integrator)
    {
        ds_sim *sim = make((ds_integrator)integrator, DS_BOUNDARY_WALLS, 1, 5.0, 100.0);
        const ds_disk d = {20.0, 50.0, -8.0, 3.0};
        assert_int_equal(ds_sim_set_disks(sim, &d, NULL), DS_OK);
        assert_int_equal(ds_sim_set_restitution(sim, 1.0, e, NULL), DS_OK);
        ds_sim_run(sim, 2500, NULL); /* 2.5: the wall at t = 1.875, nothing after */
        const ds_disk after = ds_sim_get_disk(sim, 0);
        assert_true(after.vx == 4.0 && after.vy == 3.0);
        assert_int_equal(ds_sim_get_wall_count(sim), 1);
        assert_true(ds_sim_get_wall_impulse(sim) == 12.0);
        assert_true(ds_sim_get_energy_lost(sim) == 0.5 * (64.0 - 16.0));
        ds_sim_destroy(sim);
    }
}

/* e = 1, set or not, is the elastic collision to the bit: a run of a
 * mixture with walls, both integrators, and the same with the rules set
 * to 1 give the same disks; nothing is lost. */
static void test_restitution_one_is_the_elastic_collision_to_the_bit(void **state)
{
    (void)state;
    const ds_species kinds[2] = {{60, 6.0, 0.0, NULL}, {60, 4.0, 0.0, NULL}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    FOR_EACH_DYNAMIC_INTEGRATOR(integrator)
    {
        ds_sim *sim[2];
        for (int k = 0; k < 2; ++k) {
            ds_params p = ds_params_default(120, 5.0);
            p.integrator = (ds_integrator)integrator;
            p.box = 300.0;
            sim[k] = NULL;
            assert_int_equal(ds_sim_create(&p, &mixture, &sim[k], NULL), DS_OK);
        }
        assert_int_equal(ds_sim_set_restitution(sim[1], 1.0, 1.0, NULL), DS_OK);
        ds_sim_run(sim[0], 3000, NULL);
        ds_sim_run(sim[1], 3000, NULL);
        ds_disk a[120], b[120];
        assert_int_equal(ds_sim_get_disks(sim[0], a, NULL), DS_OK);
        assert_int_equal(ds_sim_get_disks(sim[1], b, NULL), DS_OK);
        assert_memory_equal(a, b, sizeof a);
        assert_true(ds_sim_get_collision_count(sim[0]) > 100);
        assert_true(ds_sim_get_energy_lost(sim[1]) == 0.0);
        ds_sim_destroy(sim[0]);
        ds_sim_destroy(sim[1]);
    }
}

/* The TC model: a wall turn within the contact time of the disk's
 * previous collision is elastic, one after it is not. Disk b sits gap
 * from the right wall's band; a hits it at 10, sending it at (1 + e) 5
 * into the wall gap / 7.5 later: with the contact time above that, b
 * comes back at its full speed, below it at e times it. */
static void test_a_collision_within_the_contact_time_is_elastic(void **state)
{
    (void)state;
    const double e = 0.5, gap = 0.075; /* b reaches the wall 0.01 after the collision */
    for (int within = 0; within < 2; ++within) {
        ds_sim *sim = make(DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_WALLS, 2, 5.0, 100.0);
        const ds_disk d[2] = {{70.0 - gap, 50.0, 10.0, 0.0}, {95.0 - gap, 50.0, 0.0, 0.0}};
        assert_int_equal(ds_sim_set_disks(sim, d, NULL), DS_OK);
        assert_int_equal(ds_sim_set_restitution(sim, e, e, NULL), DS_OK);
        assert_int_equal(ds_sim_set_contact_time(sim, within ? 0.02 : 0.005, NULL), DS_OK);
        /* To t = 1.512: the collision at 1.5, the wall at 1.51 (b back
         * into a at 1.515, a's next collision, is after). */
        ds_sim_run(sim, 1512, NULL);
        const double vb = ds_sim_get_disk(sim, 1).vx;
        const double want = -(1.0 + e) * 5.0 * (within ? 1.0 : e);
        if (fabs(vb - want) > 1e-12)
            fail_msg("contact time %s the wall's delay: v_b = %.17g, want %.17g",
                     within ? "beyond" : "within", vb, want);
        ds_sim_destroy(sim);
    }
}

/* The kinetic energy lost in a cooling gas is what the books say, to
 * rounding, with both integrators, walls or periodic, disk and wall
 * restitution: K + lost = K at the start. The bound: each collision's
 * loss and each velocity's change round once relative to the energy, so
 * a few DBL_EPSILON per collision of the kinetic energy at the start. */
static void test_the_energy_lost_is_the_kinetic_energy_gone(void **state)
{
    (void)state;
    FOR_EACH_DYNAMIC_INTEGRATOR(integrator)
    for (int boundary = 0; boundary < DS_BOUNDARY_COUNT; ++boundary) {
        ds_params p = ds_params_default(200, 5.0);
        p.integrator = (ds_integrator)integrator;
        p.boundary = (ds_boundary)boundary;
        p.box = 400.0;
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        assert_int_equal(ds_sim_set_restitution(sim, 0.8, 0.7, NULL), DS_OK);
        const double k0 = ds_sim_get_kinetic_energy(sim);
        ds_sim_run(sim, 2000, NULL);
        const double k = ds_sim_get_kinetic_energy(sim), lost = ds_sim_get_energy_lost(sim);
        const double events =
            (double)(ds_sim_get_collision_count(sim) + ds_sim_get_wall_count(sim));
        assert_true(k < 0.9 * k0 && lost > 0.1 * k0);
        if (!(fabs(k + lost - k0) <= 8.0 * DBL_EPSILON * k0 * (events + 200.0)))
            fail_msg("%s, %s: K + lost - K0 = %g", ds_integrator_name(p.integrator),
                     ds_boundary_name(p.boundary), k + lost - k0);
        assert_true(ds_sim_get_power_lost(sim) == lost / ds_sim_get_time(sim));
        ds_sim_reset_observables(sim);
        assert_true(ds_sim_get_energy_lost(sim) == 0.0);
        ds_sim_destroy(sim);
    }
}

/* The inelastic collapse: at e = 0.3 and area fraction 0.5 clusters
 * form whose collisions come ever closer together (McNamara and Young
 * 1994); without the TC model (a contact time of 1e-300) this run of 1000
 * disks took 20 times the collisions, 1.7 million by t = 4, and nothing
 * but rounding bounds them. With the default contact time every step
 * ends, with walls or periodic, and the gas goes on losing energy. */
static void test_a_dense_gas_at_low_restitution_finishes_every_step(void **state)
{
    (void)state;
    for (int boundary = 0; boundary < 2; ++boundary) {
        const size_t n = quick_mode() ? 200 : 1000;
        const double r = 5.0, box = sqrt((double)n * PI * r * r / 0.5);
        ds_sim *sim = make(DS_INTEGRATOR_EVENT_DRIVEN, (ds_boundary)boundary, n, r, box);
        assert_int_equal(ds_sim_set_restitution(sim, 0.3, 0.3, NULL), DS_OK);
        const double k0 = ds_sim_get_kinetic_energy(sim);
        const uint64_t steps = long_run(4000);
        for (uint64_t s = 0; s < steps; ++s)
            assert_int_equal(ds_sim_step(sim, NULL), DS_OK);
        assert_int_equal(ds_sim_get_steps(sim), steps);
        assert_true(ds_sim_get_kinetic_energy(sim) < 0.1 * k0);
        ds_sim_destroy(sim);
    }
}

/* Refusals name the value and the limit, and change nothing. */
static void test_restitution_outside_zero_to_one_is_refused(void **state)
{
    (void)state;
    ds_sim *sim = make(DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_WALLS, 10, 5.0, 200.0);
    const double bad[] = {0.0, -0.5, 1.0000001, NAN, INFINITY};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        ds_error err;
        assert_int_equal(ds_sim_set_restitution(sim, bad[k], 1.0, &err), DS_ERR_ARG);
        assert_string_equal(err.field, "restitution");
        assert_int_equal(ds_sim_set_restitution(sim, 0.9, bad[k], &err), DS_ERR_ARG);
        assert_string_equal(err.field, "wall_restitution");
        assert_true(ds_sim_get_restitution(sim) == 1.0);
        assert_true(ds_sim_get_wall_restitution(sim) == 1.0);
    }
    const double bad_times[] = {-1.0, NAN, INFINITY, -INFINITY};
    for (size_t k = 0; k < sizeof bad_times / sizeof bad_times[0]; ++k) {
        ds_error err;
        assert_int_equal(ds_sim_set_contact_time(sim, bad_times[k], &err), DS_ERR_ARG);
        assert_string_equal(err.field, "contact_time");
    }
    const double tc = ds_sim_get_contact_time(sim);
    assert_true(tc == DS_CONTACT_TIME_DEFAULT * 2.0 * 5.0 / 100.0);
    assert_int_equal(ds_sim_set_contact_time(sim, 0.5, NULL), DS_OK);
    assert_true(ds_sim_get_contact_time(sim) == 0.5);
    assert_int_equal(ds_sim_set_contact_time(sim, 0.0, NULL), DS_OK);
    assert_true(ds_sim_get_contact_time(sim) == tc);
    assert_int_equal(ds_sim_set_restitution(NULL, 0.5, 0.5, NULL), DS_ERR_ARG);
    assert_true(ds_sim_get_restitution(NULL) == 1.0);
    ds_sim_destroy(sim);
}

/* Event chains have no dynamics to make granular: a restitution below 1,
 * a field and a drive are refused naming the integrator, and nothing
 * changes; the elastic rules and a contact time (which changes nothing
 * elastic) are taken. */
static void test_event_chains_refuse_granular_rules(void **state)
{
    (void)state;
    ds_sim *sim = make(DS_INTEGRATOR_EVENT_CHAIN, DS_BOUNDARY_WALLS, 10, 5.0, 200.0);
    ds_error err;
    assert_int_equal(ds_sim_set_restitution(sim, 0.9, 1.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "integrator");
    assert_int_equal(ds_sim_set_restitution(sim, 1.0, 0.5, &err), DS_ERR_ARG);
    assert_int_equal(ds_sim_set_gravity(sim, 0.0, -10.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "integrator");
    assert_int_equal(ds_sim_set_drive(sim, 10.0, &err), DS_ERR_ARG);
    assert_string_equal(err.field, "integrator");
    assert_true(ds_sim_get_restitution(sim) == 1.0 && ds_sim_get_wall_restitution(sim) == 1.0);
    double gx = 1.0, gy = 1.0;
    ds_sim_get_gravity(sim, &gx, &gy);
    assert_true(gx == 0.0 && gy == 0.0);
    assert_int_equal(ds_sim_set_restitution(sim, 1.0, 1.0, &err), DS_OK);
    assert_int_equal(ds_sim_set_contact_time(sim, 0.5, &err), DS_OK);
    ds_sim_destroy(sim);
}

/* Haff's law: a homogeneous gas cooling freely has T(t) = T0 / (1 +
 * t / tau)^2, tau = 4 / ((1 - e^2) omega_E(T0)) with the Enskog collision
 * frequency omega_E = 2 sigma n chi sqrt(pi T / m) and Henderson's chi =
 * (1 - 7 eta / 16) / (1 - eta)^2 (docs/physics.md derives it). Area
 * fraction 0.05, a gas first relaxed elastically from the placement's
 * equal speeds, checked at t = tau / 2, tau and 3 tau / 2 (T down to 0.16
 * of T0). The tolerance: the run cools a little slower than Haff's law,
 * by 1 to 2.5% of T at 3 tau / 2 over 16 runs of 2000 and 8 of 8000
 * disks (velocity correlations: docs/physics.md), and one run's T
 * scatters by 0.5% at 8000 disks, as 1 / sqrt(n) (the random losses);
 * 2.5% and three standard deviations. */
static void test_a_freely_cooling_gas_follows_haffs_law(void **state)
{
    (void)state;
    const double es[2] = {0.9, 0.95};
    const size_t n = quick_mode() ? 1000 : 8000;
    const double tolerance = 0.025 + 3.0 * 0.005 * sqrt(8000.0 / (double)n);
    for (int k = 0; k < 2; ++k) {
        const double r = 5.0, eta = 0.05, box = sqrt((double)n * PI * r * r / eta);
        ds_params p = ds_params_default(n, r);
        p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
        p.boundary = DS_BOUNDARY_PERIODIC;
        p.box = box;
        p.dt = 0.01;
        p.seed = 5 + (uint64_t)k;
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        ds_sim_run(sim, 500, NULL); /* ~8 collisions a disk, elastic: Maxwell-Boltzmann */
        assert_int_equal(ds_sim_set_restitution(sim, es[k], 1.0, NULL), DS_OK);
        const double t0 = ds_sim_get_time(sim), temp0 = ds_sim_get_temperature(sim);
        const double chi = (1.0 - 7.0 * eta / 16.0) / ((1.0 - eta) * (1.0 - eta));
        const double omega = 2.0 * (2.0 * r) * ((double)n / (box * box)) * chi * sqrt(PI * temp0);
        const double tau = 4.0 / ((1.0 - es[k] * es[k]) * omega);
        for (int point = 1; point <= 3; ++point) {
            const double t = 0.5 * point * tau;
            ds_sim_run(sim, (uint64_t)((t0 + t) / p.dt + 0.5) - ds_sim_get_steps(sim), NULL);
            const double s = (ds_sim_get_time(sim) - t0) / tau;
            const double haff = temp0 / ((1.0 + s) * (1.0 + s));
            const double ratio = ds_sim_get_temperature(sim) / haff;
            if (!(fabs(ratio - 1.0) < tolerance))
                fail_msg("e = %g, t = %g tau: T / Haff's = %.4f", es[k], s, ratio);
        }
        ds_sim_destroy(sim);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_head_on_collision_keeps_e_of_the_relative_velocity),
        cmocka_unit_test(test_a_wall_turn_keeps_e_of_the_normal_velocity),
        cmocka_unit_test(test_restitution_one_is_the_elastic_collision_to_the_bit),
        cmocka_unit_test(test_a_collision_within_the_contact_time_is_elastic),
        cmocka_unit_test(test_the_energy_lost_is_the_kinetic_energy_gone),
        cmocka_unit_test(test_a_dense_gas_at_low_restitution_finishes_every_step),
        cmocka_unit_test(test_restitution_outside_zero_to_one_is_refused),
        cmocka_unit_test(test_event_chains_refuse_granular_rules),
        cmocka_unit_test(test_a_freely_cooling_gas_follows_haffs_law),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
