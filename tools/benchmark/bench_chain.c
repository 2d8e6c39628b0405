/* SPDX-License-Identifier: MIT */
/* Section 6 of tools/bench: event-chain Monte Carlo. Public API only.
 *
 * Events per CPU second at area fraction 0.70 in the periodic square box,
 * N = 1024 and 10^5, from the lattice, with the default chain length
 * (a quarter of the box's side, 250). An event is what the literature
 * counts (Bernard, Krauth and Wilson 2009; docs/performance.md): a
 * lifting, where the chain passes from one disk to the one it touches
 * (ds_sim_get_collision_count), and a chain's end, where the next chain
 * starts at a disk drawn afresh. Chain ends are not counted by the
 * library: a step carries N speed dt of displacement, so they are that
 * over the chain length (about 1% of the events at N = 1024, 0.1% at
 * 10^5). Cell crossings are bookkeeping, not events. Each system is
 * created and relaxed once, for ~10 liftings per disk, then timed in
 * every round over ~5 x 10^6 liftings; time is the process's CPU time
 * (CLOCK_PROCESS_CPUTIME_ID), which other jobs on a shared machine do not
 * inflate as they do the wall clock. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "bench.h"
#include "disk_sim.h"

#define PI 3.14159265358979323846
#define FRACTION 0.70
#define CHAIN_LENGTH 250.0 /* DS_CHAIN_LENGTH_OF_BOX times the side, 1000 */

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Liftings per step of dt = 0.001 at area fraction 0.70: ~40 per disk per
 * time unit at N = 1024 (docs/physics.md), growing as 1 / R, sqrt(N). */
static double liftings_per_step(size_t n) { return 0.04 * (double)n * sqrt((double)n / 1024.0); }

static ds_sim *chains(size_t n)
{
    ds_params p = ds_params_default(n, sqrt(FRACTION * 1e6 / ((double)n * PI)));
    p.integrator = DS_INTEGRATOR_EVENT_CHAIN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.placement = DS_PLACEMENT_LATTICE;
    ds_sim *sim = NULL;
    ds_error err;
    if (ds_sim_create(&p, NULL, &sim, &err) != DS_OK) {
        fprintf(stderr, "bench: ds_sim_create(N = %zu, chain): %s\n", n, err.message);
        return NULL;
    }
    ds_sim_run(sim, (uint64_t)ceil(10.0 * (double)n / liftings_per_step(n)), NULL);
    return sim;
}

/* ns of CPU time per event over ~5 x 10^6 liftings; *ends the share of
 * chain ends among the events. */
static double ns_per_event(ds_sim *sim, double *ends)
{
    const size_t n = ds_sim_get_count(sim);
    const uint64_t steps = (uint64_t)ceil(5e6 / liftings_per_step(n));
    const uint64_t l0 = ds_sim_get_collision_count(sim);
    const double t0 = cpu_now();
    ds_sim_run(sim, steps, NULL);
    const double seconds = cpu_now() - t0;
    const double lifts = (double)(ds_sim_get_collision_count(sim) - l0);
    const double chain_ends = (double)steps * (double)n * 100.0 * 0.001 / CHAIN_LENGTH;
    *ends = chain_ends / (lifts + chain_ends);
    return 1e9 * seconds / (lifts + chain_ends);
}

int bench_chain(void)
{
    static const size_t sizes[] = {1024, 100000};
    enum { SIZES = sizeof sizes / sizeof sizes[0] };
    double ns[SIZES][ROUNDS], ends[SIZES] = {0.0};
    ds_sim *sims[SIZES] = {NULL};
    int ok = 1;
    for (int c = 0; ok && c < SIZES; ++c)
        ok = (sims[c] = chains(sizes[c])) != NULL;
    for (int k = 0; ok && k < ROUNDS; ++k)
        for (int c = 0; c < SIZES; ++c)
            ns[c][k] = ns_per_event(sims[c], &ends[c]);
    for (int c = 0; c < SIZES; ++c)
        ds_sim_destroy(sims[c]);
    if (!ok)
        return 0;
    printf("\n6. Event-chain Monte Carlo, area fraction 0.70, periodic, from the lattice, chains\n"
           "   of length 250: ~5 x 10^6 events per case; an event is a lifting or a chain's\n"
           "   end; ns of CPU time per event\n");
    const double scaling = median_ratio(ns[1], ns[0]);
    printf("%8s %8s %12s %14s %12s\n", "N", "R", "ns/event", "events/s", "chain ends");
    double m[SIZES];
    for (int c = 0; c < SIZES; ++c) {
        m[c] = median(ns[c], ROUNDS);
        printf("%8zu %8.4f %12.1f %14.3g %11.2f%%\n", sizes[c],
               sqrt(FRACTION * 1e6 / ((double)sizes[c] * PI)), m[c], 1e9 / m[c], 100.0 * ends[c]);
    }
    printf("   events/s at N = 1024: %.3g (target >= 1e7)\n", 1e9 / m[0]);
    printf("   ns/event, N = 10^5 / N = 1024: %.2f\n", scaling);
    fflush(stdout);
    return 1;
}

int bench_chain_one(unsigned long n)
{
    ds_sim *sim = n >= 2 ? chains(n) : NULL;
    if (!sim)
        return 0;
    double ends, ns[ROUNDS];
    for (int k = 0; k < ROUNDS; ++k)
        ns[k] = ns_per_event(sim, &ends);
    ds_sim_destroy(sim);
    const double m = median(ns, ROUNDS);
    printf("N = %lu, area fraction 0.70, periodic, event chains: %.1f ns of CPU per event, %.3g "
           "events/s (median of %d), chain ends %.2f%% of events\n",
           n, m, 1e9 / m, ROUNDS, 100.0 * ends);
    return 1;
}
