/* SPDX-License-Identifier: MIT */
/* disks: the command-line front end. Runs the simulation, writes
 * frame_NNNN.txt files crash-safe, prints the seed's timing. All printing
 * and exit codes live in cli/, never in the library (cli.h says which
 * file does what).
 *
 * The order is the promise of docs/cli.md: the command line, then every
 * path, then where the run starts (its checkpoint or frame read and
 * checked, or a new request checked and its disks placed) and its growth,
 * then the frames of another run, and only then is anything made: --out,
 * the outputs' temporaries. A failure up to the first frame leaves
 * nothing behind. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
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
    double elapsed = ds_timer_now() - pr->started;
    double rate = elapsed > 0.0 ? (double)steps / elapsed : 0.0;
    double left = frame > 0 ? elapsed * (double)(frames - frame) / (double)frame : 0.0;
    fprintf(stderr, "\rframe %ld of %ld  %.0f steps/s  %.0f s left  ", frame, frames, rate, left);
}

static void progress_clear(const progress *pr)
{
    if (pr->enabled)
        fputs("\r\033[K", stderr);
}

/* What a run writes, frame by frame. */
typedef struct run {
    const options *o;
    ds_sim *sim;
    long first, last; /* the frames this run writes */
    char *frame_buf;
    size_t frame_cap;
    char *json; /* frames.json, written with the first frame */
    output stats, trajectory, gsd_file;
    stats_books books;     /* the stress integral at the last row, for the next */
    ds_writer *xyz;        /* --trajectory's writer, into trajectory.f */
    ds_writer *gsd;        /* --gsd's, into gsd_file.f */
    long checkpoint_frame; /* the frame of the last checkpoint written, -1 */
    long jammed_frame;     /* the frame in which growth jammed, -1 */
    progress pr;
    double sim_seconds, out_seconds;
    int measuring; /* --measure-after's reset has been made (or needs none) */
} run;

/* A trajectory's frame: a write that fails ends the run. */
static void trajectory_frame(ds_writer *w, const output *out, const ds_sim *sim)
{
    errno = 0;
    if (w && ds_writer_write(w, sim, NULL) != DS_OK)
        die(EXIT_RUN, "cannot write %s %s: %s", out->option, out->path,
            strerror(errno ? errno : EIO));
}

/* The frame file, its trajectory frames and its stats row, with the
 * signals held: at any moment they agree. The run's first frame puts
 * frames.json beside it, and so does a frame at which growth jammed (its
 * time is off the frames' spacing). */
static void emit_frame(run *r, long frame, int jammed)
{
    const options *o = r->o;
    sigset_t old;
    hold_signals(&old);
    char name[32];
    const char *why = "";
    size_t len = 0;
    snprintf(name, sizeof name, "frame_%04ld.txt", frame);
    ds_frame_format(r->sim, o->velocities, r->frame_buf, r->frame_cap, &len, NULL);
    if (write_file_atomic(o->out_dir, name, r->frame_buf, len, 0, &why) != 0) {
        progress_clear(&r->pr);
        die(EXIT_RUN, "cannot write %s/%s: %s", o->out_dir, name, why);
    }
    if (jammed) {
        free(r->json);
        r->json = frames_json_text(r->sim, o, frame);
    }
    if (frame == r->first || jammed)
        frames_json_write(o, r->json);
    trajectory_frame(r->xyz, &r->trajectory, r->sim);
    trajectory_frame(r->gsd, &r->gsd_file, r->sim);
    if (r->stats.f)
        stats_row(&r->stats, frame, r->sim, &r->books);
    keep_created_dirs(); /* --out holds a frame now */
    release_signals(&old);
}

static void write_checkpoint(run *r, long frame)
{
    /* The outputs first: a checkpoint never holds a frame that the files
     * beside it lack (a restart drops the rows past its checkpoint). */
    if (r->stats.f)
        output_publish(&r->stats);
    if (r->trajectory.f)
        output_publish(&r->trajectory);
    if (r->gsd_file.f)
        output_publish(&r->gsd_file);
    checkpoint_write(r->sim, r->o->checkpoint_path);
    r->checkpoint_frame = frame;
}

