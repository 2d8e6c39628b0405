/* SPDX-License-Identifier: MIT */
/* Two builds of the library in one process (tools/benchmark/ab.sh): this file is
 * compiled once per build with AB_SIDE set to its symbol prefix (A_ or
 * B_), the prefix tools/benchmark/ab.sh gives every global symbol of that build's
 * libdisksim.a, and once with AB_MAIN for the program that alternates
 * them. Each side builds the same system, then the rounds time each side
 * in turn, which side goes first alternating, so that both see the same
 * state of a shared, noisy machine:
 * - event (the default): area fraction 0.5, walls, event-driven, relaxed
 *   ~1 collision per disk, rounds of ~10^6 collisions, ns per collision;
 * - step: the time step at area fraction 0.1 (the broad phase DS_BROADPHASE_AUTO
 *   picks: SAP up to ~4000 disks, strips beyond), rounds of ~2 x 10^7
 *   disk-steps, ns of collision processing per disk-step;
 * - seed: the seed case, 400 disks of R = 5, rounds of 5000 steps;
 * - chain (3.x only): event chains at area fraction 0.70, periodic, from
 *   the lattice (tools/benchmark/bench_chain.c's case), rounds of ~5 x
 *   10^6 liftings, ns of CPU time (the process's) per lifting.
 * Prints each side's median and the median of the per-round ratios B / A
 * with its quartiles. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#if defined(AB_SIDE)
#include "disk_sim.h"

#define AB_CAT2(a, b) a##b
#define AB_CAT(a, b) AB_CAT2(a, b)
#define AB(x) AB_CAT(AB_SIDE, x)

/* The public calls, under this build's prefix, as this build's own
 * headers (ab.sh compiles each side against its revision's include/)
 * spell them: 2.x's names and 3.0's, so that 2.1 and 3.0 can be timed
 * against each other. The side's functions below use the 3.0 forms. */
#if DS_VERSION_MAJOR >= 3
ds_params AB(ds_params_default)(size_t n, double radius);
ds_status AB(ds_sim_create)(const ds_params *params, const ds_mixture *mixture, ds_sim **out,
                            ds_error *err);
ds_status AB(ds_sim_run)(ds_sim *sim, uint64_t steps, ds_error *err);
uint64_t AB(ds_sim_get_collision_count)(const ds_sim *sim);
double AB(ds_sim_get_collision_seconds)(const ds_sim *sim);
void AB(ds_sim_destroy)(ds_sim *sim);
#define params_default AB(ds_params_default)
#define sim_create(p, out) AB(ds_sim_create)(p, NULL, out, NULL)
#define sim_run(sim, k) ((void)AB(ds_sim_run)(sim, k, NULL))
#define collision_count AB(ds_sim_get_collision_count)
#define collision_seconds AB(ds_sim_get_collision_seconds)
#define sim_destroy AB(ds_sim_destroy)
#define EVENT_DRIVEN DS_INTEGRATOR_EVENT_DRIVEN
#define TIME_STEP DS_INTEGRATOR_TIME_STEP
#define HAS_CHAIN 1
#else
ds_params AB(ds_default_params)(size_t n, double radius);
ds_status AB(ds_create)(const ds_params *params, ds_sim **out);
void AB(ds_run)(ds_sim *sim, uint64_t steps);
uint64_t AB(ds_collision_count)(const ds_sim *sim);
double AB(ds_collision_seconds)(const ds_sim *sim);
void AB(ds_destroy)(ds_sim *sim);
#define params_default AB(ds_default_params)
#define sim_create(p, out) AB(ds_create)(p, out)
#define sim_run(sim, k) AB(ds_run)(sim, k)
#define collision_count AB(ds_collision_count)
#define collision_seconds AB(ds_collision_seconds)
#define sim_destroy AB(ds_destroy)
#define EVENT_DRIVEN DS_EVENT_DRIVEN
#define TIME_STEP DS_TIME_STEP
#define HAS_CHAIN 0
#endif

void *AB(ab_make)(size_t n, int kind);
double AB(ab_round)(void *sim, size_t n, int kind);
void AB(ab_done)(void *sim);

/* Collisions per step at area fraction 0.5 (as tools/benchmark/bench_events.c). */
static double per_step(size_t n) { return 3.1e-4 * pow((double)n, 1.5); }

