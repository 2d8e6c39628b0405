/* SPDX-License-Identifier: MIT */
/* pressure: the compressibility factor Z = P A / (N kT) of one system, with
 * an error bar from block averages. Public API only. The scripts
 * tools/analysis/pressure_vs_dt.sh and tools/analysis/eos.sh run it over parameter sweeps.
 *
 *   pressure N ETA [--integrator step|event|chain] [--dt DT] [--periodic]
 *            [--lattice] [--box-y H] [--relax T] [--blocks B] [--block T]
 *            [--seed S] [--thermostat KIND] [--pressure BP]
 *            [--barostat-every K] [--block-file FILE] [--memory]
 *
 * The N disks cover the area fraction ETA of the 1000 x H box (H = 1000
 * unless --box-y): R = sqrt(ETA 1000 H / (N pi)). After T time units of relaxation (default
 * 5) it runs B blocks (default 20) of T time units each (default 1),
 * taking Z in each block from the collision virial, the canonical Z of
 * ds_sim_get_compressibility_factor (kT = K / N with walls, K_int / (N - 1) in a
 * periodic box, where the momentum is conserved: the Z of Monte Carlo at
 * the same N; with event chains, from their liftings), and with walls also
 * from the walls (ds_sim_get_pressure A / K; the chains' wall turns),
 * both with A the area the centres reach. Z is the mean over the blocks; its error is the
 * standard error of that mean, sqrt(var / (B - 1)), which is honest when
 * a block is much longer than the time over which the pressure stays
 * correlated (collision times, here ~1e-3 to 1e-2; near a phase transition
 * far longer: use longer blocks there).
 *
 * Prints one line:
 *   eta N integrator dt boundary Z_virial error Z_walls error collisions seconds
 * (Z_walls and its error are "-" in a periodic box). --thermostat sets a
 * heat bath at the start's temperature (the canonical ensemble, Z at its
 * kT); --pressure BP sets the barostat at beta P sigma^2 = BP, so the run
 * starts at ETA and its box moves (the isobaric ensemble), and the line
 * ends with two more columns, the mean area fraction and its error: the
 * area fraction after every move (every K steps, a stretch at constant
 * area behind it), its error corrected for the samples' correlation by
 * blocking (the area forgets itself over hundreds of moves). --block-file
 * writes each block's Z to FILE, one a line, in order: the error above is
 * honest only if neighbouring blocks are uncorrelated, which the series
 * shows (their lag-1 correlation, or the error of the mean of pairs of
 * blocks against that of the blocks). With --memory it runs
 * nothing and prints the bytes the simulation would allocate
 * (ds_memory_needed), which tools/analysis/eos.sbatch asks Slurm for. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "analysis_util.h"
#include "disk_sim.h"

#define PI 3.14159265358979323846

static const char usage_text[] =
    "usage: pressure N ETA [--integrator step|event|chain] [--dt DT] [--periodic] [--lattice]\n"
    "                [--box-y H] [--relax T] [--blocks B] [--block T] [--seed S]\n"
    "                [--thermostat KIND] [--pressure BP] [--barostat-every K]\n"
    "                [--block-file FILE] [--memory]\n"
    "Prints Z = P A / (N kT) of N disks covering the area fraction ETA of the\n"
    "1000 x H box, with the standard error of its mean over B blocks, as one line\n"
    "  eta N integrator dt boundary Z_virial error Z_walls error collisions seconds\n"
    "(with --pressure two more: the mean area fraction and its error)\n"
    "  --integrator I  step, event or chain (default event)\n"
    "  --dt DT         time step, and with events or chains the interval between\n"
    "                  observations\n"
    "  --periodic      periodic box instead of walls\n"
    "  --lattice       start on a triangular lattice instead of random placement\n"
    "  --box-y H       height of the box (default 1000)\n"
    "  --relax T       time units of relaxation before the blocks (default 5)\n"
    "  --blocks B      number of blocks (default 20)\n"
    "  --block T       time units per block (default 1)\n"
    "  --seed S        seed (default 20260101)\n"
    "  --thermostat KIND  a heat bath at the start's temperature: andersen or\n"
    "                  isokinetic\n"
    "  --pressure BP   the barostat at beta P sigma^2 = BP (periodic): the box moves,\n"
    "                  and the line ends with the mean area fraction and its error\n"
    "  --barostat-every K  a move of the box every K steps (default 10)\n"
    "  --block-file FILE  write each block's Z_virial to FILE, one a line, to check\n"
    "                  that the blocks are independent\n"
    "  --memory        run nothing: print the bytes the simulation would allocate\n"
    "  --help          show this help and exit\n"
    "exit status: 0 success, 1 parameters the library refuses or a --block-file\n"
    "             that cannot be written, 2 usage error\n";

static void usage(void)
{
    fputs(usage_text, stderr);
    exit(2);
}

static double number(const char *s, double lo, double hi, const char *what)
{
    return tool_number("pressure", s, lo, hi, what);
}

/* The ensemble asked for, set once the simulation exists. */
typedef struct ensemble {
    ds_thermostat thermostat; /* DS_THERMOSTAT_NONE: constant energy */
    double pressure;          /* 0: a box of fixed sides */
    uint64_t every;           /* steps between moves of the box */
    FILE *blocks;             /* each block's Z, or NULL */
} ensemble;

