/* SPDX-License-Identifier: MIT */
/* gr: the radial distribution function g(r) of one frame file. Public API
 * only (the frame is read with ds_frame_read).
 *
 *   gr [--box L] [--box-y H] [--boundary B] [--dr X] [--rmax X] FRAME.txt
 *
 * The box and its boundary are the run's, from the frames.json disks
 * wrote beside the frame (tools/common/frames_json.h), unless the options
 * give them.
 *
 * Prints "r g(r)" lines, r the middle of each bin: the pairs whose centres
 * are r to r + dr apart, over the pairs an ideal gas of the same N in the
 * same area would have there, N (N - 1) / 2 * pi ((r + dr)^2 - r^2) / A.
 * The pairs are counted by the library (ds_pair_histogram): O(N) at a
 * fixed density. Plot with tools/analysis/plot_gr.plt. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "disk_sim.h"
#include "frames_json.h"

#define PI 3.14159265358979323846
#define MAX_BINS 10000000

enum { EXIT_RUN = 1, EXIT_USAGE = 2 };

static const char usage_text[] =
    "usage: gr [options] FRAME.txt\n"
    "Prints the radial distribution function g(r) of one frame (lines \"x y R\"\n"
    "or \"x y R vx vy\") as lines \"r g(r)\", r the middle of each bin, normalised\n"
    "by the pair count of an ideal gas of the same N in the same area.\n"
    "The box and its boundary are the run's, from the frames.json beside the\n"
    "frame, unless the options give them.\n"
    "  --box L      width of the box (default: the run's, else 1000)\n"
    "  --box-y H    height of the box (default: the run's, else the width)\n"
    "  --boundary B walls, periodic or channel (default: the run's, else walls).\n"
    "               Periodic: distances are minimum images, the area is L H and\n"
    "               rmax at most half the shorter side. With walls the area is\n"
    "               the one the centres reach, (L - 2R)(H - 2R), and the\n"
    "               normalisation ignores the walls, so g(r) falls below 1 as r\n"
    "               grows (pairs near a wall lose the partners beyond it),\n"
    "               towards 0 as rmax nears the box. A channel is periodic\n"
    "               along x (rmax at most L/2), walls along y: L (H - 2R)\n"
    "  --periodic   the same as --boundary periodic\n"
    "  --dr X       bin width (default 0.05 d, d = 2R the largest diameter)\n"
    "  --rmax X     largest r (default 10 d, at most half the shorter side)\n"
    "  --help       show this help and exit\n"
    "exit status: 0 success, 1 unreadable or bad frame, 2 usage error\n";

static void die(int code, const char *fmt, ...)
{
    va_list ap;
    fputs("gr: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

/* A finite number > 0, the whole argument. */
static double positive(const char *opt, const char *s)
{
    if (!s)
        die(EXIT_USAGE, "%s needs a value", opt);
    char *end;
    const double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v) || !(v > 0.0))
        die(EXIT_USAGE, "%s needs a positive number, got '%s'", opt, s);
    return v;
}

/* The box and boundary the options did not give, from the run's
 * frames.json beside the frame; a contradiction is said. */
static void run_box(const char *path, double *box, double *box_y, int *boundary)
{
    char dir[4200], why[512];
    const char *slash = strrchr(path, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path + (slash == path)) : 1,
             slash ? path : ".");
    fj_run run;
    const int got = fj_read(dir, &run, why, sizeof why);
    if (got < 0)
        die(EXIT_RUN, "%s", why);
    const int given = *box > 0.0 || *box_y > 0.0;
    if (*box <= 0.0)
        *box = given || !(run.box_x > 0.0) ? 1000.0 : run.box_x;
    if (*box_y <= 0.0)
        *box_y = given || !(run.box_y > 0.0) ? *box : run.box_y;
    if (got && given && run.box_x > 0.0 && (*box != run.box_x || *box_y != run.box_y))
        fprintf(stderr,
                "gr: warning: %s/%s gives the box %g x %g; taken %g x %g as the options say\n", dir,
                FJ_NAME, run.box_x, run.box_y, *box, *box_y);
    if (got && *boundary >= 0 && run.boundary >= 0 && *boundary != run.boundary)
        fprintf(stderr, "gr: warning: %s/%s gives the boundary %s; taken %s as the options say\n",
                dir, FJ_NAME, ds_boundary_name((ds_boundary)run.boundary),
                ds_boundary_name((ds_boundary)*boundary));
    if (*boundary < 0)
        *boundary = got && run.boundary >= 0 ? run.boundary : DS_BOUNDARY_WALLS;
}