static double radius_at(size_t n, double fraction)
{
    return sqrt(fraction * 1e6 / ((double)n * 3.14159265358979));
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Liftings per step at area fraction 0.70 (as tools/benchmark/bench_chain.c). */
static double lifts_per_step(size_t n) { return 0.04 * (double)n * sqrt((double)n / 1024.0); }

void *AB(ab_make)(size_t n, int kind)
{
#if HAS_CHAIN
    if (kind == 3) {
        ds_params p = params_default(n, radius_at(n, 0.70));
        p.integrator = DS_INTEGRATOR_EVENT_CHAIN;
        p.boundary = DS_BOUNDARY_PERIODIC;
        p.placement = DS_PLACEMENT_LATTICE;
        ds_sim *sim = NULL;
        if (sim_create(&p, &sim) != DS_OK)
            return NULL;
        sim_run(sim, (unsigned long)(10.0 * (double)n / lifts_per_step(n)) + 1);
        return sim;
    }
#else
    if (kind == 3)
        return NULL;
#endif
    ds_params p = params_default(n, radius_at(n, kind == 0 ? 0.5 : 0.1));
    if (kind == 2)
        p = params_default(400, 5.0);
    p.integrator = kind == 0 ? EVENT_DRIVEN : TIME_STEP;
    ds_sim *sim = NULL;
    if (sim_create(&p, &sim) != DS_OK)
        return NULL;
    sim_run(sim, kind ? 100 : (unsigned long)(0.5 * (double)n / per_step(n)) + 2);
    return sim;
}

double AB(ab_round)(void *s, size_t n, int kind)
{
    ds_sim *sim = s;
    if (kind == 3) {
        const unsigned long steps = (unsigned long)(5e6 / lifts_per_step(n)) + 1;
        const uint64_t c0 = collision_count(sim);
        const double t0 = cpu_now();
        sim_run(sim, steps);
        return 1e9 * (cpu_now() - t0) / (double)(collision_count(sim) - c0);
    }
    if (kind) {
        const unsigned long steps = kind == 2 ? 5000 : (unsigned long)(2e7 / (double)n) + 1;
        const double s0 = collision_seconds(sim);
        sim_run(sim, steps);
        const double disks = kind == 2 ? 400.0 : (double)n;
        return 1e9 * (collision_seconds(sim) - s0) / (disks * (double)steps);
    }
    unsigned long steps = (unsigned long)(1e6 / per_step(n));
    steps = steps < 4 ? 4 : steps;
    const uint64_t c0 = collision_count(sim);
    const double s0 = collision_seconds(sim);
    sim_run(sim, steps);
    return 1e9 * (collision_seconds(sim) - s0) / (double)(collision_count(sim) - c0);
}

void AB(ab_done)(void *sim) { sim_destroy(sim); }

#elif defined(AB_MAIN)
void *A_ab_make(size_t n, int kind);
double A_ab_round(void *sim, size_t n, int kind);
void A_ab_done(void *sim);
void *B_ab_make(size_t n, int kind);
double B_ab_round(void *sim, size_t n, int kind);
void B_ab_done(void *sim);

#define MAX_ROUNDS 1000

static int compare(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    const size_t n = argc > 1 ? strtoul(argv[1], NULL, 10) : 0;
    const int rounds = argc > 2 ? atoi(argv[2]) : 0;
    static const char *const kinds[] = {"event", "step", "seed", "chain"};
    int kind = -1;
    for (int k = 0; k < 4; ++k)
        if (strcmp(argc > 3 ? argv[3] : "event", kinds[k]) == 0)
            kind = k;
    if (n < 2 || rounds < 1 || rounds > MAX_ROUNDS || kind < 0) {
        fprintf(stderr, "usage: %s N ROUNDS [event|step|seed|chain] (N >= 2, 1 <= ROUNDS <= %d)\n",
                argv[0], MAX_ROUNDS);
        return 2;
    }
    void *a = A_ab_make(n, kind), *b = B_ab_make(n, kind);
    if (!a || !b) {
        fprintf(stderr, "%s: could not create the systems\n", argv[0]);
        return 1;
    }
    static double na[MAX_ROUNDS], nb[MAX_ROUNDS], ratio[MAX_ROUNDS];
    for (int r = 0; r < rounds; ++r) {
        if (r % 2) {
            nb[r] = B_ab_round(b, n, kind);
            na[r] = A_ab_round(a, n, kind);
        } else {
            na[r] = A_ab_round(a, n, kind);
            nb[r] = B_ab_round(b, n, kind);
        }
        ratio[r] = nb[r] / na[r];
    }
    qsort(na, (size_t)rounds, sizeof *na, compare);
    qsort(nb, (size_t)rounds, sizeof *nb, compare);
    qsort(ratio, (size_t)rounds, sizeof *ratio, compare);
    printf("%s, N = %zu, %d rounds: A %.1f ns per %s, B %.1f (medians); B / A %.3f "
           "(quartiles %.3f, %.3f)\n",
           kinds[kind], kind == 2 ? (size_t)400 : n, rounds, na[rounds / 2],
           kind == 3 ? "lifting"
           : kind    ? "disk-step"
                     : "collision",
           nb[rounds / 2], ratio[rounds / 2], ratio[rounds / 4], ratio[(3 * rounds) / 4]);
    A_ab_done(a);
    B_ab_done(b);
    return 0;
}
#endif
