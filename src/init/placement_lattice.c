/* SPDX-License-Identifier: MIT */
/* Lattice placement (DS_PLACEMENT_LATTICE): the disks on a triangular lattice that
 * fills the box as evenly as it can, the way dense states are started.
 *
 * The lattice has m rows of c sites, alternate rows shifted by half a site,
 * with c m >= n. Along a periodic axis the sites tile it exactly (spacing
 * box / c along x, box_y / m between rows, m even so the shifted rows
 * alternate across the seam too); along walls they span the band the
 * centres reach, edge to edge.
 * Of all (c, m), the one whose closest pair of sites is farthest apart is
 * taken; a box with box_y / box = sqrt(3) m / (2 c) fits it without strain, up to
 * close packing (area fraction pi / (2 sqrt 3) = 0.9069). The c m - n
 * sites left empty are spread evenly over the lattice.
 *
 * Speeds and directions are drawn as for random placement; in a periodic
 * box the mean velocity is then taken out (zero total momentum, so the
 * crystal does not drift) and the speeds scaled back to the same kinetic
 * energy, n speed^2 / 2. */
#include <math.h>
#include <stdlib.h>

#include "init/init.h"

typedef struct lattice {
    uint64_t columns, rows;
    double dx, dy;  /* site spacing along a row, between rows */
    double x0, y0;  /* the first site */
    double closest; /* the closest distance between two sites */
} lattice;

/* The closest two sites: along a row (dx), to the next row (half a site
 * across, dy down) and to the row after it (straight down, 2 dy, which is
 * the closest when few columns make the rows zigzag far across). Along a
 * periodic axis the images count too. */
static double closest_sites(double dx, double dy, uint64_t columns, uint64_t rows, int px, int py)
{
    double d = INFINITY;
    if (columns > 1 || px)
        d = dx;
    if (rows > 1)
        d = fmin(d, sqrt(0.25 * dx * dx + dy * dy));
    if (rows > 2 || py)
        d = fmin(d, 2.0 * dy);
    return d;
}

/* The spacing along a row and the first site's x for c columns of m
 * rows, and the same between rows and for y: tiling a periodic axis,
 * edge to edge between walls, one row along the middle. */
static void site_spacing(lattice *l, const ds_box *box, double radius)
{
    const int px = ds_box_periodic(box, 0), py = ds_box_periodic(box, 1);
    const double width = ds_box_span(box, 0, radius), height = ds_box_span(box, 1, radius);
    const double columns = (double)l->columns, rows = (double)l->rows;
    if (px) {
        l->dx = width / columns;
        l->x0 = 0.0;
    } else if (l->rows == 1) {
        l->dx = l->columns > 1 ? width / (columns - 1.0) : 0.0;
        l->x0 = l->columns > 1 ? radius : 0.5 * box->side[0];
    } else { /* a row and the shifted one span c - 1/2 sites */
        l->dx = width / (columns - 0.5);
        l->x0 = radius;
    }
    if (py) {
        l->dy = height / rows;
        l->y0 = 0.0;
    } else if (l->rows == 1) {
        l->dy = 0.0;
        l->y0 = 0.5 * box->side[1];
    } else {
        l->dy = height / (rows - 1.0);
        l->y0 = radius;
    }
}

