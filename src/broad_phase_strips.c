/* DS_SAP_STRIPS: sweep and prune in horizontal strips.
 *
 * Plain SAP tests every pair closer than 2R in x, wherever they are in y:
 * at fixed area fraction that is ~ n 2R / box candidates per disk, which
 * grows like sqrt(n). Here the box is cut into S horizontal strips of
 * height h >= 2R, the disks are kept grouped by strip and sorted by x
 * inside each strip (key (strip, x)), and each strip is swept against
 * itself and against the strip above. Candidates per disk then depend on
 * the area fraction only, not on n.
 *
 * Hysteresis. A disk leaves strip t only when its centre is more than a
 * margin m outside [t h, (t+1) h). Disks two strips apart are then still
 * more than h - 2m >= 2R apart in y, so they cannot overlap, and a disk
 * jittering on a strip boundary does not change strip every step.
 *
 * Keeping the order. Within a strip the order barely changes between
 * steps, so an insertion sort per strip restores it in nearly linear time,
 * as in plain SAP. A disk that changes strip would have to travel past a
 * whole strip of disks in an insertion sort on (strip, x): at n = 10^6
 * that is hundreds of moves per crossing. Instead the crossing disks are
 * taken out, bucketed by target strip (counting sort), sorted by x inside
 * each small bucket, and merged with the disks that stay in one pass into
 * a second set of arrays, which then becomes the current one. That pass is
 * O(n), needs no per-disk strip number, and runs only on steps where some
 * disk changes strip. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim_internal.h"

/* Strip height as a multiple of 2R. Taller strips mean fewer crossings
 * (each one costs a merge pass) but more candidates per disk (6 n R h /
 * box^2, all rejected cheaply); 2 was the fastest from 10^3 to 10^6 disks
 * at area fraction 0.1 in `make bench`. */
#define STRIP_HEIGHT_DIAMETERS 2.0

struct ds_strips {
    size_t count;           /* S */
    double height, margin;  /* h, m with h - 2m > 2R (see strips_geometry) */
    uint32_t *start;        /* S + 1: strip t holds slots [start[t], start[t+1]) */
    uint32_t *next_start;   /* S + 1: the layout being built */
    uint32_t *bucket_start; /* S + 2: movers for strip t at [bucket_start[t], ..[t+1]) */
    uint32_t *mover;        /* n: slots leaving their strip, ascending */
    uint32_t *mover_strip;  /* n: their target strips */
    uint32_t *incoming;     /* n: mover slots bucketed by target, sorted by x */
    /* The second set of arrays (n + 1 each, sentinel at n), swapped with
     * the simulation's after each merge. */
    double *x, *y, *vx, *vy;
    uint32_t *id;
};

/* Chooses S, h and m. Rounding in t h - m and (t+1) h + m is below a few
 * box * DBL_EPSILON; the slack keeps h - 2m above 2R despite it. */
static void strips_geometry(const ds_sim *sim, size_t *count, double *height, double *margin)
{
    const double diameter = 2.0 * sim->radius, box = sim->box;
    double s = floor(box / (STRIP_HEIGHT_DIAMETERS * diameter));
    /* No more strips than disks: empty strips cost a loop iteration each. */
    if (s > (double)sim->n)
        s = (double)sim->n;
    if (s < 1.0)
        s = 1.0;
    size_t strips = (size_t)s;
    double h = box / (double)strips, slack = h - diameter - 16.0 * box * DBL_EPSILON;
    while (strips > 1 && slack < 0.0) {
        --strips;
        h = box / (double)strips;
        slack = h - diameter - 16.0 * box * DBL_EPSILON;
    }
    *count = strips;
    *height = h;
    *margin = strips > 1 ? 0.5 * slack : 0.0;
}

/* The band of y a disk of strip t may occupy; the outer strips are open
 * towards the walls, so a disk slightly outside the box stays put. */
static double band_low(const struct ds_strips *st, size_t t)
{
    return t == 0 ? -INFINITY : (double)t * st->height - st->margin;
}

static double band_high(const struct ds_strips *st, size_t t)
{
    return t + 1 == st->count ? INFINITY : (double)(t + 1) * st->height + st->margin;
}

