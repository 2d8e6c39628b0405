/* SPDX-License-Identifier: MIT */
/* disks: the command-line front end. Parses arguments, runs the simulation,
 * writes frame_NNNN.txt files crash-safe, prints the seed's timing. All
 * printing and exit codes live here, never in the library. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "disk_sim.h"

enum { EXIT_RUN = 1, EXIT_USAGE = 2 };
#define MAX_FRAMES 10000 /* frame_NNNN.txt has four digits */

typedef struct options {
    size_t n;
    double radius;
    uint64_t seed;
    long frames;
    uint64_t steps_per_frame;
    const char *out_dir;
    const char *stats_path;
    const char *trajectory_path;
    int quiet, velocities;
    ds_broadphase broadphase;
    ds_integrator integrator;
    ds_placement placement;
    ds_boundary boundary;
    double box_y; /* 0: square */
} options;

static const char *const usage_text =
    "usage: disks N R [options]\n"
    "Simulates N hard disks of radius R in the box [0,1000]^2 and writes\n"
    "frame_0000.txt, frame_0001.txt, ... with one line \"x y R\" per disk.\n"
    "\n"
    "options:\n"
    "  --seed S             random seed, 0..2^64-1 (default %u)\n"
    "  --frames F           frames to write, 1..10000 (default 500)\n"
    "  --steps-per-frame K  steps of dt = 0.001 between frames (default 100)\n"
    "  --out DIR            directory for the frames, created if missing (default .)\n"
    "  --velocities         write \"x y R vx vy\" lines instead of \"x y R\"\n"
    "  --stats FILE         write one CSV row of observables per frame to FILE\n"
    "  --trajectory FILE    also write every frame to FILE, one extended XYZ trajectory\n"
    "  --lattice            start on a triangular lattice instead of at random\n"
    "  --periodic           periodic box (nearest image) instead of walls\n"
    "  --box-y H            height of the box, 0 < H <= 1e9 (default 1000, square)\n"
    "  --integrator I       step (the fixed time step, default) or event (exact\n"
    "                       event-driven dynamics)\n"
    "  --broadphase B       step: sap, strips, brute or auto; event: cells, brute\n"
    "                       or auto (default auto)\n"
    "  -q, --quiet          print nothing but errors and warnings\n"
    "  -h, --help           show this help and exit\n"
    "  --version            show the version and exit\n"
    "\n"
    "exit status: 0 success, 1 run-time error (placement, I/O), 2 usage error\n";

