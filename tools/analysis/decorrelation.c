/* SPDX-License-Identifier: MIT */
/* Decorrelation per CPU second (docs/performance.md, "Decorrelation per
 * CPU second"): how much CPU time an algorithm needs to forget the global
 * bond order and the pressure of dense hard disks. Public API only.
 *
 *   tools/decorrelation ALGO ETA N CPU_SECONDS [SAMPLE [RELAX [RATE]]]
 *
 * ALGO is edmd (event-driven dynamics), andersen (the same with
 * Andersen's heat bath of RATE collisions per disk per time unit, 0: the
 * library's default 0.1 sqrt(kT) / sigma) or ecmc (straight event
 * chains, the default length). N disks at area fraction ETA in the
 * periodic box 1000 x 866.0254 (aspect sqrt(3)/2, which a triangular
 * lattice of m x m disks fills), started on the lattice, run RELAX CPU
 * seconds (default a fifth of CPU_SECONDS) to relax, then sampled every
 * SAMPLE time units (default 1) until CPU_SECONDS of sampling have run.
 * CPU seconds are the process's (CLOCK_PROCESS_CPUTIME_ID), which other
 * jobs on a shared machine do not inflate; measuring psi6 is left out of
 * them.
 *
 * At each sample: the global psi6 = (1/N) sum_j psi6_j (ds_psi6_local,
 * cutoff 1.4 d), and Z measured over the interval since the last sample
 * (the observables reset at each sample). Their integrated
 * autocorrelation times (Sokal's automatic window, c = 6), in samples,
 * become CPU seconds with the CPU time per sample. Prints one line:
 *   algo eta n samples cpu_per_sample
 *   tau_abs_psi6 err  tau_re_psi6 err  tau_z err  (all in CPU seconds)
 *   mean|psi6| meanZ  run/tau_abs run/tau_re run/tau_z
 * and, with DS_DECORRELATION_SERIES=FILE in the environment, the series
 * (time, cpu seconds, |psi6|, re, im, Z) into FILE. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "analysis_util.h"
#include "disk_sim.h"

#define PI 3.14159265358979323846
#define BOX_Y 866.0254037844386 /* 1000 sqrt(3) / 2 */
#define WINDOW_C 6.0            /* Sokal's c: the window W is the first lag >= c tau */

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void check(ds_status s, const ds_error *err)
{
    if (s != DS_OK) {
        fprintf(stderr, "decorrelation: %s (%s)\n", ds_status_name(s), err ? err->message : "");
        exit(1);
    }
}

/* Sokal's integrated autocorrelation time of series x (count samples),
 * in samples, with the automatic window: tau = 1/2 + sum_{t=1}^{W}
 * rho(t), W the first lag with W >= c tau(W). Its statistical error,
 * Sokal's estimate for a long series, tau sqrt(2 (2W + 1) / count). */
static double tau_int(const double *x, size_t count, double *error)
{
    double m = 0.0;
    for (size_t t = 0; t < count; ++t)
        m += x[t];
    m /= (double)count;
    double c0 = 0.0;
    for (size_t t = 0; t < count; ++t)
        c0 += (x[t] - m) * (x[t] - m);
    c0 /= (double)count;
    double tau = 0.5;
    size_t lag = 1;
    for (; lag < count / 2; ++lag) {
        double c = 0.0;
        for (size_t t = 0; t + lag < count; ++t)
            c += (x[t] - m) * (x[t + lag] - m);
        tau += c / (double)count / c0;
        if ((double)lag >= WINDOW_C * tau)
            break;
    }
    *error = tau * sqrt(2.0 * (2.0 * (double)lag + 1.0) / (double)count);
    return tau;
}