static uint32_t strip_of(const struct ds_strips *st, double y)
{
    double t = floor(y / st->height);
    size_t k = t <= 0.0 ? 0 : t >= (double)(st->count - 1) ? st->count - 1 : (size_t)t;
    /* Division rounding can land a hair outside the band: step back in. */
    while (k > 0 && y < band_low(st, k))
        --k;
    while (k + 1 < st->count && !(y < band_high(st, k)))
        ++k;
    return (uint32_t)k;
}

static void swap_double(double **a, double **b)
{
    double *t = *a;
    *a = *b;
    *b = t;
}

static void swap_u32(uint32_t **a, uint32_t **b)
{
    uint32_t *t = *a;
    *a = *b;
    *b = t;
}

/* Makes the second set of arrays current, and next_start the layout. */
static void swap_buffers(ds_sim *sim, struct ds_strips *st)
{
    swap_double(&sim->x, &st->x);
    swap_double(&sim->y, &st->y);
    swap_double(&sim->vx, &st->vx);
    swap_double(&sim->vy, &st->vy);
    swap_u32(&sim->id, &st->id);
    swap_u32(&st->start, &st->next_start);
}

static void copy_disk(const ds_sim *sim, struct ds_strips *st, size_t from, size_t to)
{
    st->x[to] = sim->x[from];
    st->y[to] = sim->y[from];
    st->vx[to] = sim->vx[from];
    st->vy[to] = sim->vy[from];
    st->id[to] = sim->id[from];
}

/* Insertion sort of the slot list [lo, hi) by x. The lists are short
 * (the disks crossing into one strip in one step) and arrive as two runs
 * already in x order (from the strips below and above). */
static void sort_slots_by_x(uint32_t *slots, size_t lo, size_t hi, const double *x)
{
    for (size_t k = lo + 1; k < hi; ++k) {
        const uint32_t s = slots[k];
        const double xs = x[s];
        size_t j = k;
        for (; j > lo && xs < x[slots[j - 1]]; --j)
            slots[j] = slots[j - 1];
        slots[j] = s;
    }
}

/* Groups the slots of `incoming` (nm of them, targets in mover_strip by
 * position) by target strip, stably, then sorts each group by x. */
static void bucket_movers(const ds_sim *sim, struct ds_strips *st, size_t nm)
{
    const size_t strips = st->count;
    uint32_t *b = st->bucket_start;
    memset(b, 0, (strips + 2) * sizeof *b);
    for (size_t m = 0; m < nm; ++m)
        ++b[st->mover_strip[m] + 2];
    for (size_t t = 2; t < strips + 2; ++t)
        b[t] += b[t - 1];
    /* b[t + 1] is now the write cursor of bucket t; after the scatter it is
     * the end of bucket t, that is the start of bucket t + 1. */
    for (size_t m = 0; m < nm; ++m)
        st->incoming[b[st->mover_strip[m] + 1]++] = st->mover[m];
    for (size_t t = 0; t < strips; ++t)
        sort_slots_by_x(st->incoming, b[t], b[t + 1], sim->x);
}

/* Merges, strip by strip, the disks that stay (slots not in mover[],
 * in their current order) with the bucket of incoming disks, by x, into
 * the second arrays; then swaps. */
static void merge_strips(ds_sim *sim, struct ds_strips *st, size_t nm)
{
    const double *x = sim->x;
    size_t w = 0, mp = 0;
    for (size_t t = 0; t < st->count; ++t) {
        st->next_start[t] = (uint32_t)w;
        size_t k = st->start[t];
        const size_t end = st->start[t + 1];
        size_t in = st->bucket_start[t];
        const size_t in_end = st->bucket_start[t + 1];
        for (;;) {
            while (k < end && mp < nm && st->mover[mp] == k) { /* leaving: skip */
                ++k;
                ++mp;
            }
            if (k < end && (in == in_end || !(x[st->incoming[in]] < x[k])))
                copy_disk(sim, st, k++, w++);
            else if (in < in_end)
                copy_disk(sim, st, st->incoming[in++], w++);
            else
                break;
        }
    }
    st->next_start[st->count] = (uint32_t)w;
    swap_buffers(sim, st);
}

/* Finds the disks outside their strip's band and moves them to the strip
 * their centre is in. */
