/* SPDX-License-Identifier: MIT */
/* What lies ahead of a chain's active disk: the cells it can reach before
 * it leaves its own (the stencil), the scans that find the nearest disk
 * in its way there (the cells' slots, their overflow lists, or every disk
 * for brute force), and the cells fetched ahead. Static and inlined into
 * the hot loop of chain_move.c, its only user; private to chain/. */
#ifndef DS_CHAIN_SCAN_H
#define DS_CHAIN_SCAN_H

#include <math.h>

#include "chain/chain_state.h"
#include "core/lanes.h"
#include "core/prefetch.h"

/* The active disk as the loop holds it: its centre along and across the
 * chain, its radius, its cell's index along and across, and where its
 * coordinate along the chain is kept in its cell (a scratch double for a
 * disk in an overflow list). */
typedef struct ch_front {
    uint32_t disk;
    uint32_t along, across;
    double u, v, r;
    double *slot;
} ch_front;

/* The six cells a disk moving along axis can reach before it leaves its
 * cell: its own column of three (along its own index, across -1, 0, +1)
 * and the one ahead, with the shifts of the images they stand for. */
typedef struct ch_stencil {
    uint32_t cell[6];
    double su[6], sv[6];
    uint32_t along_at[2], across_at[3]; /* the cells' indices: cell 3 i + j is (i, j) */
} ch_stencil;

/* What a scan found: how far the active disk moves to touch the nearest
 * disk ahead (+infinity: none within reach), that disk, and the pair's
 * separation across the chain then (v_j - v_i, through the image); for a
 * disk in a slot, its stencil cell and slot (else cell 6), from which the
 * next front is read without touching the disk's own records. */
typedef struct ch_hit {
    double distance;
    uint32_t disk;
    double across;
    uint32_t cell, slot;
} ch_hit;

static DS_ALWAYS_INLINE void stencil_of(const ch_grid *g, uint32_t axis, uint32_t up,
                                        const ch_front *f, ch_stencil *st)
{
    const uint32_t across = axis ^ 1u;
    const uint32_t along_at[2] = {f->along, g->near[axis][2 * f->along + up]};
    const double along_shift[2] = {0.0, g->shift[axis][2 * f->along + up]};
    const uint32_t across_at[3] = {g->near[across][2 * f->across], f->across,
                                   g->near[across][2 * f->across + 1]};
    const double across_shift[3] = {g->shift[across][2 * f->across], 0.0,
                                    g->shift[across][2 * f->across + 1]};
    const uint32_t along_stride = axis ? g->count[0] : 1u, across_stride = axis ? 1u : g->count[0];
    st->along_at[0] = along_at[0];
    st->along_at[1] = along_at[1];
    for (int j = 0; j < 3; ++j)
        st->across_at[j] = across_at[j];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j) {
            const int k = 3 * i + j;
            const int inside = along_at[i] != CH_NONE && across_at[j] != CH_NONE;
            st->cell[k] = inside ? along_at[i] * along_stride + across_at[j] * across_stride
                                 : (uint32_t)g->cells;
            st->su[k] = along_shift[i];
            st->sv[k] = across_shift[j];
        }
}

/* The cells two along the chain ahead of the active disk's, three
 * across, asked for now: a chain goes straight, so they are the next
 * stencil's column after the one it reads now, and at 10^5 disks they
 * come from beyond the second-level cache. */
static DS_ALWAYS_INLINE void fetch_ahead(const ch_grid *g, uint32_t axis, uint32_t up,
                                         const ch_stencil *st)
{
    const uint32_t beyond = st->along_at[1];
    if (beyond == CH_NONE)
        return;
    const uint32_t ahead = g->near[axis][2 * beyond + up];
    if (ahead == CH_NONE)
        return;
    const uint32_t along_stride = axis ? g->count[0] : 1u, across_stride = axis ? 1u : g->count[0];
    for (int j = 0; j < 3; ++j)
        if (st->across_at[j] != CH_NONE) {
            const size_t cell =
                (size_t)ahead * along_stride + (size_t)st->across_at[j] * across_stride;
            ds_prefetch(g->pos + cell * 2 * CH_SLOTS);
            ds_prefetch(g->who + cell * CH_SLOTS);
        }
}