int main(int argc, char **argv)
{
    double box = 0.0, box_y = 0.0, dr = 0.0, rmax = 0.0;
    int boundary = -1;
    const char *path = NULL;
    for (int a = 1; a < argc; ++a) {
        const char *s = argv[a], *v = a + 1 < argc ? argv[a + 1] : NULL;
        if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
            fputs(usage_text, stdout);
            return 0;
        } else if (!strcmp(s, "--periodic")) {
            boundary = DS_BOUNDARY_PERIODIC;
            continue;
        } else if (!strcmp(s, "--boundary")) {
            ds_boundary b = DS_BOUNDARY_WALLS; /* clang cannot see that die() does not return */
            if (!v || ds_boundary_parse(v, &b, NULL) != DS_OK)
                die(EXIT_USAGE, "--boundary must be walls, periodic or channel, got '%s'",
                    v ? v : "");
            boundary = (int)b;
        } else if (!strcmp(s, "--box")) {
            box = positive(s, v);
        } else if (!strcmp(s, "--box-y")) {
            box_y = positive(s, v);
        } else if (!strcmp(s, "--dr")) {
            dr = positive(s, v);
        } else if (!strcmp(s, "--rmax")) {
            rmax = positive(s, v);
        } else if (s[0] == '-' && s[1]) {
            die(EXIT_USAGE, "unknown option '%s' (try --help)", s);
        } else if (path) {
            die(EXIT_USAGE, "one frame file only, got '%s' and '%s'", path, s);
        } else {
            path = s;
            continue;
        }
        ++a;
    }
    if (!path)
        die(EXIT_USAGE, "no frame file given (try --help)");
    run_box(path, &box, &box_y, &boundary);
    const int periodic = boundary == DS_BOUNDARY_PERIODIC,
              channel = boundary == DS_BOUNDARY_CHANNEL;
    const double half = channel ? 0.5 * box : 0.5 * fmin(box, box_y);
    if ((periodic || channel) && rmax > half)
        die(EXIT_USAGE, "--rmax must be at most half the %s (%g) in a %s box, got %g",
            channel ? "width" : "shorter side", half, channel ? "channel" : "periodic", rmax);

    ds_frame f;
    ds_error fe;
    ds_status st = ds_frame_read(path, &f, &fe);
    if (st != DS_OK) {
        char where[160];
        snprintf(where, sizeof where, "%s:%zu", path, fe.index);
        die(EXIT_RUN, "%s: %s", fe.index ? where : path, fe.message);
    }
    if (f.count < 2)
        die(EXIT_RUN, "%s: g(r) needs at least two disks", path);
    double radius = 0.0, covered = 0.0;
    for (size_t j = 0; j < f.count; ++j) {
        const ds_frame_disk *d = &f.disks[j];
        if (!(d->x >= 0.0 && d->x <= box && d->y >= 0.0 && d->y <= box_y))
            die(EXIT_RUN,
                "%s: disk %zu at (%g, %g) is outside the %g x %g box (give --box, --box-y)", path,
                j + 1, d->x, d->y, box, box_y);
        radius = fmax(radius, d->r);
        covered += PI * d->r * d->r;
    }
    const double area = periodic  ? box * box_y
                        : channel ? box * fmax(box_y - 2.0 * radius, 0.0)
                                  : fmax(box - 2.0 * radius, 0.0) * fmax(box_y - 2.0 * radius, 0.0);
    if (!(area > 0.0))
        die(EXIT_RUN, "%s: the disks leave their centres no area in the box", path);
    if (dr == 0.0)
        dr = 0.05 * 2.0 * radius;
    if (rmax == 0.0)
        rmax = fmin(10.0 * 2.0 * radius, half);
    /* Whole bins up to rmax (a hair of slack for rmax an exact multiple). */
    if (rmax / dr > MAX_BINS)
        die(EXIT_USAGE, "--rmax / --dr gives more than 10^7 bins");
    const size_t nbins = (size_t)floor(rmax / dr * (1.0 + 1e-12));
    if (nbins == 0)
        die(EXIT_USAGE, "--dr (%g) must be at most --rmax (%g)", dr, rmax);

    double *xy = malloc(2 * f.count * sizeof *xy);
    uint64_t *hist = calloc(nbins, sizeof *hist);
    if (!xy || !hist)
        die(EXIT_RUN, "out of memory for the disks of %s", path);
    for (size_t j = 0; j < f.count; ++j) {
        xy[j] = f.disks[j].x;
        xy[f.count + j] = f.disks[j].y;
    }
    st = ds_pair_histogram(f.count, xy, xy + f.count, box, box_y, (ds_boundary)boundary, dr, nbins,
                           hist, &fe);
    if (st != DS_OK)
        die(st == DS_ERR_NOMEM ? EXIT_RUN : EXIT_USAGE, "cannot count the pairs of %s: %s", path,
            fe.message);
    free(xy);

    const double n = (double)f.count;
    /* The state point, which tools/analysis/plot_gr.plt puts in its title. */
    printf("# g(r) of %s: N = %zu, area fraction %.4g, d = %g, box %g x %g, %s, dr = %g\n", path,
           f.count, covered / (box * box_y), 2.0 * radius, box, box_y,
           periodic  ? "periodic"
           : channel ? "channel (normalisation ignores its walls)"
                     : "walls (normalisation ignores them)",
           dr);
    for (size_t b = 0; b < nbins; ++b) {
        const double r0 = (double)b * dr, r1 = r0 + dr;
        const double ideal = 0.5 * n * (n - 1.0) * PI * (r1 * r1 - r0 * r0) / area;
        printf("%.9g %.9g\n", r0 + 0.5 * dr, (double)hist[b] / ideal);
    }
    free(hist);
    ds_frame_free(&f);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("gr: cannot write the output\n", stderr);
        return EXIT_RUN;
    }
    return 0;
}
