/* SPDX-License-Identifier: MIT */
/* ds_sim_get_stress_integral: the time integral of the pressure tensor, against
 * a lone disk's flight, one collision worked by hand, the virial pressure
 * it must contain, and the shear viscosity of a dilute gas. */
#include "test_util.h"

#define PI 3.14159265358979323846

/* A lone disk of a 100 x 100 box at (50, 40), velocity (3, 2), for 120
 * time units: its kinetic tensor is m v_a v_b, constant in a periodic
 * box; with walls each turn changes the sign of vx vy (x turns at 16.3,
 * 49, 81.7 and 114.3, y at 29.5 and 78.5). The integral must be
 *   s_xx = 9 t, s_yy = 4 t, s_xy = int vx vy dt.
 * The time step flies each step at the velocities it starts with, so the
 * sum of vx vy dt over the steps is its integral up to rounding; the
 * event-driven integrator turns inside a step, and each turn moves the
 * sum by at most 2 |vx vy| dt. */
static void lone_disk(ds_integrator integ, ds_boundary boundary)
{
    ds_params p = ds_params_default(1, 1.0);
    p.box = 100.0;
    p.boundary = boundary;
    p.integrator = integ;
    p.dt = 0.01;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    const ds_disk start = {50.0, 40.0, 3.0, 2.0};
    assert_int_equal(ds_sim_set_disk(sim, 0, start, NULL), DS_OK);
    enum { STEPS = 12000 };
    double sum = 0.0;
    for (int k = 0; k < STEPS; ++k) {
        const ds_disk d = ds_sim_get_disk(sim, 0);
        sum += d.vx * d.vy * p.dt;
        ds_sim_step(sim, NULL);
    }
    const double t = STEPS * p.dt;
    double s[3];
    assert_int_equal(ds_sim_get_stress_integral(sim, s, NULL), DS_OK);
    const uint64_t turns = ds_sim_get_wall_count(sim);
    if (boundary == DS_BOUNDARY_WALLS)
        assert_true(turns == 6);
    /* Rounding: STEPS additions of terms up to 9 dt, each off by an ulp. */
    const double rounding = 4.0 * STEPS * DBL_EPSILON * 9.0 * t;
    assert_true(fabs(s[0] - 9.0 * t) <= rounding);
    assert_true(fabs(s[1] - 4.0 * t) <= rounding);
    const double turning =
        integ == DS_INTEGRATOR_EVENT_DRIVEN ? (double)turns * 2.0 * 6.0 * p.dt : 0.0;
    assert_true(fabs(s[2] - sum) <= turning + rounding);
    if (boundary == DS_BOUNDARY_PERIODIC)
        assert_true(fabs(s[2] - 6.0 * t) <= rounding);
    ds_sim_destroy(sim);
}

static void test_lone_disk_time_step_walls(void **state)
{
    (void)state;
    lone_disk(DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_WALLS);
}

static void test_lone_disk_time_step_periodic(void **state)
{
    (void)state;
    lone_disk(DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_PERIODIC);
}

static void test_lone_disk_event_walls(void **state)
{
    (void)state;
    lone_disk(DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_WALLS);
}

static void test_lone_disk_event_periodic(void **state)
{
    (void)state;
    lone_disk(DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC);
}

/* Disk a at (20, 50) moving (u, 0), u = 1, meets disk b at rest at (30,
 * 50 + sigma sin(alpha)), sigma = 2, alpha = 30 degrees: at contact the
 * line of centres is n = (cos, sin) alpha, a is at 30 - sigma cos(alpha)
 * at t_c = 10 - sigma cos(alpha), and a hands b its velocity along n:
 *   v_a = u s (s, -c), v_b = u c (c, s)   (s, c the sine and cosine),
 * so the kinetic tensor goes from (u^2, 0, 0) to u^2 (s^4 + c^4, 2 s^2
 * c^2, s c (c^2 - s^2)), and the collision's virial tensor (r_a - r_b)_a
 * dp_a,b = (-sigma n_a) (-u c n_b) = sigma u c n_a n_b. Nothing else
 * happens before t = 20: the two separate, and no seam or wall is near. */
