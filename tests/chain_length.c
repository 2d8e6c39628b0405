/* SPDX-License-Identifier: MIT */
/* The measurement behind the event chains' default length
 * (DS_CHAIN_LENGTH_OF_BOX, src/chain/chain.h; docs/physics.md, "Event-chain
 * Monte Carlo"): how fast chains of several lengths decorrelate the
 * slowest thing a dense liquid of hard disks does, the orientation of its
 * bond order, and what a time unit costs. Not a test (it asserts
 * nothing); a program of tests/ because it sets the chain length, which
 * the public API does not offer.
 *
 *   make build/tests/chain_length
 *   build/tests/chain_length N UNITS [SEEDS [FRACTION...]]
 *
 * N disks at area fraction 0.70 in the periodic 1000 x 1000 box, from
 * the lattice, relaxed 200 time units with the default chains; then for
 * each FRACTION (default 0.05 0.1 0.25 0.5 1 2 4) the same state runs
 * UNITS time units with chains FRACTION times the square root of the
 * box's area long, the global psi6 = (1/N) sum_j psi6_j (complex,
 * ds_psi6_local) sampled every time unit. Its integrated autocorrelation
 * time tau (Sokal's window: the sum of the normalised autocorrelation up
 * to the first lag W >= 5 tau) says how many time units make an
 * independent sample; every time unit carries the same chain
 * displacement, N speed, whatever the length, so tau compares the
 * lengths at equal work (the seconds per unit say so: CPU seconds of the
 * process, clock(), which a shared machine's other work does not inflate
 * as it does the wall clock). With several seeds
 * each has its own start, and the line gives the mean over seeds and its
 * standard error. The same for Z, measured over each time unit (the
 * observables reset at its start): the pressure relaxes faster than the
 * order, and a chain length could favour one over the other. A FRACTION
 * of 0 runs the event-driven dynamics instead, from the same start, for
 * comparison.
 *
 * Prints one line per fraction:
 *   fraction  tau_psi6 +- error  Z  seconds-per-unit  liftings-per-disk-per-unit
 *   tau_Z +- error */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "chain/chain.h"
#include "disk_sim.h"

#define PI 3.14159265358979323846

/* The global complex psi6 of sim's disks. */
static void global_psi6(const ds_sim *sim, double *x, double *y, double *re, double *im,
                        double *out_re, double *out_im)
{
    const size_t n = ds_sim_get_count(sim);
    ds_disk *d = malloc(n * sizeof *d);
    if (!d || ds_sim_get_disks(sim, d, NULL) != DS_OK)
        exit(1);
    for (size_t k = 0; k < n; ++k) {
        x[k] = d[k].x;
        y[k] = d[k].y;
    }
    free(d);
    const double cutoff = 1.4 * 2.0 * ds_sim_get_radius(sim);
    if (ds_psi6_local(n, x, y, ds_sim_get_box_width(sim), ds_sim_get_box_height(sim),
                      DS_BOUNDARY_PERIODIC, cutoff, re, im, NULL) != DS_OK)
        exit(1);
    double sr = 0.0, si = 0.0;
    for (size_t k = 0; k < n; ++k) {
        sr += re[k];
        si += im[k];
    }
    *out_re = sr / (double)n;
    *out_im = si / (double)n;
}

/* Sokal's integrated autocorrelation time of the complex series (its
 * mean taken out), in samples; im NULL for a real series. */
