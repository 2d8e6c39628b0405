/* SPDX-License-Identifier: MIT */
/* The chains: the event-chain integrator's hot loop.
 *
 * A chain moves one disk at a time along its axis until it would touch
 * another; there the motion passes to the disk it touches (a lifting),
 * which goes on in the same direction, until the chain's length is used
 * up. Each piece is a translation, so the chain maps a configuration and
 * a starting disk one to one onto a configuration and an ending disk, and
 * keeps the measure: the chain run backwards from its end (the opposite
 * direction, from the last disk) brings it back. So if every disk is as
 * likely to start, the uniform distribution over the allowed
 * configurations (the canonical one of hard disks) is kept: for each
 * final (configuration, last disk) there is exactly one start. Chains
 * along x and along y in turn make the sampler reach everything
 * (Bernard, Krauth and Wilson 2009).
 *
 * Walls. A chain moving up cannot pass a wall, and going only up it
 * could not keep the balance (no configuration would flow into those with
 * a disk at the lower wall). At a wall the disk turns: the chain goes on
 * with the same disk moving down. That is the lifting a wall asks for:
 * the flow a disk moving up brings to the wall leaves it as the flow of
 * the same disk moving down, which nothing else would bring. With both
 * directions along a walled axis, the one-to-one argument above needs
 * each chain's sign drawn (up or down, even odds), which ds_ch_new_chain
 * does; along a periodic axis chains move up only.
 *
 * What is tallied (docs/physics.md derives it): at each lifting the
 * separation of the two centres along the chain (Michel, Kapfer and Krauth
 * 2014: beta P / rho = 1 + <sum of them> / <chain displacement>) and across
 * it (the pressure tensor's xy part), and each wall turn. */
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

void ds_ch_new_chain(ds_chain *c)
{
    ch_chain *ch = &c->chain;
    ch->axis ^= 1u;
    ch->active = (uint32_t)ds_rng_uniform(&c->rng, 0.0, (double)c->n);
    if (ch->active >= c->n) /* cannot happen: uniform is below n */
        ch->active = (uint32_t)c->n - 1;
    ch->sign = 1.0;
    if (!ds_box_periodic(&c->box, (int)ch->axis))
        ch->sign = ds_rng_next(&c->rng) >> 63 ? 1.0 : -1.0;
    ch->left = c->length;
    ch->stalled = 0;
    ++c->chains;
}

static DS_ALWAYS_INLINE void front_of(ds_chain *c, const ds_disks *d, double radius, ch_front *f)
{
    const uint32_t k = c->chain.active, axis = c->chain.axis;
    const ch_disk *cd = &c->disk[k];
    f->disk = k;
    f->u = axis ? d->y[k] : d->x[k];
    f->v = axis ? d->x[k] : d->y[k];
    f->r = d->r ? d->r[k] : radius;
    f->along = axis ? cd->row : cd->column;
    f->across = axis ? cd->column : cd->row;
    double *slot = ds_ch_slot_coord(c, k, axis);
    f->slot = slot ? slot : &c->scratch;
}

/* The same for the disk a lifting passes the chain to, when it is in a
 * slot of the stencil: its centre, radius and cell from the stencil's
 * cells, which the scan has just read, rather than from its records
 * (the columns and c->disk), which at 10^5 disks are lines from beyond
 * the second-level cache at each lifting. The slot holds the centre the
 * columns hold, to the bit (write_u, ds_ch_add), so the chain is the
 * same. */
static DS_ALWAYS_INLINE void front_from_stencil(const ch_grid *g, const ch_stencil *st,
                                                const ch_hit *hit, uint32_t axis, double radius,
                                                int mixture, ch_front *f)
{
    double *line = g->pos + (size_t)st->cell[hit->cell] * 2 * CH_SLOTS;
    f->disk = hit->disk;
    f->u = line[axis * CH_SLOTS + hit->slot];
    f->v = line[(axis ^ 1u) * CH_SLOTS + hit->slot];
    f->r = mixture ? g->radius[(size_t)st->cell[hit->cell] * CH_SLOTS + hit->slot] : radius;
    f->along = st->along_at[hit->cell / 3];
    f->across = st->across_at[hit->cell % 3];
    f->slot = line + axis * CH_SLOTS + hit->slot;
}

