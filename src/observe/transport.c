/* SPDX-License-Identifier: MIT */
/* Transport: the mean-squared displacement and the velocity
 * autocorrelation with multiple time origins, and the self-diffusion
 * coefficient from each (Einstein and Green-Kubo).
 *
 * Every origin_every-th sample is kept as an origin in a ring of
 * ceil(lags / origin_every) slots, so an origin's slot is reused only once
 * its last lag has passed. Each new sample closes one lag of every live
 * origin: a pass over the n disks per origin, adding |r - r0|^2 and
 * v . v0 in structure-of-arrays order. The sums over the disks of one
 * (origin, lag) are added as their mean, so the accumulators stay of the
 * size of the result and a long run loses no more than a few ulps per
 * sample to rounding. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "observe/observe.h"

struct ds_transport {
    size_t n, lags, every, slots;
    uint64_t samples;  /* samples added so far */
    double *origin;    /* slots blocks of 4 n: x, y, vx, vy */
    double *msd_sum;   /* lags sums of the per-origin mean |r - r0|^2 */
    double *vacf_sum;  /* lags sums of the per-origin mean v . v0 */
    uint64_t *origins; /* lags counts of origins seen at each lag */
    double *scratch;   /* 4 n: one sample of a sim (xy, then v) */
};

/* The accumulator's memory refused. */
static ds_status no_memory(ds_error *err, size_t n, size_t lags)
{
    return ds_refuse(err, DS_ERR_NOMEM, "n", (double)n, NAN,
                     "n = %zu disks: no memory for an accumulator of %zu lags", n, lags);
}

ds_status ds_transport_create(size_t n, size_t lags, size_t origin_every, ds_transport **out,
                              ds_error *err)
{
    ds_error_clear(err);
    if (!out)
        return ds_refuse(err, DS_ERR_ARG, "out", NAN, NAN, "out: NULL");
    *out = NULL;
    if (n == 0)
        return ds_refuse(err, DS_ERR_ARG, "n", 0.0, 1.0, "n = 0: there must be a disk");
    if (lags < 2)
        return ds_refuse(err, DS_ERR_ARG, "lags", (double)lags, 2.0,
                         "lags = %zu: there must be 2 at least (lag 0 and one more)", lags);
    if (origin_every == 0)
        return ds_refuse(err, DS_ERR_ARG, "origin_every", 0.0, 1.0,
                         "origin_every = 0: every sample, 1, at most");
    const size_t slots = lags / origin_every + (lags % origin_every != 0);
    /* 4 n doubles per slot and for the scratch sample must fit a size_t. */
    if (n > SIZE_MAX / (4 * sizeof(double)) / (slots + 1) || lags > SIZE_MAX / sizeof(double))
        return no_memory(err, n, lags);
    ds_transport *tr = calloc(1, sizeof *tr);
    if (!tr)
        return no_memory(err, n, lags);
    tr->n = n;
    tr->lags = lags;
    tr->every = origin_every;
    tr->slots = slots;
    tr->origin = malloc(slots * 4 * n * sizeof(double));
    tr->scratch = malloc(4 * n * sizeof(double));
    tr->msd_sum = calloc(lags, sizeof(double));
    tr->vacf_sum = calloc(lags, sizeof(double));
    tr->origins = calloc(lags, sizeof(uint64_t));
    if (!tr->origin || !tr->scratch || !tr->msd_sum || !tr->vacf_sum || !tr->origins) {
        ds_transport_destroy(tr);
        return no_memory(err, n, lags);
    }
    *out = tr;
    return DS_OK;
}

void ds_transport_destroy(ds_transport *tr)
{
    if (!tr)
        return;
    free(tr->origin);
    free(tr->scratch);
    free(tr->msd_sum);
    free(tr->vacf_sum);
    free(tr->origins);
    free(tr);
}

size_t ds_transport_get_lags(const ds_transport *tr) { return tr ? tr->lags : 0; }

/* Adds lag `lag` of the origin in block o (x, y, vx, vy of n disks) against
 * the sample (xy, v). */
static void close_lag(ds_transport *tr, const double *o, size_t lag, const double *xy,
                      const double *v)
{
    const size_t n = tr->n;
    const double *ox = o, *oy = o + n, *ovx = o + 2 * n, *ovy = o + 3 * n;
    double msd = 0.0, vacf = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double dx = xy[2 * i] - ox[i], dy = xy[2 * i + 1] - oy[i];
        msd += dx * dx + dy * dy;
        vacf += v[2 * i] * ovx[i] + v[2 * i + 1] * ovy[i];
    }
    tr->msd_sum[lag] += msd / (double)n;
    tr->vacf_sum[lag] += vacf / (double)n;
    ++tr->origins[lag];
}

