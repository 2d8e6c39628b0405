/* SPDX-License-Identifier: MIT */
/* The collision rule, in one place for every integrator: an elastic
 * collision of two disks along their line of centres, and what it adds to
 * the virial. Not installed. */
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

/* The same from the integrator time tally->stress_clock to t, which it
 * then is: before a velocity changes at t. */
static inline void ds_tally_flight_to(ds_tally *t, double to)
{
    ds_tally_flight(t, to - t->stress_clock);
    t->stress_clock = to;
}

/* A wall turn of a disk of mass m and velocity (vx, vy) before it: one
 * component changes sign, so only m vx vy does. */
static inline void ds_tally_wall_turn(ds_tally *t, double m, double vx, double vy)
{
    t->kinetic[2] -= 2.0 * m * vx * vy;
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

#endif
