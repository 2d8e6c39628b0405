/* SPDX-License-Identifier: MIT */
/* bench: how fast the broad phases are, how they scale, what placement and
 * output cost. Uses the public API only; prints a table and asserts
 * nothing (timings depend on the machine and its load).
 *
 *   tools/bench            every case (a few minutes on 2 cores)
 *   tools/bench scale N    one scaling case, e.g. under /usr/bin/time -v
 *   tools/bench events N [C]  one event-driven case (area fraction 0.5),
 *                          likewise, timed after ~C collisions per disk
 *   tools/bench chain N    one event-chain case (area fraction 0.70, periodic)
 *
 * Ratios are between figures measured in the same run, so they are less
 * sensitive to the machine than the absolute times. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"
#include "disk_sim.h"

#define AREA_FRACTION 0.1
#define BOX 1000.0
#define PI 3.14159265358979323846

typedef struct result {
    size_t n;
    double radius;
    ds_broadphase bp;
    unsigned long steps;
    double collision_seconds;
    double create_seconds;
    double pairs_per_step;
} result;

static double fraction_of(size_t n, double r) { return (double)n * PI * r * r / (BOX * BOX); }

static double radius_for_fraction(size_t n, double fraction)
{
    return sqrt(fraction * BOX * BOX / ((double)n * PI));
}

static double ns_per_disk_step(const result *r)
{
    return 1e9 * r->collision_seconds / ((double)r->n * (double)r->steps);
}

static int run_case(size_t n, double radius, ds_broadphase bp, unsigned long steps, result *out)
{
    ds_params p = ds_params_default(n, radius);
    p.broadphase = bp;
    ds_sim *sim;
    double t0 = ds_timer_now();
    ds_status st = ds_sim_create(&p, NULL, &sim, NULL);
    double t1 = ds_timer_now();
    if (st != DS_OK) {
        fprintf(stderr, "bench: ds_sim_create(N = %zu, NULL, R = %g, NULL): %s\n", n, radius,
                ds_status_name(st));
        return 0;
    }
    ds_sim_run(sim, steps, NULL);
    out->n = n;
    out->radius = radius;
    out->bp = ds_sim_get_broadphase(sim);
    out->steps = steps;
    out->collision_seconds = ds_sim_get_collision_seconds(sim);
    out->create_seconds = t1 - t0;
    out->pairs_per_step = (double)ds_sim_get_pairs_tested(sim) / (double)steps;
    ds_sim_destroy(sim);
    return 1;
}

typedef struct bench_case {
    size_t n;
    double radius;
    ds_broadphase bp;
    unsigned long steps;
} bench_case;

/* Runs the cases in ROUNDS rounds: ns[c][k] is case c's ns per disk-step in
 * round k, rows[c] case c with its median collision time. */
static int run_rounds(const bench_case *cases, int count, double ns[][ROUNDS], result *rows)
{
    for (int k = 0; k < ROUNDS; ++k)
        for (int c = 0; c < count; ++c) {
            if (!run_case(cases[c].n, cases[c].radius, cases[c].bp, cases[c].steps, &rows[c]))
                return 0;
            ns[c][k] = ns_per_disk_step(&rows[c]);
        }
    for (int c = 0; c < count; ++c) {
        double t[ROUNDS];
        for (int k = 0; k < ROUNDS; ++k)
            t[k] = ns[c][k];
        rows[c].collision_seconds =
            median(t, ROUNDS) * 1e-9 * (double)rows[c].n * (double)rows[c].steps;
    }
    return 1;
}

/* Seconds of one ds_sim_create, the median of `repeats` (odd, at most 64):
 * placement alone at small N takes well under a millisecond, too short
 * for one measurement. */
static double create_seconds(size_t n, double radius, ds_broadphase bp, int repeats)
{
    double t[64] = {0.0};
    if (repeats < 1 || repeats > 64)
        return NAN;
    for (int k = 0; k < repeats; ++k) {
        ds_params p = ds_params_default(n, radius);
        p.broadphase = bp;
        ds_sim *sim;
        double t0 = ds_timer_now();
        if (ds_sim_create(&p, NULL, &sim, NULL) != DS_OK)
            return NAN;
        t[k] = ds_timer_now() - t0;
        ds_sim_destroy(sim);
    }
    return median(t, repeats);
}

static void print_header(void)
{
    printf("%-8s %8s %8s %6s %-7s %7s %10s %10s %12s\n", "case", "N", "R", "phi", "broad", "steps",
           "coll. s", "ns/disk", "tests/step");
}

