/* Collision response: free flight, wall reflection or the periodic wrap,
 * equal-mass elastic pairs. */
#include <math.h>

#include "boundary.h"
#include "sim_internal.h"

void ds_move_and_reflect(ds_sim *sim)
{
    const size_t n = sim->n;
    const double dt = sim->dt, lo = sim->radius;
    const double hi_x = sim->box - sim->radius, hi_y = sim->box_y - sim->radius;
    double *restrict x = sim->x, *restrict y = sim->y;
    double *restrict vx = sim->vx, *restrict vy = sim->vy;
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
            impulse += 2.0 * fabs(vx[k]);
            vx[k] = -vx[k];
            ++hits;
        }
        if ((py < lo && vy[k] < 0.0) || (py > hi_y && vy[k] > 0.0)) {
            impulse += 2.0 * fabs(vy[k]);
            vy[k] = -vy[k];
            ++hits;
        }
    }
    sim->wall_count += hits;
    sim->wall_impulse += impulse;
}

void ds_move_and_wrap(ds_sim *sim)
{
    const size_t n = sim->n;
    const double dt = sim->dt, box_x = sim->box, box_y = sim->box_y;
    double *restrict x = sim->x, *restrict y = sim->y;
    const double *restrict vx = sim->vx, *restrict vy = sim->vy;
    for (size_t k = 0; k < n; ++k) {
        x[k] = ds_wrap(x[k] + vx[k] * dt, box_x);
        y[k] = ds_wrap(y[k] + vy[k] * dt, box_y);
    }
}

/* The response to a pair whose separation from a to b is (dx, dy). */
static inline void resolve(ds_sim *sim, size_t a, size_t b, double dx, double dy)
{
    double *restrict vx = sim->vx, *restrict vy = sim->vy;
    const double dvx = vx[b] - vx[a], dvy = vy[b] - vy[a];
    const double approach = dvx * dx + dvy * dy;
    /* Only an approaching pair collides. An overlapping pair that already
     * separates was resolved on an earlier step; swapping again would turn
     * it back towards each other and the disks would stick together. */
    if (approach >= 0.0)
        return;
    const double d2 = dx * dx + dy * dy; /* > 0: approach < 0 needs dx,dy != 0 */
    /* Equal masses: exchange the velocity components along the line of
     * centres n = d/|d|. The change of each is (dv . n) n = approach/d2 * d. */
    const double s = approach / d2;
    vx[a] += s * dx;
    vy[a] += s * dy;
    vx[b] -= s * dx;
    vy[b] -= s * dy;
    /* r_ab . dp_a = (-d) . (s d) = -approach > 0 */
    sim->virial -= approach;
    ++sim->collisions;
}

void ds_resolve_pair(ds_sim *sim, size_t a, size_t b, void *ctx)
{
    (void)ctx;
    resolve(sim, a, b, sim->x[b] - sim->x[a], sim->y[b] - sim->y[a]);
}

void ds_resolve_pair_periodic(ds_sim *sim, size_t a, size_t b, void *ctx)
{
    (void)ctx;
    resolve(sim, a, b, ds_nearest(sim->x[b] - sim->x[a], sim->box),
            ds_nearest(sim->y[b] - sim->y[a], sim->box_y));
}