/* How far the active disk moves to touch each of the two disks in slots
 * h and h + 1 of stencil cell k, or +infinity. Along the chain du = sign
 * ((u_j - u) + shift) (subtracting first makes a pair's du exactly minus
 * what the other disk sees, so two disks never both see the other
 * ahead), across dv = (v_j - v) + shift; the disk is ahead and in the way
 * if du > 0 and dv^2 < sigma^2, and then the active disk touches it after
 * du - sqrt(sigma^2 - dv^2). Free slots (+infinity) and the active disk
 * itself (du = 0) fail the test. Both slots in one pair of lanes
 * (core/lanes.h), every value computed and the answer chosen with masks. */
typedef struct ch_scan {
    ds_x2 u, v, sign, zero, far, own, sigma2;
    size_t along_at, across_at;
} ch_scan;

static DS_ALWAYS_INLINE ds_x2 to_touch_pair(const ch_grid *g, const ch_stencil *st,
                                            const ch_scan *sc, int k, int h, int mixture)
{
    const double *p = g->pos + (size_t)st->cell[k] * 2 * CH_SLOTS;
    const ds_x2 du =
        ds_x2_mul(sc->sign, ds_x2_add(ds_x2_sub(ds_x2_load(p + sc->along_at + h), sc->u),
                                      ds_x2_set1(st->su[k])));
    const ds_x2 dv =
        ds_x2_add(ds_x2_sub(ds_x2_load(p + sc->across_at + h), sc->v), ds_x2_set1(st->sv[k]));
    ds_x2 sig2 = sc->sigma2;
    if (mixture) {
        const ds_x2 sig =
            ds_x2_add(sc->own, ds_x2_load(g->radius + (size_t)st->cell[k] * CH_SLOTS + (size_t)h));
        sig2 = ds_x2_mul(sig, sig);
    }
    const ds_x2 room = ds_x2_sub(sig2, ds_x2_mul(dv, dv));
    const ds_x2 in_way = ds_x2_and(ds_x2_gt(du, sc->zero), ds_x2_gt(room, sc->zero));
    const ds_x2 to_touch = ds_x2_sub(du, ds_x2_sqrt(ds_x2_max(room, sc->zero)));
    return ds_x2_select(in_way, to_touch, sc->far);
}

/* The lowest set bit of a nonzero mask. */
static inline int lowest_bit(unsigned bits)
{
#if defined(__GNUC__)
    return __builtin_ctz(bits);
#else
    int k = 0;
    while (!(bits >> k & 1u))
        ++k;
    return k;
#endif
}

/* The nearest of count pairs of slots d[] (pairs = 6: slots 0 and 1 of
 * each cell; 12: all four), into hit. The minimum is found as a tree and
 * its place as the first lane equal to it: no chain of dependent choices
 * from one pair to the next, and ties go to the first slot. */
static DS_ALWAYS_INLINE void nearest_of(const ch_grid *g, const ch_stencil *st, const ch_scan *sc,
                                        const ds_x2 *d, int pairs, const ch_front *f, ch_hit *hit)
{
    ds_x2 m = d[0];
    for (int j = 1; j < pairs; ++j)
        m = ds_x2_min(m, d[j]);
    const double best = ds_x2_first(ds_x2_min(m, ds_x2_high(m)));
    hit->distance = best;
    hit->disk = CH_NONE;
    hit->across = 0.0;
    hit->cell = 6;
    if (!(best < INFINITY))
        return;
    const ds_x2 b = ds_x2_set1(best);
    unsigned bits = 0;
    for (int j = 0; j + 1 < pairs; j += 2)
        bits |= ds_x2_bits_pair(ds_x2_eq(d[j], b), ds_x2_eq(d[j + 1], b)) << (2 * j);
    const int lane = lowest_bit(bits), pair = lane >> 1;
    const int k = pairs == 6 ? pair : pair >> 1;
    const int slot = (pairs == 6 ? 0 : 2 * (pair & 1)) + (lane & 1);
    const size_t cell = st->cell[k];
    hit->disk = g->who[cell * CH_SLOTS + (size_t)slot];
    hit->across = (g->pos[cell * 2 * CH_SLOTS + sc->across_at + (size_t)slot] - f->v) + st->sv[k];
    hit->cell = (uint32_t)k;
    hit->slot = (uint32_t)slot;
}

/* The nearest disk ahead among the stencil's slots. A cell's disks fill
 * its slots from the first (chain_grid.c), and a dense liquid's cells
 * hold one or two (at area fraction 0.70: 5% hold two, none more): the
 * first two slots of the six cells are read unless some third slot is
 * taken. */