static void die(int code, const char *fmt, ...)
{
    va_list ap;
    fputs("disks: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

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

static ds_broadphase broadphase_arg(const char *s)
{
    const ds_broadphase all[] = {DS_SAP, DS_SAP_STRIPS, DS_BRUTE_FORCE, DS_AUTO, DS_CELLS};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k)
        if (strcmp(s, ds_broadphase_name(all[k])) == 0)
            return all[k];
    die(EXIT_USAGE, "--broadphase must be sap, strips, cells, brute or auto, got '%s'", s);
    return DS_AUTO;
}

/* The integrators are the library's, by name: ds_integrator_name says
 * "unknown" past the last one. */
static ds_integrator integrator_arg(const char *s)
{
    char known[128] = "";
    for (int k = 0; strcmp(ds_integrator_name((ds_integrator)k), "unknown") != 0; ++k) {
        const char *name = ds_integrator_name((ds_integrator)k);
        if (strcmp(s, name) == 0)
            return (ds_integrator)k;
        snprintf(known + strlen(known), sizeof known - strlen(known), "%s%s", k ? " or " : "",
                 name);
    }
    die(EXIT_USAGE, "--integrator must be %s, got '%s'", known, s);
    return DS_TIME_STEP;
}

static options parse_args(int argc, char **argv)
{
    options o;
    memset(&o, 0, sizeof o);
    o.seed = DS_DEFAULT_SEED;
    o.frames = 500;
    o.steps_per_frame = 100;
    o.out_dir = ".";
    o.broadphase = DS_AUTO;

    const char *positional[2];
    int npos = 0;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            printf(usage_text, (unsigned)DS_DEFAULT_SEED);
            exit(0);
        }
        if (strcmp(a, "--version") == 0) {
            printf("disks %s\n", ds_version());
            exit(0);
        }
        if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            o.quiet = 1;
            continue;
        }
        if (strcmp(a, "--velocities") == 0) {
            o.velocities = 1;
            continue;
        }
        if (strcmp(a, "--lattice") == 0) {
            o.placement = DS_LATTICE;
            continue;
        }
        if (strcmp(a, "--periodic") == 0) {
            o.boundary = DS_PERIODIC;
            continue;
        }
        if (a[0] == '-' && a[1] == '-') {
            /* --name VALUE or --name=VALUE */
            const char *eq = strchr(a, '=');
            size_t len = eq ? (size_t)(eq - a) : strlen(a);
            const char *value = eq ? eq + 1 : (i + 1 < argc ? argv[i + 1] : NULL);
            const char *names[] = {"--seed",       "--frames",     "--steps-per-frame",
                                   "--out",        "--stats",      "--broadphase",
                                   "--integrator", "--trajectory", "--box-y"};
            int which = -1;
            for (int k = 0; k < (int)(sizeof names / sizeof names[0]); ++k)
                if (strlen(names[k]) == len && strncmp(a, names[k], len) == 0)
                    which = k;
            if (which < 0)
                die(EXIT_USAGE, "unknown option '%.*s' (try --help)", (int)len, a);
            if (!value)
                die(EXIT_USAGE, "%s needs a value (try --help)", names[which]);
            if (!eq)
                ++i;
            switch (which) {
            case 0:
                o.seed = count_arg("--seed", value, 0, UINT64_MAX);
                break;
            case 1:
                o.frames = (long)count_arg("--frames", value, 1, MAX_FRAMES);
                break;
            case 2:
                o.steps_per_frame = count_arg("--steps-per-frame", value, 1, 1000000000u);
                break;
            case 3:
                if (!*value)
                    die(EXIT_USAGE, "--out needs a directory name");
                o.out_dir = value;
                break;
            case 4:
                if (!*value)
                    die(EXIT_USAGE, "--stats needs a file name");
                o.stats_path = value;
                break;
            case 5:
                o.broadphase = broadphase_arg(value);
                break;
            case 6:
                o.integrator = integrator_arg(value);
                break;
            case 7:
                if (!*value)
                    die(EXIT_USAGE, "--trajectory needs a file name");
                o.trajectory_path = value;
                break;
            default:
                o.box_y = box_y_arg(value);
            }
            continue;
        }
        /* "-5" and "-inf" are (bad) numbers, reported as such below. */
        char *num_end;
        (void)strtod(a, &num_end);
        if (a[0] == '-' && a[1] != '\0' && num_end == a)
            die(EXIT_USAGE, "unknown option '%s' (try --help)", a);
        if (npos == 2)
            die(EXIT_USAGE, "unexpected argument '%s': expected only N and R (try --help)", a);
        positional[npos++] = a;
    }
    if (npos < 2)
        die(EXIT_USAGE, "missing %s: usage: disks N R [options] (try --help)",
            npos == 0 ? "N and R" : "R");
    o.n = (size_t)count_arg("N", positional[0], 1, UINT64_MAX);
    o.radius = radius_arg(positional[1]);
    return o;
}

/* The library's sentence about a field, in the command's words: a
 * message begins with the ds_params member it is about ("radius = 600
 * ..."), which the command calls by its option or argument. */
static const char *in_command_words(const char *field, const char *message, char *out, size_t cap)
{
    static const char *const names[][2] = {
        {"n", "N"},
        {"radius", "R"},
        {"box_y", "--box-y"},
        {"broadphase", "--broadphase"},
        {"integrator", "--integrator"},
    };
    const size_t flen = strlen(field);
    for (size_t k = 0; *field && k < sizeof names / sizeof names[0]; ++k) {
        if (strcmp(field, names[k][0]) != 0 || strncmp(message, field, flen) != 0 ||
            strncmp(message + flen, " = ", 3) != 0)
            continue;
        /* An option takes its value as "--box-y 5", an argument as "R = 5". */
        snprintf(out, cap, "%s%s%s", names[k][1], names[k][1][0] == '-' ? " " : " = ",
                 message + flen + 3);
        return out;
    }
    return message;
}

/* Refuses, before any work, what the library would refuse (in its words)
 * or what this machine cannot hold, and passes on its warnings. */