/* What a step adds to the tally, kept in registers until its end. */
typedef struct ch_tally {
    uint64_t lifts, tested;
    double along[2]; /* separations along the chain at liftings: x chains, y chains */
    double across;   /* sign times the separation across (the xy part) */
} ch_tally;

/* The smaller and the larger of two numbers, neither a NaN: one
 * instruction each, where fmin and fmax are calls (their NaN rules). */
static inline double least(double a, double b) { return a < b ? a : b; }
static inline double most(double a, double b) { return a > b ? a : b; }

static DS_ALWAYS_INLINE void write_u(ds_disks *d, const ch_front *f, uint32_t axis)
{
    (axis ? d->y : d->x)[f->disk] = f->u;
    *f->slot = f->u;
}

/* The active disk at the edge of its cell into the next one beyond, at
 * the edge exactly (wrapped at a periodic box's edge, its image counted). */
static void cross(ds_chain *c, ds_disks *d, ch_front *f, uint32_t axis, uint32_t up,
                  uint32_t beyond)
{
    const ch_grid *g = &c->grid;
    const double shift = g->shift[axis][2 * f->along + up];
    f->u = g->edge[axis][f->along + up] - shift;
    if (shift != 0.0) {
        int32_t *image = (axis ? d->iy : d->ix) + f->disk;
        *image = (int32_t)((uint32_t)*image + (up ? 1u : UINT32_MAX));
    }
    (axis ? d->y : d->x)[f->disk] = f->u;
    ds_ch_remove(c, f->disk, d);
    f->along = beyond;
    ds_ch_add(c, f->disk, axis ? f->across : beyond, axis ? beyond : f->across, d->x[f->disk],
              d->y[f->disk], f->r);
    double *slot = ds_ch_slot_coord(c, f->disk, axis);
    f->slot = slot ? slot : &c->scratch;
}

/* The active disk at the wall line turns: the chain goes on with it the
 * other way. The walls' tally is the impulse molecular dynamics at kT
 * would give them on average: a disk meets a wall once per unit of its
 * displacement along the axis with probability n_c L / N (n_c the
 * density of centres at the wall line, L its length), and beta P = n_c
 * there, so each turn stands for 2 N kT dt / d_a of impulse over a step,
 * d_a = n speed dt / 2 the step's displacement along the axis: 4 kT /
 * speed (docs/physics.md). */
static void turn(ds_sim *sim, ds_chain *c, ch_front *f, uint32_t axis, uint32_t up)
{
    f->u = up ? c->box.side[axis] - f->r : f->r;
    write_u(&sim->disks, f, axis);
    c->chain.sign = -c->chain.sign;
    ds_tally *t = &sim->tally;
    const double impulse = 4.0 * c->kt / sim->world.speed;
    ++t->wall_count;
    t->wall_impulse += impulse;
    if (sim->disks.r || sim->disks.m)
        t->wall_reach += impulse / ds_box_wall_reached(&c->box, f->r);
}

/* The step's liftings into the tally. A step carries n speed dt of chain
 * displacement, half of it along each axis (the chains alternate), so
 * the virial molecular dynamics would tally over it is 2 kT / speed times
 * the separations along x (y) for xx (yy), and half that times those
 * across for xy (both axes estimate it); sim->tally.virial keeps the plain
 * sum of separations along, a length, for the compressibility
 * (event_chain.c). */
static void add_tally(ds_sim *sim, const ds_chain *c, const ch_tally *t)
{
    ds_tally *s = &sim->tally;
    s->collisions += t->lifts;
    s->pairs_tested += t->tested;
    s->virial += t->along[0] + t->along[1];
    const double per = 2.0 * c->kt / sim->world.speed;
    s->stress_virial[0] += per * t->along[0];
    s->stress_virial[1] += per * t->along[1];
    s->stress_virial[2] += 0.5 * per * t->across;
}