/* A trajectory's writer finished, and its file put in place. */
static void close_trajectory(ds_writer **w, output *out)
{
    if (*w && ds_writer_close(*w, NULL) != DS_OK)
        die(EXIT_RUN, "cannot write %s %s: %s", out->option, out->path, strerror(EIO));
    *w = NULL;
    if (out->f)
        output_close(out);
}

static void close_outputs(run *r)
{
    close_trajectory(&r->xyz, &r->trajectory);
    close_trajectory(&r->gsd, &r->gsd_file);
    if (r->stats.f)
        output_close(&r->stats);
}

/* A signal asked the run to stop: the frame it was making is written;
 * now everything goes into place and the command ends by the signal. */
static void stop_by_signal(run *r, int sig, long frame)
{
    sigset_t old;
    hold_signals(&old);
    progress_clear(&r->pr);
    close_outputs(r);
    if (r->o->checkpoint_path && r->checkpoint_frame != frame)
        write_checkpoint(r, frame);
    if (!r->o->quiet)
        fprintf(stderr, "disks: stopped by %s after frame %ld%s%s%s\n",
                sig == SIGINT    ? "SIGINT"
                : sig == SIGTERM ? "SIGTERM"
                                 : "SIGHUP",
                frame, r->o->checkpoint_path ? "; the checkpoint " : "",
                r->o->checkpoint_path ? r->o->checkpoint_path : "",
                r->o->checkpoint_path ? " holds it" : "");
    end_by_signal(sig);
}

/* The writer of format on a trajectory's file (GSD writes its header
 * here). A write that fails says its errno; a refusal the library's
 * reason, which names its stream "out", here the option's file. */
static ds_writer *writer_on(const output *out, ds_format format)
{
    ds_writer *w = NULL;
    ds_error err;
    errno = 0;
    if (ds_writer_open(format, out->f, 0, &w, &err) == DS_OK)
        return w;
    if (err.status == DS_ERR_IO)
        die(EXIT_RUN, "cannot write %s %s: %s", out->option, out->path,
            strerror(errno ? errno : EIO));
    die(EXIT_RUN, "cannot write %s %s: %s", out->option, out->path,
        strncmp(err.message, "out: ", 5) == 0 ? err.message + 5 : err.message);
}

/* Opens --stats, --trajectory and --gsd (their temporaries) and makes
 * sure the frames and the checkpoint can be written, before any disk is
 * placed. */
static void open_outputs(run *r)
{
    const options *o = r->o;
    char name[32];
    snprintf(name, sizeof name, "frame_%04ld.txt", r->first);
    int err = probe_dir(o->out_dir, name);
    if (err)
        die(EXIT_RUN, "cannot write %s/%s: %s", o->out_dir, name, strerror(err));
    if (o->checkpoint_path)
        checkpoint_probe(o->checkpoint_path);
    if (o->trajectory_path) {
        output_open(&r->trajectory, "--trajectory", o->trajectory_path);
        if (o->trajectory_continues && r->trajectory.slot >= 0)
            carry_over_trajectory(&r->trajectory, r->sim, o->steps_per_frame, r->first - 1);
        r->xyz = writer_on(&r->trajectory, DS_FORMAT_XYZ);
    }
    if (o->gsd_path) {
        output_open(&r->gsd_file, "--gsd", o->gsd_path);
        if (o->gsd_continues && r->gsd_file.slot >= 0)
            carry_over_gsd(&r->gsd_file, r->sim);
        r->gsd = writer_on(&r->gsd_file, DS_FORMAT_GSD);
    }
    if (o->stats_path) {
        output_open(&r->stats, "--stats", o->stats_path);
        /* A restart going on with its run's file keeps its header and rows. */
        if (!(o->stats_continues && r->stats.slot >= 0 &&
              carry_over_stats(&r->stats, stats_header, r->first - 1)))
            output_write(&r->stats, stats_header, strlen(stats_header));
    }
}

