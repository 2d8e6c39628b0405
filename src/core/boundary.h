/* SPDX-License-Identifier: MIT */
/* The periodic box in one place: wrapping a coordinate into the box and
 * the separation to the nearest image. Every part that meets the
 * boundary (the integrators, the broad phases, placement) calls these.
 *
 * ds_nearest assumes what ds_params_check guarantees: a periodic box is
 * more than two diameters wide along each axis, so two disks within 2R of
 * each other are so along exactly one image. */
#ifndef DS_BOUNDARY_H
#define DS_BOUNDARY_H

#include <math.h>
#include <stdint.h>

/* u moved into [0, box): one shift, which is all a step that moves a disk
 * less than a side needs, else ds_wrap_any (below). */
static inline double ds_wrap_any(double u, double box);
static inline double ds_wrap(double u, double box)
{
    if (u >= box)
        u -= box;
    else if (u < 0.0)
        u += box;
    if (u >= 0.0 && u < box)
        return u;
    /* A step longer than a side (a fast disk, a long dt, a thin box), or
     * -tiny + box rounded to box itself (0 then, the same point). */
    return ds_wrap_any(u, box);
}

/* u brought into [0, box) from anywhere (a caller's centres need not be
 * wrapped, a step may jump sides): u - box floor(u / box), exact for u
 * already inside. */
static inline double ds_wrap_any(double u, double box)
{
    u -= box * floor(u / box);
    return u >= 0.0 && u < box ? u : 0.0; /* rounding can reach box itself */
}

/* ds_wrap that also counts the boxes crossed into *image (+1 for each
 * side u went past box, -1 for each below 0), so that u + image box is
 * the same point before and after, up to the rounding of one subtraction
 * (exact for a single shift: u - box and u + box are then exact). The
 * count wraps (unsigned arithmetic) rather than overflow. */
static inline double ds_wrap_counting(double u, double box, int32_t *image)
{
    if (u >= box) {
        u -= box;
        *image = (int32_t)((uint32_t)*image + 1u);
    } else if (u < 0.0) {
        u += box;
        *image = (int32_t)((uint32_t)*image - 1u);
    }
    if (u >= 0.0 && u < box)
        return u;
    const double f = floor(u / box);
    u -= box * f;
    /* The count wraps modulo 2^32, so only f modulo 2^32 counts: fmod is
     * exact, and keeps the conversion defined however far u was (a forged
     * checkpoint's 1e34); a u that is not finite counts nothing. */
    const double turns = fmod(f, 4294967296.0);
    if (turns == turns)
        *image = (int32_t)((uint32_t)*image + (uint32_t)(int64_t)turns);
    if (u >= box) { /* rounding reached box itself: the next box's 0 */
        *image = (int32_t)((uint32_t)*image + 1u);
        return 0.0;
    }
    return u >= 0.0 ? u : 0.0;
}

/* A separation r along one axis of a periodic box of side box, taken to
 * the nearest image: into [-box/2, box/2], given |r| < 1.5 box. */
static inline double ds_nearest(double r, double box)
{
    if (r > 0.5 * box)
        r -= box;
    else if (r < -0.5 * box)
        r += box;
    return r;
}

#endif
