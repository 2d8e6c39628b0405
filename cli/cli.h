/* SPDX-License-Identifier: MIT */
/* The disks command's one header: what its files share. options.c reads
 * the command line, usage.c says what it takes (--help); start.c checks
 * where the run starts (a new request, --restart's checkpoint, --from's
 * frame); outputs.c checks every path and makes --out; frames_json.c
 * describes the run beside its frames; files.c writes files so that no
 * partial one is ever seen, and decides what a signal does; checkpoint.c
 * writes checkpoints; stats.c the --stats rows; report.c says what went
 * wrong; disks.c runs. The
 * command uses the library only through disk_sim.h, and only it prints. */
#ifndef DISKS_CLI_H
#define DISKS_CLI_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "disk_sim.h"

enum { EXIT_RUN = 1, EXIT_USAGE = 2 };
#define MAX_FRAMES 10000 /* frame_NNNN.txt has four digits */
#define PATH_CAP 4200    /* a path and the suffix of its temporary */

typedef struct options {
    size_t n; /* N and R: given (have_n), or from --restart's or --from's file */
    double radius;
    int have_n;
    uint64_t seed;
    long frames;
    uint64_t steps_per_frame;
    const char *out_dir;
    const char *stats_path;
    const char *trajectory_path;
    const char *gsd_path;        /* --gsd FILE, or NULL */
    const char *checkpoint_path; /* NULL: none */
    long checkpoint_every;       /* 0: only at the end */
    const char *restart_path;    /* --restart FILE, or NULL */
    const char *from_path;       /* --from FRAME, or NULL */
    int quiet, velocities, overwrite;
    ds_broadphase broadphase;
    ds_integrator integrator;
    ds_placement placement;
    ds_boundary boundary;
    double box_y; /* 0: square */
    /* --box, --dt, --speed (0: the library's defaults); --area-fraction,
     * from which R is worked out (0: R given) */
    double box, dt, speed, area_fraction;
    /* --mixture RATIO:FRACTION: a FRACTION of the disks of radius RATIO R
     * (mix_fraction 0: one kind); --mass area|equal */
    double mix_ratio, mix_fraction;
    const char *mixture_text;
    ds_mass_rule mass_rule;
    /* --grow RATE, --until-eta, --until-z (0: not given) */
    double grow_rate, until_eta, until_z;
    /* --measure-after T: the observables reset at the first frame at t >=
     * T (0: never) */
    double measure_after;
    /* --restitution, --wall-restitution (NaN: not given), --contact-time,
     * --drive, --gravity (0: not given) */
    double restitution, wall_restitution, contact_time, drive, gravity;
    /* --thermostat KIND (NONE: not given), --temperature KT,
     * --thermostat-rate NU (0: not given, the library's default) */
    ds_thermostat thermostat;
    double temperature, thermostat_rate;
    /* --pressure BP (0: none), --barostat-every K, --barostat-step D (0:
     * the library's defaults), --barostat-aspect */
    double pressure, barostat_step;
    uint64_t barostat_every;
    int barostat_aspect;
    /* --shear RATE (any finite number; shear_given: it was given, so
     * that --shear 0 stops a checkpoint's shear) */
    double shear;
    int shear_given;
    /* Which of the run's settings the command line gave: a restart takes
     * the others from its checkpoint (run_settings.c). */
    int frames_given, steps_given, out_given;
    /* --stats, --trajectory, --gsd: the file the checkpointed run wrote,
     * which the restart goes on writing (its rows up to the checkpoint
     * kept). */
    int stats_continues, trajectory_continues, gsd_continues;
} options;

/* gcc and clang check die's format and know it does not return. */
#if defined(__GNUC__)
#define DIES __attribute__((noreturn, format(printf, 2, 3)))
#define DIES_QUIETLY __attribute__((noreturn))
#else
#define DIES
#define DIES_QUIETLY
#endif

/* report.c: "disks: " and the message on one line of stderr, then exit. */
void die(int code, const char *fmt, ...) DIES;
/* report.c: the library's reason in the command's words: a sentence that
 * begins with the field it names ("radius = 600 ...", "rate = 5 ...")
 * begins with the command's name for it ("R = 600 ...", "--grow 5 ...");
 * out (cap bytes) holds it, or the library's sentence is returned. */
const char *in_command_words(const ds_error *err, char *out, size_t cap);

/* usage.c: the help (--help), on stdout */
void print_usage(void);

/* options.c */
options parse_args(int argc, char **argv);

/* arguments.c: a value of the command line, or a usage error naming it. */
int is_decimal_text(const char *s); /* digits, '.', 'e', signs only (no hex, nan, inf) */
uint64_t count_arg(const char *name, const char *s, uint64_t min, uint64_t max);
double radius_arg(const char *s);
double side_arg(const char *option, const char *s);                  /* --box, --box-y */
double positive_arg(const char *option, const char *s, double most); /* most 0: no bound */
double number_arg(const char *option, const char *s);                /* any finite decimal number */
void mixture_arg(const char *s, options *o);
void refuse_name(ds_status st, const ds_error *err); /* a name the library did not parse */
const char *file_arg(const char *option, const char *value);

/* suggest.c: of names[0 .. count), the one nearest to typed (len bytes),
 * if near enough to be a typo of it; else NULL. */
const char *closest_option(const char *typed, size_t len, const char *const *names, size_t count);

/* start.c: the request checked (with --from, as the frame's: from is its
 * path), a new simulation, or one from a checkpoint or a frame. */
