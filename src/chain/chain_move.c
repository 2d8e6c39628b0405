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

#include "chain/chain_scan.h"
#include "chain/chain_state.h"

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
 * event loop is one piece, its state in registers; the scans are
 * chain_scan.h's and the rarer events the functions above. */
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
