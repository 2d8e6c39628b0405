/* SPDX-License-Identifier: MIT */
/* The collision rule, in one place for every integrator: a collision of
 * two disks along their line of centres, elastic or with a coefficient of
 * restitution, a wall turn, the TC model's choice between them, and what
 * each adds to the virial, the pressure tensor's parts and the energy
 * books. Not installed. */
#ifndef DS_COLLIDE_H
#define DS_COLLIDE_H

#include "core/core.h"

/* What a collision adds to the pressure tensor's parts, mu = 2 ma mb /
 * (ma + mb) (1 for equal masses), s = approach / r^2 < 0, dv = v_b - v_a
 * before: the virial tensor (r_a - r_b)_a dp_a,b = -mu s r_a r_b (its
 * trace -mu approach is the virial's), and the change of the kinetic
 * tensor sum m v_a v_b of the two disks, from v_a' = v_a + (mb / M) 2 s r
 * and v_b' = v_b - (ma / M) 2 s r: mu (2 s^2 r_a r_b - s (r_a dv_b + r_b
 * dv_a)). Energy is conserved, so the change of yy is minus that of xx. */
static inline void ds_collide_stress(double rx, double ry, double s, double mu, double dvx,
                                     double dvy, ds_tally *t)
{
    const double sx = s * rx, sy = s * ry;
    t->stress_virial[0] -= mu * sx * rx;
    t->stress_virial[1] -= mu * sy * ry;
    t->stress_virial[2] -= mu * sx * ry;
    const double kxx = mu * (2.0 * sx * sx - 2.0 * sx * dvx);
    t->kinetic[0] += kxx;
    t->kinetic[1] -= kxx;
    t->kinetic[2] += mu * (2.0 * sx * sy - sx * dvy - sy * dvx);
}

/* The kinetic tensor's time integral carried over span of unchanged
 * velocities. */
static inline void ds_tally_flight(ds_tally *t, double span)
{
    t->kinetic_integral[0] += t->kinetic[0] * span;
    t->kinetic_integral[1] += t->kinetic[1] * span;
    t->kinetic_integral[2] += t->kinetic[2] * span;
}

/* The kinetic tensor's integral over span of falling disks: every
 * velocity is v + g tau after tau, so the tensor sum m v_a v_b is K_ab +
 * tau (g_a P_b + P_a g_b) + tau^2 M g_a g_b (P the momentum, M the total
 * mass), whose integral is taken exactly; K and P are left at the end. */
static inline void ds_tally_fall(ds_tally *t, double span)
{
    const double gx = t->field[0], gy = t->field[1], px = t->momentum[0], py = t->momentum[1];
    const double lin[3] = {2.0 * gx * px, 2.0 * gy * py, gx * py + gy * px};
    const double quad[3] = {t->mass * gx * gx, t->mass * gy * gy, t->mass * gx * gy};
    for (int c = 0; c < 3; ++c) {
        t->kinetic_integral[c] +=
            span * (t->kinetic[c] + span * (0.5 * lin[c] + span * quad[c] / 3.0));
        t->kinetic[c] += span * (lin[c] + span * quad[c]);
    }
    t->momentum[0] += t->mass * gx * span;
    t->momentum[1] += t->mass * gy * span;
}

/* The kinetic tensor's integral over span in a sheared box: xy that of
 * the peculiar velocities, sum m vx vy - rate M(t) with the moment M =
 * sum m (y - H/2) vy growing at K_yy = sum m vy^2 (core.h). */
static inline void ds_tally_shear_flight(ds_tally *t, double span)
{
    t->kinetic_integral[0] += t->kinetic[0] * span;
    t->kinetic_integral[1] += t->kinetic[1] * span;
    t->kinetic_integral[2] +=
        (t->kinetic[2] - t->shear_rate * (t->shear_moment + 0.5 * t->kinetic[1] * span)) * span;
    t->shear_moment += t->kinetic[1] * span;
}

