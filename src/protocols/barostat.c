/* SPDX-License-Identifier: MIT */
/* The barostat: the isobaric ensemble at reduced pressure beta P
 * sigma^2 (sigma the largest diameter: Engel et al. 2013, Phys. Rev. E
 * 87, 042134), as a protocol. Between stretches of the integrator (at the
 * end of every `every`-th step) it makes a Monte Carlo move of the box:
 *
 * - the area: ln A' = ln A + d, d uniform in [-max_step, max_step], both
 *   sides scaled by exp(d / 2) and every centre with them (the scaled
 *   coordinates s = (x / L_x, y / L_y) stay), accepted with probability
 *   min(1, exp(-beta P (A' - A) + (N + 1) d)) unless a pair would overlap.
 *   The isobaric weight of (A, s) is A^N exp(-beta P A) (the N from the
 *   positions' Jacobian) times the configurations' uniform measure; a
 *   walk in ln A proposes symmetrically in ln A, whose measure dA = A d ln
 *   A adds one more A: hence N + 1. For an ideal gas the area is then
 *   Gamma(N + 1, 1 / (beta P)) distributed, <A> = (N + 1) / (beta P) and
 *   <N / A> = beta P exactly (the area fraction, proportional to 1 / A,
 *   averages what the canonical one at that pressure is);
 * - optionally the aspect (a crystal's box must find its own shape):
 *   ln(L_x / L_y) moved by d in [-max_step, max_step] at fixed area, the
 *   sides times exp(d / 2) and exp(-d / 2), accepted unless a pair would
 *   overlap (a uniform measure on ln(L_x / L_y); a fluid's box has nothing
 *   to hold its shape, and drifts).
 *
 * Hard disks have no potential energy, so temperature does not enter:
 * beta P is the parameter, and the configurations the integrator samples
 * between moves are the same uniform measure at any energy (a heat bath
 * or none). The integrator rescales the box (its resize service: a new
 * state built beside the old and swapped in); a move it refuses (an
 * overlap, a side too short for the largest disk, past 1e9) is rejected.
 * The moves use a stream of the simulation's seed, kept here and carried
 * by checkpoints. */
#include <math.h>
#include <stdlib.h>

#include "protocols/protocols.h"

/* The stream's own seed: the simulation's, mixed with "barostat". */
#define STREAM 0x626172736f737461ull

typedef struct barostat {
    double pressure; /* beta P sigma^2 */
    uint64_t every;  /* steps between moves */
    double max_step; /* the largest change of ln A (and of ln aspect) a move proposes */
    int aspect;      /* also moves of the aspect */
    ds_rng rng;
    uint64_t tried, accepted; /* area moves since it was set */
} barostat;

/* beta P in the box's units: the reduced pressure over the largest
 * diameter squared. */
static double beta_p(const ds_sim *sim, const barostat *b)
{
    const double sigma = 2.0 * sim->world.radius_max;
    return b->pressure / (sigma * sigma);
}

/* A move of ln A by d: the Metropolis test first (the uniform is drawn
 * whatever the odds, so the stream does not depend on them), the
 * overlaps only if it passes. DS_ERR_NOMEM stops the run. */
static ds_status area_move(ds_sim *sim, barostat *b)
{
    const ds_box *box = &sim->world.box;
    const double area = box->side[0] * box->side[1];
    const double d = ds_rng_uniform(&b->rng, -b->max_step, b->max_step);
    const double u = ds_rng_uniform(&b->rng, 0.0, 1.0);
    const double n = (double)sim->world.n;
    const double log_odds = -beta_p(sim, b) * area * expm1(d) + (n + 1.0) * d;
    ++b->tried;
    if (!(log_odds >= 0.0 || log1p(-u) < log_odds))
        return DS_OK;
    const double s = exp(0.5 * d);
    const ds_status st = sim->integrator->resize(sim, s, s);
    b->accepted += st == DS_OK;
    return st == DS_ERR_NOMEM ? st : DS_OK;
}

