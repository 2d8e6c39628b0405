/* SPDX-License-Identifier: MIT */
/* The command line of disks: N, R and the options, each checked as it is
 * read; anything malformed or out of range ends the command with a usage
 * error that names it. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* The combinations the command refuses: a checkpoint holds the system
 * (N, R, the box, the integrator and its broad phase, and the state the
 * seed and placement made), so --restart takes none of them; a frame holds
 * every position and velocity, so --from takes no seed or placement. */
static void check_combination(const options *o, int npos, const char *system_option,
                              const char *placement_option)
{
    if (o->restart_path && o->from_path)
        die(EXIT_USAGE, "--restart and --from are two ways to start a run: give one");
    if (o->restart_path && npos > 0)
        die(EXIT_USAGE, "--restart takes N and R from the checkpoint: give no N and R");
    if (o->restart_path && system_option)
        die(EXIT_USAGE, "%s cannot be given with --restart: the checkpoint holds the system",
            system_option);
    if (o->from_path && placement_option)
        die(EXIT_USAGE,
            "%s cannot be given with --from: the frame gives every position and velocity",
            placement_option);
    /* (A restart's may come from its checkpoint: run_settings.c.) */
    if (o->checkpoint_every && !o->checkpoint_path && !o->restart_path)
        die(EXIT_USAGE, "--checkpoint-every needs --checkpoint FILE");
    if (o->from_path && o->mixture_text)
        die(EXIT_USAGE, "--mixture cannot be given with --from: the frame gives every radius");
    if (o->from_path && o->area_fraction > 0.0)
        die(EXIT_USAGE,
            "--area-fraction cannot be given with --from: the frame gives every radius");
    if (o->from_path && o->speed > 0.0)
        die(EXIT_USAGE, "--speed cannot be given with --from: the frame gives every velocity");
    if (o->area_fraction > 0.0 && npos == 2)
        die(EXIT_USAGE, "give R or --area-fraction, not both");
    if ((o->until_eta > 0.0 || o->until_z > 0.0) && !(o->grow_rate > 0.0))
        die(EXIT_USAGE, "%s needs --grow RATE", o->until_eta > 0.0 ? "--until-eta" : "--until-z");
    /* Growth needs exact contact times and no walls; a checkpoint's
     * system is checked once it is read. */
    if (o->grow_rate > 0.0 && !o->restart_path && o->integrator != DS_INTEGRATOR_EVENT_DRIVEN)
        die(EXIT_USAGE, "--grow needs --integrator event (only exact dynamics grows disks)");
    if (o->grow_rate > 0.0 && !o->restart_path && o->boundary != DS_BOUNDARY_PERIODIC)
        die(EXIT_USAGE, "--grow needs --periodic (the compression runs in a periodic box)");
    /* A heat bath's and a barostat's numbers need them; growth takes out
     * its own heat in a box of its own. */
    if ((o->temperature > 0.0 || o->thermostat_rate > 0.0) && o->thermostat == DS_THERMOSTAT_NONE)
        die(EXIT_USAGE, "%s needs --thermostat andersen|isokinetic",
            o->temperature > 0.0 ? "--temperature" : "--thermostat-rate");
    if ((o->barostat_every || o->barostat_step > 0.0 || o->barostat_aspect) && !(o->pressure > 0.0))
        die(EXIT_USAGE, "%s needs --pressure BP",
            o->barostat_every        ? "--barostat-every"
            : o->barostat_step > 0.0 ? "--barostat-step"
                                     : "--barostat-aspect");
    if (o->pressure > 0.0 && !o->restart_path && o->boundary != DS_BOUNDARY_PERIODIC)
        die(EXIT_USAGE, "--pressure needs --periodic (the barostat moves a periodic box only)");
    if (o->grow_rate > 0.0 &&
        (o->thermostat != DS_THERMOSTAT_NONE || o->pressure > 0.0 || o->shear_given))
        die(EXIT_USAGE,
            "%s cannot be given with --grow: growth takes out its own heat in a box "
            "of its own",
            o->pressure > 0.0 ? "--pressure"
            : o->shear_given  ? "--shear"
                              : "--thermostat");
    /* Growth measures its own Z over windows of collisions, and its
     * pressure is not an equilibrium one to average. */
    if (o->measure_after > 0.0 && o->grow_rate > 0.0)
        die(EXIT_USAGE, "--measure-after cannot be given with --grow: a growing packing has no "
                        "equilibrium to measure");
    if ((npos == 1 && !(o->area_fraction > 0.0)) ||
        (npos == 0 && !o->restart_path && !o->from_path))
        die(EXIT_USAGE, "missing %s: usage: disks N R [options] (try --help)",
            npos == 0 ? "N and R" : "R (or --area-fraction ETA)");
}