static void test_one_collision_by_hand(void **state)
{
    (void)state;
    ds_params p = ds_params_default(2, 1.0);
    p.box = 100.0;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.dt = 0.01;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    const double sigma = 2.0, s = 0.5, c = sqrt(3.0) / 2.0, u = 1.0;
    const ds_disk start[2] = {{20.0, 50.0, u, 0.0}, {30.0, 50.0 + sigma * s, 0.0, 0.0}};
    ds_error err;
    assert_int_equal(ds_sim_set_disks(sim, start, &err), DS_OK);
    ds_sim_run(sim, 2000, NULL);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    const double t = 20.0, t_c = 10.0 - sigma * c, after = t - t_c;
    const double want[3] = {
        u * u * t_c + u * u * (s * s * s * s + c * c * c * c) * after + sigma * u * c * c * c,
        u * u * 2.0 * s * s * c * c * after + sigma * u * c * s * s,
        u * u * s * c * (c * c - s * s) * after + sigma * u * c * c * s,
    };
    double got[3];
    assert_int_equal(ds_sim_get_stress_integral(sim, got, NULL), DS_OK);
    /* The contact time is exact to about 1e-9 of the positions' scale
     * (the header's promise), 1e-7 here, which moves the kinetic part by
     * |dK| 1e-7 <= 1e-7. */
    for (int k = 0; k < 3; ++k)
        assert_true(fabs(got[k] - want[k]) <= 1e-7);
    ds_sim_destroy(sim);
}

/* The trace of the integral is the virial pressure: with no reset since
 * creation, (s_xx + s_yy) / (2 A t) = (K + W / (2 t)) / A, A the area of
 * ds_sim_get_virial_pressure, as the kinetic energy K is conserved and the trace
 * of each collision's virial tensor is its virial. Both integrators, both
 * boundaries, 300 disks at area fraction 0.3; to rounding (1e-9 bounds
 * the energy's drift and the collisions' sums, ~1e-13 and 1e5 eps). */
static void trace_is_the_virial_pressure(ds_integrator integ, ds_boundary boundary)
{
    ds_params p = ds_params_default(300, sqrt(0.3 * 1e6 / (300.0 * PI)));
    p.integrator = integ;
    p.boundary = boundary;
    p.seed = 5;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_sim_run(sim, 2000, NULL); /* 2 time units, cheap even under valgrind */
    assert_true(ds_sim_get_collision_count(sim) > 1000);
    double s[3];
    assert_int_equal(ds_sim_get_stress_integral(sim, s, NULL), DS_OK);
    const double r = p.radius,
                 area = boundary == DS_BOUNDARY_PERIODIC ? 1e6 : (1000 - 2 * r) * (1000 - 2 * r);
    const double pressure = (s[0] + s[1]) / (2.0 * area * ds_sim_get_time(sim));
    assert_true(fabs(pressure - ds_sim_get_virial_pressure(sim)) <=
                1e-9 * ds_sim_get_virial_pressure(sim));
    ds_sim_destroy(sim);
}

static void test_trace_time_step_walls(void **state)
{
    (void)state;
    trace_is_the_virial_pressure(DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_WALLS);
}

static void test_trace_time_step_periodic(void **state)
{
    (void)state;
    trace_is_the_virial_pressure(DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_PERIODIC);
}

static void test_trace_event_walls(void **state)
{
    (void)state;
    trace_is_the_virial_pressure(DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_WALLS);
}

static void test_trace_event_periodic(void **state)
{
    (void)state;
    trace_is_the_virial_pressure(DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC);
}

static void test_null_is_refused(void **state)
{
    (void)state;
    double s[3];
    assert_int_equal(ds_sim_get_stress_integral(NULL, s, NULL), DS_ERR_ARG);
    ds_sim *sim = test_create(2, 5.0, 1, DS_BROADPHASE_AUTO);
    assert_int_equal(ds_sim_get_stress_integral(sim, NULL, NULL), DS_ERR_ARG);
    ds_sim_destroy(sim);
}

