/* SPDX-License-Identifier: MIT */
/* Section 5 of tools/bench: the event-driven integrator. Public API only.
 *
 * 5a. Disk-disk collisions per second at area fraction 0.5 with walls, for
 *     N = 10^3 to 10^6: each system is created and relaxed for about one
 *     collision per disk, then timed in every round (ds_sim_get_collision_seconds:
 *     predicting and processing events) over about 10^6 collisions.
 * 5c. A mixture: 50:50 of radius ratio 1.4 against one size, both at
 *     area fraction 0.5 and N = 10^5 with walls, in the same rounds.
 * 5b. What exactness costs: one simulated time unit event-driven against
 *     the time step at the dt whose pressure bias is 0.1%, for N = 4000 at
 *     area fraction 0.3, the system of the Z(dt) test. The bias of the
 *     time step is measured here, from the collision virial at dt = 0.002
 *     and 0.001 against the event-driven value (it is linear in dt). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "disk_sim.h"

#define PI 3.14159265358979323846

static double radius_at(size_t n, double fraction)
{
    return sqrt(fraction * 1000.0 * 1000.0 / ((double)n * PI));
}

static ds_sim *create(size_t n, double fraction, ds_integrator integrator, double dt)
{
    ds_params p = ds_params_default(n, radius_at(n, fraction));
    p.integrator = integrator;
    p.dt = dt;
    ds_sim *sim = NULL;
    ds_status st = ds_sim_create(&p, NULL, &sim, NULL);
    if (st != DS_OK)
        fprintf(stderr, "bench: ds_sim_create(N = %zu): %s\n", n, ds_status_name(st));
    return sim;
}

/* At area fraction 0.5 a disk collides ~0.62 sqrt(N) times per time unit
 * (box 1000, speed 100): N / 2 of those per unit in all. */
static double collisions_per_step(size_t n) { return 3.1e-4 * pow((double)n, 1.5); }

static unsigned long at_least(double steps, unsigned long least)
{
    return steps > (double)least ? (unsigned long)steps : least;
}

/* A system at area fraction 0.5 relaxed for about `per_disk` collisions
 * per disk (each collision counts for two); NULL on failure. *created gets
 * the seconds of ds_sim_create: random placement this close to its jamming
 * limit (0.547) takes seconds at 10^6 disks, so each system is created
 * once and timed in every round. */
static ds_sim *relaxed(size_t n, double per_disk, double *created)
{
    const double t0 = ds_timer_now();
    ds_sim *sim = create(n, 0.5, DS_INTEGRATOR_EVENT_DRIVEN, 0.0);
    *created = ds_timer_now() - t0;
    if (sim)
        ds_sim_run(sim, at_least(0.5 * per_disk * (double)n / collisions_per_step(n), 2), NULL);
    return sim;
}

/* ns per collision over about 10^6 more collisions. */
static double ns_per_collision(ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    const uint64_t c0 = ds_sim_get_collision_count(sim);
    const double s0 = ds_sim_get_collision_seconds(sim);
    ds_sim_run(sim, at_least(1e6 / collisions_per_step(n), 4), NULL);
    return 1e9 * (ds_sim_get_collision_seconds(sim) - s0) /
           (double)(ds_sim_get_collision_count(sim) - c0);
}

int bench_events_one(unsigned long n, double per_disk)
{
    double created;
    ds_sim *sim = n >= 2 && per_disk >= 0.0 ? relaxed(n, per_disk, &created) : NULL;
    if (!sim)
        return 0;
    const double ns = ns_per_collision(sim);
    ds_sim_destroy(sim);
    printf("N = %lu, area fraction 0.5, event-driven, after %g collisions per disk: %.0f ns per "
           "collision, %.3g collisions/s; create %.2f s; peak RSS %ld KB\n",
           n, per_disk, ns, 1e9 / ns, created, peak_rss_kb());
    return 1;
}

/* N disks at area fraction 0.5, half of radius r and half of 1.4 r:
 * r^2 = 0.5 A / (pi N (1 + 1.96) / 2). Relaxed as relaxed() does. */
static ds_sim *relaxed_mixture(size_t n, double per_disk)
{
    const double r = sqrt(0.5 * 1000.0 * 1000.0 / (PI * (double)n * 1.48));
    ds_params p = ds_params_default(n, r);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    const ds_species kinds[2] = {{n / 2, r, 0.0, NULL}, {n - n / 2, 1.4 * r, 0.0, NULL}};
    const ds_mixture mix = {2, kinds, NULL, NULL, DS_MASS_EQUAL};
    ds_sim *sim = NULL;
    ds_status st = ds_sim_create(&p, &mix, &sim, NULL);
    if (st != DS_OK) {
        fprintf(stderr, "bench: ds_sim_create(N = %zu, a mixture): %s\n", n, ds_status_name(st));
        return NULL;
    }
    ds_sim_run(sim, at_least(0.5 * per_disk * (double)n / collisions_per_step(n), 2), NULL);
    return sim;
}

