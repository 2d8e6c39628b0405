/* Order: the bond-orientational order parameter psi6, per disk and for the
 * whole system.
 *
 * psi6_j = (1/n_j) sum_k exp(6 i theta_jk) over the n_j disks k whose
 * centres are closer than a cutoff to j's, theta_jk the angle of the bond
 * j -> k from the x axis. Six neighbours at multiples of 60 degrees give 1
 * times the lattice's phase, a liquid's bonds point anywhere and average
 * out. Neighbours are found in a cell grid of cells at least a cutoff wide,
 * so each disk looks only at the 3 x 3 cells around its own: O(N). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "observe/observe.h"

/* Closer centres are the first shell of neighbours: the first peak of
 * g(r) of the dense liquid has fallen below 1 by 1.4 diameters, and its
 * first minimum (1.55 d at area fraction 0.70) and a crystal's second
 * shell (sqrt 3 spacings) lie beyond. */
#define PSI6_CUTOFF_DIAMETERS 1.4

/* A dilute system would want more cells than disks (a tiny cutoff in a huge
 * box); beyond a few cells per disk, larger cells cost only a few more
 * distance tests, far less than clearing and scanning empty cells. */
#define CELLS_PER_DISK 4
#define MIN_CELL_CAP 64

typedef struct grid {
    size_t nx, ny;
    double inv_wx, inv_wy; /* cells per unit length */
    size_t *start;         /* nx * ny + 1: disks of cell c are order[start[c] .. start[c+1]) */
    size_t *order;         /* n disk numbers sorted by cell */
    size_t *cell;          /* n: the cell of each disk */
} grid;

/* Cells along a side of length len, each at least cutoff wide, at most cap. */
static size_t cells_along(double len, double cutoff, size_t cap)
{
    const double fit = floor(len / cutoff);
    if (!(fit >= 1.0))
        return 1;
    return fit >= (double)cap ? cap : (size_t)fit;
}

/* Wraps (periodic) or clamps (walls) a coordinate to a cell index. */
static size_t cell_index(double v, double len, double inv_w, size_t cells, int periodic)
{
    if (periodic)
        v -= len * floor(v / len);
    const double c = floor(v * inv_w);
    if (!(c >= 0.0))
        return 0;
    /* v == len after rounding in the wrap, or a centre outside a wall box. */
    return c >= (double)cells ? cells - 1 : (size_t)c;
}

static void grid_free(grid *g)
{
    free(g->start);
    free(g->order);
    free(g->cell);
}

static ds_status grid_build(grid *g, size_t n, const double *x, const double *y, double box_x,
                            double box_y, double cutoff, int periodic)
{
    /* The caller made sure n * CELLS_PER_DISK cells are addressable. */
    const size_t cap = n * CELLS_PER_DISK < MIN_CELL_CAP ? MIN_CELL_CAP : n * CELLS_PER_DISK;
    g->nx = cells_along(box_x, cutoff, cap);
    g->ny = cells_along(box_y, cutoff, cap);
    /* Too many cells: merge them, which keeps every cell at least a cutoff
     * wide (nx only ever decreases). */
    while ((double)g->nx * (double)g->ny > (double)cap) {
        if (g->nx >= g->ny)
            g->nx = (g->nx + 1) / 2;
        else
            g->ny = (g->ny + 1) / 2;
    }
    g->inv_wx = (double)g->nx / box_x;
    g->inv_wy = (double)g->ny / box_y;
    const size_t cells = g->nx * g->ny;
    g->start = calloc(cells + 1, sizeof *g->start);
    g->order = malloc(n * sizeof *g->order);
    g->cell = malloc(n * sizeof *g->cell);
    if (!g->start || !g->order || !g->cell) {
        grid_free(g);
        return DS_ERR_NOMEM;
    }
    /* A counting sort by cell: each cell's disks end up side by side. */
    for (size_t j = 0; j < n; ++j) {
        const size_t cx = cell_index(x[j], box_x, g->inv_wx, g->nx, periodic);
        const size_t cy = cell_index(y[j], box_y, g->inv_wy, g->ny, periodic);
        g->cell[j] = cy * g->nx + cx;
        ++g->start[g->cell[j] + 1];
    }
    for (size_t c = 0; c < cells; ++c)
        g->start[c + 1] += g->start[c];
    for (size_t j = 0; j < n; ++j)
        g->order[g->start[g->cell[j]]++] = j;
    /* The scatter moved each start to the next cell's: shift back. */
    for (size_t c = cells; c > 0; --c)
        g->start[c] = g->start[c - 1];
    g->start[0] = 0;
    return DS_OK;
}

/* The neighbouring cell offsets along a side of `cells` cells, each cell
 * once: with one or two cells a periodic -1 and +1 are the same cell (or
 * the cell itself), which must not be scanned twice. */
static int offsets(size_t cells, int periodic, int *out)
{
    if (periodic && cells < 3) {
        out[0] = 0;
        out[1] = 1;
        return (int)cells;
    }
    out[0] = -1;
    out[1] = 0;
    out[2] = 1;
    return 3;
}