/* The options that take a value, in the order of their table, names[]. */
enum {
    SEED,
    FRAMES,
    STEPS,
    OUT,
    STATS,
    BROADPHASE,
    INTEGRATOR,
    TRAJECTORY,
    BOX_Y,
    CHECKPOINT,
    CHECKPOINT_EVERY,
    RESTART,
    FROM,
    MIXTURE,
    MASS,
    GROW,
    UNTIL_ETA,
    UNTIL_Z,
    MEASURE_AFTER,
    BOUNDARY,
    BOX,
    DT,
    SPEED,
    AREA_FRACTION,
    GSD,
    RESTITUTION,
    WALL_RESTITUTION,
    CONTACT_TIME,
    DRIVE,
    GRAVITY,
    THERMOSTAT,
    TEMPERATURE,
    THERMOSTAT_RATE,
    PRESSURE,
    BAROSTAT_EVERY,
    BAROSTAT_STEP,
    SHEAR
};
/* Those that describe the system with a system flag. */
static const struct {
    const char *name;
    int system;
} names[] = {{"--seed", 1},
             {"--frames", 0},
             {"--steps-per-frame", 0},
             {"--out", 0},
             {"--stats", 0},
             {"--broadphase", 1},
             {"--integrator", 1},
             {"--trajectory", 0},
             {"--box-y", 1},
             {"--checkpoint", 0},
             {"--checkpoint-every", 0},
             {"--restart", 0},
             {"--from", 0},
             {"--mixture", 1},
             {"--mass", 1},
             {"--grow", 0},
             {"--until-eta", 0},
             {"--until-z", 0},
             {"--measure-after", 0},
             {"--boundary", 1},
             {"--box", 1},
             {"--dt", 1},
             {"--speed", 1},
             {"--area-fraction", 1},
             {"--gsd", 0},
             {"--restitution", 0},
             {"--wall-restitution", 0},
             {"--contact-time", 0},
             {"--drive", 0},
             {"--gravity", 0},
             {"--thermostat", 0},
             {"--temperature", 0},
             {"--thermostat-rate", 0},
             {"--pressure", 0},
             {"--barostat-every", 0},
             {"--barostat-step", 0},
             {"--shear", 0}};

/* The first option given that describes the system, the first that
 * describes the placement (see check_combination), and the boundary
 * asked for (--boundary, --periodic), if any. */
typedef struct first_options {
    const char *system, *placement, *boundary;
} first_options;

/* --boundary B (--periodic being --boundary periodic): given twice, the
 * same both times. */
static void boundary_arg(options *o, const char *value, first_options *first)
{
    ds_error err;
    refuse_name(ds_boundary_parse(value, &o->boundary, &err), &err);
    if (first->boundary && strcmp(first->boundary, value) != 0)
        die(EXIT_USAGE, "two boundaries asked for: %s and %s (--periodic is --boundary periodic)",
            first->boundary, value);
    first->boundary = value;
}

/* The granular rules: numbers here, held to their bounds by the library
 * once the simulation exists (start.c). */
static void granular_arg(options *o, int which, const char *value)
{
    if (which == RESTITUTION)
        o->restitution = number_arg("--restitution", value);
    else if (which == WALL_RESTITUTION)
        o->wall_restitution = number_arg("--wall-restitution", value);
    else if (which == CONTACT_TIME)
        o->contact_time = positive_arg("--contact-time", value, 0.0);
    else if (which == DRIVE)
        o->drive = positive_arg("--drive", value, 0.0);
    else
        o->gravity = positive_arg("--gravity", value, 0.0);
}

/* The heat bath's, the barostat's and the shear's options: numbers (> 0
 * but the shear's) here, held to their bounds by the library (start.c). */
static void ensemble_option(options *o, int which, const char *value)
{
    ds_error err;
    switch (which) {
    case THERMOSTAT:
        refuse_name(ds_thermostat_parse(value, &o->thermostat, &err), &err);
        break;
    case TEMPERATURE:
        o->temperature = positive_arg("--temperature", value, 0.0);
        break;
    case THERMOSTAT_RATE:
        o->thermostat_rate = positive_arg("--thermostat-rate", value, 0.0);
        break;
    case PRESSURE:
        o->pressure = positive_arg("--pressure", value, 0.0);
        break;
    case BAROSTAT_EVERY:
        o->barostat_every = count_arg("--barostat-every", value, 1, 1000000000u);
        break;
    case SHEAR: /* either sign; 0 stops a checkpoint's shear */
        o->shear = number_arg("--shear", value);
        o->shear_given = 1;
        break;
    default:
        o->barostat_step = positive_arg("--barostat-step", value, 0.0);
    }
}

