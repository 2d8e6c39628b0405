/* SPDX-License-Identifier: MIT */
/* The time step's free flight: every disk moves by v dt, then a disk past
 * a wall turns, or in a periodic box wraps to the opposite edge. */
#include <math.h>

#include "core/boundary.h"
#include "core/collide.h"
#include "timestep/timestep.h"

/* A mixture: each disk turns at its own radius, and hands the walls 2 m
 * |v_n| over the perimeter its centre reaches (tally.wall_reach), so that
 * the partial pressures of the kinds add up (observables.c). */
static void move_and_reflect_mixture(ds_disks *d, const ds_world *w, ds_tally *t)
{
    const size_t n = d->n;
    const double dt = w->dt;
    uint64_t hits = 0;
    double impulse = 0.0, reach = 0.0;
    for (size_t k = 0; k < n; ++k) {
        const double r = d->r ? d->r[k] : w->radius, m = d->m ? d->m[k] : 1.0;
        const double perimeter = 2.0 * (w->box - 2.0 * r) + 2.0 * (w->box_y - 2.0 * r);
        const double px = d->x[k] + d->vx[k] * dt, py = d->y[k] + d->vy[k] * dt;
        d->x[k] = px;
        d->y[k] = py;
        if ((px < r && d->vx[k] < 0.0) || (px > w->box - r && d->vx[k] > 0.0)) {
            ds_tally_wall_turn(t, m, d->vx[k], d->vy[k]);
            impulse += 2.0 * m * fabs(d->vx[k]);
            reach += 2.0 * m * fabs(d->vx[k]) / perimeter;
            d->vx[k] = -d->vx[k];
            ++hits;
        }
        if ((py < r && d->vy[k] < 0.0) || (py > w->box_y - r && d->vy[k] > 0.0)) {
            ds_tally_wall_turn(t, m, d->vx[k], d->vy[k]);
            impulse += 2.0 * m * fabs(d->vy[k]);
            reach += 2.0 * m * fabs(d->vy[k]) / perimeter;
            d->vy[k] = -d->vy[k];
            ++hits;
        }
    }
    t->wall_count += hits;
    t->wall_impulse += impulse;
    t->wall_reach += reach;
}

void ds_move_and_reflect(ds_disks *d, const ds_world *w, ds_tally *t)
{
    if (d->r || d->m) {
        move_and_reflect_mixture(d, w, t);
        return;
    }
    const size_t n = d->n;
    const double dt = w->dt, lo = w->radius;
    const double hi_x = w->box - w->radius, hi_y = w->box_y - w->radius;
    double *restrict x = d->x, *restrict y = d->y;
    double *restrict vx = d->vx, *restrict vy = d->vy;
    uint64_t hits = 0;
    double impulse = 0.0;

    for (size_t k = 0; k < n; ++k) {
        double px = x[k] + vx[k] * dt, py = y[k] + vy[k] * dt;
        x[k] = px;
        y[k] = py;
        /* Reflect only a disk that is outside the band *and* moving further
         * out. The seed's literal rule also re-inverts a disk still outside
         * after its reflection, sending it back out: it sticks to the wall. */
        if ((px < lo && vx[k] < 0.0) || (px > hi_x && vx[k] > 0.0)) {
            ds_tally_wall_turn(t, 1.0, vx[k], vy[k]);
            impulse += 2.0 * fabs(vx[k]);
            vx[k] = -vx[k];
            ++hits;
        }
        if ((py < lo && vy[k] < 0.0) || (py > hi_y && vy[k] > 0.0)) {
            ds_tally_wall_turn(t, 1.0, vx[k], vy[k]);
            impulse += 2.0 * fabs(vy[k]);
            vy[k] = -vy[k];
            ++hits;
        }
    }
    t->wall_count += hits;
    t->wall_impulse += impulse;
}

void ds_move_and_wrap(ds_disks *d, const ds_world *w)
{
    const size_t n = d->n;
    const double dt = w->dt, box_x = w->box, box_y = w->box_y;
    double *restrict x = d->x, *restrict y = d->y;
    const double *restrict vx = d->vx, *restrict vy = d->vy;
    if (!d->ix) {
        for (size_t k = 0; k < n; ++k) {
            x[k] = ds_wrap(x[k] + vx[k] * dt, box_x);
            y[k] = ds_wrap(y[k] + vy[k] * dt, box_y);
        }
        return;
    }
    int32_t *restrict ix = d->ix, *restrict iy = d->iy;
    for (size_t k = 0; k < n; ++k) {
        x[k] = ds_wrap_counting(x[k] + vx[k] * dt, box_x, &ix[k]);
        y[k] = ds_wrap_counting(y[k] + vy[k] * dt, box_y, &iy[k]);
    }
}