/* The same from the integrator time tally->stress_clock to t, which it
 * then is: before a velocity changes at t. Straight flights keep their
 * bits; falling ones (tally->falling) change the tensor as they go. */
static inline void ds_tally_flight_to(ds_tally *t, double to)
{
    if (t->falling)
        ds_tally_fall(t, to - t->stress_clock);
    else if (t->shear_rate != 0.0)
        ds_tally_shear_flight(t, to - t->stress_clock);
    else
        ds_tally_flight(t, to - t->stress_clock);
    t->stress_clock = to;
}

/* A wall turn of a disk of mass m and velocity (vx, vy) before it: one
 * component changes sign, so only m vx vy does. */
static inline void ds_tally_wall_turn(ds_tally *t, double m, double vx, double vy)
{
    t->kinetic[2] -= 2.0 * m * vx * vy;
}

/* A wall turn in general: the normal component along axis (0: x, 1: y) of
 * a disk of mass m and velocity (vx, vy) becomes `after` (-e v_n, or what
 * a field's floor gives it, time_step.c and event/falling.c): the kinetic
 * tensor's changes, the momentum's, and the kinetic energy lost. */
static inline void ds_tally_wall_bounce(ds_tally *t, double m, double vx, double vy, int axis,
                                        double after)
{
    const double normal = axis ? vy : vx, other = axis ? vx : vy;
    t->kinetic[axis] += m * (after * after - normal * normal);
    t->kinetic[2] += m * other * (after - normal);
    t->momentum[axis] += m * (after - normal);
    t->dissipated += 0.5 * m * (normal * normal - after * after);
}

/* The TC model (Luding and McNamara 1998, Granular Matter 1, 113): a
 * collision at time t of disks whose previous collisions were at *last_a
 * and *last_b (-infinity: none; one disk and a wall: both the same) is
 * elastic if either came within contact_time before it, else restitution
 * applies; both times become t. A cluster's collisions can then come no
 * closer than contact_time apart and still dissipate, so their number in
 * a finite time stays finite: the inelastic collapse (McNamara and Young
 * 1994), infinitely many collisions in finite time, cannot happen. */
static inline double ds_tc_restitution(double restitution, double contact_time, double t,
                                       double *last_a, double *last_b)
{
    const int elastic = t - *last_a < contact_time || t - *last_b < contact_time;
    *last_a = *last_b = t;
    return elastic ? 1.0 : restitution;
}

/* A disk of mass m whose velocity is set from (vx, vy) to (wx, wy) (a
 * heat bath's collision): the kinetic tensor's change. */
static inline void ds_tally_velocity(ds_tally *t, double m, double vx, double vy, double wx,
                                     double wy)
{
    t->kinetic[0] += m * (wx * wx - vx * vx);
    t->kinetic[1] += m * (wy * wy - vy * vy);
    t->kinetic[2] += m * (wx * wy - vx * vy);
}

/* Disks a and b with velocities (*avx, *avy) and (*bvx, *bvy), b seen
 * from a at (rx, ry), and approach = (v_b - v_a) . r < 0: equal masses
 * exchange the velocity components along the line of centres n = r/|r|;
 * the change of each is (dv . n) n = approach / r^2 * r. Adds the
 * collision to the tally: r_ab . dp_a = (-r) . (s r) = -approach > 0. */
static inline void ds_collide(double rx, double ry, double approach, double *avx, double *avy,
                              double *bvx, double *bvy, ds_tally *t)
{
    const double s = approach / (rx * rx + ry * ry);
    ds_collide_stress(rx, ry, s, 1.0, *bvx - *avx, *bvy - *avy, t);
    *avx += s * rx;
    *avy += s * ry;
    *bvx -= s * rx;
    *bvy -= s * ry;
    t->virial -= approach;
    ++t->collisions;
}

