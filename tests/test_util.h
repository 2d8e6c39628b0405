/* SPDX-License-Identifier: MIT */
/* Shared includes and helpers for the cmocka tests. */
#ifndef DS_TEST_UTIL_H
#define DS_TEST_UTIL_H

#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "disk_sim.h"

/* Creates a simulation or fails the test. */
static inline ds_sim *test_create(size_t n, double radius, uint64_t seed, ds_broadphase bp)
{
    ds_params p = ds_params_default(n, radius);
    p.seed = seed;
    p.broadphase = bp;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_non_null(sim);
    return sim;
}

/* psi6 of the disks of sim (ds_sim_get_psi6), NaN where it refuses. */
static inline double psi6_of(const ds_sim *sim)
{
    double psi6 = NAN;
    (void)ds_sim_get_psi6(sim, &psi6, NULL);
    return psi6;
}

/* Disk i's radius and mass (ds_sim_get_radii, ds_sim_get_masses: 2.x's
 * ds_radius_of and ds_mass_of), 0 out of range. */
static inline double radius_of(const ds_sim *sim, size_t i)
{
    const size_t n = ds_sim_get_count(sim);
    double *r = malloc((n ? n : 1) * sizeof *r), v = 0.0;
    assert_non_null(r);
    if (i < n && ds_sim_get_radii(sim, r, NULL) == DS_OK)
        v = r[i];
    free(r);
    return v;
}

static inline double mass_of(const ds_sim *sim, size_t i)
{
    const size_t n = ds_sim_get_count(sim);
    double *m = malloc((n ? n : 1) * sizeof *m), v = 0.0;
    assert_non_null(m);
    if (i < n && ds_sim_get_masses(sim, m, NULL) == DS_OK)
        v = m[i];
    free(m);
    return v;
}

/* DS_TEST_QUICK=1 (for the valgrind run in CI) shortens the long runs; a
 * test whose tolerance depends on the run's length recomputes it from the
 * shorter run, so the quick tests are weaker but still honest. */
static inline int quick_mode(void)
{
    const char *q = getenv("DS_TEST_QUICK");
    return q && *q && strcmp(q, "0") != 0;
}

/* Steps of a long run, a tenth of them in quick mode. */
static inline uint64_t long_run(uint64_t steps) { return quick_mode() ? steps / 10 : steps; }

/* The mean of a run's n blocks and its standard error, sqrt(var / (n - 1))
 * with var the blocks' variance about their mean. */
typedef struct block_stats {
    double mean, error;
} block_stats;

static inline block_stats stats_of(const double *x, int n)
{
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i)
        sum += x[i];
    const double mean = sum / n;
    for (int i = 0; i < n; ++i)
        sum2 += (x[i] - mean) * (x[i] - mean);
    block_stats s = {mean, sqrt(sum2 / ((double)n * (n - 1)))};
    return s;
}

static inline int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Kolmogorov-Smirnov distance between the speeds and the Rayleigh law with
 * the same <v^2>: F(v) = 1 - exp(-v^2 / <v^2>) (2D Maxwell-Boltzmann with
 * sigma^2 = <v^2>/2 per component). */
static inline double ks_distance_to_rayleigh(const ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    ds_disk *disks = malloc(n * sizeof *disks);
    double *speed = malloc(n * sizeof *speed);
    assert_non_null(disks);
    assert_non_null(speed);
    assert_int_equal(ds_sim_get_disks(sim, disks, NULL), DS_OK);
    for (size_t k = 0; k < n; ++k)
        speed[k] = sqrt(disks[k].vx * disks[k].vx + disks[k].vy * disks[k].vy);
    qsort(speed, n, sizeof *speed, compare_doubles);
    const double v2 = 2.0 * ds_sim_get_kinetic_energy(sim) / (double)n;
    double d = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double f = 1.0 - exp(-speed[i] * speed[i] / v2);
        double above = (double)(i + 1) / (double)n - f, below = f - (double)i / (double)n;
        if (above > d)
            d = above;
        if (below > d)
            d = below;
    }
    free(speed);
    free(disks);
    return d;
}