static void check_request(const ds_params *p)
{
    unsigned warnings = 0;
    ds_params_error why;
    char words[sizeof why.message + 16];
    ds_status st = ds_diagnose_params(p, &warnings, &why);
    if (st == DS_ERR_NOMEM)
        die(EXIT_USAGE, "%s", in_command_words(why.field, why.message, words, sizeof words));
    size_t bytes = 0;
    if (st != DS_ERR_ARG && ds_memory_needed(p, &bytes) != DS_OK)
        die(EXIT_USAGE, "N = %zu disks cannot be held in memory", p->n);
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0 && (double)bytes > 0.8 * (double)pages * (double)page)
        die(EXIT_USAGE, "N = %zu disks need %.1f GiB, more than this machine's %.1f GiB", p->n,
            (double)bytes / 1073741824.0, (double)pages * (double)page / 1073741824.0);
    if (st != DS_OK)
        die(st == DS_ERR_PLACEMENT ? EXIT_RUN : EXIT_USAGE, "%s",
            in_command_words(why.field, why.message, words, sizeof words));
    if (warnings)
        fprintf(stderr, "disks: warning: %s\n",
                in_command_words("radius", why.warning, words, sizeof words));
}

static void make_dirs(const char *path)
{
    char buf[4096];
    size_t len = strlen(path);
    if (len >= sizeof buf)
        die(EXIT_USAGE, "--out path is too long");
    memcpy(buf, path, len + 1);
    for (size_t k = 1; k <= len; ++k) {
        if (buf[k] != '/' && buf[k] != '\0')
            continue;
        char saved = buf[k];
        buf[k] = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            die(EXIT_RUN, "cannot create directory '%s': %s", buf, strerror(errno));
        buf[k] = saved;
    }
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode))
        die(EXIT_RUN, "'%s' is not a directory", path);
}

/* Writes len bytes to f and closes it, checking every step (fwrite into
 * stdio's buffer succeeds even on a full disk; only the flush and the
 * close tell). Returns 0, or the errno of the first failure. */
static int write_and_close(FILE *f, const char *data, size_t len)
{
    size_t put = fwrite(data, 1, len, f);
    int failed = put != len || fflush(f) != 0 || ferror(f);
    int saved = failed ? (errno ? errno : EIO) : 0;
    if (fclose(f) != 0 && !saved)
        saved = errno ? errno : EIO;
    return saved;
}

/* Writes len bytes to dir/name via a temporary file and rename(), so a
 * reader never sees a half-written file. Returns 0 or sets *why. */
static int write_file_atomic_now(const char *dir, const char *name, const char *data, size_t len,
                                 const char **why)
{
    char final_path[4200], tmp_path[4200];
    snprintf(final_path, sizeof final_path, "%s/%s", dir, name);
    snprintf(tmp_path, sizeof tmp_path, "%s/.%s.XXXXXX", dir, name);
    int fd = mkstemp(tmp_path);
    if (fd < 0) {
        *why = strerror(errno);
        return -1;
    }
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        *why = strerror(errno);
        close(fd);
        unlink(tmp_path);
        return -1;
    }
    fchmod(fd, 0644);
    int saved = write_and_close(f, data, len);
    if (!saved && rename(tmp_path, final_path) != 0)
        saved = errno ? errno : EIO;
    if (saved) {
        unlink(tmp_path);
        *why = strerror(saved);
        return -1;
    }
    return 0;
}

/* Ctrl-C, kill and hang-up wait while a file is written: the signal is
 * delivered once the temporary is renamed or removed, so an interrupted run
 * leaves complete frames and no temporary (only SIGKILL can still strand
 * one, as a hidden .frame_NNNN.txt.XXXXXX). */
static int write_file_atomic(const char *dir, const char *name, const char *data, size_t len,
                             const char **why)
{
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigprocmask(SIG_BLOCK, &block, &old);
    int rc = write_file_atomic_now(dir, name, data, len, why);
    sigprocmask(SIG_SETMASK, &old, NULL);
    return rc;
}

/* --stats may name a device, a pipe or a symbolic link (/dev/full, a FIFO,
 * /dev/stdout): renaming a temporary over it would replace the device node
 * or the link itself, so only a regular file (or a new name) is replaced;
 * anything else is written in place, with the same error checks. */
static int is_special_file(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && !S_ISREG(st.st_mode);
}

static int write_file_in_place(const char *path, const char *data, size_t len, const char **why)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        *why = strerror(errno);
        return -1;
    }
    int saved = write_and_close(f, data, len);
    if (saved)
        *why = strerror(saved);
    return saved ? -1 : 0;
}