int main(int argc, char **argv)
{
    const char *me = "decorrelation";
    if (argc < 5 || argc > 8) {
        fprintf(stderr, "usage: decorrelation edmd|andersen|ecmc ETA N CPU_SECONDS [SAMPLE [RELAX "
                        "[RATE]]]\n");
        return 2;
    }
    const char *algo = argv[1];
    const int chain = !strcmp(algo, "ecmc"), bath = !strcmp(algo, "andersen");
    if (!chain && !bath && strcmp(algo, "edmd")) {
        fprintf(stderr, "decorrelation: ALGO must be edmd, andersen or ecmc, got '%s'\n", algo);
        return 2;
    }
    const double eta = tool_number(me, argv[2], 0.01, 0.9, "ETA");
    const size_t n = (size_t)tool_number(me, argv[3], 16, 1e7, "N");
    const double budget = tool_number(me, argv[4], 1, 1e6, "CPU_SECONDS");
    const double sample = argc > 5 ? tool_number(me, argv[5], 0.001, 1e4, "SAMPLE") : 1.0;
    const double relax = argc > 6 ? tool_number(me, argv[6], 0, 1e6, "RELAX") : budget / 5.0;
    const double rate = argc > 7 ? tool_number(me, argv[7], 0, 1e6, "RATE") : 0.0;

    ds_params p = ds_params_default(n, sqrt(eta * 1000.0 * BOX_Y / ((double)n * PI)));
    p.box_y = BOX_Y;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.placement = DS_PLACEMENT_LATTICE;
    p.integrator = chain ? DS_INTEGRATOR_EVENT_CHAIN : DS_INTEGRATOR_EVENT_DRIVEN;
    p.dt = 0.001; /* a sample is SAMPLE / dt steps */
    ds_error err = {0};
    ds_sim *sim = NULL;
    check(ds_sim_create(&p, NULL, &sim, &err), &err);
    if (bath)
        check(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ANDERSEN, 0.0, rate, &err), &err);
    const uint64_t steps = (uint64_t)llround(sample / p.dt);
    if (steps < 1) {
        fprintf(stderr, "decorrelation: SAMPLE %g is shorter than dt %g\n", sample, p.dt);
        return 2;
    }

    const double relax_start = cpu_seconds();
    while (cpu_seconds() - relax_start < relax)
        check(ds_sim_run(sim, steps, &err), &err);

    size_t cap = 4096, count = 0;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    double *re = malloc(n * sizeof *re), *im = malloc(n * sizeof *im);
    ds_disk *d = malloc(n * sizeof *d);
    double *sa = malloc(cap * sizeof *sa), *sr = malloc(cap * sizeof *sr);
    double *si = malloc(cap * sizeof *si), *sz = malloc(cap * sizeof *sz);
    double *sc = malloc(cap * sizeof *sc);
    if (!x || !y || !re || !im || !d || !sa || !sr || !si || !sz || !sc)
        return 1;
    const double cutoff = 1.4 * 2.0 * p.radius;
    double spent = 0.0;
    while (spent < budget) {
        ds_sim_reset_observables(sim);
        const double t0 = cpu_seconds();
        check(ds_sim_run(sim, steps, &err), &err);
        spent += cpu_seconds() - t0;
        if (count == cap) {
            cap *= 2;
            double **arrays[] = {&sa, &sr, &si, &sz, &sc};
            for (size_t k = 0; k < 5; ++k) {
                double *grown = realloc(*arrays[k], cap * sizeof **arrays[k]);
                if (!grown)
                    return 1;
                *arrays[k] = grown;
            }
        }
        sz[count] = ds_sim_get_compressibility_factor(sim);
        check(ds_sim_get_disks(sim, d, &err), &err);
        for (size_t k = 0; k < n; ++k) {
            x[k] = d[k].x;
            y[k] = d[k].y;
        }
        check(ds_psi6_local(n, x, y, 1000.0, BOX_Y, DS_BOUNDARY_PERIODIC, cutoff, re, im, &err),
              &err);
        double r = 0.0, i = 0.0;
        for (size_t k = 0; k < n; ++k) {
            r += re[k];
            i += im[k];
        }
        sr[count] = r / (double)n;
        si[count] = i / (double)n;
        sa[count] = hypot(sr[count], si[count]);
        sc[count] = spent;
        ++count;
    }
    if (count < 64) {
        fprintf(stderr, "decorrelation: only %zu samples; give more CPU_SECONDS\n", count);
        return 1;
    }
    const char *series = getenv("DS_DECORRELATION_SERIES");
    if (series && *series) {
        FILE *f = fopen(series, "w");
        if (!f) {
            fprintf(stderr, "decorrelation: cannot write %s\n", series);
            return 1;
        }
        fprintf(f, "# time cpu_seconds abs_psi6 re_psi6 im_psi6 Z\n");
        for (size_t k = 0; k < count; ++k)
            fprintf(f, "%.6g %.6g %.6f %.6f %.6f %.6f\n", (double)(k + 1) * sample, sc[k], sa[k],
                    sr[k], si[k], sz[k]);
        fclose(f);
    }
    const double per = spent / (double)count;
    double ea, er, ez;
    const double ta = tau_int(sa, count, &ea), tr = tau_int(sr, count, &er),
                 tz = tau_int(sz, count, &ez);
    double ma = 0.0, mz = 0.0;
    for (size_t k = 0; k < count; ++k) {
        ma += sa[k];
        mz += sz[k];
    }
    const double c = (double)count;
    printf("%s %.2f %zu %zu %.4g  %.4g %.2g  %.4g %.2g  %.4g %.2g  %.4f %.4f  %.0f %.0f %.0f\n",
           algo, eta, n, count, per, ta * per, ea * per, tr * per, er * per, tz * per, ez * per,
           ma / c, mz / c, c / ta, c / tr, c / tz);
    free(x);
    free(y);
    free(re);
    free(im);
    free(d);
    free(sa);
    free(sr);
    free(si);
    free(sz);
    free(sc);
    ds_sim_destroy(sim);
    return 0;
}