static ds_status aspect_move(ds_sim *sim, barostat *b)
{
    const double d = ds_rng_uniform(&b->rng, -b->max_step, b->max_step);
    const ds_status st = sim->integrator->resize(sim, exp(0.5 * d), exp(-0.5 * d));
    return st == DS_ERR_NOMEM ? st : DS_OK;
}

static ds_status step_end(ds_sim *sim, void *self)
{
    barostat *b = self;
    if (sim->steps % b->every != 0)
        return DS_OK;
    ds_status st = area_move(sim, b);
    if (st == DS_OK && b->aspect)
        st = aspect_move(sim, b);
    return st;
}

static void save(const ds_sim *sim, const void *self, ds_state_writer *w)
{
    (void)sim;
    const barostat *b = self;
    ds_put_f64(w, b->pressure);
    ds_put_u64(w, b->every);
    ds_put_f64(w, b->max_step);
    ds_put_u32(w, (uint32_t)b->aspect);
    ds_put_u64(w, b->rng.state);
    ds_put_u64(w, b->tried);
    ds_put_u64(w, b->accepted);
}

/* What a barostat's numbers must be for the run to go on: those its
 * setter takes (sim/protocols.c), a generator's state (never 0), no more
 * moves accepted than tried, in a periodic box. */
static ds_status load(ds_sim *sim, void **self, ds_reader *r, ds_error *err)
{
    barostat rec;
    rec.pressure = ds_get_f64(r);
    rec.every = ds_get_u64(r);
    rec.max_step = ds_get_f64(r);
    const uint32_t aspect = ds_get_u32(r);
    rec.rng.state = ds_get_u64(r);
    rec.tried = ds_get_u64(r);
    rec.accepted = ds_get_u64(r);
    if (r->failed || !(rec.pressure > 0.0 && rec.pressure <= DS_BAROSTAT_MAX_PRESSURE) ||
        rec.every == 0 || !(rec.max_step > 0.0 && rec.max_step <= DS_BAROSTAT_MAX_STEP) ||
        aspect > 1u || rec.rng.state == 0 || rec.accepted > rec.tried ||
        !ds_box_periodic(&sim->world.box, 0) || !ds_box_periodic(&sim->world.box, 1))
        return ds_state_refuse(err, DS_ERR_FORMAT, "its barostat's part is not one");
    rec.aspect = (int)aspect;
    barostat *b = malloc(sizeof *b);
    if (!b)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the barostat");
    *b = rec;
    *self = b;
    return DS_OK;
}

static void destroy(void *self) { free(self); }

const ds_protocol_ops ds_barostat_ops = {
    .name = "barostat",
    .kind = DS_PROTOCOL_BAROSTAT,
    .step_end = step_end,
    .save = save,
    .load = load,
    .destroy = destroy,
};

ds_status ds_barostat_start(ds_sim *sim, double pressure, uint64_t every, double max_step,
                            int aspect)
{
    barostat *b = ds_protocols_get(sim, DS_PROTOCOL_BAROSTAT);
    if (!b) {
        if (!(b = calloc(1, sizeof *b)))
            return DS_ERR_NOMEM;
        ds_rng_seed(&b->rng, sim->world.seed ^ STREAM);
        ds_protocols_install(sim, &ds_barostat_ops, b);
    }
    /* Set again, the stream goes on; the acceptance counts from now. */
    b->pressure = pressure;
    b->every = every;
    b->max_step = max_step;
    b->aspect = aspect != 0;
    b->tried = b->accepted = 0;
    ds_protocol_clock *c = ds_protocols_clock(sim, DS_PROTOCOL_BAROSTAT);
    c->next = INFINITY;
    c->asap = c->watching = 0;
    c->stepping = 1;
    ds_protocols_refresh(&sim->protocols);
    return DS_OK;
}

double ds_barostat_get(const ds_sim *sim, double *acceptance)
{
    const barostat *b = ds_protocols_get(sim, DS_PROTOCOL_BAROSTAT);
    *acceptance = b && b->tried ? (double)b->accepted / (double)b->tried : 0.0;
    return b ? b->pressure : 0.0;
}