/* Splits the path of --stats or --trajectory into directory and base name,
 * refusing at once (before any simulation time is spent) a path that
 * cannot become a file. */
static const char *output_split(const char *option, const char *path, char *dir, size_t dir_cap)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    if (!slash)
        snprintf(dir, dir_cap, ".");
    else if (slash == path)
        snprintf(dir, dir_cap, "/");
    else
        snprintf(dir, dir_cap, "%.*s", (int)(slash - path), path);
    struct stat st;
    if (!*base || (stat(path, &st) == 0 && S_ISDIR(st.st_mode)))
        die(EXIT_USAGE, "%s needs a file name, got directory '%s'", option, path);
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
        die(EXIT_RUN, "cannot write %s %s: '%s' is not a directory", option, path, dir);
    return base;
}

/* --trajectory: every frame appended as the run goes (a trajectory can be
 * far larger than --stats, which is held in memory), into a temporary file
 * in the same directory renamed over FILE at the end, or written in place
 * for a device, pipe or link (see is_special_file). Until the rename the
 * temporary is removed by every way the run can end early: an error (die
 * exits, and exit runs remove_pending), or Ctrl-C, kill or hang-up. */
typedef struct trajectory {
    FILE *f;
    const char *path;
    char *buf;
    size_t cap;
} trajectory;

static char pending_tmp[4200]; /* the temporary not yet renamed, "" if none */

static void remove_pending(void)
{
    if (pending_tmp[0])
        unlink(pending_tmp);
}

static void remove_pending_and_die(int sig)
{
    remove_pending(); /* unlink is async-signal-safe */
    signal(sig, SIG_DFL);
    raise(sig);
}

static void block_signals(sigset_t *old)
{
    sigset_t block;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigprocmask(SIG_BLOCK, &block, old);
}

static void trajectory_open(trajectory *t, const char *path, const char *dir, const char *base,
                            const ds_sim *sim)
{
    t->path = path;
    t->cap = ds_xyz_frame_size(sim);
    if (!(t->buf = malloc(t->cap)))
        die(EXIT_RUN, "out of memory for --trajectory");
    if (is_special_file(path)) {
        if (!(t->f = fopen(path, "wb")))
            die(EXIT_RUN, "cannot write %s: %s", path, strerror(errno));
        return;
    }
    char tmp[sizeof pending_tmp];
    snprintf(tmp, sizeof tmp, "%s/.%s.XXXXXX", dir, base);
    sigset_t old;
    block_signals(&old);
    int fd = mkstemp(tmp);
    if (fd >= 0) {
        memcpy(pending_tmp, tmp, sizeof tmp);
        atexit(remove_pending);
        const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
        for (size_t k = 0; k < 3; ++k) {
            struct sigaction sa, was;
            memset(&sa, 0, sizeof sa);
            sa.sa_handler = remove_pending_and_die;
            sigemptyset(&sa.sa_mask);
            /* A signal ignored on purpose (nohup) stays ignored. */
            if (sigaction(sigs[k], NULL, &was) == 0 && was.sa_handler != SIG_IGN)
                sigaction(sigs[k], &sa, NULL);
        }
    }
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (fd < 0)
        die(EXIT_RUN, "cannot write %s: %s", path, strerror(errno));
    fchmod(fd, 0644);
    if (!(t->f = fdopen(fd, "wb")))
        die(EXIT_RUN, "cannot write %s: %s", path, strerror(errno));
}

static void trajectory_append(trajectory *t, const ds_sim *sim)
{
    size_t len = 0;
    ds_format_xyz_frame(sim, t->buf, t->cap, &len);
    /* Flushed every frame, so a full disk is reported at once. */
    if (fwrite(t->buf, 1, len, t->f) != len || fflush(t->f) != 0 || ferror(t->f))
        die(EXIT_RUN, "cannot write %s: %s", t->path, strerror(errno ? errno : EIO));
}

static void trajectory_close(trajectory *t)
{
    int saved = fclose(t->f) != 0 ? (errno ? errno : EIO) : 0;
    free(t->buf);
    if (!saved && pending_tmp[0]) {
        sigset_t old;
        block_signals(&old);
        if (rename(pending_tmp, t->path) != 0)
            saved = errno ? errno : EIO;
        else
            pending_tmp[0] = '\0';
        sigprocmask(SIG_SETMASK, &old, NULL);
    }
    if (saved)
        die(EXIT_RUN, "cannot write %s: %s", t->path, strerror(saved));
}

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
