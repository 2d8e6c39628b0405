/* SPDX-License-Identifier: MIT */
/* disks: the command-line front end. Runs the simulation, writes
 * frame_NNNN.txt files crash-safe, prints the seed's timing. All printing
 * and exit codes live in cli/, never in the library (cli.h says which
 * file does what). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"

typedef struct progress {
    int enabled;
    double started;
} progress;

static void progress_show(const progress *pr, long frame, long frames, uint64_t steps)
{
    if (!pr->enabled)
        return;
    double elapsed = ds_now() - pr->started;
    double rate = elapsed > 0.0 ? (double)steps / elapsed : 0.0;
    double left = frame > 0 ? elapsed * (double)(frames - frame) / (double)frame : 0.0;
    fprintf(stderr, "\rframe %ld of %ld  %.0f steps/s  %.0f s left  ", frame, frames, rate, left);
}

static void progress_clear(const progress *pr)
{
    if (pr->enabled)
        fputs("\r\033[K", stderr);
}

static void stats_row(char **buf, size_t *len, size_t *cap, long frame, const ds_sim *sim)
{
    char row[320];
    double px, py;
    ds_momentum(sim, &px, &py);
    int l = snprintf(row, sizeof row, "%ld,%.6f,%.17g,%.17g,%.17g,%llu,%llu,%.17g,%.17g,%.17g\n",
                     frame, ds_time(sim), ds_kinetic_energy(sim), px, py,
                     (unsigned long long)ds_collision_count(sim),
                     (unsigned long long)ds_wall_count(sim), ds_pressure(sim),
                     ds_virial_pressure(sim), ds_psi6(sim));
    if (*len + (size_t)l + 1 > *cap) {
        size_t ncap = *cap * 2 + sizeof row;
        char *grown = realloc(*buf, ncap);
        if (!grown)
            die(EXIT_RUN, "out of memory for --stats");
        *buf = grown;
        *cap = ncap;
    }
    memcpy(*buf + *len, row, (size_t)l);
    *len += (size_t)l;
}

int main(int argc, char **argv)
{
    /* A closed standard descriptor would be handed to the first frame file
     * by mkstemp, and a later printf would then write into the frame. */
    for (int fd = 0; fd <= 2; ++fd)
        if (fcntl(fd, F_GETFD) < 0 && open("/dev/null", fd ? O_WRONLY : O_RDONLY) != fd)
            return EXIT_RUN;
    options o = parse_args(argc, argv);
    ds_params p = ds_default_params(o.n, o.radius);
    p.seed = o.seed;
    p.broadphase = o.broadphase;
    p.integrator = o.integrator;
    p.placement = o.placement;
    p.boundary = o.boundary;
    p.box_y = o.box_y;
    check_request(&p);
    char stats_dir[4096], trajectory_dir[4096];
    const char *stats_base =
        o.stats_path ? output_split("--stats", o.stats_path, stats_dir, sizeof stats_dir) : NULL;
    const char *trajectory_base =
        o.trajectory_path
            ? output_split("--trajectory", o.trajectory_path, trajectory_dir, sizeof trajectory_dir)
            : NULL;
    make_dirs(o.out_dir);

    ds_sim *sim = NULL;
    ds_status st = ds_create(&p, &sim);
    if (st == DS_ERR_PLACEMENT)
        die(EXIT_RUN, "could not place %zu disks of R = %g without overlap (seed %llu): %s", o.n,
            o.radius, (unsigned long long)o.seed, "try another --seed, or fewer or smaller disks");
    if (st != DS_OK)
        die(EXIT_RUN, "cannot create the simulation: %s", ds_status_str(st));
    if (!o.quiet) {
        /* The box is named only when it is not the seed's square with walls. */
        char box[96] = "";
        if (ds_boundary_used(sim) != DS_WALLS || ds_box_y(sim) != ds_box(sim))
            snprintf(box, sizeof box, ", box = %g x %g %s", ds_box(sim), ds_box_y(sim),
                     ds_boundary_name(ds_boundary_used(sim)));
        printf("disks: N = %zu, R = %g, seed = %llu%s, integrator = %s, broad phase = %s, %ld "
               "frames x %llu steps -> %s\n",
               o.n, o.radius, (unsigned long long)o.seed, box,
               ds_integrator_name(ds_integrator_used(sim)),
               ds_broadphase_name(ds_broadphase_used(sim)), o.frames,
               (unsigned long long)o.steps_per_frame, o.out_dir);
    }
    fflush(stdout);

    size_t cap = ds_frame_size(sim, o.velocities), len = 0;
    char *buf = malloc(cap ? cap : 1);
    char *stats = NULL;
    size_t stats_len = 0, stats_cap = 0;
    if (!buf)
        die(EXIT_RUN, "out of memory for the frame buffer");
    if (o.stats_path) {
        const char *header = "frame,time,kinetic_energy,px,py,collisions,wall_reflections,pressure,"
                             "virial_pressure,psi6\n";
        stats_cap = 4096;
        stats = malloc(stats_cap);
        if (!stats)
            die(EXIT_RUN, "out of memory for --stats");
        stats_len = strlen(header);
        memcpy(stats, header, stats_len);
    }

    trajectory traj = {NULL, NULL, NULL, 0};
    if (o.trajectory_path)
        trajectory_open(&traj, o.trajectory_path, trajectory_dir, trajectory_base, sim);

    progress pr = {!o.quiet && isatty(STDERR_FILENO), ds_now()};
    double sim_seconds = 0.0, out_seconds = 0.0;
    for (long frame = 0; frame < o.frames; ++frame) {
        if (frame > 0) {
            double t0 = ds_now();
            ds_run(sim, o.steps_per_frame);
            sim_seconds += ds_now() - t0;
        }
        double t0 = ds_now();
        char name[32];
        const char *why = "";
        snprintf(name, sizeof name, "frame_%04ld.txt", frame);
        ds_format_frame(sim, o.velocities, buf, cap, &len);
        if (write_file_atomic(o.out_dir, name, buf, len, &why) != 0) {
            progress_clear(&pr);
            die(EXIT_RUN, "cannot write %s/%s: %s", o.out_dir, name, why);
        }
        if (traj.f)
            trajectory_append(&traj, sim);
        if (stats)
            stats_row(&stats, &stats_len, &stats_cap, frame, sim);
        out_seconds += ds_now() - t0;
        progress_show(&pr, frame + 1, o.frames, ds_steps(sim));
    }
    progress_clear(&pr);
    if (traj.f)
        trajectory_close(&traj);
    if (stats) {
        const char *why = "";
        int failed = is_special_file(o.stats_path)
                         ? write_file_in_place(o.stats_path, stats, stats_len, &why)
                         : write_file_atomic(stats_dir, stats_base, stats, stats_len, &why);
        if (failed)
            die(EXIT_RUN, "cannot write %s: %s", o.stats_path, why);
    }
    if (!o.quiet) {
        printf("collision processing time: %.6f s (%s over %llu steps)\n",
               ds_collision_seconds(sim),
               ds_integrator_used(sim) == DS_EVENT_DRIVEN
                   ? "predicting and processing collisions, wall turns and cell crossings"
                   : "sorting, pruning, testing and resolving pairs",
               (unsigned long long)ds_steps(sim));
        printf("disk-disk collisions: %llu, wall reflections: %llu\n",
               (unsigned long long)ds_collision_count(sim), (unsigned long long)ds_wall_count(sim));
        printf("simulation %.3f s, output %.3f s\n", sim_seconds, out_seconds);
    }
    free(buf);
    free(stats);
    ds_destroy(sim);
    /* The timing report is output too: `disks 400 5 > /dev/full` must not
     * succeed silently with it lost. */
    int lost = ferror(stdout);
    if (fflush(stdout) != 0 || lost)
        die(EXIT_RUN, "cannot write the report to standard output: %s",
            strerror(errno ? errno : EIO));
    return 0;
}
