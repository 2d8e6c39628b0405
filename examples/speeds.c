/* SPDX-License-Identifier: MIT */
/* Takes the whole state out in one call (ds_sim_get_disks) and prints the speed
 * distribution against the two-dimensional Maxwell-Boltzmann law:
 *
 *   speeds N R [TIME]        e.g. speeds 2000 3 20
 *
 * Every disk starts at speed 100; collisions share the energy out until the
 * speeds follow the Rayleigh density f(v) = v / s^2 exp(-v^2 / 2 s^2) with
 * s^2 = <v^2> / 2. Each row is one bin of width 20: the fraction of disks in
 * it, the fraction Rayleigh predicts, and a bar of the measured one. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <disk_sim.h>

#define BINS 12
#define BIN_WIDTH 20.0

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4) {
        fprintf(stderr, "usage: speeds N R [TIME]\n");
        return 2;
    }
    ds_params params = ds_params_default(strtoul(argv[1], NULL, 10), strtod(argv[2], NULL));
    double time = argc > 3 ? strtod(argv[3], NULL) : 20.0;
    ds_sim *sim = NULL;
    ds_status status = ds_sim_create(&params, NULL, &sim, NULL); /* also refuses a bad N or R */
    if (status != DS_OK || !(time >= 0.0 && time <= 1e6)) {
        fprintf(stderr, "speeds: %s\n", status != DS_OK ? ds_status_name(status) : "bad TIME");
        ds_sim_destroy(sim);
        return 1;
    }
    ds_sim_run(sim, (uint64_t)(time / ds_sim_get_dt(sim) + 0.5), NULL);

    size_t n = ds_sim_get_count(sim);
    ds_disk *disks = malloc(n * sizeof *disks);
    if (!disks || ds_sim_get_disks(sim, disks, NULL) != DS_OK) {
        fprintf(stderr, "speeds: out of memory\n");
        free(disks);
        ds_sim_destroy(sim);
        return 1;
    }
    double v2 = 0.0;
    size_t count[BINS] = {0};
    for (size_t i = 0; i < n; ++i) {
        double v = hypot(disks[i].vx, disks[i].vy);
        v2 += v * v / (double)n;
        size_t bin = (size_t)(v / BIN_WIDTH);
        if (bin < BINS)
            ++count[bin];
    }
    double s2 = v2 / 2.0; /* Rayleigh: the cumulative law is 1 - exp(-v^2 / 2 s^2) */
    printf("%zu disks at t = %.1f, rms speed %.1f\n", n, ds_sim_get_time(sim), sqrt(v2));
    printf("   speed    disks  Rayleigh\n");
    for (int b = 0; b < BINS; ++b) {
        double lo = b * BIN_WIDTH, hi = lo + BIN_WIDTH;
        double expected = exp(-lo * lo / (2.0 * s2)) - exp(-hi * hi / (2.0 * s2));
        double measured = (double)count[b] / (double)n;
        printf("%3.0f-%-3.0f  %6.3f  %6.3f  ", lo, hi, measured, expected);
        for (int k = 0; k < (int)(measured * 200.0 + 0.5); ++k)
            putchar('#');
        putchar('\n');
    }
    free(disks);
    ds_sim_destroy(sim);
    return 0;
}
