/* SPDX-License-Identifier: MIT */
/* The contacts of a packing and its rattlers (ds_sim_get_contacts): every
 * pair within the gap through the neighbour pairs, each disk's contacts in a
 * list, then the disks with fewer than 3 taken away one at a time, each
 * taking its contacts from its neighbours, which may then go too. */
#include <math.h>
#include <stdlib.h>

#include "core/pairs.h"
#include "observe/observe.h"

typedef struct contact_lists {
    size_t *start;    /* n + 1: disk j's neighbours are other[start[j] .. start[j + 1]) */
    uint32_t *other;  /* 2 pairs */
    uint32_t *count;  /* n: contacts left */
    uint8_t *removed; /* n: 1 once taken away, 2 while waiting to be */
} contact_lists;

/* One pass over the pairs in contact: the first counts each disk's
 * contacts; the second, with start[] made from the counts, writes the
 * lists. */
typedef struct contact_pass {
    const ds_disks *d;
    double radius, gap;
    uint32_t *count;
    size_t *start;
    uint32_t *other; /* NULL: count only */
    size_t pairs;
} contact_pass;

static int in_contact(void *ctx, size_t j, size_t k, double dx, double dy, double r2)
{
    contact_pass *c = ctx;
    (void)dx;
    (void)dy;
    const double reach = (c->d->r ? c->d->r[j] + c->d->r[k] : 2.0 * c->radius) * (1.0 + c->gap);
    if (!(r2 < reach * reach))
        return 0;
    if (c->other) {
        c->other[c->start[j] + c->count[j]++] = (uint32_t)k;
        c->other[c->start[k] + c->count[k]++] = (uint32_t)j;
    } else {
        ++c->count[j];
        ++c->count[k];
    }
    ++c->pairs;
    return 0;
}

/* Each pair j < k (slots) in contact, through the neighbour pairs;
 * returns the count, or SIZE_MAX without memory. */
static size_t for_each_contact(const ds_sim *sim, double gap, uint32_t *count, size_t *start,
                               uint32_t *other)
{
    const ds_world *w = &sim->world;
    contact_pass c = {&sim->disks, w->radius, gap, count, start, other, 0};
    ds_pairs p;
    if (ds_pairs_begin(&p, &w->box, w->n, sim->disks.x, sim->disks.y,
                       2.0 * w->radius_max * (1.0 + gap), 4 * w->n + 16, 1) != DS_OK)
        return SIZE_MAX;
    ds_pairs_each(&p, 0, in_contact, &c);
    ds_pairs_end(&p);
    return c.pairs;
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