/* The blocks: Z of each (and with walls P A / K), and with a barostat the
 * area fraction after every move, whose mean and corrected error go to
 * *eta and *eta_error (the samples kept in samples). */
static void run_blocks(ds_sim *sim, const ensemble *e, int blocks, uint64_t per_block,
                       double area, stats *virial, stats *wall, double *eta, double *eta_error)
{
    const int walls = ds_sim_get_boundary(sim) == DS_BOUNDARY_WALLS;
    const uint64_t chunk = e->pressure > 0.0 ? e->every : per_block;
    const size_t count = (size_t)blocks * (size_t)((per_block + chunk - 1) / chunk);
    double *samples = e->pressure > 0.0 ? malloc(count * sizeof *samples) : NULL;
    if (e->pressure > 0.0 && !samples) {
        fprintf(stderr, "pressure: no memory for %zu samples of the area fraction\n", count);
        exit(1);
    }
    size_t taken = 0;
    for (int b = 0; b < blocks; ++b) {
        ds_sim_reset_observables(sim);
        for (uint64_t done = 0; done < per_block; done += chunk) {
            ds_sim_run(sim, chunk < per_block - done ? chunk : per_block - done, NULL);
            if (samples)
                samples[taken++] = ds_sim_get_area_fraction(sim);
        }
        const double z = ds_sim_get_compressibility_factor(sim);
        add(virial, z);
        if (e->blocks)
            fprintf(e->blocks, "%.6f\n", z);
        if (walls)
            add(wall, ds_sim_get_pressure(sim) * area / ds_sim_get_kinetic_energy(sim));
    }
    if (samples)
        *eta = blocked_mean(samples, taken, eta_error);
    free(samples);
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
    const size_t n = (size_t)number(argv[1], 1, 1e8, "N");
    const double eta = number(argv[2], 1e-9, 0.9069, "ETA");
    ds_params p = ds_params_default(n, 1.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.box_y = 1000.0;
    double relax = 5.0, block = 1.0;
    int blocks = 20, memory = 0;
    ensemble e = {DS_THERMOSTAT_NONE, 0.0, 10, NULL};
    const char *block_file = NULL;
    for (int i = 3; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--periodic") == 0) {
            p.boundary = DS_BOUNDARY_PERIODIC;
            continue;
        }
        if (strcmp(a, "--lattice") == 0) {
            p.placement = DS_PLACEMENT_LATTICE;
            continue;
        }
        if (strcmp(a, "--memory") == 0) {
            memory = 1;
            continue;
        }
        if (!v)
            usage();
        ++i;
        /* The integrators by the library's names for them. */
        if (strcmp(a, "--integrator") == 0) {
            if (ds_integrator_parse(v, &p.integrator, NULL) != DS_OK)
                usage();
        } else if (strcmp(a, "--dt") == 0)
            p.dt = number(v, 1e-9, 1.0, "--dt");
        else if (strcmp(a, "--relax") == 0)
            relax = number(v, 0.0, 1e6, "--relax");
        else if (strcmp(a, "--blocks") == 0)
            blocks = (int)number(v, 2, 100000, "--blocks");
        else if (strcmp(a, "--block") == 0)
            block = number(v, 1e-6, 1e6, "--block");
        else if (strcmp(a, "--box-y") == 0)
            p.box_y = number(v, 1e-3, 1e9, "--box-y");
        else if (strcmp(a, "--seed") == 0)
            p.seed = (uint64_t)number(v, 0, 9007199254740992.0, "--seed");
        else if (strcmp(a, "--thermostat") == 0) {
            if (ds_thermostat_parse(v, &e.thermostat, NULL) != DS_OK)
                usage();
        } else if (strcmp(a, "--pressure") == 0)
            e.pressure = number(v, 1e-300, 1e9, "--pressure");
        else if (strcmp(a, "--barostat-every") == 0)
            e.every = (uint64_t)number(v, 1, 1e9, "--barostat-every");
        else if (strcmp(a, "--block-file") == 0)
            block_file = v;
        else
            usage();
    }
    p.radius = sqrt(eta * 1000.0 * p.box_y / ((double)n * PI));
    ds_sim *sim = NULL;
    ds_error why;
    ds_status st = ds_params_check(&p, NULL, NULL, &why);
    if (memory && st == DS_OK) {
        size_t bytes = 0;
        st = ds_params_memory(&p, NULL, &bytes, &why);
        if (st == DS_OK) {
            printf("%zu\n", bytes);
            return 0;
        }
    }
    if (st == DS_OK)
        st = ds_sim_create(&p, NULL, &sim, &why);
    if (st == DS_OK && e.thermostat != DS_THERMOSTAT_NONE)
        st = ds_sim_set_thermostat(sim, e.thermostat, 0.0, 0.0, &why);
    if (st == DS_OK && e.pressure > 0.0)
        st = ds_sim_set_barostat(sim, e.pressure, e.every, 0.0, 0, &why);
    if (st != DS_OK) {
        ds_sim_destroy(sim);
        /* The library's sentence when it refuses the parameters. */
        fprintf(stderr, "pressure: N = %zu at area fraction %g: %s\n", n, eta, why.message);
        return 1;
    }
    /* Opened before the run, so that a path that cannot be written fails
     * at once rather than after hours. */
    if (block_file && !(e.blocks = fopen(block_file, "w"))) {
        ds_sim_destroy(sim);
        fprintf(stderr, "pressure: cannot write --block-file %s\n", block_file);
        return 1;
    }
    const double dt = ds_sim_get_dt(sim), t0 = ds_timer_now();
    const uint64_t per_block = (uint64_t)llround(block / dt);
    ds_sim_run(sim, (uint64_t)llround(relax / dt), NULL);
    const int walls = p.boundary == DS_BOUNDARY_WALLS;
    const double inset = walls ? 2.0 * p.radius : 0.0;
    const double area = (ds_sim_get_box_width(sim) - inset) * (ds_sim_get_box_height(sim) - inset);
    stats virial = {0, 0, 0}, wall = {0, 0, 0};
    double eta_mean = 0.0, eta_error = 0.0;
    const uint64_t collisions = ds_sim_get_collision_count(sim);
    run_blocks(sim, &e, blocks, per_block, area, &virial, &wall, &eta_mean, &eta_error);
    printf("%.6g %zu %s %g %s %.6f %.6f ", eta, n, ds_integrator_name(ds_sim_get_integrator(sim)),
           dt, ds_boundary_name(ds_sim_get_boundary(sim)), mean(&virial), error(&virial));
    if (walls)
        printf("%.6f %.6f", mean(&wall), error(&wall));
    else
        printf("- -");
    printf(" %llu %.1f", (unsigned long long)(ds_sim_get_collision_count(sim) - collisions),
           ds_timer_now() - t0);
    if (e.pressure > 0.0)
        printf(" %.6f %.6f", eta_mean, eta_error);
    printf("\n");
    ds_sim_destroy(sim);
    if (e.blocks && fclose(e.blocks) != 0) {
        fprintf(stderr, "pressure: cannot write --block-file %s\n", block_file);
        return 1;
    }
    return 0;
}
