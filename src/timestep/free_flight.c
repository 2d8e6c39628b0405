/* SPDX-License-Identifier: MIT */
/* The time step's free flight: every disk moves by v dt, then a disk past
 * a wall turns, or in a periodic box wraps to the opposite edge; a field
 * changes every velocity by g dt first. */
#include <math.h>

#include "core/box.h"
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
        const double perimeter = ds_box_wall_reached(&w->box, r);
        const double px = d->x[k] + d->vx[k] * dt, py = d->y[k] + d->vy[k] * dt;
        d->x[k] = px;
        d->y[k] = py;
        if ((px < r && d->vx[k] < 0.0) || (px > w->box.side[0] - r && d->vx[k] > 0.0)) {
            ds_tally_wall_turn(t, m, d->vx[k], d->vy[k]);
            impulse += 2.0 * m * fabs(d->vx[k]);
            reach += 2.0 * m * fabs(d->vx[k]) / perimeter;
            d->vx[k] = -d->vx[k];
            ++hits;
        }
        if ((py < r && d->vy[k] < 0.0) || (py > w->box.side[1] - r && d->vy[k] > 0.0)) {
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

static void move_and_reflect(ds_disks *d, const ds_world *w, ds_tally *t)
{
    if (d->r || d->m) {
        move_and_reflect_mixture(d, w, t);
        return;
    }
    const size_t n = d->n;
    const double dt = w->dt, lo = w->radius;
    const double hi_x = w->box.side[0] - w->radius, hi_y = w->box.side[1] - w->radius;
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

static void move_and_wrap(ds_disks *d, const ds_world *w)
{
    const size_t n = d->n;
    const double dt = w->dt, box_x = w->box.side[0], box_y = w->box.side[1];
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

/* A box with walls along one axis and periodic along the other (a
 * channel): each axis as its edge says, a disk's own radius at the walls,
 * its crossings counted. */
static void move_mixed(ds_disks *d, const ds_world *w, ds_tally *t)
{
    const ds_box *box = &w->box;
    const double dt = w->dt;
    uint64_t hits = 0;
    double impulse = 0.0, reach = 0.0;
    for (size_t k = 0; k < d->n; ++k) {
        const double r = d->r ? d->r[k] : w->radius, m = d->m ? d->m[k] : 1.0;
        double p[2] = {d->x[k] + d->vx[k] * dt, d->y[k] + d->vy[k] * dt};
        double *v[2] = {&d->vx[k], &d->vy[k]};
        int32_t *image[2] = {d->ix ? &d->ix[k] : NULL, d->iy ? &d->iy[k] : NULL};
        for (int a = 0; a < 2; ++a) {
            if (ds_box_periodic(box, a)) {
                p[a] = image[a] ? ds_wrap_counting(p[a], box->side[a], image[a])
                                : ds_wrap(p[a], box->side[a]);
            } else if ((p[a] < r && *v[a] < 0.0) || (p[a] > box->side[a] - r && *v[a] > 0.0)) {
                ds_tally_wall_turn(t, m, d->vx[k], d->vy[k]);
                impulse += 2.0 * m * fabs(*v[a]);
                reach += 2.0 * m * fabs(*v[a]) / ds_box_wall_reached(box, r);
                *v[a] = -*v[a];
                ++hits;
            }
        }
        d->x[k] = p[0];
        d->y[k] = p[1];
    }
    t->wall_count += hits;
    t->wall_impulse += impulse;
    t->wall_reach += reach;
}

/* Walls that take energy (restitution below 1) or hold disks against a
 * field: each axis as its edge says, a disk's own radius at the walls. A
 * disk past a wall's band that moves out turns, its normal velocity -e
 * v_n; whatever it moves, it comes back into the band mirrored (a field
 * would otherwise press a disk resting on a wall a little further through
 * it every other step), no further than the band's other side. */
static void move_general(ds_disks *d, const ds_world *w, ds_tally *t)
{
    const ds_box *box = &w->box;
    const double dt = w->dt, e = w->rules.wall_restitution;
    uint64_t hits = 0;
    double impulse = 0.0, reach = 0.0;
    for (size_t k = 0; k < d->n; ++k) {
        const double r = d->r ? d->r[k] : w->radius, m = d->m ? d->m[k] : 1.0;
        double p[2] = {d->x[k] + d->vx[k] * dt, d->y[k] + d->vy[k] * dt};
        double *v[2] = {&d->vx[k], &d->vy[k]};
        int32_t *image[2] = {d->ix ? &d->ix[k] : NULL, d->iy ? &d->iy[k] : NULL};
        for (int a = 0; a < 2; ++a) {
            if (ds_box_periodic(box, a)) {
                p[a] = image[a] ? ds_wrap_counting(p[a], box->side[a], image[a])
                                : ds_wrap(p[a], box->side[a]);
                continue;
            }
            const double lo = r, hi = box->side[a] - r;
            if (!(p[a] < lo || p[a] > hi))
                continue;
            const int low = p[a] < lo;
            if (low ? *v[a] < 0.0 : *v[a] > 0.0) {
                const double after = -e * *v[a];
                ds_tally_wall_bounce(t, m, d->vx[k], d->vy[k], a, after);
                impulse += m * fabs(after - *v[a]);
                reach += m * fabs(after - *v[a]) / ds_box_wall_reached(box, r);
                *v[a] = after;
                ++hits;
            }
            p[a] = fmin(fmax(low ? 2.0 * lo - p[a] : 2.0 * hi - p[a], lo), hi);
        }
        d->x[k] = p[0];
        d->y[k] = p[1];
    }
    t->wall_count += hits;
    t->wall_impulse += impulse;
    t->wall_reach += reach;
}

void ds_fall(ds_disks *d, const ds_world *w, ds_tally *t)
{
    const double ux = w->rules.field[0] * w->dt, uy = w->rules.field[1] * w->dt;
    for (size_t k = 0; k < d->n; ++k) {
        d->vx[k] += ux;
        d->vy[k] += uy;
    }
    ds_disks_kinetic_tensor(d, t->kinetic);
}

void ds_move(ds_disks *d, const ds_world *w, ds_tally *t)
{
    if (ds_rules_fall(&w->rules) || w->rules.wall_restitution < 1.0) {
        move_general(d, w, t);
        return;
    }
    const int px = ds_box_periodic(&w->box, 0), py = ds_box_periodic(&w->box, 1);
    if (px && py)
        move_and_wrap(d, w);
    else if (!px && !py)
        move_and_reflect(d, w, t);
    else
        move_mixed(d, w, t);
}
