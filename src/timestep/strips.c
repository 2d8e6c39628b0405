/* SPDX-License-Identifier: MIT */
/* DS_BROADPHASE_STRIPS: sweep and prune in horizontal strips.
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

#include "timestep/broad_phase.h"
#include "timestep/sweep_block.h"

/* Strip height as a multiple of 2R. Taller strips mean fewer crossings
 * (each step with any crossing costs a merge pass over all disks) but
 * more candidates per disk (~6 n R h / box^2, cheap to reject). Measured
 * at area fraction 0.1: 4 to 6 fastest from 10^3 to 10^6 disks, 2 and 8
 * up to 20% slower. */
#ifndef STRIP_HEIGHT_DIAMETERS
#define STRIP_HEIGHT_DIAMETERS 4.0
#endif

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
    ds_disks spare;
};

/* Chooses S, h and m. Rounding in t h - m and (t+1) h + m is below a few
 * box * DBL_EPSILON; the slack keeps h - 2m above 2R despite it. */
static void strips_geometry(const ds_world *w, size_t *count, double *height, double *margin)
{
    const double diameter = 2.0 * w->radius_max, box = w->box.side[1]; /* strips cut the height */
    double s = floor(box / (STRIP_HEIGHT_DIAMETERS * diameter));
    /* No more strips than disks: empty strips cost a loop iteration each. */
    if (s > (double)w->n)
        s = (double)w->n;
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

static void swap_u32(uint32_t **a, uint32_t **b)
{
    uint32_t *t = *a;
    *a = *b;
    *b = t;
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
static void bucket_movers(const ds_disks *d, struct ds_strips *st, size_t nm)
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
        sort_slots_by_x(st->incoming, b[t], b[t + 1], d->x);
}

/* Writes strip t of the new layout at w: the disks that stay (slots of
 * the previous arrays, st->spare, not in mover[], in their previous
 * order) merged by x with the bucket of incoming disks. *mp walks
 * mover[], which is in slot order. Returns the end of the strip. Compiled
 * twice (mixture constant): with one kind of disk the copy has no branch
 * on a mixture's arrays (3.5% of a step at 10^5 disks with it). */
static DS_ALWAYS_INLINE size_t merge_into(ds_disks *d, struct ds_strips *st, size_t t, size_t w,
                                          size_t nm, size_t *mp, int mixture)
{
    const ds_disks *prev = &st->spare;
    const double *restrict x0 = prev->x;
    const uint32_t *restrict mover = st->mover, *restrict incoming = st->incoming;
    size_t k = st->start[t], m = *mp;
    const size_t end = st->start[t + 1];
    size_t in = st->bucket_start[t];
    const size_t in_end = st->bucket_start[t + 1];
    st->next_start[t] = (uint32_t)w;
    for (;;) {
        while (k < end && m < nm && mover[m] == k) { /* leaving: skip */
            ++k;
            ++m;
        }
        size_t from;
        if (k < end && (in == in_end || !(x0[incoming[in]] < x0[k])))
            from = k++;
        else if (in < in_end)
            from = incoming[in++];
        else
            break;
        if (mixture)
            ds_disks_copy(d, w++, prev, from);
        else
            ds_disks_copy_motion(d, w++, prev, from);
    }
    *mp = m;
    return w;
}

static size_t merge_strip(ds_disks *d, struct ds_strips *st, size_t t, size_t w, size_t nm,
                          size_t *mp)
{
    return ds_disks_columns(d) != DS_DISKS_EVERY_COLUMN ? merge_into(d, st, t, w, nm, mp, 1)
                                                        : merge_into(d, st, t, w, nm, mp, 0);
}

/* Lists the disks outside their strip's band, with the strip their
 * centre is now in, and buckets them; returns how many. */
static size_t find_movers(ds_disks *d, struct ds_strips *st)
{
    const double *y = d->y;
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
    if (nm)
        bucket_movers(d, st, nm);
    return nm;
}

/* The first layout, from disks in generation order: a counting sort by
 * strip (one sequential pass over y), then inside each strip a counting
 * sort by an x cell about one disk wide, which leaves the strip in nearly
 * x order, so the insertion sort that follows is linear. Only two passes
 * read the arrays in random order: x inside each strip, and the final
 * gather of every disk into its place. */
static void initial_layout(ds_disks *d, const ds_world *world, struct ds_strips *st, ds_scan scan)
{
    const size_t n = d->n, strips = st->count;
    const double *x = d->x;
    uint32_t *b = st->bucket_start;
    memset(b, 0, (strips + 2) * sizeof *b);
    for (size_t k = 0; k < n; ++k) {
        st->mover_strip[k] = strip_of(st, d->y[k]);
        ++b[st->mover_strip[k] + 2];
    }
    for (size_t t = 2; t < strips + 2; ++t)
        b[t] += b[t - 1];
    for (size_t k = 0; k < n; ++k) /* stable: slots ascend in each strip */
        st->incoming[b[st->mover_strip[k] + 1]++] = (uint32_t)k;

    /* Strip t's slots are incoming[b[t] .. b[t+1]); sorted into mover[].
     * The second id array is free until the gather: its entries
     * b[t] .. b[t+1] (one more than the strip holds) count the cells. */
    uint32_t *count = st->spare.id;
    for (size_t t = 0; t < strips; ++t) {
        const size_t lo = b[t], len = b[t + 1] - lo;
        if (len == 0)
            continue;
        uint32_t *cell_start = count + lo;
        const double cells_per_unit = (double)len / world->box.side[0];
        memset(cell_start, 0, (len + 1) * sizeof *cell_start);
        for (size_t m = lo; m < lo + len; ++m) {
            double c = floor(x[st->incoming[m]] * cells_per_unit);
            st->mover_strip[m] = c <= 0.0                 ? 0u
                                 : c >= (double)(len - 1) ? (uint32_t)(len - 1)
                                                          : (uint32_t)c;
            ++cell_start[st->mover_strip[m] + 1];
        }
        for (size_t c = 1; c <= len; ++c)
            cell_start[c] += cell_start[c - 1];
        for (size_t m = lo; m < lo + len; ++m)
            st->mover[lo + cell_start[st->mover_strip[m]]++] = st->incoming[m];
    }

    ds_disks_swap(d, &st->spare);
    for (size_t w = 0; w < n; ++w)
        ds_disks_copy(d, w, &st->spare, st->mover[w]);
    memcpy(st->start, b, strips * sizeof *b);
    st->start[strips] = (uint32_t)n;
    for (size_t t = 0; t < strips; ++t)
        ds_bp_insertion_sort(d, st->start[t], st->start[t + 1], scan);
}

/* The strips' structure for world w, no disk in it yet. */
static ds_status strips_alloc(ds_bp *bp, const ds_world *w, const ds_disks *d)
{
    const size_t n = d->n;
    struct ds_strips *st = calloc(1, sizeof *st);
    if (!st)
        return DS_ERR_NOMEM;
    bp->strips = st;
    strips_geometry(w, &st->count, &st->height, &st->margin);
    st->start = malloc((st->count + 1) * sizeof *st->start);
    st->next_start = malloc((st->count + 1) * sizeof *st->next_start);
    st->bucket_start = malloc((st->count + 2) * sizeof *st->bucket_start);
    st->mover = malloc(n * sizeof *st->mover);
    st->mover_strip = malloc(n * sizeof *st->mover_strip);
    st->incoming = malloc(n * sizeof *st->incoming);
    if (!st->start || !st->next_start || !st->bucket_start || !st->mover || !st->mover_strip ||
        !st->incoming || ds_disks_alloc_like(&st->spare, d) != DS_OK) {
        ds_strips_destroy(bp);
        return DS_ERR_NOMEM;
    }
    return DS_OK;
}

ds_status ds_strips_create(ds_bp *bp, const ds_world *w, ds_disks *d)
{
    const size_t n = d->n;
    const ds_status st = strips_alloc(bp, w, d);
    if (st != DS_OK)
        return st;
    initial_layout(d, w, bp->strips, bp->scan);
    /* initial_layout used one id array as counters: restore its sentinel. */
    d->id[n] = bp->strips->spare.id[n] = UINT32_MAX;
    return DS_OK;
}

/* Which slots each strip holds is history (a disk changes strip only past
 * a margin): a checkpoint keeps it. */
void ds_strips_save(const ds_bp *bp, ds_state_writer *w)
{
    const struct ds_strips *st = bp->strips;
    ds_put_u64(w, st->count);
    for (size_t t = 0; t <= st->count; ++t)
        ds_put_u32(w, st->start[t]);
}

ds_status ds_strips_load(ds_bp *bp, const ds_world *w, ds_disks *d, ds_reader *r, ds_error *err)
{
    ds_status status = strips_alloc(bp, w, d);
    if (status != DS_OK)
        return ds_state_refuse(err, status, "no memory for the strips of %zu disks", d->n);
    struct ds_strips *st = bp->strips;
    const uint64_t count = ds_get_u64(r);
    if (r->failed || count != st->count)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the strips do not match the box: %llu, not %zu",
                               (unsigned long long)count, st->count);
    for (size_t t = 0; t <= st->count; ++t) {
        st->start[t] = ds_get_u32(r);
        const int ordered = t == 0 ? st->start[t] == 0 : st->start[t] >= st->start[t - 1];
        if (r->failed || !ordered || st->start[t] > d->n ||
            (t == st->count && st->start[t] != d->n))
            return ds_state_refuse(err, DS_ERR_FORMAT, "strip %zu's slots are out of order", t);
    }
    return DS_OK;
}

