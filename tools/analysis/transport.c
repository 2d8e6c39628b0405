/* SPDX-License-Identifier: MIT */
/* transport: self-diffusion and shear viscosity of hard disks in a
 * periodic box, with the mean-squared displacement, the velocity
 * autocorrelation and the Helfand moment of the stress against time, and
 * the Enskog values to compare with. Public API only (ds_transport,
 * ds_sim_get_stress_integral).
 *
 *   transport N ETA [--lattice] [--relax T] [--interval H] [--lags L]
 *             [--every E] [--blocks B] [--block T] [--window A:B] [--seed S]
 *
 * The N disks cover the area fraction ETA of the periodic 1000 x 1000 box,
 * event-driven. Times default to multiples of the Enskog mean free time
 * t_E = 1 / nu_E, nu_E = (4 / sigma) (Z - 1) sqrt(kT / (pi m)) the
 * collisions per disk per unit time at the Z of Henderson's equation of
 * state (only to choose the defaults; what is printed is measured):
 * relaxation 50 t_E (1000 t_E from a lattice, --lattice, which dense
 * systems need: random placement stops near area fraction 0.54), interval 0.1 t_E, 400 lags (to 40
 * t_E), an origin every 5 samples, 10 blocks each 10 times the longest lag. Each block has its own
 * accumulator; a curve is the mean over the blocks and its error the standard error of that mean.
 *
 * Prints '#' lines with the system and its Enskog values,
 *   D_0 = (1 / (2 n sigma)) sqrt(kT / (pi m))   (Gass 1971),
 *   D_E = D_0 / g(sigma),  g(sigma) = (Z - 1) / (2 eta),
 * with Z measured (ds_sim_get_compressibility_factor) and kT = ds_sim_get_temperature, the
 * diffusion coefficient over the window of lags A:B (default 200:399)
 * from the Einstein slope and from Green-Kubo (ds_transport_get_diffusion),
 * the shear viscosity over the same window from the Helfand moments of
 * s_xy and (s_xx - s_yy) / 2 (ds_sim_get_stress_integral), slope / (2 A kT),
 * against Enskog's (Gass 1971, with his Sonine factor 1.022)
 *   eta_E = 1.022 eta_0 (1 / g + 2 eta + (1 + 8 / pi) eta^2 g),
 *   eta_0 = (1 / (2 sigma)) sqrt(m kT / pi),
 * then one line per lag:
 *   t t/t_c msd error C/C0 error D(t) error eta(t) error
 * where t_c = 1 / nu is the measured mean free time, C/C0 the velocity
 * autocorrelation over its value at t = 0, D(t) = (1/2) int_0^t C and
 * eta(t) = <(s(t0 + t) - s(t0))^2> / (2 A kT t), the Helfand moment's
 * running estimate (the mean of the two shear components). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "analysis_util.h"
#include "disk_sim.h"

#define PI 3.14159265358979323846

static const char usage_text[] =
    "usage: transport N ETA [--lattice] [--relax T] [--interval H] [--lags L]\n"
    "                 [--every E] [--blocks B] [--block T] [--window A:B] [--seed S]\n"
    "Self-diffusion and shear viscosity of N disks covering the area fraction ETA\n"
    "of the periodic 1000 x 1000 box, event-driven, with the mean-squared\n"
    "displacement, velocity autocorrelation and Helfand moment per lag. Times\n"
    "default to multiples of t_E, Enskog's mean free time at Henderson's Z.\n"
    "  --lattice       start on a triangular lattice (random placement stops\n"
    "                  near area fraction 0.54)\n"
    "  --relax T       time units of relaxation (default 50 t_E, 1000 t_E from a lattice)\n"
    "  --interval H    time between samples (default 0.1 t_E)\n"
    "  --lags L        lags of the correlations, 0 to L - 1 samples (default 400)\n"
    "  --every E       a time origin every E samples (default 5)\n"
    "  --blocks B      number of blocks (default 10)\n"
    "  --block T       time units per block, at least L samples (default 10 L samples)\n"
    "  --window A:B    the lags over which D is measured (default L/2 : L - 1)\n"
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
    return tool_number("transport", s, lo, hi, what);
}

static void *checked_calloc(size_t n, size_t size)
{
    void *p = calloc(n, size);
    if (!p) {
        fputs("transport: out of memory\n", stderr);
        exit(1);
    }
    return p;
}

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--help") == 0) {
            fputs(usage_text, stdout);
            return 0;
        }
    if (argc < 3)
        usage();
    const size_t n = (size_t)number(argv[1], 2, 1e8, "N");
    const double eta = number(argv[2], 1e-6, 0.9, "ETA");
    ds_params p = ds_params_default(n, 1.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.box = 1000.0;
    p.radius = sqrt(eta * p.box * p.box / ((double)n * PI));
    /* The defaults' clock: the Enskog collision rate at Henderson's Z,
     * (1 + eta^2 / 8) / (1 - eta)^2, with kT / m = speed^2 / 2. */
    const double z_guess = (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
    const double speed = p.speed > 0.0 ? p.speed : 100.0; /* 0 means 100 */
    const double t_guess =
        1.0 / (2.0 / p.radius * (z_guess - 1.0) * sqrt(0.5 * speed * speed / PI));
    double relax = 50.0 * t_guess, interval = 0.1 * t_guess, block = 0.0;
    size_t lags = 400, every = 5, from = 0, to = 0;
    int blocks = 10, relax_given = 0; /* -1: --lattice's default relaxation */
    for (int i = 3; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--lattice") == 0) {
            p.placement = DS_PLACEMENT_LATTICE;
            relax_given = relax_given ? relax_given : -1;
            continue;
        }
        if (!v)
            usage();
        ++i;
        if (strcmp(a, "--relax") == 0) {
            relax = number(v, 0.0, 1e9, "--relax");
            relax_given = 1;
        } else if (strcmp(a, "--interval") == 0)
            interval = number(v, 1e-9, 1e6, "--interval");
        else if (strcmp(a, "--lags") == 0)
            lags = (size_t)number(v, 3, 1e6, "--lags");
        else if (strcmp(a, "--every") == 0)
            every = (size_t)number(v, 1, 1e6, "--every");
        else if (strcmp(a, "--blocks") == 0)
            blocks = (int)number(v, 2, 100000, "--blocks");
        else if (strcmp(a, "--block") == 0)
            block = number(v, 1e-9, 1e9, "--block");
        else if (strcmp(a, "--window") == 0) {
            char *colon = strchr(v, ':');
            if (!colon)
                usage();
            *colon = '\0';
            from = (size_t)number(v, 0, 1e6, "--window's A");
            to = (size_t)number(colon + 1, 1, 1e6, "--window's B");
        } else if (strcmp(a, "--seed") == 0)
            p.seed = (uint64_t)number(v, 0, 9007199254740992.0, "--seed");
        else
            usage();
    }
    if (relax_given == -1)
        relax = 1000.0 * t_guess;
    if (to == 0) {
        from = lags / 2;
        to = lags - 1;
    }
    if (from >= to || to >= lags) {
        fprintf(stderr, "transport: --window A:B needs A < B < %zu (the lags)\n", lags);
        return 2;
    }
    const uint64_t per_block = block > 0.0 ? (uint64_t)llround(block / interval) : 10 * lags;
    if (per_block < lags) {
        fprintf(stderr, "transport: a block of %llu samples is shorter than the %zu lags\n",
                (unsigned long long)per_block, lags);
        return 2;
    }
    p.dt = interval;
    ds_sim *sim = NULL;
    ds_error why;
    if (ds_sim_create(&p, NULL, &sim, &why) != DS_OK) {
        fprintf(stderr, "transport: N = %zu at area fraction %g: %s\n", n, eta, why.message);
        return 1;
    }
    const double t0 = ds_timer_now();
    ds_sim_run(sim, (uint64_t)llround(relax / interval), NULL);
    ds_sim_reset_observables(sim);
    const uint64_t collisions0 = ds_sim_get_collision_count(sim);
    const double time0 = ds_sim_get_time(sim);

    stats *msd = checked_calloc(lags, sizeof *msd), *vacf = checked_calloc(lags, sizeof *vacf);
    stats *dt_gk = checked_calloc(lags, sizeof *dt_gk),
          *eta_t = checked_calloc(lags, sizeof *eta_t);
    stats einstein = {0, 0, 0}, green_kubo = {0, 0, 0}, ratio = {0, 0, 0}, z = {0, 0, 0};
    stats viscosity = {0, 0, 0}, viscosity_ratio = {0, 0, 0};
    double *m = checked_calloc(lags, sizeof *m), *c = checked_calloc(lags, sizeof *c);
    double *h = checked_calloc(lags, sizeof *h);
    const double area = p.box * p.box;
    const double sigma = 2.0 * p.radius, density = (double)n / (p.box * p.box);
    double kt = 0.0;
    for (int b = 0; b < blocks; ++b) {
        /* The stress is one collective quantity, cheap to correlate: an
         * origin at every sample. */
        ds_transport *tr = NULL, *stress = NULL;
        if (ds_transport_create(n, lags, every, &tr, NULL) != DS_OK ||
            ds_transport_create(1, lags, 1, &stress, NULL) != DS_OK) {
            fputs("transport: out of memory for the correlations\n", stderr);
            return 1;
        }
        ds_sim_reset_observables(sim);
        for (uint64_t s = 0; s < per_block; ++s) {
            if (s)
                ds_sim_step(sim, NULL);
            ds_transport_sample(tr, sim, NULL);
            double si[3];
            ds_sim_get_stress_integral(sim, si, NULL);
            const double shear[2] = {si[2], 0.5 * (si[0] - si[1])}, unused[2] = {0.0, 0.0};
            ds_transport_add(stress, shear, unused, NULL);
        }
        ds_transport_get(tr, m, c, NULL, NULL);
        ds_transport_get(stress, h, NULL, NULL, NULL);
        double e, g, helfand;
        ds_transport_get_diffusion(tr, interval, from, to, &e, &g, NULL);
        ds_transport_get_diffusion(stress, interval, from, to, &helfand, NULL, NULL);
        ds_transport_destroy(tr);
        ds_transport_destroy(stress);
        kt = ds_sim_get_temperature(sim); /* the same in every block: energy is conserved */
        const double zb = ds_sim_get_compressibility_factor(sim);
        const double d_enskog = sqrt(kt / PI) / (2.0 * density * sigma) * (2.0 * eta) / (zb - 1.0);
        add(&z, zb);
        add(&einstein, e);
        add(&green_kubo, g);
        add(&ratio, e / d_enskog);
        /* The Einstein slope over 4 of the two components' sum is the
         * mean component's slope over 2: eta A kT. */
        const double visc = helfand / (area * kt), gb = (zb - 1.0) / (2.0 * eta);
        add(&viscosity, visc);
        add(&viscosity_ratio, visc / tool_enskog_viscosity(kt, sigma, eta, gb));
        double d = 0.0;
        for (size_t k = 0; k < lags; ++k) {
            if (k)
                d += 0.25 * interval * (c[k - 1] + c[k]);
            add(&msd[k], m[k]);
            add(&vacf[k], c[k] / c[0]);
            add(&dt_gk[k], d);
            add(&eta_t[k], k ? h[k] / (4.0 * area * kt * (double)k * interval) : 0.0);
        }
    }
    const double nu = 2.0 * (double)(ds_sim_get_collision_count(sim) - collisions0) /
                      ((double)n * (ds_sim_get_time(sim) - time0));
    const double zm = mean(&z), g_contact = (zm - 1.0) / (2.0 * eta);
    const double d0 = sqrt(kt / PI) / (2.0 * density * sigma), de = d0 / g_contact;
    printf("# transport: N %zu eta %.6g periodic event seed %llu, %d blocks of %llu samples\n", n,
           eta, (unsigned long long)p.seed, blocks, (unsigned long long)per_block);
    printf("# sigma %.9g n %.9g kT/m %.9g interval %.9g lags %zu every %zu\n", sigma, density, kt,
           interval, lags, every);
    printf("# Z %.6f +- %.6f g(sigma) %.6f nu %.6g t_c %.6g\n", zm, error(&z), g_contact, nu,
           1.0 / nu);
    printf("# D_0 %.6g D_E %.6g\n", d0, de);
    printf("# window %zu:%zu (t %.6g to %.6g, %.3g to %.3g t_c): D_einstein %.6g +- %.6g"
           " D_green_kubo %.6g +- %.6g D/D_E %.5f +- %.5f\n",
           from, to, (double)from * interval, (double)to * interval, (double)from * interval * nu,
           (double)to * interval * nu, mean(&einstein), error(&einstein), mean(&green_kubo),
           error(&green_kubo), mean(&ratio), error(&ratio));
    printf("# viscosity over the window: eta %.6g +- %.6g eta_0 %.6g eta_E %.6g eta/eta_E %.5f +- "
           "%.5f\n",
           mean(&viscosity), error(&viscosity), sqrt(kt / PI) / (2.0 * sigma),
           tool_enskog_viscosity(kt, sigma, eta, g_contact), mean(&viscosity_ratio),
           error(&viscosity_ratio));
    printf("# %llu collisions, %.1f s\n",
           (unsigned long long)(ds_sim_get_collision_count(sim) - collisions0),
           ds_timer_now() - t0);
    printf("# t t/t_c msd error C/C0 error D(t) error eta(t) error\n");
    for (size_t k = 0; k < lags; ++k)
        printf("%.9g %.6g %.9g %.3g %.9g %.3g %.9g %.3g %.9g %.3g\n", (double)k * interval,
               (double)k * interval * nu, mean(&msd[k]), error(&msd[k]), mean(&vacf[k]),
               error(&vacf[k]), mean(&dt_gk[k]), error(&dt_gk[k]), mean(&eta_t[k]),
               error(&eta_t[k]));
    free(eta_t);
    free(h);
    free(msd);
    free(vacf);
    free(dt_gk);
    free(m);
    free(c);
    ds_sim_destroy(sim);
    return 0;
}