static void print_row(const char *name, const result *r)
{
    printf("%-8s %8zu %8.4f %6.3f %-7s %7lu %10.4f %10.2f %12.0f\n", name, r->n, r->radius,
           fraction_of(r->n, r->radius), ds_broadphase_name(r->bp), r->steps, r->collision_seconds,
           ns_per_disk_step(r), r->pairs_per_step);
    fflush(stdout);
}

/* Steps for a scaling case: about 4e7 disk-steps, so each case takes a
 * fraction of a second to a second whatever N. */
static unsigned long scaling_steps(size_t n)
{
    unsigned long s = (unsigned long)(4e7 / (double)n);
    return s < 20 ? 20 : s;
}

/* ------------------------------------------------------------ disks 400 5 */

/* Seconds of the parts of one `disks 400 5` run. */
typedef struct disks_times {
    double simulation; /* ds_sim_create and ds_sim_run */
    double formatting; /* ds_frame_format */
    double writing;    /* fwrite and fclose: handing the bytes to the kernel */
    double files;      /* fopen and rename: creating and naming 500 files */
} disks_times;

/* The work of `disks 400 5`, through the same calls: 500 frames, 100 steps
 * apart, each formatted into a buffer and written with one fwrite to a
 * temporary file renamed into place, in a new directory under parent. */
static int disks_run(const char *parent, disks_times *t)
{
    char dir[4096];
    if (snprintf(dir, sizeof dir, "%s/disksim-bench-XXXXXX", parent) >= (int)sizeof dir - 32) {
        fprintf(stderr, "bench: directory name too long: %s\n", parent);
        return 0;
    }
    if (!mkdtemp(dir)) {
        fprintf(stderr, "bench: cannot create a directory in %s: %s\n", parent, strerror(errno));
        return 0;
    }
    ds_params p = ds_params_default(400, 5.0);
    ds_sim *sim;
    *t = (disks_times){0.0, 0.0, 0.0, 0.0};
    double t0 = ds_timer_now();
    if (ds_sim_create(&p, NULL, &sim, NULL) != DS_OK)
        return 0;
    t->simulation = ds_timer_now() - t0;
    size_t cap = ds_frame_get_size(sim, 0);
    char *buf = malloc(cap);
    char path[4096 + 32], tmp[4096 + 32]; /* dir, then at most "/.frame_0499.tmp" */
    int ok = buf != NULL;
    for (int frame = 0; ok && frame < 500; ++frame) {
        if (frame > 0) {
            t0 = ds_timer_now();
            ds_sim_run(sim, 100, NULL);
            t->simulation += ds_timer_now() - t0;
        }
        t0 = ds_timer_now();
        size_t len = 0;
        ok = ds_frame_format(sim, 0, buf, cap, &len, NULL) == DS_OK;
        double t1 = ds_timer_now();
        t->formatting += t1 - t0;
        snprintf(path, sizeof path, "%s/frame_%04d.txt", dir, frame);
        snprintf(tmp, sizeof tmp, "%s/.frame_%04d.tmp", dir, frame);
        FILE *f = fopen(tmp, "wb");
        double t2 = ds_timer_now();
        ok = ok && f && fwrite(buf, 1, len, f) == len;
        ok = f && fclose(f) == 0 && ok;
        double t3 = ds_timer_now();
        ok = ok && rename(tmp, path) == 0;
        t->writing += t3 - t2;
        t->files += (t2 - t1) + (ds_timer_now() - t3);
    }
    for (int frame = 0; frame < 500; ++frame) {
        snprintf(path, sizeof path, "%s/frame_%04d.txt", dir, frame);
        remove(path);
    }
    rmdir(dir);
    free(buf);
    ds_sim_destroy(sim);
    return ok;
}

static void print_machine(void)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[256];
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, "model name", 10) == 0) {
            char *colon = strchr(line, ':');
            printf("cpu:%s", colon ? colon + 1 : line);
            break;
        }
    if (f)
        fclose(f);
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    printf("online cpus: %ld; disksim %s\n", cores, ds_version());
}