void ds_strips_destroy(ds_bp *bp)
{
    struct ds_strips *st = bp->strips;
    if (!st)
        return;
    free(st->start);
    free(st->next_start);
    free(st->bucket_start);
    free(st->mover);
    free(st->mover_strip);
    free(st->incoming);
    ds_disks_free(&st->spare);
    free(st);
    bp->strips = NULL;
}

/* Reports the pairs of disk i with the disks of [j, end) that have
 * x < xlim (a prefix: the range is sorted by x); returns where that prefix
 * ends. A block of four first, branch-free (see sweep_block.h); the loop
 * only for longer windows, or near the end of the arrays. */
static DS_ALWAYS_INLINE size_t sweep_block(ds_disks *d, double diameter, size_t i, size_t j,
                                           size_t end, double xlim, double d2max,
                                           ds_pair_fn on_pair, void *ctx)
{
    const double *x = d->x, *y = d->y;
    if (j + 3 > d->n) /* the block would read past the sentinel */
        return ds_sweep_range(d, diameter, i, j, end, xlim, on_pair, ctx);
    unsigned inside;
    const unsigned close = ds_test_four(x, y, j, x[i], y[i], xlim, d2max, &inside);
    inside &= ds_block_mask(end - j);
    for (unsigned hit = inside & close, k = 0; hit; ++k, hit >>= 1)
        if (hit & 1u)
            on_pair(d, i, j + k, ctx);
    if (inside == 0xFu)
        return ds_sweep_range(d, diameter, i, j + 4, end, xlim, on_pair, ctx);
    return j + ds_prefix_length(inside);
}

