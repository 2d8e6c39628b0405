/* Broad phases: which pairs of disks are close enough to test.
 *
 * DS_SAP is the seed's sweep and prune: keep the disks sorted by x with
 * insertion sort (nearly linear, since the order barely changes between
 * steps) and test a pair only while their x distance is below 2R.
 * DS_BRUTE_FORCE tests all pairs and is the reference the others are
 * checked against. DS_SAP_STRIPS lives in broad_phase_strips.c. */
#include <math.h>

#include "sim_internal.h"

void ds_bp_insertion_sort_x(ds_sim *sim)
{
    const size_t n = sim->n;
    double *restrict x = sim->x, *restrict y = sim->y;
    double *restrict vx = sim->vx, *restrict vy = sim->vy;
    uint32_t *restrict id = sim->id;

    for (size_t k = 1; k < n; ++k) {
        const double xk = x[k];
        if (!(xk < x[k - 1]))
            continue; /* the common case: already in order */
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
        } while (j > 0 && xk < x[j - 1]);
        x[j] = xk;
        y[j] = yk;
        vx[j] = vxk;
        vy[j] = vyk;
        id[j] = idk;
    }
}

static uint64_t sweep_sap(ds_sim *sim, ds_pair_fn on_pair, void *ctx)
{
    const size_t n = sim->n;
    const double *restrict x = sim->x, *restrict y = sim->y;
    const double diameter = 2.0 * sim->radius, d2max = diameter * diameter;
    uint64_t tested = 0;

    /* x[n] = +inf is a sentinel: the inner loop needs no bound check. */
    for (size_t i = 0; i < n; ++i) {
        const double xi = x[i], yi = y[i], xlim = xi + diameter;
        size_t j = i + 1;
        for (; x[j] < xlim; ++j) {
            const double dx = x[j] - xi, dy = y[j] - yi;
            if (dx * dx + dy * dy < d2max)
                on_pair(sim, i, j, ctx);
        }
        tested += j - i - 1;
    }
    return tested;
}

static uint64_t sweep_brute_force(ds_sim *sim, ds_pair_fn on_pair, void *ctx)
{
    const size_t n = sim->n;
    const double *x = sim->x, *y = sim->y;
    const double diameter = 2.0 * sim->radius, d2max = diameter * diameter;

    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            const double dx = x[j] - x[i], dy = y[j] - y[i];
            if (dx * dx + dy * dy < d2max)
                on_pair(sim, i, j, ctx);
        }
    return (uint64_t)n * (n - 1) / 2;
}

uint64_t ds_bp_find_pairs(ds_sim *sim, ds_pair_fn on_pair, void *ctx)
{
    switch (sim->broadphase) {
    case DS_BRUTE_FORCE:
        return sweep_brute_force(sim, on_pair, ctx);
    case DS_SAP_STRIPS:
        return ds_strips_find_pairs(sim, on_pair, ctx);
    case DS_SAP:
    case DS_AUTO:
        break;
    }
    ds_bp_insertion_sort_x(sim);
    return sweep_sap(sim, on_pair, ctx);
}