ds_status ds_transport_add(ds_transport *tr, const double *xy, const double *v, ds_error *err)
{
    ds_error_clear(err);
    if (!tr || !xy || !v) {
        const char *which = !tr ? "tr" : !xy ? "xy" : "v";
        return ds_refuse(err, DS_ERR_ARG, which, NAN, NAN, "%s: NULL", which);
    }
    const size_t n = tr->n;
    for (size_t i = 0; i < 2 * n; ++i)
        if (!isfinite(xy[i]) || !isfinite(v[i])) {
            ds_error_index(err, i / 2);
            return ds_refuse(err, DS_ERR_ARG, "disk", isfinite(xy[i]) ? v[i] : xy[i], NAN,
                             "disk %zu has a %s that is not a finite number", i / 2,
                             isfinite(xy[i]) ? "velocity" : "position");
        }
    const uint64_t j = tr->samples, every = tr->every;
    if (j % every == 0) {
        double *o = tr->origin + (size_t)((j / every) % tr->slots) * 4 * n;
        for (size_t i = 0; i < n; ++i) {
            o[i] = xy[2 * i];
            o[n + i] = xy[2 * i + 1];
            o[2 * n + i] = v[2 * i];
            o[3 * n + i] = v[2 * i + 1];
        }
    }
    /* Live origins, newest first: origin number q sits at sample q every
     * and is live while j - q every < lags. */
    for (uint64_t q = j / every + 1; q-- > 0;) {
        const uint64_t lag = j - q * every;
        if (lag >= tr->lags)
            break;
        close_lag(tr, tr->origin + (size_t)(q % tr->slots) * 4 * n, (size_t)lag, xy, v);
    }
    tr->samples = j + 1;
    return DS_OK;
}

ds_status ds_transport_sample(ds_transport *tr, const ds_sim *sim, ds_error *err)
{
    ds_error_clear(err);
    if (!tr || !sim)
        return ds_refuse(err, DS_ERR_ARG, tr ? "sim" : "tr", NAN, NAN, "%s: NULL",
                         tr ? "sim" : "tr");
    if (sim->world.n != tr->n)
        return ds_refuse(err, DS_ERR_ARG, "sim", (double)sim->world.n, (double)tr->n,
                         "sim has %zu disks, not the accumulator's %zu", sim->world.n, tr->n);
    /* Unwrapped centres and velocities in generation order, as
     * ds_sim_get_unwrapped gives them. */
    double *xy = tr->scratch, *v = tr->scratch + 2 * tr->n;
    const ds_disks *a = &sim->disks;
    const double box_x = sim->world.box.side[0], box_y = sim->world.box.side[1];
    for (size_t k = 0; k < a->n; ++k) {
        const size_t i = a->id[k];
        xy[2 * i] = a->ix ? a->x[k] + (double)a->ix[k] * box_x : a->x[k];
        xy[2 * i + 1] = a->iy ? a->y[k] + (double)a->iy[k] * box_y : a->y[k];
        v[2 * i] = a->vx[k];
        v[2 * i + 1] = a->vy[k];
    }
    return ds_transport_add(tr, xy, v, err);
}

ds_status ds_transport_get(const ds_transport *tr, double *msd, double *vacf, uint64_t *origins,
                           ds_error *err)
{
    ds_error_clear(err);
    if (!tr)
        return ds_refuse(err, DS_ERR_ARG, "tr", NAN, NAN, "tr: NULL");
    for (size_t k = 0; k < tr->lags; ++k) {
        const uint64_t c = tr->origins[k];
        if (msd)
            msd[k] = c ? tr->msd_sum[k] / (double)c : 0.0;
        if (vacf)
            vacf[k] = c ? tr->vacf_sum[k] / (double)c : 0.0;
        if (origins)
            origins[k] = c;
    }
    return DS_OK;
}

static double mean_at(const double *sum, const uint64_t *count, size_t k)
{
    return sum[k] / (double)count[k];
}

/* The window [from, to] of lags refused, or DS_OK. */
static ds_status check_window(const ds_transport *tr, double interval, size_t from, size_t to,
                              ds_error *err)
{
    if (!tr)
        return ds_refuse(err, DS_ERR_ARG, "tr", NAN, NAN, "tr: NULL");
    if (!(interval > 0.0 && isfinite(interval)))
        return ds_refuse(err, DS_ERR_ARG, "interval", interval, 0.0,
                         "interval = %g must be finite and > 0", interval);
    if (from >= to)
        return ds_refuse(err, DS_ERR_ARG, "from", (double)from, (double)to,
                         "from = %zu must be below to = %zu", from, to);
    if (to >= tr->lags)
        return ds_refuse(err, DS_ERR_ARG, "to", (double)to, (double)tr->lags,
                         "to = %zu must be below the accumulator's lags, %zu", to, tr->lags);
    if (tr->origins[to] == 0)
        return ds_refuse(err, DS_ERR_ARG, "to", (double)to, NAN,
                         "to = %zu: no origin has reached that lag yet", to);
    return DS_OK;
}

ds_status ds_transport_get_diffusion(const ds_transport *tr, double interval, size_t from,
                                     size_t to, double *einstein, double *green_kubo, ds_error *err)
{
    ds_error_clear(err);
    const ds_status st = check_window(tr, interval, from, to, err);
    if (st != DS_OK)
        return st;
    const uint64_t *c = tr->origins; /* origins[k] >= origins[to] > 0 for k <= to */
    const double h = interval;
    if (einstein)
        *einstein = (mean_at(tr->msd_sum, c, to) - mean_at(tr->msd_sum, c, from)) /
                    (4.0 * (double)(to - from) * h);
    if (green_kubo) {
        /* D(k h) = (1/2) int_0^{k h} vacf by trapezoids, then its mean over
         * [from h, to h] by trapezoids: d msd / dt = 4 D(t) makes this the
         * Einstein slope's own average. */
        double d = 0.0, previous = 0.0, window = 0.0;
        for (size_t k = 1; k <= to; ++k) {
            d += 0.25 * h * (mean_at(tr->vacf_sum, c, k - 1) + mean_at(tr->vacf_sum, c, k));
            if (k > from)
                window += 0.5 * (previous + d);
            previous = d;
        }
        *green_kubo = window / (double)(to - from);
    }
    return DS_OK;
}