/* Option which (names[]) with its value, if it is one of the run's: its
 * frames, its files, where it starts; 0 if not. */
static int set_run_option(options *o, int which, const char *value)
{
    switch (which) {
    case FRAMES:
        o->frames = (long)count_arg("--frames", value, 1, MAX_FRAMES);
        o->frames_given = 1;
        return 1;
    case STEPS:
        o->steps_per_frame = count_arg("--steps-per-frame", value, 1, 1000000000u);
        o->steps_given = 1;
        return 1;
    case OUT:
        if (!*value)
            die(EXIT_USAGE, "--out needs a directory name");
        o->out_dir = value;
        o->out_given = 1;
        return 1;
    case STATS:
        o->stats_path = file_arg("--stats", value);
        return 1;
    case TRAJECTORY:
        o->trajectory_path = file_arg("--trajectory", value);
        return 1;
    case GSD:
        o->gsd_path = file_arg("--gsd", value);
        return 1;
    case CHECKPOINT:
        o->checkpoint_path = file_arg("--checkpoint", value);
        return 1;
    case CHECKPOINT_EVERY:
        o->checkpoint_every = (long)count_arg("--checkpoint-every", value, 1, MAX_FRAMES);
        return 1;
    case RESTART:
        o->restart_path = file_arg("--restart", value);
        return 1;
    case FROM:
        o->from_path = file_arg("--from", value);
        return 1;
    case MEASURE_AFTER:
        o->measure_after = positive_arg("--measure-after", value, 1e12);
        return 1;
    default:
        return 0;
    }
}

/* Option which (names[]) with its value: the run's, or the system's and
 * its protocols'. Numbers are held here to being numbers > 0, and to
 * their bounds by the library (start.c), which says why in its words. */
static void set_option(options *o, int which, const char *value, first_options *first)
{
    ds_error err;
    if (set_run_option(o, which, value))
        return;
    switch (which) {
    case SEED:
        o->seed = count_arg("--seed", value, 0, UINT64_MAX);
        if (!first->placement)
            first->placement = "--seed";
        break;
    case BROADPHASE:
        refuse_name(ds_broadphase_parse(value, &o->broadphase, &err), &err);
        break;
    case INTEGRATOR:
        refuse_name(ds_integrator_parse(value, &o->integrator, &err), &err);
        break;
    case BOX_Y:
        o->box_y = side_arg("--box-y", value);
        break;
    case MIXTURE:
        mixture_arg(value, o);
        break;
    case MASS:
        refuse_name(ds_mass_rule_parse(value, &o->mass_rule, &err), &err);
        break;
    case GROW:
        o->grow_rate = positive_arg("--grow", value, 0.0);
        break;
    case UNTIL_ETA:
        o->until_eta = positive_arg("--until-eta", value, 0.0);
        break;
    case UNTIL_Z:
        o->until_z = positive_arg("--until-z", value, 0.0);
        break;
    case BOUNDARY:
        boundary_arg(o, value, first);
        break;
    case BOX:
        o->box = side_arg("--box", value);
        break;
    case DT:
        o->dt = positive_arg("--dt", value, 0.0);
        break;
    case SPEED:
        o->speed = positive_arg("--speed", value, 0.0);
        break;
    case AREA_FRACTION:
        o->area_fraction = positive_arg("--area-fraction", value, 0.0);
        if (!(o->area_fraction < 1.0))
            die(EXIT_USAGE, "--area-fraction must be a number > 0 and < 1, got '%s'", value);
        break;
    default:
        if (which < THERMOSTAT)
            granular_arg(o, which, value);
        else
            ensemble_option(o, which, value);
    }
}

/* The options without a value (flag_option). */
static const char *const flags[] = {"--help",       "-h",          "--version", "--quiet",   "-q",
                                    "--velocities", "--overwrite", "--lattice", "--periodic"};

/* An option the command does not know, and the one perhaps meant. */
static void unknown_option(const char *typed, size_t len)
{
    const size_t count = sizeof names / sizeof names[0], nflags = sizeof flags / sizeof flags[0];
    const char *all[sizeof names / sizeof names[0] + sizeof flags / sizeof flags[0]];
    for (size_t k = 0; k < count; ++k)
        all[k] = names[k].name;
    for (size_t k = 0; k < nflags; ++k)
        all[count + k] = flags[k];
    const char *meant = closest_option(typed, len, all, count + nflags);
    if (meant)
        die(EXIT_USAGE, "unknown option '%.*s': did you mean %s? (try --help)", (int)len, typed,
            meant);
    die(EXIT_USAGE, "unknown option '%.*s' (try --help)", (int)len, typed);
}