static void restripe(ds_sim *sim, struct ds_strips *st)
{
    const double *y = sim->y;
    size_t nm = 0;
    for (size_t t = 0; t < st->count; ++t) {
        const double lo = band_low(st, t), hi = band_high(st, t);
        for (size_t k = st->start[t]; k < st->start[t + 1]; ++k) {
            const double yk = y[k];
            if (yk >= lo && yk < hi)
                continue;
            st->mover[nm] = (uint32_t)k;
            st->mover_strip[nm] = strip_of(st, yk);
            ++nm;
        }
    }
    if (nm == 0)
        return;
    bucket_movers(sim, st, nm);
    merge_strips(sim, st, nm);
}

/* Insertion sort by x inside each strip (all arrays move together). */
static void sort_strips(ds_sim *sim, const struct ds_strips *st)
{
    double *restrict x = sim->x, *restrict y = sim->y;
    double *restrict vx = sim->vx, *restrict vy = sim->vy;
    uint32_t *restrict id = sim->id;
    for (size_t t = 0; t < st->count; ++t) {
        const size_t lo = st->start[t], hi = st->start[t + 1];
        for (size_t k = lo + 1; k < hi; ++k) {
            const double xk = x[k];
            if (!(xk < x[k - 1]))
                continue;
            const double yk = y[k], vxk = vx[k], vyk = vy[k];
            const uint32_t idk = id[k];
            size_t j = k;
            do {
                x[j] = x[j - 1];
                y[j] = y[j - 1];
                vx[j] = vx[j - 1];
                vy[j] = vy[j - 1];
                id[j] = id[j - 1];
                --j;
            } while (j > lo && xk < x[j - 1]);
            x[j] = xk;
            y[j] = yk;
            vx[j] = vxk;
            vy[j] = vyk;
            id[j] = idk;
        }
    }
}

/* The first layout, from disks in generation order: counting sort by a
 * fine x cell, then a stable counting sort by strip, leaves each strip in
 * nearly x order, so the insertion sort that follows is linear. */
static void initial_layout(ds_sim *sim, struct ds_strips *st)
{
    const size_t n = sim->n;
    /* About one disk per x cell; the second id array (n + 1 counters) is
     * free until the first merge. */
    const size_t cells = n;
    uint32_t *cell_start = st->id;
    const double cells_per_unit = (double)cells / sim->box;
    memset(cell_start, 0, (n + 1) * sizeof *cell_start);
    for (size_t k = 0; k < n; ++k) {
        double c = floor(sim->x[k] * cells_per_unit);
        st->mover_strip[k] = c <= 0.0 ? 0u : c >= (double)(cells - 1) ? (uint32_t)(cells - 1) : (uint32_t)c;
        ++cell_start[st->mover_strip[k] + 1];
    }
    for (size_t c = 1; c <= cells; ++c)
        cell_start[c] += cell_start[c - 1];
    for (size_t k = 0; k < n; ++k)
        st->mover[cell_start[st->mover_strip[k]]++] = (uint32_t)k;

    /* mover[] now lists every slot in x-cell order: bucket them by strip
     * (stable, so x-cell order survives inside each strip). */
    for (size_t m = 0; m < n; ++m)
        st->mover_strip[m] = strip_of(st, sim->y[st->mover[m]]);
    uint32_t *b = st->bucket_start;
    memset(b, 0, (st->count + 2) * sizeof *b);
    for (size_t m = 0; m < n; ++m)
        ++b[st->mover_strip[m] + 2];
    for (size_t t = 2; t < st->count + 2; ++t)
        b[t] += b[t - 1];
    for (size_t m = 0; m < n; ++m)
        st->incoming[b[st->mover_strip[m] + 1]++] = st->mover[m];

    for (size_t w = 0; w < n; ++w)
        copy_disk(sim, st, st->incoming[w], w);
    memcpy(st->next_start, b, st->count * sizeof *b);
    st->next_start[st->count] = (uint32_t)n;
    swap_buffers(sim, st);
    sort_strips(sim, st);
}