void check_request(const ds_params *p, const ds_mixture *mixture, const char *from);
ds_params params_of(const options *o);
/* --mixture's two kinds into kinds and mix; NULL for one kind. */
const ds_mixture *mixture_of(const options *o, ds_species kinds[2], ds_mixture *mix);
ds_sim *create_fresh(const ds_params *p, const ds_mixture *mixture);
/* --grow started, once the simulation exists (a new one, a checkpoint's
 * or a frame's), or refused with the library's reason. */
void start_growth(const options *o, ds_sim *sim);
/* --restitution, --wall-restitution, --contact-time, --gravity and
 * --drive set on the simulation, or refused with the library's reason
 * (a usage error), before anything is made. */
void start_granular(const options *o, ds_sim *sim);
/* --thermostat, --pressure and --shear set likewise (a checkpoint's go
 * on unless given again). */
void start_ensemble(const options *o, ds_sim *sim);
ds_sim *restart_from(const char *path);
long restart_frame(const options *o, const ds_sim *sim); /* the checkpoint's frame */
void check_restart_frame_file(const options *o, const ds_sim *sim, long frame);
ds_sim *start_from_frame(options *o); /* sets o->n and o->radius */

/* run_settings.c: the run's settings in its checkpoints (the library's
 * metadata text), and a restart going on with them: the options the
 * command line did not give come from the checkpoint, a contradiction is
 * refused. resume_run_settings returns the checkpoint's frame. */
void record_run_settings(ds_sim *sim, const options *o, long last);
long resume_run_settings(options *o, const ds_sim *sim);

/* outputs.c */
void check_paths(const options *o);
int frame_number(const char *base); /* k of frame_kkkk.txt, else -1 */
void make_out_dir(const char *path);
/* The frames in --out that are another run's: those numbered after last,
 * or all of them when its frames.json describes another run (json is this
 * run's). Refused unless --overwrite; a restart (first > 0) keeps the
 * frames before first, so their frames.json must be its run's. Returns
 * whether frames.json is another run's, for remove_other_runs. */
int check_other_runs(const options *o, long first, long last, const char *json);
void remove_other_runs(const options *o, long last, int other_json);

/* frames_json.c: the run's description beside its frames, frames.json:
 * its text (jammed_frame >= 0: the frame at which growth jammed, at
 * ds_sim_get_time), written atomically into --out; and an existing
 * frames.json in dir compared with json: 0 if none or the same run's, 1
 * another run's, 2 not a disksim one, with why ("has box [1000, 500],
 * this run's [1000, 1000]"). */
char *frames_json_text(const ds_sim *sim, const options *o, long jammed_frame);
void frames_json_write(const options *o, const char *json);
int frames_json_compare(const char *dir, const char *json, char *why, size_t cap);

/* files.c: signals */
void catch_signals(void);
void hold_signals(sigset_t *old);
void release_signals(const sigset_t *old);
void frames_begin(void);
int stop_signal(void); /* the signal that asked the run to stop, or 0 */
void end_by_signal(int sig) DIES_QUIETLY;
/* files.c: directories made by the run, removed if it fails before a frame */
void note_created_dir(const char *path);
void keep_created_dirs(void);
/* files.c: whole files */
void split_path(const char *path, char *dir, size_t cap, const char **base);
/* snprintf for a path: one too long for the buffer ends the command. */
void path_printf(char *out, size_t cap, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
int write_file_atomic(const char *dir, const char *name, const void *data, size_t len, int durable,
                      const char **why);
int probe_dir(const char *dir, const char *name); /* 0, or why a file cannot be made there */
int is_special_file(const char *path);
int write_file_in_place(const char *path, const void *data, size_t len, const char **why);
/* files.c: files that grow frame by frame (--stats, --trajectory, --gsd) */
typedef struct output {
    const char *option, *path;
    FILE *f;
    int slot; /* its pending temporary, -1 when written in place */
} output;
void output_open(output *out, const char *option, const char *path);
void output_write(output *out, const void *data, size_t len);
void output_close(output *out);
/* The file so far put in place (its temporary renamed over the path), and
 * written in place from then on: at a checkpoint, so that a run killed
 * later keeps its rows up to there for the restart to go on with. */
void output_publish(output *out);

/* carry_over.c: a restart going on with the --stats or --trajectory file
 * its run wrote copies its rows or frames up to frame `last` into out
 * (just opened); 1 if there was a file to go on with, 0 if none. The
 * --gsd file is copied whole, its frames after sim's step taken out of
 * its index; its writer then goes on with it. */
int carry_over_stats(output *out, const char *header, long last);
int carry_over_trajectory(output *out, const ds_sim *sim, uint64_t steps_per_frame, long last);
int carry_over_gsd(output *out, const ds_sim *sim);

/* stats.c: the --stats file's header and its rows. The shear stress of a
 * row is the mean over the time since the row before (or since the
 * checkpoint a restart starts from): stats_mark records the stress
 * integral there, and each row records its own for the next. */
extern const char stats_header[];
typedef struct stats_books {
    int marked;        /* a previous row's (or the checkpoint's) integral is held */
    double s_xy, time; /* ds_sim_get_stress_integral's xy part, and the time */
} stats_books;
void stats_mark(stats_books *b, const ds_sim *sim);
void stats_row(output *out, long frame, const ds_sim *sim, stats_books *b);

/* checkpoint.c */
void checkpoint_write(const ds_sim *sim, const char *path);
void checkpoint_probe(const char *path);

#endif
