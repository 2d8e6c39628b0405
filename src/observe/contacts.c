/* SPDX-License-Identifier: MIT */
/* The contacts of a packing and its rattlers (ds_sim_get_contacts): every
 * pair within the gap through the cell grid, each disk's contacts in a
 * list, then the disks with fewer than 3 taken away one at a time, each
 * taking its contacts from its neighbours, which may then go too. */
#include <math.h>
#include <stdlib.h>

#include "core/boundary.h"
#include "core/grid.h"
#include "observe/observe.h"

typedef struct contact_lists {
    size_t *start;    /* n + 1: disk j's neighbours are other[start[j] .. start[j + 1]) */
    uint32_t *other;  /* 2 pairs */
    uint32_t *count;  /* n: contacts left */
    uint8_t *removed; /* n: 1 once taken away, 2 while waiting to be */
} contact_lists;

/* Calls found(j, k) for each pair j < k (slots) in contact; returns the
 * count, or SIZE_MAX without memory. */
static size_t for_each_contact(const ds_sim *sim, double gap, uint32_t *count, size_t *start,
                               uint32_t *other)
{
    const ds_world *w = &sim->world;
    const ds_disks *d = &sim->disks;
    const size_t n = d->n;
    const int periodic = w->boundary == DS_BOUNDARY_PERIODIC;
    ds_grid g;
    ds_grid_init(&g, w->box, w->box_y, 2.0 * w->radius_max * (1.0 + gap), 4 * n + 16, periodic);
    ds_grid_bins bins;
    if (ds_grid_bin(&g, n, d->x, d->y, &bins) != DS_OK)
        return SIZE_MAX;
    size_t pairs = 0;
    for (size_t j = 0; j < n; ++j) {
        size_t around[9];
        const int cells = ds_grid_neighbours(&g, bins.cell[j] % g.nx, bins.cell[j] / g.nx, around);
        for (int c = 0; c < cells; ++c)
            for (size_t s = bins.start[around[c]]; s < bins.start[around[c] + 1]; ++s) {
                const size_t k = bins.order[s];
                if (k <= j)
                    continue;
                double dx = d->x[k] - d->x[j], dy = d->y[k] - d->y[j];
                if (periodic) {
                    dx = ds_nearest(dx, w->box);
                    dy = ds_nearest(dy, w->box_y);
                }
                const double reach = (d->r ? d->r[j] + d->r[k] : 2.0 * w->radius) * (1.0 + gap);
                if (!(dx * dx + dy * dy < reach * reach))
                    continue;
                /* The first pass counts; the second, with start[] made
                 * from the counts, writes the lists. */
                if (other) {
                    other[start[j] + count[j]++] = (uint32_t)k;
                    other[start[k] + count[k]++] = (uint32_t)j;
                } else {
                    ++count[j];
                    ++count[k];
                }
                ++pairs;
            }
    }
    ds_grid_bins_free(&bins);
    return pairs;
}

ds_status ds_sim_get_contacts(const ds_sim *sim, double gap, ds_contacts *out, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !out)
        return ds_refuse(err, DS_ERR_ARG, sim ? "out" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "out" : "sim");
    if (!(gap >= 0.0 && gap < 1.0))
        return ds_refuse(err, DS_ERR_ARG, "gap", gap, gap < 0.0 ? 0.0 : 1.0,
                         "gap = %g must be in [0, 1)", gap);
    const size_t n = sim->disks.n;
    contact_lists c;
    c.start = calloc(n + 1, sizeof *c.start);
    c.count = calloc(n ? n : 1, sizeof *c.count);
    c.removed = calloc(n ? n : 1, sizeof *c.removed);
    c.other = NULL;
    ds_status st = c.start && c.count && c.removed ? DS_OK : DS_ERR_NOMEM;
    size_t pairs = st == DS_OK ? for_each_contact(sim, gap, c.count, NULL, NULL) : 0;
    if (pairs == SIZE_MAX)
        st = DS_ERR_NOMEM;
    if (st == DS_OK) {
        for (size_t j = 0; j < n; ++j)
            c.start[j + 1] = c.start[j] + c.count[j];
        c.other = malloc((pairs > 0 ? 2 * pairs : 1) * sizeof *c.other);
        if (!c.other)
            st = DS_ERR_NOMEM;
    }
    if (st == DS_OK) {
        for (size_t j = 0; j < n; ++j)
            c.count[j] = 0;
        if (for_each_contact(sim, gap, c.count, c.start, c.other) == SIZE_MAX)
            st = DS_ERR_NOMEM;
    }
    if (st == DS_OK) {
        /* Rattlers: a stack of the disks to take away, each pushed once
         * (waiting, 2); a disk taken away (1) takes its contacts with the
         * disks still there. */
        uint32_t *stack = malloc((n ? n : 1) * sizeof *stack);
        if (!stack)
            st = DS_ERR_NOMEM;
        size_t top = 0, rattlers = 0;
        for (size_t j = 0; stack && j < n; ++j)
            if (c.count[j] < 3) {
                c.removed[j] = 2;
                stack[top++] = (uint32_t)j;
            }
        while (stack && top > 0) {
            const uint32_t j = stack[--top];
            c.removed[j] = 1;
            ++rattlers;
            for (size_t s = c.start[j]; s < c.start[j + 1]; ++s) {
                const uint32_t k = c.other[s];
                if (c.removed[k] == 1)
                    continue;
                --pairs; /* the contact j-k goes with j */
                if (--c.count[k] < 3 && c.removed[k] == 0) {
                    c.removed[k] = 2;
                    stack[top++] = k;
                }
            }
        }
        free(stack);
        if (st == DS_OK) {
            out->pairs = pairs;
            out->rattlers = rattlers;
            out->per_disk = n > rattlers ? 2.0 * (double)pairs / (double)(n - rattlers) : 0.0;
            out->rattler_fraction = n ? (double)rattlers / (double)n : 0.0;
        }
    }
    free(c.start);
    free(c.count);
    free(c.removed);
    free(c.other);
    if (st != DS_OK)
        return ds_refuse(err, st, "n", (double)n, NAN,
                         "n = %zu disks: no memory for their contacts", n);
    return DS_OK;
}