/* One step: chains for n speed dt of displacement in all. Long: the
 * event loop is one piece, its state in registers; the scans and the
 * rarer events are the functions above. */
static DS_ALWAYS_INLINE void step_with(ds_sim *sim, ds_chain *c, int mixture, int brute)
{
    ds_disks *d = &sim->disks;
    const ch_grid *g = &c->grid;
    ch_chain *ch = &c->chain;
    const double radius = sim->world.radius, sigma2 = 4.0 * radius * radius;
    const uint64_t per_scan = brute ? (uint64_t)c->n : 6 * CH_SLOTS; /* every slot, read or not */
    double left = c->per_step;
    ch_tally t = {0, 0, {0.0, 0.0}, 0.0};
    ch_front f;
    front_of(c, d, radius, &f);
    while (left > 0.0) {
        const uint32_t axis = ch->axis, up = ch->sign > 0.0;
        ch_hit hit;
        ch_stencil st;
        if (brute) {
            scan_all(c, d, axis, ch->sign, &f, sigma2, &hit);
        } else {
            stencil_of(g, axis, up, &f, &st);
            fetch_ahead(g, axis, up, &st);
            scan_cells(g, &st, axis, ch->sign, &f, sigma2, mixture, &hit);
            if (g->overflowing)
                scan_overflow(c, d, &st, axis, ch->sign, &f, sigma2, &hit);
        }
        t.tested += per_scan;
        /* How far the disk may go before it leaves its cell or meets a
         * wall, a chain's end or the step's. */
        const uint32_t beyond = g->near[axis][2 * f.along + up];
        const double wall = up ? c->box.side[axis] - f.r : f.r;
        const double edge = beyond == CH_NONE ? wall : g->edge[axis][f.along + up];
        const double to_edge = most(ch->sign * (edge - f.u), 0.0);
        const double lim = least(least(to_edge, c->reach[axis]), least(ch->left, left));
        if (hit.distance < lim) { /* a lifting, the common event */
            const double move = most(hit.distance, 0.0);
            f.u += ch->sign * move;
            write_u(d, &f, axis);
            ch->left -= move;
            left -= move;
            const double sigma = mixture ? f.r + d->r[hit.disk] : 2.0 * radius;
            ++t.lifts;
            t.along[axis] += sqrt(most(sigma * sigma - hit.across * hit.across, 0.0));
            t.across += ch->sign * hit.across;
            ch->stalled = move > 0.0 ? 0 : ch->stalled + 1;
            ch->active = hit.disk;
            /* Disks touching all along the chain's line (a rigid row
             * across a periodic box, a jammed packing) pass the motion
             * round for ever without moving: past n such liftings the
             * rest of the chain counts as used, nothing having moved
             * (nothing can), so that the step ends. */
            if (ch->stalled > c->n) {
                const double rest = least(ch->left, left);
                ch->left -= rest;
                left -= rest;
                ch->stalled = 0;
            }
            if (!brute && hit.cell < 6)
                front_from_stencil(g, &st, &hit, axis, radius, mixture, &f);
            else
                front_of(c, d, radius, &f);
            if (ch->left > 0.0)
                continue;
        } else {
            f.u += ch->sign * lim;
            write_u(d, &f, axis);
            ch->left -= lim;
            left -= lim;
            if (lim > 0.0)
                ch->stalled = 0;
            if (lim == to_edge) {
                if (beyond == CH_NONE)
                    turn(sim, c, &f, axis, up);
                else
                    cross(c, d, &f, axis, up, beyond);
            }
        }
        if (ch->left <= 0.0) {
            ds_ch_new_chain(c);
            front_of(c, d, radius, &f);
        }
    }
    add_tally(sim, c, &t);
}

void ds_ch_step(ds_sim *sim, ds_chain *c)
{
    if (c->brute)
        step_with(sim, c, sim->disks.r != NULL, 1);
    else if (sim->disks.r)
        step_with(sim, c, 1, 0);
    else
        step_with(sim, c, 0, 0);
}