/* Sweeps strip t against itself and against strip t + 1 (if any). */
static uint64_t sweep_strip(ds_disks *d, double diameter, const uint32_t *start, size_t t,
                            size_t strips, ds_pair_fn on_pair, void *ctx)
{
    const double *x = d->x;
    const double d2max = diameter * diameter;
    const size_t lo = start[t], hi = start[t + 1];
    const size_t up_hi = t + 1 < strips ? start[t + 2] : hi; /* empty above the top */
    size_t up = hi; /* first disk above with x > xi - 2R: only moves right */
    uint64_t tested = 0;
    for (size_t i = lo; i < hi; ++i) {
        const double xi = x[i], xlim = xi + diameter, xlow = xi - diameter;
        size_t end = sweep_block(d, diameter, i, i + 1, hi, xlim, d2max, on_pair, ctx);
        tested += end - i - 1;
        /* up advances about one disk per disk, by 0 to 3 often enough that
         * a loop testing one disk at a time mispredicts its exit: four at
         * once, without a branch, and again only if all four were passed
         * (x is sorted, so the passed ones are a prefix). The scalar loop
         * only where four would read past the sentinel at n. */
        for (;;) {
            if (up + 3 > d->n) {
                while (up < up_hi && !(x[up] > xlow))
                    ++up;
                break;
            }
            const unsigned passed = ds_at_most_four(x, up, xlow) & ds_block_mask(up_hi - up);
            up += ds_prefix_length(passed);
            if (passed != 0xFu)
                break;
        }
        end = sweep_block(d, diameter, i, up, up_hi, xlim, d2max, on_pair, ctx);
        tested += end - up;
    }
    return tested;
}

/* One pass over the strips, bottom to top, while each is in cache: build
 * strip t (merge, if disks changed strip), sort it, then sweep strip t - 1,
 * whose own disks and those above are now final. At 10^6 disks this reads
 * and writes the arrays once per step instead of once per phase. */
uint64_t ds_strips_find_pairs(ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx)
{
    struct ds_strips *st = bp->strips;
    if (!st)
        return 0;
    const size_t strips = st->count, nm = find_movers(d, st);
    if (nm)
        ds_disks_swap(d, &st->spare); /* d: arrays to fill; st->spare: previous ones */
    const uint32_t *start = nm ? st->next_start : st->start;
    uint64_t tested = 0;
    size_t w = 0, mp = 0;
    for (size_t t = 0; t < strips; ++t) {
        if (nm) {
            w = merge_strip(d, st, t, w, nm, &mp);
            st->next_start[t + 1] = (uint32_t)w; /* strip t's end, for its sweep */
        }
        ds_bp_insertion_sort(d, start[t], start[t + 1], bp->scan);
        if (t > 0)
            tested += sweep_strip(d, bp->diameter, start, t - 1, strips, on_pair, ctx);
    }
    if (nm)
        swap_u32(&st->start, &st->next_start);
    return tested + sweep_strip(d, bp->diameter, st->start, strips - 1, strips, on_pair, ctx);
}