/* 5c: ns per collision of the mixture and of one size, interleaved. */
static int bench_mixture(void)
{
    const size_t n = 100000;
    double created, ns[2][ROUNDS];
    ds_sim *one = relaxed(n, 1.0, &created), *mix = one ? relaxed_mixture(n, 1.0) : NULL;
    for (int k = 0; mix && k < ROUNDS; ++k) {
        ns[0][k] = ns_per_collision(one);
        ns[1][k] = ns_per_collision(mix);
    }
    const int ok = mix != NULL;
    ds_sim_destroy(one);
    ds_sim_destroy(mix);
    if (!ok)
        return 0;
    const double ratio = median_ratio(ns[1], ns[0]);
    printf("\n   A mixture, 50:50 of radius ratio 1.4, against one size (N = 10^5, area fraction\n"
           "   0.5, walls; cells sized by the largest pair, 2.3 r, not 2 r, r the one size's):\n");
    printf(
        "   one size %.0f ns/collision, mixture %.0f: mixture / one size = %.2f (target <= 1.3)\n",
        median(ns[0], ROUNDS), median(ns[1], ROUNDS), ratio);
    fflush(stdout);
    return 1;
}

/* Z = P A / E from the collision virial (A = (box - 2R)^2) over `units`
 * time units after 2 of relaxation, and the wall-clock seconds of ds_sim_run
 * per time unit. */
static int virial_z(ds_integrator integrator, double dt, int units, double *z, double *seconds)
{
    const size_t n = 4000;
    ds_sim *sim = create(n, 0.3, integrator, dt);
    if (!sim)
        return 0;
    const unsigned long per_unit = (unsigned long)llround(1.0 / dt);
    ds_sim_run(sim, 2 * per_unit, NULL);
    ds_sim_reset_observables(sim);
    const double t0 = ds_timer_now();
    ds_sim_run(sim, (unsigned long)units * per_unit, NULL);
    *seconds = (ds_timer_now() - t0) / units;
    const double span = 1000.0 - 2.0 * ds_sim_get_radius(sim);
    *z = ds_sim_get_virial_pressure(sim) * span * span / ds_sim_get_kinetic_energy(sim);
    ds_sim_destroy(sim);
    return 1;
}

int bench_events(void)
{
    static const size_t sizes[] = {1000, 10000, 100000, 1000000};
    enum { SIZES = sizeof sizes / sizeof sizes[0] };
    double ns[SIZES][ROUNDS], created[SIZES];
    ds_sim *sims[SIZES] = {NULL};
    int ok = 1;
    for (int c = 0; ok && c < SIZES; ++c)
        ok = (sims[c] = relaxed(sizes[c], 1.0, &created[c])) != NULL;
    for (int k = 0; ok && k < ROUNDS; ++k)
        for (int c = 0; c < SIZES; ++c)
            ns[c][k] = ns_per_collision(sims[c]);
    for (int c = 0; c < SIZES; ++c)
        ds_sim_destroy(sims[c]);
    if (!ok)
        return 0;
    printf(
        "\n5. Event-driven integrator, area fraction 0.5, walls: ~10^6 collisions per case\n"
        "   after ~1 per disk of relaxation; ns per collision from ds_sim_get_collision_seconds\n");
    /* median() sorts its input: the ratio first, while the rounds pair up. */
    const double scaling = median_ratio(ns[3], ns[0]);
    printf("%8s %8s %14s %14s %10s\n", "N", "R", "ns/collision", "collisions/s", "create s");
    double m[SIZES];
    for (int c = 0; c < SIZES; ++c) {
        m[c] = median(ns[c], ROUNDS);
        printf("%8zu %8.4f %14.0f %14.3g %10.2f\n", sizes[c], radius_at(sizes[c], 0.5), m[c],
               1e9 / m[c], created[c]);
    }
    printf("   collisions/s at N = 10^5: %.3g (target >= 2e6)\n", 1e9 / m[2]);
    printf("   ns/collision, N = 10^6 / N = 10^3: %.2f (target <= 1.5)\n", scaling);
    fflush(stdout);
    if (!bench_mixture())
        return 0;

    double z_exact, s_exact, z2, s2, z1, s1;
    if (!virial_z(DS_INTEGRATOR_EVENT_DRIVEN, 0.001, 10, &z_exact, &s_exact) ||
        !virial_z(DS_INTEGRATOR_TIME_STEP, 0.002, 10, &z2, &s2) ||
        !virial_z(DS_INTEGRATOR_TIME_STEP, 0.001, 10, &z1, &s1))
        return 0;
    /* The bias is a dt (fitted through the exact value, weighting the two
     * points equally); 0.1% of Z needs dt = 0.001 Z / |a|, and costs the
     * time step's seconds per step at dt = 0.001 times 1 / dt steps. */
    const double slope = 0.5 * ((z2 - z_exact) / 0.002 + (z1 - z_exact) / 0.001);
    const double dt_needed = 1e-3 * z_exact / fabs(slope);
    const double step_cost = s1 * 1e-3 / dt_needed;
    printf("\n   What exactness costs (N = 4000, area fraction 0.3, walls; Z from the virial):\n");
    printf("   event-driven Z = %.4f, %.3f s per time unit\n", z_exact, s_exact);
    printf("   time step: Z = %.4f at dt = 0.002, %.4f at dt = 0.001: bias %.1f dt\n", z2, z1,
           slope);
    printf("   a 0.1%% bias needs dt = %.2g: %.3f s per time unit, %.0f times the event-driven "
           "cost\n",
           dt_needed, step_cost, step_cost / s_exact);
    return 1;
}
