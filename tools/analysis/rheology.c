/* SPDX-License-Identifier: MIT */
/* rheology: the shear viscosity of hard disks from a steady shear flow
 * (Lees-Edwards boundaries, ds_sim_set_shear), the other way to the
 * Helfand moments of tools/transport. Public API only.
 *
 *   rheology N ETA RATE [--lattice] [--relax T] [--blocks B] [--block T]
 *            [--interval H] [--bins K] [--kt KT] [--seed S]
 *
 * The N disks cover the area fraction ETA of the periodic 1000 x 1000
 * box, event-driven, sheared at RATE = dv_x/dy, the isokinetic thermostat
 * holding the peculiar temperature at KT (default 5000: speed 100 at unit
 * mass). Times default to multiples of t_E, Enskog's mean free time at
 * Henderson's Z (as tools/transport): relaxation 200 t_E (1000 t_E from a
 * lattice, --lattice) under the shear, then B blocks (default 20) of T
 * time units (default 100 t_E), the disks looked at every H (default 0.1
 * t_E). At each look:
 *   - the apparent viscosity -P_xy / RATE, P_xy the change of the stress
 *     integral's xy component (ds_sim_get_stress_integral: kinetic part
 *     of the peculiar velocities, collisions' part exact) over A = W H and
 *     the time between looks;
 *   - the velocity profile: the mean v_x in K (default 10) bins of y, and
 *     its least-squares slope at each look.
 * The means are over every look, their errors the standard errors
 * corrected for the correlation between looks (Flyvbjerg and Petersen's
 * blocking, analysis_util.h): the box's slowest shear mode relaxes in
 * H^2 / (4 pi^2 nu), nu the kinematic viscosity, which can pass a block.
 * Prints '#' lines with the system, the measured mean free time t_c, the
 * reduced rate RATE t_c and Enskog's viscosity (Gass 1971) at the
 * measured Z, the profile (y, mean v_x and its error per bin), then one
 * line:
 *   eta N rate viscosity error temperature slope slope_error reduced_rate eta_enskog
 * the last two the rate times the measured mean free time t_c and
 * Enskog's viscosity. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "analysis_util.h"
#include "disk_sim.h"

#define PI 3.14159265358979323846

static const char usage_text[] =
    "usage: rheology N ETA RATE [--lattice] [--relax T] [--blocks B] [--block T]\n"
    "                [--interval H] [--bins K] [--kt KT] [--seed S]\n"
    "The shear viscosity of N disks covering the area fraction ETA of the\n"
    "periodic 1000 x 1000 box, event-driven, sheared at RATE (dv_x/dy) with\n"
    "Lees-Edwards boundaries and the isokinetic thermostat. Times default to\n"
    "multiples of t_E, Enskog's mean free time at Henderson's Z. Prints one line:\n"
    "  eta N rate viscosity error temperature slope slope_error reduced_rate eta_enskog\n"
    "  --lattice       start on a triangular lattice (random placement stops\n"
    "                  near area fraction 0.54)\n"
    "  --relax T       time units sheared before measuring (default 200 t_E,\n"
    "                  1000 t_E from a lattice)\n"
    "  --blocks B      number of blocks (default 20)\n"
    "  --block T       time units per block (default 100 t_E)\n"
    "  --interval H    time between looks at the profile, the time step (default 0.1 t_E)\n"
    "  --bins K        bins of y for the velocity profile (default 10)\n"
    "  --kt KT         the thermostat's temperature (default 5000: speed 100, unit mass)\n"
    "  --seed S        seed (default 20260101)\n"
    "  --help          show this help and exit\n"
    "exit status: 0 success, 1 parameters the library refuses, 2 usage error\n";

static void usage(void)
{
    fputs(usage_text, stderr);
    exit(2);
}

static double number(const char *s, double lo, double hi, const char *what)
{
    return tool_number("rheology", s, lo, hi, what);
}

/* A refusal of the library, printed, and exit status 1. */
static void check(ds_status st, const ds_error *why, const char *what)
{
    if (st == DS_OK)
        return;
    fprintf(stderr, "rheology: %s: %s\n", what, why->message);
    exit(1);
}

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--help") == 0) {
            fputs(usage_text, stdout);
            return 0;
        }
    if (argc < 4)
        usage();
    const size_t n = (size_t)number(argv[1], 2, 1e8, "N");
    const double eta = number(argv[2], 1e-6, 0.9, "ETA");
    const double rate = number(argv[3], -1e9, 1e9, "RATE");
    if (rate == 0.0) {
        fputs("rheology: RATE must not be 0 (the viscosity is -P_xy / RATE)\n", stderr);
        return 2;
    }
    ds_params p = ds_params_default(n, 1.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.box = 1000.0;
    p.radius = sqrt(eta * p.box * p.box / ((double)n * PI));
    p.seed = 20260101;
    /* The defaults' clock, as tools/transport's: Enskog's collision rate
     * at Henderson's Z, (1 + eta^2 / 8) / (1 - eta)^2, at kT = 5000. */
    const double z_guess = (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
    double kt = 5000.0;
    int blocks = 20, relax_given = 0;
    size_t bins = 10;
    double relax = -1.0, block = -1.0, interval = -1.0;
    for (int i = 4; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--lattice") == 0) {
            p.placement = DS_PLACEMENT_LATTICE;
            continue;
        }
        if (!v)
            usage();
        ++i;
        if (strcmp(a, "--relax") == 0) {
            relax = number(v, 0.0, 1e9, "--relax");
            relax_given = 1;
        } else if (strcmp(a, "--blocks") == 0)
            blocks = (int)number(v, 2, 100000, "--blocks");
        else if (strcmp(a, "--block") == 0)
            block = number(v, 1e-9, 1e9, "--block");
        else if (strcmp(a, "--interval") == 0)
            interval = number(v, 1e-9, 1e6, "--interval");
        else if (strcmp(a, "--bins") == 0)
            bins = (size_t)number(v, 2, 10000, "--bins");
        else if (strcmp(a, "--kt") == 0)
            kt = number(v, 1e-12, 1e18, "--kt");
        else if (strcmp(a, "--seed") == 0)
            p.seed = (uint64_t)number(v, 0, 9007199254740992.0, "--seed");
        else
            usage();
    }
    const double t_guess = 1.0 / (2.0 / p.radius * (z_guess - 1.0) * sqrt(kt / PI));
    if (!relax_given)
        relax = (p.placement == DS_PLACEMENT_LATTICE ? 1000.0 : 200.0) * t_guess;
    if (block < 0.0)
        block = 100.0 * t_guess;
    if (interval < 0.0)
        interval = 0.1 * t_guess;
    const uint64_t per_block = (uint64_t)llround(block / interval);
    if (per_block < 1) {
        fputs("rheology: --block must be at least one --interval\n", stderr);
        return 2;
    }
    p.dt = interval;
    p.speed = sqrt(2.0 * kt); /* unit mass: kT = v^2 / 2 */
    ds_sim *sim = NULL;
    ds_error why;
    check(ds_sim_create(&p, NULL, &sim, &why), &why, "the system");
    check(ds_sim_set_shear(sim, rate, &why), &why, "the shear");
    check(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ISOKINETIC, kt, 0.0, &why), &why,
          "the thermostat");
    const double t0 = ds_timer_now();
    check(ds_sim_run(sim, (uint64_t)llround(relax / interval), &why), &why, "the relaxation");
    ds_sim_reset_observables(sim);
    const uint64_t collisions0 = ds_sim_get_collision_count(sim);
    const double time0 = ds_sim_get_time(sim);
    const double width = ds_sim_get_box_width(sim), height = ds_sim_get_box_height(sim);
    const double area = width * height;
    ds_disk *d = malloc(n * sizeof *d);
    double *sum = malloc(bins * sizeof *sum), *count = malloc(bins * sizeof *count);
    stats *profile = calloc(bins, sizeof *profile);
    if (!d || !sum || !count || !profile) {
        fputs("rheology: out of memory\n", stderr);
        return 1;
    }
    /* One viscosity and one slope per look (the stress integral's change
     * over the interval, the profile of the one configuration): their
     * means are the blocks' means, and their errors are corrected for
     * the correlation (analysis_util.h's blocked_mean), which the slow
     * shear modes of the box carry past a block's length. */
    const size_t looks = (size_t)blocks * per_block;
    double *visc = malloc(looks * sizeof *visc), *slopes = malloc(looks * sizeof *slopes);
    double *here = malloc(2 * bins * sizeof *here); /* a look's own bins, for its slope */
    if (!visc || !slopes || !here) {
        fputs("rheology: out of memory for the samples\n", stderr);
        return 1;
    }
    stats temperature = {0, 0, 0}, z = {0, 0, 0};
    size_t look = 0;
    double s0[3];
    ds_sim_get_stress_integral(sim, s0, NULL);
    for (int b = 0; b < blocks; ++b) {
        ds_sim_reset_observables(sim);
        for (size_t k = 0; k < bins; ++k)
            sum[k] = count[k] = 0.0;
        for (uint64_t s = 0; s < per_block; ++s, ++look) {
            const double start = ds_sim_get_time(sim);
            check(ds_sim_step(sim, &why), &why, "the run");
            double s1[3];
            ds_sim_get_stress_integral(sim, s1, NULL);
            visc[look] = -(s1[2] - s0[2]) / (area * (ds_sim_get_time(sim) - start) * rate);
            s0[0] = s1[0], s0[1] = s1[1], s0[2] = s1[2];
            ds_sim_get_disks(sim, d, NULL);
            for (size_t k = 0; k < 2 * bins; ++k)
                here[k] = 0.0;
            for (size_t i = 0; i < n; ++i) {
                size_t k = (size_t)(d[i].y / height * (double)bins);
                k = k < bins ? k : bins - 1;
                sum[k] += d[i].vx;
                count[k] += 1.0;
                here[2 * k] += d[i].vx;
                here[2 * k + 1] += 1.0;
            }
            double sy = 0.0, syy = 0.0, su = 0.0, syu = 0.0, m = 0.0;
            for (size_t f = 0; f < bins; ++f) {
                if (here[2 * f + 1] == 0.0)
                    continue;
                const double y = ((double)f + 0.5) * height / (double)bins;
                const double u = here[2 * f] / here[2 * f + 1];
                sy += y;
                syy += y * y;
                su += u;
                syu += y * u;
                m += 1.0;
            }
            slopes[look] = (m * syu - sy * su) / (m * syy - sy * sy);
        }
        add(&temperature, ds_sim_get_temperature(sim));
        add(&z, ds_sim_get_compressibility_factor(sim));
        for (size_t k = 0; k < bins; ++k)
            if (count[k] > 0.0)
                add(&profile[k], sum[k] / count[k]);
    }
    double visc_error, slope_error;
    const double visc_mean = blocked_mean(visc, looks, &visc_error);
    const double slope_mean = blocked_mean(slopes, looks, &slope_error);
    free(visc);
    free(slopes);
    free(here);
    const double nu = 2.0 * (double)(ds_sim_get_collision_count(sim) - collisions0) /
                      ((double)n * (ds_sim_get_time(sim) - time0));
    const double sigma = 2.0 * p.radius, g = (mean(&z) - 1.0) / (2.0 * eta);
    const double eta_e = tool_enskog_viscosity(mean(&temperature), sigma, eta, g);
    printf("# rheology: N %zu eta %.6g periodic event sheared, isokinetic kT %.9g, seed %llu, "
           "%d blocks of %llu steps of %.6g\n",
           n, eta, kt, (unsigned long long)p.seed, blocks, (unsigned long long)per_block, interval);
    printf("# Z %.6f +- %.6f g(sigma) %.6f nu %.6g t_c %.6g rate*t_c %.6g\n", mean(&z), error(&z),
           g, nu, 1.0 / nu, rate / nu);
    printf("# eta_E %.6g (Enskog, Gass 1971, at the measured Z) viscosity/eta_E %.5f +- %.5f\n",
           eta_e, visc_mean / eta_e, visc_error / eta_e);
    printf("# %llu collisions, %.1f s\n",
           (unsigned long long)(ds_sim_get_collision_count(sim) - collisions0),
           ds_timer_now() - t0);
    printf("# y mean_vx error (the profile, rate (y - H/2) expected)\n");
    for (size_t k = 0; k < bins; ++k)
        printf("# %.6g %.6g %.3g\n", ((double)k + 0.5) * height / (double)bins, mean(&profile[k]),
               error(&profile[k]));
    printf("# eta N rate viscosity error temperature slope slope_error reduced_rate eta_enskog\n");
    printf("%.6g %zu %.9g %.9g %.3g %.9g %.9g %.3g %.6g %.6g\n", eta, n, rate, visc_mean,
           visc_error, mean(&temperature), slope_mean, slope_error, rate / nu, eta_e);
    free(d);
    free(sum);
    free(count);
    free(profile);
    ds_sim_destroy(sim);
    return 0;
}