/* The neighbour cell c + d along a side, or -1 past a wall. */
static long shifted(size_t c, int d, size_t cells, int periodic)
{
    long s = (long)c + d;
    if (s < 0 || s >= (long)cells) {
        if (!periodic)
            return -1;
        s = s < 0 ? s + (long)cells : s - (long)cells;
    }
    return s;
}

/* The minimum image of a separation along a periodic side of length len.
 * round, not a single shift by len: a caller of the public function may
 * pass centres that are not wrapped into the box, any number of boxes
 * away. */
static double nearest_image(double d, double len) { return d - len * round(d / len); }

ds_status ds_local_psi6(size_t n, const double *x, const double *y, double box_x, double box_y,
                        ds_boundary boundary, double cutoff, double *re, double *im)
{
    if (!x || !y || !re || !im)
        return DS_ERR_ARG;
    if (!(box_x > 0.0) || !isfinite(box_x) || !(box_y > 0.0) || !isfinite(box_y) ||
        !(cutoff > 0.0) || !isfinite(cutoff))
        return DS_ERR_ARG;
    if (boundary != DS_WALLS && boundary != DS_PERIODIC)
        return DS_ERR_ARG;
    const int periodic = boundary == DS_PERIODIC;
    /* Beyond half the box a second image could be as close as the first. */
    if (periodic && !(cutoff < 0.5 * fmin(box_x, box_y)))
        return DS_ERR_ARG;
    for (size_t j = 0; j < n; ++j)
        if (!isfinite(x[j]) || !isfinite(y[j]))
            return DS_ERR_ARG;
    if (n == 0)
        return DS_OK;
    if (n > SIZE_MAX / sizeof(size_t) / CELLS_PER_DISK - 1)
        return DS_ERR_NOMEM;

    grid g;
    ds_status st = grid_build(&g, n, x, y, box_x, box_y, cutoff, periodic);
    if (st != DS_OK)
        return st;
    int ox[3], oy[3];
    const int kx = offsets(g.nx, periodic, ox), ky = offsets(g.ny, periodic, oy);
    const double cut2 = cutoff * cutoff;
    for (size_t j = 0; j < n; ++j) {
        const size_t cx = g.cell[j] % g.nx, cy = g.cell[j] / g.nx;
        double sum_re = 0.0, sum_im = 0.0;
        size_t bonds = 0;
        for (int b = 0; b < ky; ++b) {
            const long ny = shifted(cy, oy[b], g.ny, periodic);
            if (ny < 0)
                continue;
            for (int a = 0; a < kx; ++a) {
                const long nx = shifted(cx, ox[a], g.nx, periodic);
                if (nx < 0)
                    continue;
                const size_t c = (size_t)ny * g.nx + (size_t)nx;
                for (size_t s = g.start[c]; s < g.start[c + 1]; ++s) {
                    const size_t k = g.order[s];
                    double dx = x[k] - x[j], dy = y[k] - y[j];
                    if (periodic) {
                        dx = nearest_image(dx, box_x);
                        dy = nearest_image(dy, box_y);
                    }
                    const double r2 = dx * dx + dy * dy;
                    /* A coincident centre has no bond direction. */
                    if (k == j || !(r2 < cut2) || r2 == 0.0)
                        continue;
                    /* exp(6 i theta) = (u / |u|)^6 for u = dx + i dy: three
                     * complex products and no trigonometry. */
                    const double inv = 1.0 / sqrt(r2);
                    const double ur = dx * inv, ui = dy * inv;
                    const double u2r = ur * ur - ui * ui, u2i = 2.0 * ur * ui;
                    const double u3r = u2r * ur - u2i * ui, u3i = u2r * ui + u2i * ur;
                    sum_re += u3r * u3r - u3i * u3i;
                    sum_im += 2.0 * u3r * u3i;
                    ++bonds;
                }
            }
        }
        re[j] = bonds ? sum_re / (double)bonds : 0.0;
        im[j] = bonds ? sum_im / (double)bonds : 0.0;
    }
    grid_free(&g);
    return DS_OK;
}

double ds_psi6(const ds_sim *sim)
{
    if (!sim)
        return NAN;
    const ds_world *w = &sim->world;
    const size_t n = w->n;
    double *re = malloc(n * sizeof *re), *im = malloc(n * sizeof *im);
    double result = NAN;
    /* The arrays hold the disks in slot order, which the mean ignores. */
    if (re && im &&
        ds_local_psi6(n, sim->disks.x, sim->disks.y, w->box, w->box_y, w->boundary,
                      PSI6_CUTOFF_DIAMETERS * 2.0 * w->radius, re, im) == DS_OK) {
        double sum_re = 0.0, sum_im = 0.0;
        for (size_t j = 0; j < n; ++j) {
            sum_re += re[j];
            sum_im += im[j];
        }
        result = hypot(sum_re, sum_im) / (double)n;
    }
    free(re);
    free(im);
    return result;
}