/* The best lattice for n disks in the box, or closest = 0 if none. */
static lattice best_lattice(size_t n, double radius, const ds_box *box)
{
    lattice best = {0, 0, 0.0, 0.0, 0.0, 0.0, 0.0};
    const int px = ds_box_periodic(box, 0), py = ds_box_periodic(box, 1);
    const double width = ds_box_span(box, 0, radius), height = ds_box_span(box, 1, radius);
    /* Rows: as many as make sense for a near-square cell, ~2 sqrt(n) at
     * most; the search is O(sqrt n). */
    const double rows_wanted = 2.0 * sqrt((double)n * height / width) + 4.0;
    /* A band a rounding error wide makes that huge (or infinite): no more
     * rows than disks, and no conversion out of range. */
    const uint64_t most = rows_wanted < (double)n + 1.0 ? (uint64_t)rows_wanted : (uint64_t)n + 1;
    for (uint64_t rows = py ? 2 : 1; rows <= most && rows <= n + 1; rows += py ? 2 : 1) {
        const uint64_t columns = (n + rows - 1) / rows;
        lattice l = {columns, rows, 0.0, 0.0, 0.0, 0.0, 0.0};
        site_spacing(&l, box, radius);
        l.closest = closest_sites(l.dx, l.dy, columns, rows, px, py);
        if (l.closest > best.closest ||
            (l.closest == best.closest && columns * rows < best.columns * best.rows))
            best = l;
    }
    return best;
}

/* Relative slack for a lattice packed exactly at contact: box / c can
 * round a hair below 2R. */
#define FIT_SLACK 1e-12

double ds_lattice_closest(size_t n, double radius, const ds_box *box)
{
    return best_lattice(n, radius, box).closest;
}

int ds_lattice_fits(size_t n, double radius, const ds_box *box)
{
    return ds_lattice_closest(n, radius, box) >= 2.0 * radius * (1.0 - FIT_SLACK);
}

ds_status ds_place_lattice(ds_disks *d, const ds_world *w)
{
    const size_t n = w->n;
    /* Sites for the largest disk of a mixture. */
    const double r = w->radius_max;
    const lattice l = best_lattice(n, r, &w->box);
    if (!(l.closest >= 2.0 * r * (1.0 - FIT_SLACK)))
        return DS_ERR_PLACEMENT;
    /* The disks of a mixture take the sites in an order drawn from the
     * seed (a stream of its own, so the directions are those of a lattice
     * of one kind): kinds mixed over the box, not one kind in a band. */
    uint32_t *disk_at = malloc((n ? n : 1) * sizeof *disk_at);
    if (!disk_at)
        return DS_ERR_NOMEM;
    for (size_t i = 0; i < n; ++i)
        disk_at[i] = (uint32_t)i;
    if (d->r || d->m) {
        ds_rng shuffle;
        ds_rng_seed(&shuffle, w->seed ^ 0x5bd1e995u);
        for (size_t i = n; i-- > 1;) {
            const size_t j = (size_t)(ds_rng_next(&shuffle) % (i + 1));
            const uint32_t t = disk_at[i];
            disk_at[i] = disk_at[j];
            disk_at[j] = t;
        }
    }

    /* Site s (row-major) is taken when floor((s + 1) n / sites) steps up:
     * the empty ones fall evenly along the rows. */
    const uint64_t sites = l.columns * l.rows;
    size_t placed = 0;
    for (uint64_t s = 0; s < sites && placed < n; ++s) {
        if ((s + 1) * n / sites == s * n / sites)
            continue;
        const uint64_t row = s / l.columns, column = s % l.columns;
        double x = l.x0 + l.dx * ((double)column + 0.5 * (double)(row & 1));
        double y = l.y0 + l.dy * (double)row;
        /* The last site of a row is R from the far wall, up to rounding,
         * which must not put it past the wall line. */
        if (!ds_box_periodic(&w->box, 0))
            x = fmin(x, w->box.side[0] - r);
        if (!ds_box_periodic(&w->box, 1))
            y = fmin(y, w->box.side[1] - r);
        d->x[disk_at[placed]] = x;
        d->y[disk_at[placed]] = y;
        ++placed;
    }
    free(disk_at);

    ds_rng rng;
    ds_rng_seed(&rng, w->seed);
    for (size_t i = 0; i < n; ++i) {
        const double angle = ds_rng_uniform(&rng, 0.0, DS_TWO_PI);
        d->vx[i] = w->speed * cos(angle);
        d->vy[i] = w->speed * sin(angle);
    }
    if (ds_box_any_periodic(&w->box))
        ds_stop_centre_of_mass(d, w);
    return DS_OK;
}
