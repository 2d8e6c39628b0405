/* gr: the radial distribution function g(r) of one frame file. Public API
 * only (the frame is read with ds_read_frame).
 *
 *   gr [--box L] [--box-y H] [--periodic] [--dr X] [--rmax X] FRAME.txt
 *
 * Prints "r g(r)" lines, r the middle of each bin: the pairs whose centres
 * are r to r + dr apart, over the pairs an ideal gas of the same N in the
 * same area would have there, N (N - 1) / 2 * pi ((r + dr)^2 - r^2) / A.
 * Pairs are found in a cell grid of cells at least rmax wide: O(N) at a
 * fixed density. Plot with tools/analysis/plot_gr.plt. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "disk_sim.h"

#define PI 3.14159265358979323846
#define MAX_BINS 10000000

enum { EXIT_RUN = 1, EXIT_USAGE = 2 };

static const char usage_text[] =
    "usage: gr [options] FRAME.txt\n"
    "Prints the radial distribution function g(r) of one frame (lines \"x y R\"\n"
    "or \"x y R vx vy\") as lines \"r g(r)\", r the middle of each bin, normalised\n"
    "by the pair count of an ideal gas of the same N in the same area.\n"
    "  --box L      width of the box (default 1000)\n"
    "  --box-y H    height of the box (default: the width)\n"
    "  --periodic   periodic box: distances are minimum images, the area is\n"
    "               L H and rmax at most half the shorter side. Without it the\n"
    "               box has walls: the area is the one the centres reach,\n"
    "               (L - 2R)(H - 2R), and the normalisation ignores the walls,\n"
    "               so g(r) falls below 1 as r grows (pairs near a wall lose\n"
    "               the partners beyond it), towards 0 as rmax nears the box\n"
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

typedef struct grid {
    size_t nx, ny;
    size_t *start; /* nx ny + 1: disks of cell c are order[start[c] .. start[c + 1]) */
    size_t *order;
    size_t *cell;
} grid;

static size_t cells_along(double len, double side, size_t cap)
{
    const double fit = floor(len / side);
    return !(fit >= 1.0) ? 1 : fit >= (double)cap ? cap : (size_t)fit;
}

static size_t index_of(double v, double len, size_t cells)
{
    const double c = floor(v / len * (double)cells);
    return !(c >= 0.0) ? 0 : c >= (double)cells ? cells - 1 : (size_t)c;
}

/* Cells at least `side` wide, at most about four per disk (a huge box with
 * a small rmax would want far more, mostly empty). 0, or -1 out of memory. */
static int grid_build(grid *g, const ds_frame *f, double bx, double by, double side)
{
    const size_t n = f->count, cap = 4 * n + 64;
    g->nx = cells_along(bx, side, cap);
    g->ny = cells_along(by, side, cap);
    while ((double)g->nx * (double)g->ny > (double)cap) {
        if (g->nx >= g->ny)
            g->nx = (g->nx + 1) / 2;
        else
            g->ny = (g->ny + 1) / 2;
    }
    const size_t cells = g->nx * g->ny;
    g->start = calloc(cells + 1, sizeof *g->start);
    g->order = malloc(n * sizeof *g->order);
    g->cell = malloc(n * sizeof *g->cell);
    if (!g->start || !g->order || !g->cell)
        return -1;
    for (size_t j = 0; j < n; ++j) {
        g->cell[j] =
            index_of(f->disks[j].y, by, g->ny) * g->nx + index_of(f->disks[j].x, bx, g->nx);
        ++g->start[g->cell[j] + 1];
    }
    for (size_t c = 0; c < cells; ++c)
        g->start[c + 1] += g->start[c];
    for (size_t j = 0; j < n; ++j)
        g->order[g->start[g->cell[j]]++] = j;
    for (size_t c = cells; c > 0; --c)
        g->start[c] = g->start[c - 1];
    g->start[0] = 0;
    return 0;
}