/* --name VALUE or --name=VALUE at argv[*i] (a, starting with "--"). */
static void value_option(options *o, int argc, char **argv, int *i, first_options *first)
{
    const char *a = argv[*i];
    const char *eq = strchr(a, '=');
    size_t len = eq ? (size_t)(eq - a) : strlen(a);
    const char *value = eq ? eq + 1 : (*i + 1 < argc ? argv[*i + 1] : NULL);
    int which = -1;
    for (int k = 0; k < (int)(sizeof names / sizeof names[0]); ++k)
        if (strlen(names[k].name) == len && strncmp(a, names[k].name, len) == 0)
            which = k;
    if (which < 0)
        unknown_option(a, len);
    if (!value)
        die(EXIT_USAGE, "%s needs a value (try --help)", names[which].name);
    if (!eq)
        ++*i;
    if (names[which].system && !first->system)
        first->system = names[which].name;
    set_option(o, which, value, first);
}

/* An option without a value: whether a is one (--help and --version end
 * the command here). */
static int flag_option(options *o, const char *a, first_options *first)
{
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
        print_usage();
        exit(0);
    }
    if (strcmp(a, "--version") == 0) {
        printf("disks %s\n", ds_version());
        exit(0);
    }
    if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0)
        o->quiet = 1;
    else if (strcmp(a, "--velocities") == 0)
        o->velocities = 1;
    else if (strcmp(a, "--overwrite") == 0)
        o->overwrite = 1;
    else if (strcmp(a, "--lattice") == 0)
        o->placement = DS_PLACEMENT_LATTICE;
    else if (strcmp(a, "--periodic") == 0)
        boundary_arg(o, "periodic", first);
    else if (strcmp(a, "--barostat-aspect") == 0)
        o->barostat_aspect = 1;
    else
        return 0;
    if (strcmp(a, "--lattice") == 0 && !first->placement)
        first->placement = "--lattice";
    if ((strcmp(a, "--lattice") == 0 || strcmp(a, "--periodic") == 0) && !first->system)
        first->system = a;
    return 1;
}

/* --area-fraction's R: N pi R^2 (the small kind's, and RATIO^2 R^2 for
 * the large ones of a --mixture, counted as start.c counts them) over the
 * box's area is ETA. */
static double radius_of_area_fraction(const options *o)
{
    const double width = o->box > 0.0 ? o->box : 1000.0;
    const double height = o->box_y > 0.0 ? o->box_y : width;
    const double n = (double)o->n;
    const double large = o->mixture_text ? floor(o->mix_fraction * n + 0.5) : 0.0;
    const double weight = (n - large) + large * o->mix_ratio * o->mix_ratio;
    const double r = sqrt(o->area_fraction * width * height / (3.14159265358979323846 * weight));
    if (!(r > 0.0) || !isfinite(r))
        die(EXIT_USAGE, "--area-fraction %g gives no radius for N = %zu", o->area_fraction, o->n);
    return r;
}

options parse_args(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    o.seed = DS_DEFAULT_SEED;
    o.frames = 500;
    o.steps_per_frame = 100;
    o.out_dir = ".";
    o.broadphase = DS_BROADPHASE_AUTO;
    o.restitution = o.wall_restitution = NAN; /* not given */

    const char *positional[2];
    int npos = 0;
    first_options first = {NULL, NULL, NULL};
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (flag_option(&o, a, &first))
            continue;
        if (a[0] == '-' && a[1] == '-') {
            value_option(&o, argc, argv, &i, &first);
            continue;
        }
        /* "-5" and "-inf" are (bad) numbers, reported as such below. */
        char *num_end;
        (void)strtod(a, &num_end);
        if (a[0] == '-' && a[1] != '\0' && num_end == a)
            unknown_option(a, strlen(a));
        if (npos < 2)
            positional[npos++] = a;
        else
            die(EXIT_USAGE, "unexpected argument '%s': expected only N and R (try --help)", a);
    }
    check_combination(&o, npos, first.system, first.placement);
    if (npos >= 1) {
        o.n = (size_t)count_arg("N", positional[0], 1, UINT64_MAX);
        o.radius = npos == 2 ? radius_arg(positional[1]) : radius_of_area_fraction(&o);
        o.have_n = 1;
    }
    return o;
}