/* The shear viscosity of a dilute gas, area fraction 0.02, 256 disks,
 * from the Helfand moments of s_xy and (s_xx - s_yy) / 2 (the header),
 * fed to a ds_transport of one "disk" whose Einstein slope is then
 * A kT eta. The window is 4 to 8 mean free times, where the stress (which
 * relaxes in about one, the Maxwell time eta_0 / (n kT) = 1 / nu_0) has
 * died out: the slope is 1 - e^-4 of its limit or more.
 * Bounds, on the ratio to the Enskog first approximation eta_E1 =
 * eta_0 (1 / g + 2 eta + (1 + 8 / pi) eta^2 g), eta_0 = (1 / (2 sigma))
 * sqrt(m kT / pi) (Gass 1971):
 * - below: the first Chapman-Enskog approximation bounds the viscosity
 *   from below (its variational principle), and at fixed energy and zero
 *   momentum the kinetic stress's variance is (N - 1)^2 / N (kT)^2, not
 *   N (kT)^2 (velocities on the energy sphere of 2 (N - 1) dimensions),
 *   so the finite gas's eta is lower by that factor (N - 1)^2 / N^2;
 * - above: the Sonine series adds 2.2% at second order (Gass), and less
 *   than 3% converged (the diffusion's series, test_transport, adds 2.7%);
 * each side widened by 5 standard errors over the blocks. */
static void test_dilute_gas_viscosity_is_enskogs(void **state)
{
    (void)state;
    enum { BLOCKS = 20, N = 256 };
    const double eta = 0.02, kt_guess = 5000.0;
    const double radius = sqrt(eta * 1e6 / ((double)N * PI)), sigma = 2.0 * radius;
    const double density = N / 1e6;
    const double t_free = 1.0 / (2.0 * density * sigma * sqrt(PI * kt_guess)); /* 1 / nu_0 */
    ds_params p = ds_params_default(N, radius);
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.seed = 23;
    p.dt = 0.5 * t_free;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_sim_run(sim, 100, NULL); /* 50 mean free times */
    enum { LAGS = 17 };
    const int blocks = quick_mode() ? 3 : BLOCKS, samples = quick_mode() ? 200 : 1600;
    double ratio[BLOCKS], lower = 0.0;
    for (int b = 0; b < blocks; ++b) {
        ds_sim_reset_observables(sim);
        ds_transport *tr = NULL;
        assert_int_equal(ds_transport_create(1, LAGS, 1, &tr, NULL), DS_OK);
        for (int k = 0; k < samples; ++k) {
            if (k)
                ds_sim_step(sim, NULL);
            double s[3];
            assert_int_equal(ds_sim_get_stress_integral(sim, s, NULL), DS_OK);
            const double shear[2] = {s[2], 0.5 * (s[0] - s[1])}, unused[2] = {0.0, 0.0};
            assert_int_equal(ds_transport_add(tr, shear, unused, NULL), DS_OK);
        }
        double slope;
        assert_int_equal(ds_transport_get_diffusion(tr, p.dt, 8, 16, &slope, NULL, NULL), DS_OK);
        ds_transport_destroy(tr);
        const double kt = ds_sim_get_temperature(sim), z = ds_sim_get_compressibility_factor(sim);
        const double g = (z - 1.0) / (2.0 * eta), eta_0 = sqrt(kt / PI) / (2.0 * sigma);
        const double first = eta_0 * (1.0 / g + 2.0 * eta + (1.0 + 8.0 / PI) * eta * eta * g);
        ratio[b] = slope / (1e6 * kt) / first;
        lower = (N - 1.0) * (N - 1.0) / ((double)N * N);
    }
    const block_stats r = stats_of(ratio, blocks);
    if (getenv("DS_TEST_VERBOSE"))
        printf("eta %.2f: viscosity / eta_E1 = %.4f +- %.4f, bounds [%.4f, 1.03]\n", eta, r.mean,
               r.error, lower);
    assert_true(r.mean >= lower - 5.0 * r.error);
    assert_true(r.mean <= 1.03 + 5.0 * r.error);
    assert_true(r.error < (quick_mode() ? 0.15 : 0.04));
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lone_disk_time_step_walls),
        cmocka_unit_test(test_lone_disk_time_step_periodic),
        cmocka_unit_test(test_lone_disk_event_walls),
        cmocka_unit_test(test_lone_disk_event_periodic),
        cmocka_unit_test(test_one_collision_by_hand),
        cmocka_unit_test(test_trace_time_step_walls),
        cmocka_unit_test(test_trace_time_step_periodic),
        cmocka_unit_test(test_trace_event_walls),
        cmocka_unit_test(test_trace_event_periodic),
        cmocka_unit_test(test_null_is_refused),
        cmocka_unit_test(test_dilute_gas_viscosity_is_enskogs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