static void print_start(const run *r)
{
    const options *o = r->o;
    const ds_sim *sim = r->sim;
    /* The box is named only when it is not the seed's square with walls. */
    char box[96] = "", start[PATH_CAP + 128], frames[64];
    if (ds_sim_get_boundary(sim) != DS_BOUNDARY_WALLS ||
        ds_sim_get_box_height(sim) != ds_sim_get_box_width(sim))
        snprintf(box, sizeof box, ", box = %g x %g %s", ds_sim_get_box_width(sim),
                 ds_sim_get_box_height(sim), ds_boundary_name(ds_sim_get_boundary(sim)));
    if (o->restart_path)
        snprintf(start, sizeof start, "restart of %s at frame %ld (t = %g): ", o->restart_path,
                 r->first - 1, ds_sim_get_time(sim));
    else
        start[0] = '\0';
    char what[PATH_CAP + 64];
    if (o->from_path)
        snprintf(what, sizeof what, "from %s", o->from_path);
    else if (o->restart_path)
        snprintf(what, sizeof what, "from the checkpoint");
    else
        snprintf(what, sizeof what, "seed = %llu", (unsigned long long)o->seed);
    if (r->first == 0)
        snprintf(frames, sizeof frames, "%ld frames", o->frames);
    else
        snprintf(frames, sizeof frames, "frames %ld to %ld", r->first, r->last);
    /* The ensemble is named only when a heat bath, a barostat or a shear is
     * set. */
    char ensemble[128] = "";
    if (ds_sim_get_thermostat(sim) != DS_THERMOSTAT_NONE)
        snprintf(ensemble, sizeof ensemble, ", thermostat = %s at kT = %g",
                 ds_thermostat_name(ds_sim_get_thermostat(sim)),
                 ds_sim_get_thermostat_temperature(sim));
    if (ds_sim_get_barostat_pressure(sim) > 0.0)
        snprintf(ensemble + strlen(ensemble), sizeof ensemble - strlen(ensemble), ", pressure = %g",
                 ds_sim_get_barostat_pressure(sim));
    if (ds_sim_get_shear(sim) != 0.0)
        snprintf(ensemble + strlen(ensemble), sizeof ensemble - strlen(ensemble),
                 ", shear rate = %g", ds_sim_get_shear(sim));
    printf("disks: %sN = %zu, R = %g, %s%s, integrator = %s, broad phase = %s%s, %s x %llu steps "
           "-> %s\n",
           start, ds_sim_get_count(sim), ds_sim_get_radius(sim), what, box,
           ds_integrator_name(ds_sim_get_integrator(sim)),
           ds_broadphase_name(ds_sim_get_broadphase(sim)), ensemble, frames,
           (unsigned long long)o->steps_per_frame, o->out_dir);
}

/* A jammed packing's contacts: within 1e-4 of their contact distance (at
 * Z = 10^6 contacts are 1e-6 to 1e-4 apart; docs/physics.md). */
#define CONTACT_GAP 1e-4

static void print_report(const run *r, long asked)
{
    const ds_sim *sim = r->sim;
    const int grew =
        ds_sim_get_growth_z(sim) > 0.0 || ds_sim_get_growth_state(sim) != DS_GROWTH_NONE;
    if (grew || ds_sim_get_radius_max(sim) != ds_sim_get_radius(sim)) {
        printf("area fraction %.6f", ds_sim_get_area_fraction(sim));
        ds_contacts c;
        if (r->jammed_frame >= 0 && ds_sim_get_contacts(sim, CONTACT_GAP, &c, NULL) == DS_OK)
            printf(", jammed at Z = %.4g at t = %.6g, frame %ld (%ld of %ld frames written); "
                   "%.4f contacts per disk, rattlers %zu (%.2f%%)",
                   ds_sim_get_growth_z(sim), ds_sim_get_time(sim), r->jammed_frame,
                   r->jammed_frame - r->first + 1, asked, c.per_disk, c.rattlers,
                   100.0 * c.rattler_fraction);
        else if (ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING)
            printf(", still growing (Z = %.4g)", ds_sim_get_growth_z(sim));
        else if (ds_sim_get_growth_state(sim) == DS_GROWTH_REACHED_ETA)
            printf(", reached by growth");
        else if (ds_sim_get_growth_state(sim) == DS_GROWTH_JAMMED)
            printf(", the packing of a growth that jammed at Z = %.4g", ds_sim_get_growth_z(sim));
        printf("\n");
    }
    const ds_integrator in = ds_sim_get_integrator(sim);
    if (ds_sim_get_barostat_pressure(sim) > 0.0)
        printf("box %.6g x %.6g at beta P sigma^2 = %g: area fraction %.6f, %.1f%% of the area "
               "moves accepted\n",
               ds_sim_get_box_width(sim), ds_sim_get_box_height(sim),
               ds_sim_get_barostat_pressure(sim), ds_sim_get_area_fraction(sim),
               100.0 * ds_sim_get_barostat_acceptance(sim));
    printf("collision processing time: %.6f s (%s over %llu steps)\n",
           ds_sim_get_collision_seconds(sim),
           in == DS_INTEGRATOR_EVENT_DRIVEN
               ? "predicting and processing collisions, wall turns and cell crossings"
           : in == DS_INTEGRATOR_EVENT_CHAIN
               ? "moving the chains: their liftings, cell crossings and wall turns"
               : "sorting, pruning, testing and resolving pairs",
           (unsigned long long)ds_sim_get_steps(sim));
    /* Event chains have no collisions: a chain passes from disk to disk
     * (a lifting) and turns at walls. */
    printf(in == DS_INTEGRATOR_EVENT_CHAIN ? "liftings: %llu, wall turns: %llu\n"
                                           : "disk-disk collisions: %llu, wall reflections: %llu\n",
           (unsigned long long)ds_sim_get_collision_count(sim),
           (unsigned long long)ds_sim_get_wall_count(sim));
    printf("simulation %.3f s, output %.3f s\n", r->sim_seconds, r->out_seconds);
}