static double tau_of(const double *re, const double *im, int count)
{
    double mr = 0.0, mi = 0.0;
    for (int t = 0; t < count; ++t) {
        mr += re[t];
        mi += im ? im[t] : 0.0;
    }
    mr /= count;
    mi /= count;
    double c0 = 0.0;
    for (int t = 0; t < count; ++t)
        c0 += (re[t] - mr) * (re[t] - mr) + (im ? (im[t] - mi) * (im[t] - mi) : 0.0);
    c0 /= count;
    double tau = 0.5;
    for (int lag = 1; lag < count / 2; ++lag) {
        double c = 0.0;
        for (int t = 0; t + lag < count; ++t)
            c += (re[t] - mr) * (re[t + lag] - mr) + (im ? (im[t] - mi) * (im[t + lag] - mi) : 0.0);
        tau += c / (count - lag) / c0;
        if (lag >= 5.0 * tau)
            break;
    }
    return tau;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: chain_length N UNITS [SEEDS [FRACTION...]]\n");
        return 2;
    }
    const size_t n = (size_t)atol(argv[1]);
    const int units = atoi(argv[2]), seeds = argc > 3 ? atoi(argv[3]) : 1;
    static const double fallback[] = {0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0};
    const int given = argc > 4 ? argc - 4 : (int)(sizeof fallback / sizeof fallback[0]);
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    double *re = malloc(n * sizeof *re), *im = malloc(n * sizeof *im);
    double *sr = malloc((size_t)units * sizeof *sr), *si = malloc((size_t)units * sizeof *si);
    double *zs = malloc((size_t)units * sizeof *zs);
    if (!x || !y || !re || !im || !sr || !si || !zs || n < 2 || units < 100 || seeds < 1)
        return 2;
    for (int f = 0; f < given; ++f) {
        const double fraction = argc > 4 ? atof(argv[4 + f]) : fallback[f];
        double tau_sum = 0.0, tau_sum2 = 0.0, z_sum = 0.0, seconds = 0.0, lifts = 0.0;
        double tz_sum = 0.0, tz_sum2 = 0.0;
        for (int s = 0; s < seeds; ++s) {
            ds_params p = ds_params_default(n, sqrt(0.70 * 1e6 / ((double)n * PI)));
            p.boundary = DS_BOUNDARY_PERIODIC;
            p.placement = DS_PLACEMENT_LATTICE;
            p.integrator = fraction > 0.0 ? DS_INTEGRATOR_EVENT_CHAIN : DS_INTEGRATOR_EVENT_DRIVEN;
            p.seed = 1000 + (uint64_t)s;
            ds_sim *sim = NULL;
            if (ds_sim_create(&p, NULL, &sim, NULL) != DS_OK)
                return 1;
            const uint64_t unit = 1000; /* steps of dt = 0.001 */
            ds_sim_run(sim, 200 * unit, NULL);
            if (fraction > 0.0)
                ds_chain_set_length(sim, fraction * 1000.0);
            const uint64_t before = ds_sim_get_collision_count(sim);
            clock_t t0 = clock();
            double z_mean = 0.0;
            for (int t = 0; t < units; ++t) {
                ds_sim_reset_observables(sim);
                ds_sim_run(sim, unit, NULL);
                zs[t] = ds_sim_get_compressibility_factor(sim);
                z_mean += zs[t] / units;
                /* psi6 is the measurement's, not the sampler's: its time is
                 * left out of the seconds per unit. */
                seconds += (double)(clock() - t0) / CLOCKS_PER_SEC;
                global_psi6(sim, x, y, re, im, &sr[t], &si[t]);
                t0 = clock();
            }
            lifts += (double)(ds_sim_get_collision_count(sim) - before);
            z_sum += z_mean;
            const double tau = tau_of(sr, si, units), tau_z = tau_of(zs, NULL, units);
            tau_sum += tau;
            tau_sum2 += tau * tau;
            tz_sum += tau_z;
            tz_sum2 += tau_z * tau_z;
            ds_sim_destroy(sim);
        }
        const double tau = tau_sum / seeds;
        const double error =
            seeds > 1 ? sqrt(fmax(tau_sum2 / seeds - tau * tau, 0.0) / (seeds - 1)) : NAN;
        const double tz = tz_sum / seeds;
        const double tz_error =
            seeds > 1 ? sqrt(fmax(tz_sum2 / seeds - tz * tz, 0.0) / (seeds - 1)) : NAN;
        printf("%g %.2f %.2f %.4f %.3g %.2f %.2f %.2f\n", fraction, tau, error, z_sum / seeds,
               seconds / ((double)seeds * units), lifts / ((double)seeds * units * (double)n), tz,
               tz_error);
        fflush(stdout);
    }
    return 0;
}
