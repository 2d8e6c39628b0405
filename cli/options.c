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

/* strtod also reads hexadecimal ("0x10"), "nan" and "infinity": a number
 * on our command line is decimal, so anything else is refused up front. */
static int is_decimal_text(const char *s)
{
    return *s && strspn(s, "0123456789.eE+-") == strlen(s);
}

/* A non-negative integer: digits only, or an exact integer in decimal
 * scientific notation (1e5), no sign, no trailing text. */
static int parse_count(const char *s, uint64_t max, uint64_t *out)
{
    if (!is_decimal_text(s) || *s == '-' || *s == '+')
        return 0;
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (*end == '\0' && end != s) {
        if (errno == ERANGE || v > max)
            return -1;
        *out = v;
        return 1;
    }
    double d = strtod(s, &end);
    if (*end != '\0' || end == s || !isfinite(d) || d != floor(d) || d < 0.0)
        return errno == ERANGE ? -1 : 0;
    /* (double)UINT64_MAX rounds up to 2^64, and converting 2^64 to uint64_t
     * is undefined: test against 2^64 itself, then compare as integers. */
    if (!(d < 18446744073709551616.0) || (uint64_t)d > max)
        return -1;
    *out = (uint64_t)d;
    return 1;
}

static uint64_t count_arg(const char *name, const char *s, uint64_t min, uint64_t max)
{
    uint64_t v = 0;
    int ok = parse_count(s, max, &v);
    if (ok == 0)
        die(EXIT_USAGE, "%s must be a whole number, got '%s'", name, s);
    if (ok < 0 || v < min)
        die(EXIT_USAGE, "%s must be between %llu and %llu, got '%s'", name, (unsigned long long)min,
            (unsigned long long)max, s);
    return v;
}

static double radius_arg(const char *s)
{
    char *end;
    errno = 0;
    double r = strtod(s, &end);
    if (end == s || *end != '\0')
        die(EXIT_USAGE, "R must be a number, got '%s'", s);
    /* ERANGE on underflow (1e-400) leaves r tiny: the range check below
     * names it better than "not finite". */
    if (!isfinite(r) || (errno == ERANGE && fabs(r) > 1.0))
        die(EXIT_USAGE, "R must be a finite number, got '%s'", s);
    if (!is_decimal_text(s))
        die(EXIT_USAGE, "R must be a decimal number, got '%s'", s);
    if (!(r > 0.0))
        die(EXIT_USAGE, "R must be a number > 0, got '%s'", s);
    return r;
}

static double box_y_arg(const char *s)
{
    char *end;
    double h = strtod(s, &end);
    if (!is_decimal_text(s) || end == s || *end != '\0' || !isfinite(h) || !(h > 0.0 && h <= 1e9))
        die(EXIT_USAGE, "--box-y must be a number > 0 and <= 1e9, got '%s'", s);
    return h;
}

/* A decimal number > 0 (and below a bound, when one is given). */
static double positive_arg(const char *option, const char *s, double most)
{
    char *end;
    double v = strtod(s, &end);
    const int number = is_decimal_text(s) && end != s && *end == '\0' && isfinite(v);
    if (!number || !(v > 0.0))
        die(EXIT_USAGE, "%s must be a number > 0, got '%s'", option, s);
    if (most > 0.0 && !(v <= most))
        die(EXIT_USAGE, "%s must be a number > 0 and <= %g, got '%s'", option, most, s);
    return v;
}

/* --mixture RATIO:FRACTION: two decimal numbers, RATIO > 0 (the library
 * holds the large disks to the box), 0 < FRACTION < 1. */
static void mixture_arg(const char *s, options *o)
{
    const char *colon = strchr(s, ':');
    char ratio[64];
    if (!colon || (size_t)(colon - s) >= sizeof ratio)
        die(EXIT_USAGE, "--mixture must be RATIO:FRACTION (e.g. 1.4:0.5), got '%s'", s);
    memcpy(ratio, s, (size_t)(colon - s));
    ratio[colon - s] = '\0';
    char *end;
    const double r = strtod(ratio, &end), f = strtod(colon + 1, &end);
    if (!is_decimal_text(ratio) || !is_decimal_text(colon + 1) || *end != '\0' ||
        !(isfinite(r) && r > 0.0) || !(f > 0.0 && f < 1.0))
        die(EXIT_USAGE,
            "--mixture must be RATIO:FRACTION, a radius ratio > 0 and a fraction between 0 "
            "and 1 (e.g. 1.4:0.5), got '%s'",
            s);
    o->mix_ratio = r;
    o->mix_fraction = f;
    o->mixture_text = s;
}

/* A name the library does not know, in the command's words
 * ("--integrator 'exact' is not one of 'step', 'event'"). */
static void refuse_name(ds_status st, const ds_error *err)
{
    if (st != DS_OK) {
        char words[sizeof err->message + 16];
        die(EXIT_USAGE, "%s", in_command_words(err, words, sizeof words));
    }
}

