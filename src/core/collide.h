/* SPDX-License-Identifier: MIT */
/* The collision rule, in one place for every integrator: an elastic
 * collision of two disks along their line of centres, and what it adds to
 * the virial. Not installed. */
#ifndef DS_COLLIDE_H
#define DS_COLLIDE_H

#include "core/core.h"

/* Disks a and b with velocities (*avx, *avy) and (*bvx, *bvy), b seen
 * from a at (rx, ry), and approach = (v_b - v_a) . r < 0: equal masses
 * exchange the velocity components along the line of centres n = r/|r|;
 * the change of each is (dv . n) n = approach / r^2 * r. Adds the
 * collision to the tally: r_ab . dp_a = (-r) . (s r) = -approach > 0. */
static inline void ds_collide(double rx, double ry, double approach, double *avx, double *avy,
                              double *bvx, double *bvy, ds_tally *t)
{
    const double s = approach / (rx * rx + ry * ry);
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
    *avx += ka * s * rx;
    *avy += ka * s * ry;
    *bvx -= kb * s * rx;
    *bvy -= kb * s * ry;
    t->virial -= 2.0 * ma * mb / total * approach;
    ++t->collisions;
}

#endif