static DS_ALWAYS_INLINE void scan_cells(const ch_grid *g, const ch_stencil *st, uint32_t axis,
                                        double sign, const ch_front *f, double sigma2, int mixture,
                                        ch_hit *hit)
{
    ch_scan sc;
    sc.along_at = axis * CH_SLOTS;
    sc.across_at = (axis ^ 1u) * CH_SLOTS;
    sc.u = ds_x2_set1(f->u);
    sc.v = ds_x2_set1(f->v);
    sc.sign = ds_x2_set1(sign);
    sc.zero = ds_x2_set1(0.0);
    sc.far = ds_x2_set1((double)INFINITY);
    sc.own = ds_x2_set1(f->r);
    sc.sigma2 = ds_x2_set1(sigma2);
    int third = 0;
    for (int k = 0; k < 6; ++k)
        third |= g->pos[(size_t)st->cell[k] * 2 * CH_SLOTS + 2] < INFINITY;
    ds_x2 d[12];
    if (!third) {
        for (int k = 0; k < 6; ++k)
            d[k] = to_touch_pair(g, st, &sc, k, 0, mixture);
        nearest_of(g, st, &sc, d, 6, f, hit);
    } else {
        for (int k = 0; k < 6; ++k) {
            d[2 * k] = to_touch_pair(g, st, &sc, k, 0, mixture);
            d[2 * k + 1] = to_touch_pair(g, st, &sc, k, 2, mixture);
        }
        nearest_of(g, st, &sc, d, 12, f, hit);
    }
}

/* The same test for the disks of the stencil's overflow lists (their
 * centres from the columns), nearer than what the slots gave. */
static void scan_overflow(const ds_chain *c, const ds_disks *d, const ch_stencil *st, uint32_t axis,
                          double sign, const ch_front *f, double sigma2, ch_hit *hit)
{
    const double *along = axis ? d->y : d->x, *across = axis ? d->x : d->y;
    for (int k = 0; k < 6; ++k)
        for (uint32_t m = c->grid.more[st->cell[k]]; m != CH_NONE; m = c->disk[m].next) {
            const double du = sign * ((along[m] - f->u) + st->su[k]);
            const double dv = (across[m] - f->v) + st->sv[k];
            const double sig = d->r ? f->r + d->r[m] : 0.0;
            const double room = (d->r ? sig * sig : sigma2) - dv * dv;
            if (!(du > 0.0 && room > 0.0))
                continue;
            const double to_touch = du - sqrt(room);
            if (to_touch < hit->distance) {
                hit->distance = to_touch;
                hit->disk = m;
                hit->across = dv;
                hit->cell = 6;
            }
        }
}

/* Brute force, the reference: every disk, through the nearest image,
 * with the same arithmetic as the cells (the nearest image's shift added
 * after the subtraction), so the two find the same liftings to the bit.
 * The nearest image is the one ahead only within half a periodic side,
 * so a disk moves no more than half a side less a diameter before it
 * looks again (reach). */
static void scan_all(const ds_chain *c, const ds_disks *d, uint32_t axis, double sign,
                     const ch_front *f, double sigma2, ch_hit *hit)
{
    const double *along = axis ? d->y : d->x, *across = axis ? d->x : d->y;
    const double side_u = c->box.side[axis], side_v = c->box.side[axis ^ 1u];
    const int wrap_u = ds_box_periodic(&c->box, (int)axis),
              wrap_v = ds_box_periodic(&c->box, (int)(axis ^ 1u));
    hit->distance = INFINITY;
    hit->disk = CH_NONE;
    hit->across = 0.0;
    hit->cell = 6;
    for (size_t m = 0; m < d->n; ++m) {
        double du = along[m] - f->u, dv = across[m] - f->v;
        if (wrap_u)
            du = ds_nearest(du, side_u);
        if (wrap_v)
            dv = ds_nearest(dv, side_v);
        du *= sign;
        const double sig = d->r ? f->r + d->r[m] : 0.0;
        const double room = (d->r ? sig * sig : sigma2) - dv * dv;
        if (!(du > 0.0 && room > 0.0))
            continue;
        const double to_touch = du - sqrt(room);
        if (to_touch < hit->distance) {
            hit->distance = to_touch;
            hit->disk = (uint32_t)m;
            hit->across = dv;
        }
    }
}

#endif