/* The broad phase DS_BROADPHASE_AUTO resolves to for (n, r). */
static const char *auto_choice(size_t n, double r)
{
    ds_params p = ds_params_default(n, r);
    ds_sim *sim = NULL;
    /* Creating places the disks; only done for small n. */
    const char *name = ds_sim_create(&p, NULL, &sim, NULL) == DS_OK
                           ? ds_broadphase_name(ds_sim_get_broadphase(sim))
                           : "?";
    ds_sim_destroy(sim);
    return name;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "scale") == 0) {
        size_t n = (size_t)strtoul(argv[2], NULL, 10);
        result r;
        if (n < 1 || !run_case(n, radius_for_fraction(n, AREA_FRACTION), DS_BROADPHASE_AUTO,
                               scaling_steps(n), &r))
            return 1;
        print_header();
        print_row("scale", &r);
        printf("create %.3f s (%.0f ns per disk), peak RSS %ld KB\n", r.create_seconds,
               1e9 * r.create_seconds / (double)n, peak_rss_kb());
        return 0;
    }
    if ((argc == 3 || argc == 4) && strcmp(argv[1], "events") == 0)
        return bench_events_one(strtoul(argv[2], NULL, 10), argc == 4 ? atof(argv[3]) : 1.0) ? 0
                                                                                             : 1;
    if (argc == 3 && strcmp(argv[1], "chain") == 0)
        return bench_chain_one(strtoul(argv[2], NULL, 10)) ? 0 : 1;
    if (argc != 1) {
        fprintf(stderr, "usage: bench [scale N | events N [collisions per disk] | chain N]\n");
        return 2;
    }
    double started = ds_timer_now();
    print_machine();

    /* 1. The seed case. Brute force runs fewer steps (it tests all 79,800
     * pairs every step); every figure is per disk-step, so they compare. */
    printf("\nEach section runs its cases in %d interleaved rounds; rows show medians\n"
           "over rounds, ratios the median of the ratios within each round.\n",
           ROUNDS);
    printf("\n1. Seed case: N = 400, R = 5. Brute force runs 5,000 steps, not 50,000:\n"
           "   compare per disk-step.\n");
    print_header();
    enum { SAP, BRUTE, STRIPS };
    const bench_case seed[] = {{400, 5.0, DS_BROADPHASE_SAP, 50000},
                               {400, 5.0, DS_BROADPHASE_BRUTE, 5000},
                               {400, 5.0, DS_BROADPHASE_STRIPS, 50000}};
    double seed_ns[3][ROUNDS];
    result seed_rows[3];
    if (!run_rounds(seed, 3, seed_ns, seed_rows))
        return 1;
    for (int c = 0; c < 3; ++c)
        print_row("seed", &seed_rows[c]);
    printf("   brute / sap = %.1f (target >= 50), strips / sap = %.2f; auto picks %s\n",
           median_ratio(seed_ns[BRUTE], seed_ns[SAP]), median_ratio(seed_ns[STRIPS], seed_ns[SAP]),
           auto_choice(400, 5.0));

    /* 2. Scaling at fixed area fraction. Plain SAP only up to 10^4: its
     * tests per disk grow like N 2R / box (357 at 10^6), and its first
     * insertion sort, from generation order, is O(N^2). Cases: SAP and
     * strips at 10^3 and 10^4, strips at 10^5 and 10^6. */
    static const size_t sizes[] = {1000, 10000, 100000, 1000000};
    enum { SIZES = sizeof sizes / sizeof sizes[0], SCALE_CASES = SIZES + 2 };
    bench_case scale[SCALE_CASES];
    int strips_case[SIZES], sap_case[2], count = 0;
    for (size_t k = 0; k < SIZES; ++k) {
        const double r = radius_for_fraction(sizes[k], AREA_FRACTION);
        const unsigned long steps = scaling_steps(sizes[k]);
        if (k < 2) {
            sap_case[k] = count;
            scale[count++] = (bench_case){sizes[k], r, DS_BROADPHASE_SAP, steps / (k ? 4 : 1)};
        }
        strips_case[k] = count;
        scale[count++] = (bench_case){sizes[k], r, DS_BROADPHASE_STRIPS, steps};
    }
    double scale_ns[SCALE_CASES][ROUNDS];
    result scale_rows[SCALE_CASES];
    printf("\n2. Scaling at area fraction %.1f, R = sqrt(%.1f * 1000^2 / (N pi))\n", AREA_FRACTION,
           AREA_FRACTION);
    print_header();
    if (!run_rounds(scale, SCALE_CASES, scale_ns, scale_rows))
        return 1;
    for (int c = 0; c < SCALE_CASES; ++c)
        print_row("scale", &scale_rows[c]);
    for (size_t k = 0; k < 2; ++k)
        printf("   N = %-7zu sap / strips = %.2f\n", sizes[k],
               median_ratio(scale_ns[sap_case[k]], scale_ns[strips_case[k]]));
    for (size_t k = 1; k < SIZES; ++k)
        printf("   strips ns/disk-step, N = %-7zu / N = 1000: %.2f%s\n", sizes[k],
               median_ratio(scale_ns[strips_case[k]], scale_ns[strips_case[0]]),
               sizes[k] == 1000000 ? " (target <= 2)" : "");
    printf("   auto picks: N = 1000 %s, N = 10000 %s (both broad phases' rows above)\n",
           auto_choice(1000, radius_for_fraction(1000, AREA_FRACTION)),
           auto_choice(10000, radius_for_fraction(10000, AREA_FRACTION)));

    /* 3. Placement. ds_sim_create with brute force is placement alone (that
     * broad phase keeps generation order); with DS_BROADPHASE_AUTO it adds the broad
     * phase's first ordering. In each round, small N take the median of
     * several creations: one takes well under a millisecond. */
    static const int create_repeats[SIZES] = {21, 9, 1, 1};
    double place_ns[SIZES][ROUNDS], order_ns[SIZES][ROUNDS];
    for (int k = 0; k < ROUNDS; ++k)
        for (size_t c = 0; c < SIZES; ++c) {
            const double r = radius_for_fraction(sizes[c], AREA_FRACTION);
            const double per_disk = 1e9 / (double)sizes[c];
            place_ns[c][k] =
                per_disk * create_seconds(sizes[c], r, DS_BROADPHASE_BRUTE, create_repeats[c]);
            order_ns[c][k] =
                per_disk * create_seconds(sizes[c], r, DS_BROADPHASE_AUTO, create_repeats[c]) -
                place_ns[c][k];
        }
    printf("\n3. Placement per disk: ds_sim_create with brute force (placement alone), and what\n"
           "   auto adds (the first strip/x ordering); small N: median of 21 and 9 per round\n");
    printf("%8s %12s %-7s %14s\n", "N", "placement ns", "auto", "+ ordering ns");
    const double place_ratio = median_ratio(place_ns[3], place_ns[1]);
    for (size_t c = 0; c < SIZES; ++c) {
        const double r = radius_for_fraction(sizes[c], AREA_FRACTION);
        printf("%8zu %12.0f %-7s %14.0f\n", sizes[c], median(place_ns[c], ROUNDS),
               c < 2 ? auto_choice(sizes[c], r) : "strips", median(order_ns[c], ROUNDS));
    }
    printf("   placement per disk, N = 10^6 / N = 10^4: %.2f (target <= 3)\n", place_ratio);

    /* 4. The whole `disks 400 5` run, each part timed on its own. The
     * program's output work is formatting the frames and writing their
     * bytes; creating and renaming 500 files costs what the file system
     * charges, which on some machines differs tenfold between directories
     * of the same disk. So both the current directory (where `disks`
     * writes by default) and $TMPDIR or /tmp, in alternation. */
    const char *tmpdir = getenv("TMPDIR") && *getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    const char *where[2] = {".", tmpdir};
    double sim_s[2][ROUNDS], fmt_s[2][ROUNDS], write_s[2][ROUNDS], files_s[2][ROUNDS];
    double out_s[2][ROUNDS], all_s[2][ROUNDS];
    for (int k = 0; k < ROUNDS; ++k)
        for (int w = 0; w < 2; ++w) {
            disks_times t;
            if (!disks_run(where[w], &t))
                return 1;
            sim_s[w][k] = t.simulation;
            fmt_s[w][k] = t.formatting;
            write_s[w][k] = t.writing;
            files_s[w][k] = t.files;
            out_s[w][k] = t.formatting + t.writing;
            all_s[w][k] = out_s[w][k] + t.files;
        }
    const double out_ratio = median_ratio(out_s[0], sim_s[0]);
    const double all_ratio[2] = {median_ratio(all_s[0], sim_s[0]),
                                 median_ratio(all_s[1], sim_s[1])};
    printf("\n4. disks 400 5: 500 frames, each into a new file renamed into place\n");
    printf("   simulation %.3f s; output %.3f s = formatting %.3f s + writing the bytes %.3f s\n",
           median(sim_s[0], ROUNDS), median(out_s[0], ROUNDS), median(fmt_s[0], ROUNDS),
           median(write_s[0], ROUNDS));
    printf("   output / simulation = %.2f (target < 1)\n", out_ratio);
    for (int w = 0; w < 2; ++w)
        printf("   creating and renaming the files in %s: %.3f s; all output / simulation = %.2f\n",
               w == 0 ? "the current directory" : where[w], median(files_s[w], ROUNDS),
               all_ratio[w]);

    if (!bench_events() || !bench_chain())
        return 1;

    printf("\npeak RSS of this process %ld KB (the N = 10^6 cases); bench took %.0f s\n",
           peak_rss_kb(), ds_timer_now() - started);
    return 0;
}