/* Steps steps. A growth that finds no memory for the wider cells it
 * needs stops at a step's end, and so does the library's run: the run
 * goes on from there at the radii of then, as the warning says. */
static void run_steps(ds_sim *sim, uint64_t steps)
{
    while (steps > 0) {
        const uint64_t before = ds_sim_get_steps(sim);
        ds_error err;
        if (ds_sim_run(sim, steps, &err) == DS_OK)
            return;
        if (err.status != DS_ERR_NOMEM)
            die(EXIT_RUN, "cannot run: %s", err.message);
        fprintf(stderr, "disks: warning: %s; the run goes on at the radii of then\n", err.message);
        steps -= ds_sim_get_steps(sim) - before;
    }
}

/* The steps up to a frame's. A growing run goes step by step, to see the
 * growth jam (Z past --until-z) in the step it does: the run ends there,
 * its frame the packing as it jammed (run on at fixed radii, a packing
 * compressed fast unjams within a time unit: docs/physics.md). Returns
 * whether it jammed. */
static int advance_frame(ds_sim *sim, uint64_t steps)
{
    uint64_t k = 0;
    while (k < steps && ds_sim_get_growth_state(sim) == DS_GROWTH_GROWING) {
        run_steps(sim, 1);
        ++k;
        if (ds_sim_get_growth_state(sim) == DS_GROWTH_JAMMED)
            return 1;
    }
    if (k < steps)
        run_steps(sim, steps - k);
    return 0;
}

static void run_frames(run *r)
{
    const options *o = r->o;
    frames_begin();
    /* A restart's first row is over the time since its checkpoint's
     * frame, as the uninterrupted run's is since its row before. */
    if (o->restart_path)
        stats_mark(&r->books, r->sim);
    for (long k = 0; k < o->frames; ++k) {
        const long frame = r->first + k;
        /* Frame 0 is the start; a restart's first frame is one frame on. */
        int jammed = 0;
        if (frame > 0 && (k > 0 || o->restart_path)) {
            double t0 = ds_timer_now();
            /* To the frame's step: a restart of a packing that jammed
             * between frames gets back onto them. */
            jammed = advance_frame(r->sim,
                                   (uint64_t)frame * o->steps_per_frame - ds_sim_get_steps(r->sim));
            r->sim_seconds += ds_timer_now() - t0;
        }
        double t0 = ds_timer_now();
        emit_frame(r, frame, jammed);
        /* The frame at T closes the relaxation: its row holds the averages
         * from the start, the rows after it those from it on. Before the
         * checkpoint, so that a restart from it carries the reset. */
        if (!r->measuring && ds_sim_get_time(r->sim) >= o->measure_after) {
            ds_sim_reset_observables(r->sim);
            r->measuring = 1;
        }
        if (o->checkpoint_every && frame > 0 && frame % o->checkpoint_every == 0 &&
            frame < r->last && !stop_signal())
            write_checkpoint(r, frame);
        r->out_seconds += ds_timer_now() - t0;
        progress_show(&r->pr, k + 1, o->frames, ds_sim_get_steps(r->sim));
        int sig = stop_signal();
        if (sig)
            stop_by_signal(r, sig, frame);
        if (jammed) { /* the packing is the run's last frame */
            r->jammed_frame = frame;
            r->last = frame;
            break;
        }
    }
    progress_clear(&r->pr);
}

