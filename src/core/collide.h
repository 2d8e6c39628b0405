/* SPDX-License-Identifier: MIT */
/* The collision rule, in one place for every integrator: an elastic
 * collision of two equal masses along their line of centres, and what it
 * adds to the virial. Not installed. */
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

#endif