/* Asymptotic KS critical value at the 1% level: 1.628 / sqrt(N). It is for
 * a fully specified law; here sigma is estimated from the same speeds,
 * which makes the true distribution of D smaller (Lilliefors), so a
 * relaxed gas fails with probability below 1%. The microcanonical marginal
 * differs from Rayleigh by O(1/N) ~ 5e-4, far below the critical value. */
static inline double ks_critical_1_percent(size_t n) { return 1.628 / sqrt((double)n); }

/* Rounding bound for the change of total momentum over `collisions` pair
 * resolutions, with speeds never above vmax. A pair adds t = s*dx to one
 * disk and subtracts the same computed t from the other, so the exact
 * change cancels and only the two roundings remain: <= eps * vmax per
 * component per collision. Each of the two ds_sim_get_momentum sums compared adds
 * <= n eps sum|v| <= n eps sqrt(n) vmax (Cauchy-Schwarz, sum v^2 <= vmax^2
 * with vmax = sqrt(2E)). */
static inline double momentum_rounding_bound(uint64_t collisions, double vmax, size_t n)
{
    return DBL_EPSILON * vmax * ((double)collisions + 2.0 * (double)n * sqrt((double)n));
}

/* Sets disk i, which must be accepted. */
static inline void place(ds_sim *sim, size_t i, double x, double y, double vx, double vy)
{
    const ds_disk d = {x, y, vx, vy};
    assert_int_equal(ds_sim_set_disk(sim, i, d, NULL), DS_OK);
}

/* |got - want| within 1e-9 of max(|want|, 1): the header's promise for
 * the event-driven integrator's contacts and wall turns. */
static inline void assert_close(double got, double want)
{
    const double scale = fabs(want) > 1.0 ? fabs(want) : 1.0;
    if (!(fabs(got - want) <= 1e-9 * scale)) {
        print_error("got %.17g, want %.17g\n", got, want);
        fail();
    }
}

/* The hard-disk virial series through B10 (Clisby and McCoy 2006, J.
 * Stat. Phys. 122, 15; reduced coefficients B_k / B_2^(k-1)), in 2 eta =
 * B_2 rho. A strict lower bound on Z, tight below eta = 0.4: Z = 1.23614
 * at 0.1 and 2.06316 at 0.3. */
static inline double virial_series(double eta)
{
    static const double b[] = {1.0,     0.78200443, 0.53223180, 0.33355604, 0.19884,
                               0.11487, 0.06499,    0.03622,    0.01995};
    double z = 1.0, power = 1.0;
    for (size_t k = 0; k < sizeof b / sizeof b[0]; ++k) {
        power *= 2.0 * eta;
        z += b[k] * power;
    }
    return z;
}

/* A copy of a through a checkpoint in memory; a refusal fails the test
 * with the library's reason. */
static inline ds_sim *through_checkpoint(const ds_sim *a)
{
    const size_t len = ds_checkpoint_get_size(a);
    uint8_t *buf = malloc(len);
    assert_non_null(buf);
    assert_int_equal(ds_checkpoint_format(a, buf, len, NULL, NULL), DS_OK);
    ds_sim *b = NULL;
    ds_error err;
    if (ds_checkpoint_parse(buf, len, &b, &err) != DS_OK)
        fail_msg("the checkpoint at t = %g was refused: %s", ds_sim_get_time(a), err.message);
    free(buf);
    return b;
}

/* The integrators with dynamics, whose velocities collisions change:
 * event chains sample equilibrium without them, and refuse what acts on
 * them (a heat bath, restitution, a field, a drive), which the tests of
 * those check. */
#define FOR_EACH_DYNAMIC_INTEGRATOR(i)                                                             \
    for (int i = 0; i < DS_INTEGRATOR_COUNT; ++i)                                                  \
        if (i != DS_INTEGRATOR_EVENT_CHAIN)

#endif