/* A file name given to an option. */
static const char *file_arg(const char *option, const char *value)
{
    if (!*value)
        die(EXIT_USAGE, "%s needs a file name", option);
    return value;
}

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
    if (o->checkpoint_every && !o->checkpoint_path)
        die(EXIT_USAGE, "--checkpoint-every needs --checkpoint FILE");
    if (o->from_path && o->mixture_text)
        die(EXIT_USAGE, "--mixture cannot be given with --from: the frame gives every radius");
    if ((o->until_eta > 0.0 || o->until_z > 0.0) && !(o->grow_rate > 0.0))
        die(EXIT_USAGE, "%s needs --grow RATE", o->until_eta > 0.0 ? "--until-eta" : "--until-z");
    /* Growth needs exact contact times and no walls; a checkpoint's
     * system is checked once it is read. */
    if (o->grow_rate > 0.0 && !o->restart_path && o->integrator != DS_INTEGRATOR_EVENT_DRIVEN)
        die(EXIT_USAGE, "--grow needs --integrator event (the time step cannot grow disks)");
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
    if (o->grow_rate > 0.0 && (o->thermostat != DS_THERMOSTAT_NONE || o->pressure > 0.0))
        die(EXIT_USAGE,
            "%s cannot be given with --grow: growth takes out its own heat in a box "
            "of its own",
            o->pressure > 0.0 ? "--pressure" : "--thermostat");
    /* Growth measures its own Z over windows of collisions, and its
     * pressure is not an equilibrium one to average. */
    if (o->measure_after > 0.0 && o->grow_rate > 0.0)
        die(EXIT_USAGE, "--measure-after cannot be given with --grow: a growing packing has no "
                        "equilibrium to measure");
    if (npos == 1 || (npos == 0 && !o->restart_path && !o->from_path))
        die(EXIT_USAGE, "missing %s: usage: disks N R [options] (try --help)",
            npos == 0 ? "N and R" : "R");
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
    THERMOSTAT,
    TEMPERATURE,
    THERMOSTAT_RATE,
    PRESSURE,
    BAROSTAT_EVERY,
    BAROSTAT_STEP
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
             {"--thermostat", 0},
             {"--temperature", 0},
             {"--thermostat-rate", 0},
             {"--pressure", 0},
             {"--barostat-every", 0},
             {"--barostat-step", 0}};

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

/* The heat bath's and the barostat's options: numbers > 0 here, held to
 * their bounds by the library (start.c). */
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
    default:
        o->barostat_step = positive_arg("--barostat-step", value, 0.0);
    }
}

/* Option which (names[]) with its value. */
static void set_option(options *o, int which, const char *value, first_options *first)
{
    ds_error err;
    switch (which) {
    case SEED:
        o->seed = count_arg("--seed", value, 0, UINT64_MAX);
        if (!first->placement)
            first->placement = "--seed";
        break;
    case FRAMES:
        o->frames = (long)count_arg("--frames", value, 1, MAX_FRAMES);
        break;
    case STEPS:
        o->steps_per_frame = count_arg("--steps-per-frame", value, 1, 1000000000u);
        break;
    case OUT:
        if (!*value)
            die(EXIT_USAGE, "--out needs a directory name");
        o->out_dir = value;
        break;
    case STATS:
        o->stats_path = file_arg("--stats", value);
        break;
    case BROADPHASE:
        refuse_name(ds_broadphase_parse(value, &o->broadphase, &err), &err);
        break;
    case INTEGRATOR:
        refuse_name(ds_integrator_parse(value, &o->integrator, &err), &err);
        break;
    case TRAJECTORY:
        o->trajectory_path = file_arg("--trajectory", value);
        break;
    case BOX_Y:
        o->box_y = box_y_arg(value);
        break;
    case CHECKPOINT:
        o->checkpoint_path = file_arg("--checkpoint", value);
        break;
    case CHECKPOINT_EVERY:
        o->checkpoint_every = (long)count_arg("--checkpoint-every", value, 1, MAX_FRAMES);
        break;
    case RESTART:
        o->restart_path = file_arg("--restart", value);
        break;
    case FROM:
        o->from_path = file_arg("--from", value);
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
    /* The growth's targets: numbers > 0 here, held to their bounds by
     * the library (start.c). */
    case UNTIL_ETA:
        o->until_eta = positive_arg("--until-eta", value, 0.0);
        break;
    case UNTIL_Z:
        o->until_z = positive_arg("--until-z", value, 0.0);
        break;
    case MEASURE_AFTER:
        o->measure_after = positive_arg("--measure-after", value, 1e12);
        break;
    case BOUNDARY:
        boundary_arg(o, value, first);
        break;
    default:
        ensemble_option(o, which, value);
    }
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
        die(EXIT_USAGE, "unknown option '%.*s' (try --help)", (int)len, a);
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
        printf(usage_text, (unsigned)DS_DEFAULT_SEED);
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

options parse_args(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    o.seed = DS_DEFAULT_SEED;
    o.frames = 500;
    o.steps_per_frame = 100;
    o.out_dir = ".";
    o.broadphase = DS_BROADPHASE_AUTO;

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
            die(EXIT_USAGE, "unknown option '%s' (try --help)", a);
        if (npos < 2)
            positional[npos++] = a;
        else
            die(EXIT_USAGE, "unexpected argument '%s': expected only N and R (try --help)", a);
    }
    check_combination(&o, npos, first.system, first.placement);
    if (npos == 2) {
        o.n = (size_t)count_arg("N", positional[0], 1, UINT64_MAX);
        o.radius = radius_arg(positional[1]);
        o.have_n = 1;
    }
    return o;
}