/* Counts each pair closer than nbins * dr once into hist. */
static void count_pairs(const ds_frame *f, const grid *g, double bx, double by, int periodic,
                        double dr, size_t nbins, double *hist)
{
    /* With one or two cells along a periodic side the cells left and right
     * are one cell: scan each neighbour cell once. */
    int ox[3] = {-1, 0, 1}, oy[3] = {-1, 0, 1}, kx = 3, ky = 3;
    if (periodic && g->nx < 3) {
        ox[0] = 0, ox[1] = 1, kx = (int)g->nx;
    }
    if (periodic && g->ny < 3) {
        oy[0] = 0, oy[1] = 1, ky = (int)g->ny;
    }
    const double rmax = (double)nbins * dr, rmax2 = rmax * rmax;
    for (size_t j = 0; j < f->count; ++j) {
        const long cx = (long)(g->cell[j] % g->nx), cy = (long)(g->cell[j] / g->nx);
        for (int b = 0; b < ky; ++b) {
            long sy = cy + oy[b];
            if (sy < 0 || sy >= (long)g->ny) {
                if (!periodic)
                    continue;
                sy = sy < 0 ? sy + (long)g->ny : sy - (long)g->ny;
            }
            for (int a = 0; a < kx; ++a) {
                long sx = cx + ox[a];
                if (sx < 0 || sx >= (long)g->nx) {
                    if (!periodic)
                        continue;
                    sx = sx < 0 ? sx + (long)g->nx : sx - (long)g->nx;
                }
                const size_t c = (size_t)sy * g->nx + (size_t)sx;
                for (size_t s = g->start[c]; s < g->start[c + 1]; ++s) {
                    const size_t k = g->order[s];
                    if (k <= j)
                        continue;
                    double dx = f->disks[k].x - f->disks[j].x, dy = f->disks[k].y - f->disks[j].y;
                    if (periodic) {
                        dx -= bx * round(dx / bx);
                        dy -= by * round(dy / by);
                    }
                    const double r2 = dx * dx + dy * dy;
                    if (r2 < rmax2) {
                        const size_t bin = (size_t)(sqrt(r2) / dr);
                        hist[bin < nbins ? bin : nbins - 1] += 1.0;
                    }
                }
            }
        }
    }
}

int main(int argc, char **argv)
{
    double box = 1000.0, box_y = 0.0, dr = 0.0, rmax = 0.0;
    int periodic = 0;
    const char *path = NULL;
    for (int a = 1; a < argc; ++a) {
        const char *s = argv[a], *v = a + 1 < argc ? argv[a + 1] : NULL;
        if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
            fputs(usage_text, stdout);
            return 0;
        } else if (!strcmp(s, "--periodic")) {
            periodic = 1;
            continue;
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
    if (box_y == 0.0)
        box_y = box;
    const double half = 0.5 * fmin(box, box_y);
    if (periodic && rmax > half)
        die(EXIT_USAGE,
            "--rmax must be at most half the shorter side (%g) in a periodic box, got %g", half,
            rmax);

    ds_frame f;
    ds_frame_error fe;
    ds_status st = ds_read_frame(path, &f, &fe);
    if (st != DS_OK) {
        char where[160];
        snprintf(where, sizeof where, "%s:%zu", path, fe.line);
        die(EXIT_RUN, "%s: %s", fe.line ? where : path,
            fe.message[0] ? fe.message : ds_status_str(st));
    }
    if (f.count < 2)
        die(EXIT_RUN, "%s: g(r) needs at least two disks", path);
    double radius = 0.0;
    for (size_t j = 0; j < f.count; ++j) {
        const ds_frame_disk *d = &f.disks[j];
        if (!(d->x >= 0.0 && d->x <= box && d->y >= 0.0 && d->y <= box_y))
            die(EXIT_RUN,
                "%s: disk %zu at (%g, %g) is outside the %g x %g box (give --box, --box-y)", path,
                j + 1, d->x, d->y, box, box_y);
        radius = fmax(radius, d->r);
    }
    const double area =
        periodic ? box * box_y : fmax(box - 2.0 * radius, 0.0) * fmax(box_y - 2.0 * radius, 0.0);
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

    grid g = {0, 0, NULL, NULL, NULL};
    double *hist = calloc(nbins ? nbins : 1, sizeof *hist);
    if (!hist || grid_build(&g, &f, box, box_y, (double)nbins * dr) != 0)
        die(EXIT_RUN, "out of memory for the disks of %s", path);
    count_pairs(&f, &g, box, box_y, periodic, dr, nbins, hist);

    const double n = (double)f.count;
    printf("# g(r) of %s: N = %zu, d = %g, box %g x %g, %s, dr = %g\n", path, f.count, 2.0 * radius,
           box, box_y, periodic ? "periodic" : "walls (normalisation ignores them)", dr);
    for (size_t b = 0; b < nbins; ++b) {
        const double r0 = (double)b * dr, r1 = r0 + dr;
        const double ideal = 0.5 * n * (n - 1.0) * PI * (r1 * r1 - r0 * r0) / area;
        printf("%.9g %.9g\n", r0 + 0.5 * dr, hist[b] / ideal);
    }
    free(hist);
    free(g.start);
    free(g.order);
    free(g.cell);
    ds_frame_free(&f);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("gr: cannot write the output\n", stderr);
        return EXIT_RUN;
    }
    return 0;
}