/* Where the run starts (a checkpoint, a frame or a new request, its
 * disks placed) and its growth, each refused before anything is made. */
static void start_run(run *r, options *o)
{
    if (o->restart_path) {
        r->sim = restart_from(o->restart_path);
        r->first = resume_run_settings(o, r->sim) + 1;
        check_paths(o); /* again, with the paths the checkpoint gave */
        check_restart_frame_file(o, r->sim, r->first - 1);
    } else if (o->from_path) {
        r->sim = start_from_frame(o);
    } else {
        ds_params p = params_of(o);
        ds_species kinds[2];
        ds_mixture mix;
        const ds_mixture *mixture = mixture_of(o, kinds, &mix);
        check_request(&p, mixture, NULL);
        r->sim = create_fresh(&p, mixture);
    }
    start_growth(o, r->sim);
    start_granular(o, r->sim);
    start_ensemble(o, r->sim);
    r->last = r->first + o->frames - 1;
    /* --measure-after: a restart past T continues the checkpoint's
     * averages (its run made the reset); a T past the last frame would
     * measure nothing. */
    r->measuring = !(o->measure_after > 0.0) || ds_sim_get_time(r->sim) >= o->measure_after;
    const double end = (double)((uint64_t)r->last * o->steps_per_frame) * ds_sim_get_dt(r->sim);
    if (!r->measuring && o->measure_after > end)
        die(EXIT_USAGE, "--measure-after %g is past the run's last frame, at t = %g",
            o->measure_after, end);
}

int main(int argc, char **argv)
{
    /* A closed standard descriptor would be handed to the first frame file
     * by mkstemp, and a later printf would then write into the frame. */
    for (int fd = 0; fd <= 2; ++fd)
        if (fcntl(fd, F_GETFD) < 0 && open("/dev/null", fd ? O_WRONLY : O_RDONLY) != fd)
            return EXIT_RUN;
    options o = parse_args(argc, argv);
    catch_signals();
    check_paths(&o);

    run r;
    memset(&r, 0, sizeof r);
    r.o = &o;
    r.checkpoint_frame = -1;
    r.jammed_frame = -1;
    start_run(&r, &o);
    record_run_settings(r.sim, &o, r.last);
    /* A restart from a growth that jammed starts after the jammed frame,
     * which is off the frames' spacing. */
    const int off_spacing =
        r.first > 0 && ds_sim_get_steps(r.sim) != (uint64_t)(r.first - 1) * o.steps_per_frame;
    r.json = frames_json_text(r.sim, &o, off_spacing ? r.first - 1 : -1);
    const int other_json = check_other_runs(&o, r.first, r.last, r.json);

    make_out_dir(o.out_dir);
    open_outputs(&r);
    remove_other_runs(&o, r.last, other_json);
    r.frame_cap = ds_frame_get_size(r.sim, o.velocities);
    r.frame_buf = malloc(r.frame_cap ? r.frame_cap : 1);
    if (!r.frame_buf)
        die(EXIT_RUN, "out of memory for the frame buffer");
    if (!o.quiet)
        print_start(&r);
    fflush(stdout);

    r.pr.enabled = !o.quiet && isatty(STDERR_FILENO);
    r.pr.started = ds_timer_now();
    run_frames(&r);
    close_outputs(&r);
    if (o.checkpoint_path && r.checkpoint_frame != r.last)
        write_checkpoint(&r, r.last);
    if (!o.quiet)
        print_report(&r, o.frames);
    free(r.frame_buf);
    free(r.json);
    ds_sim_destroy(r.sim);
    /* The timing report is output too: `disks 400 5 > /dev/full` must not
     * succeed silently with it lost. */
    int lost = ferror(stdout);
    if (fflush(stdout) != 0 || lost)
        die(EXIT_RUN, "cannot write the report to standard output: %s",
            strerror(errno ? errno : EIO));
    return 0;
}