ds_status ds_strips_create(ds_sim *sim)
{
    const size_t n = sim->n, cap = n + 1;
    struct ds_strips *st = calloc(1, sizeof *st);
    if (!st)
        return DS_ERR_NOMEM;
    sim->strips = st;
    strips_geometry(sim, &st->count, &st->height, &st->margin);
    st->start = malloc((st->count + 1) * sizeof *st->start);
    st->next_start = malloc((st->count + 1) * sizeof *st->next_start);
    st->bucket_start = malloc((st->count + 2) * sizeof *st->bucket_start);
    st->mover = malloc(n * sizeof *st->mover);
    st->mover_strip = malloc(n * sizeof *st->mover_strip);
    st->incoming = malloc(n * sizeof *st->incoming);
    st->x = malloc(cap * sizeof *st->x);
    st->y = malloc(cap * sizeof *st->y);
    st->vx = malloc(cap * sizeof *st->vx);
    st->vy = malloc(cap * sizeof *st->vy);
    st->id = malloc(cap * sizeof *st->id);
    if (!st->start || !st->next_start || !st->bucket_start || !st->mover || !st->mover_strip ||
        !st->incoming || !st->x || !st->y || !st->vx || !st->vy || !st->id) {
        ds_strips_destroy(sim);
        return DS_ERR_NOMEM;
    }
    /* Both sets of arrays carry the sweep sentinel at n. */
    st->x[n] = INFINITY;
    st->y[n] = INFINITY;
    st->vx[n] = st->vy[n] = 0.0;
    initial_layout(sim, st);
    /* initial_layout used one id array as counters: restore its sentinel. */
    sim->id[n] = st->id[n] = UINT32_MAX;
    return DS_OK;
}

void ds_strips_destroy(ds_sim *sim)
{
    struct ds_strips *st = sim->strips;
    if (!st)
        return;
    free(st->start);
    free(st->next_start);
    free(st->bucket_start);
    free(st->mover);
    free(st->mover_strip);
    free(st->incoming);
    free(st->x);
    free(st->y);
    free(st->vx);
    free(st->vy);
    free(st->id);
    free(st);
    sim->strips = NULL;
}

/* Reports the pairs (i, j), j in [j, end), with x[j] < xlim: the callback
 * runs after the loop, for the reason given in broad_phase.c (no calls
 * inside the loop). Returns where the window ended. */
#define HITS_CAP 32

static size_t sweep_range(ds_sim *sim, size_t i, size_t j, size_t end, double xlim,
                          ds_pair_fn on_pair, void *ctx)
{
    const double *restrict x = sim->x, *restrict y = sim->y;
    const double xi = x[i], yi = y[i], diameter = 2.0 * sim->radius,
                 d2max = diameter * diameter;
    uint32_t hits[HITS_CAP];
    size_t nh;
    do {
        nh = 0;
        for (; j < end && x[j] < xlim; ++j) {
            const double dx = x[j] - xi, dy = y[j] - yi;
            if (dx * dx + dy * dy < d2max) {
                hits[nh++] = (uint32_t)j;
                if (nh == HITS_CAP) {
                    ++j;
                    break;
                }
            }
        }
        for (size_t h = 0; h < nh; ++h)
            on_pair(sim, i, hits[h], ctx);
    } while (nh == HITS_CAP);
    return j;
}

uint64_t ds_strips_find_pairs(ds_sim *sim, ds_pair_fn on_pair, void *ctx)
{
    struct ds_strips *st = sim->strips;
    if (!st)
        return 0;
    restripe(sim, st);
    sort_strips(sim, st);

    const double *x = sim->x;
    const double diameter = 2.0 * sim->radius;
    uint64_t tested = 0;
    for (size_t t = 0; t < st->count; ++t) {
        const size_t lo = st->start[t], hi = st->start[t + 1];
        /* The strip above (none for the top strip: an empty range). */
        const size_t up_hi = t + 1 < st->count ? st->start[t + 2] : hi;
        size_t up = hi; /* first disk above with x > xi - 2R; moves right only */
        for (size_t i = lo; i < hi; ++i) {
            const double xi = x[i], xlim = xi + diameter, xlow = xi - diameter;
            size_t end = sweep_range(sim, i, i + 1, hi, xlim, on_pair, ctx);
            tested += end - i - 1;
            while (up < up_hi && !(x[up] > xlow))
                ++up;
            end = sweep_range(sim, i, up, up_hi, xlim, on_pair, ctx);
            tested += end - up;
        }
    }
    return tested;
}