/* The same for masses ma and mb: the momentum along the line of centres
 * exchanged as an elastic collision does, disk a's velocity changing by
 * 2 mb / (ma + mb) (dv . n) n and b's by the opposite momentum (energy and
 * momentum conserved); the virial r_ab . dp_a = -2 ma mb / (ma + mb)
 * approach. With ma = mb the factors are exactly 1, and this is
 * ds_collide to the bit. */
static inline void ds_collide_masses(double rx, double ry, double approach, double ma, double mb,
                                     double *avx, double *avy, double *bvx, double *bvy,
                                     ds_tally *t)
{
    const double s = approach / (rx * rx + ry * ry), total = ma + mb;
    const double ka = 2.0 * mb / total, kb = 2.0 * ma / total;
    ds_collide_stress(rx, ry, s, ma * ka, *bvx - *avx, *bvy - *avy, t);
    *avx += ka * s * rx;
    *avy += ka * s * ry;
    *bvx -= kb * s * rx;
    *bvy -= kb * s * ry;
    t->virial -= 2.0 * ma * mb / total * approach;
    ++t->collisions;
}

/* A collision with coefficient of restitution e in (0, 1) (at e = 1 the
 * rules take ds_collide and ds_collide_masses, which keep their bits;
 * this form agrees with them to rounding): the relative normal velocity
 * u = approach / |r| becomes -e u. Disk a's velocity changes by (1 + e)
 * mb / M s r and b's by -(1 + e) ma / M s r (M = ma + mb, momentum
 * conserved), the impulse on a is J s r with J = (1 + e) ma mb / M, the
 * virial r_ab . dp_a = -J approach, and the kinetic energy falls by
 * (1 - e^2) (ma mb / M) u^2 / 2 = (1 - e) J s approach / 2. The kinetic
 * tensor changes by J ((1 + e) s^2 r_a r_b - s (r_a dv_b + r_b dv_a)),
 * whose trace is minus twice that loss (ds_collide_stress's at e = 1). */
static inline void ds_collide_inelastic(double rx, double ry, double approach, double ma, double mb,
                                        double e, double *avx, double *avy, double *bvx,
                                        double *bvy, ds_tally *t)
{
    const double s = approach / (rx * rx + ry * ry), total = ma + mb;
    const double ka = (1.0 + e) * mb / total, kb = (1.0 + e) * ma / total, j = ma * ka;
    const double dvx = *bvx - *avx, dvy = *bvy - *avy, sx = s * rx, sy = s * ry;
    t->stress_virial[0] -= j * sx * rx;
    t->stress_virial[1] -= j * sy * ry;
    t->stress_virial[2] -= j * sx * ry;
    t->kinetic[0] += j * ((1.0 + e) * sx * sx - 2.0 * sx * dvx);
    t->kinetic[1] += j * ((1.0 + e) * sy * sy - 2.0 * sy * dvy);
    t->kinetic[2] += j * ((1.0 + e) * sx * sy - sx * dvy - sy * dvx);
    *avx += ka * sx;
    *avy += ka * sy;
    *bvx -= kb * sx;
    *bvy -= kb * sy;
    t->virial -= j * approach;
    t->dissipated += 0.5 * (1.0 - e) * j * s * approach;
    ++t->collisions;
}

/* A collision with restitution e (1: elastic, with the bits of
 * ds_collide or ds_collide_masses; masses NULL-free: ma = mb = 1 and
 * `masses` 0 for disks of one mass). */
static inline void ds_collide_with(double rx, double ry, double approach, int masses, double ma,
                                   double mb, double e, double *avx, double *avy, double *bvx,
                                   double *bvy, ds_tally *t)
{
    if (e < 1.0)
        ds_collide_inelastic(rx, ry, approach, ma, mb, e, avx, avy, bvx, bvy, t);
    else if (masses)
        ds_collide_masses(rx, ry, approach, ma, mb, avx, avy, bvx, bvy, t);
    else
        ds_collide(rx, ry, approach, avx, avy, bvx, bvy, t);
}

#endif
