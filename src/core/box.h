/* SPDX-License-Identifier: MIT */
/* The box, one object that every part asks: its two sides, a boundary per
 * axis (walls or periodic), and for sheared periodic images (Lees and
 * Edwards 1972) the shift in x of the image above. Its operations take
 * both axes at once, so no part keeps a flag of its own or calls a
 * one-axis helper twice. Not installed.
 *
 * ds_box_nearest assumes what ds_params_check guarantees: a periodic side
 * is more than two diameters long, so two disks within contact of each
 * other are so through exactly one image. */
#ifndef DS_BOX_H
#define DS_BOX_H

#include <math.h>
#include <stdint.h>

typedef enum ds_edge { DS_EDGE_WALLS = 0, DS_EDGE_PERIODIC } ds_edge;

typedef struct ds_box {
    double side[2]; /* along x (the width) and along y (the height) */
    ds_edge edge[2];
    /* Sheared images: the image above the box (y + side[1]) stands
     * shift further along x, the one below -shift; 0 without shear. Kept
     * in [0, side[0]) by whoever moves it with time. */
    double shift;
    /* How fast that image moves along x (Lees-Edwards: the shear rate
     * times the height), 0 without shear; the one below moves at
     * -shift_speed. A disk seen through the image above moves that much
     * faster than it does (ds_box_nearest_moving). */
    double shift_speed;
    /* The shift unwrapped (shift plus whole widths), for image counts. */
    double offset;
} ds_box;

/* A box of the given sides, walls or periodic along each axis. */
static inline ds_box ds_box_make(double width, double height, ds_edge along_x, ds_edge along_y)
{
    ds_box b;
    b.side[0] = width;
    b.side[1] = height;
    b.edge[0] = along_x;
    b.edge[1] = along_y;
    b.shift = 0.0;
    b.shift_speed = 0.0;
    b.offset = 0.0;
    return b;
}

static inline int ds_box_periodic(const ds_box *b, int axis)
{
    return b->edge[axis] == DS_EDGE_PERIODIC;
}

/* Whether any axis is periodic: what decides if separations need the
 * nearest image at all. */
static inline int ds_box_any_periodic(const ds_box *b)
{
    return b->edge[0] == DS_EDGE_PERIODIC || b->edge[1] == DS_EDGE_PERIODIC;
}

/* ------------------------------------------------------------------ */
/* Wrapping a coordinate into the box                                   */
/* ------------------------------------------------------------------ */

/* u brought into [0, side) from anywhere (a caller's centres need not be
 * wrapped, a step may jump sides): u - side floor(u / side), exact for u
 * already inside. */
static inline double ds_wrap_any(double u, double side)
{
    u -= side * floor(u / side);
    return u >= 0.0 && u < side ? u : 0.0; /* rounding can reach side itself */
}

/* u moved into [0, side): one shift, which is all a step that moves a
 * disk less than a side needs, else ds_wrap_any. */
static inline double ds_wrap(double u, double side)
{
    if (u >= side)
        u -= side;
    else if (u < 0.0)
        u += side;
    if (u >= 0.0 && u < side)
        return u;
    /* A step longer than a side (a fast disk, a long dt, a thin box), or
     * -tiny + side rounded to side itself (0 then, the same point). */
    return ds_wrap_any(u, side);
}

/* ds_wrap that also counts the boxes crossed into *image (+1 for each
 * side u went past `side`, -1 for each below 0), so that u + image side
 * is the same point before and after, up to the rounding of one
 * subtraction (exact for a single shift). The count wraps (unsigned
 * arithmetic) rather than overflow. */
static inline double ds_wrap_counting(double u, double side, int32_t *image)
{
    if (u >= side) {
        u -= side;
        *image = (int32_t)((uint32_t)*image + 1u);
    } else if (u < 0.0) {
        u += side;
        *image = (int32_t)((uint32_t)*image - 1u);
    }
    if (u >= 0.0 && u < side)
        return u;
    const double f = floor(u / side);
    u -= side * f;
    /* The count wraps modulo 2^32, so only f modulo 2^32 counts: fmod is
     * exact, and keeps the conversion defined however far u was (a forged
     * checkpoint's 1e34); a u that is not finite counts nothing. */
    const double turns = fmod(f, 4294967296.0);
    if (turns == turns)
        *image = (int32_t)((uint32_t)*image + (uint32_t)(int64_t)turns);
    if (u >= side) { /* rounding reached side itself: the next box's 0 */
        *image = (int32_t)((uint32_t)*image + 1u);
        return 0.0;
    }
    return u >= 0.0 ? u : 0.0;
}

/* A centre (*x, *y) back into the box along each periodic axis after a
 * flight, counting the boxes crossed into *ix, *iy (either may be NULL:
 * not counted). Along a walls axis nothing changes: the integrator turns
 * the disk. A sheared box's crossing of the top or bottom also shifts x
 * (and, for the integrator, the velocity: ds_box_crossing_velocity). */
static inline void ds_box_wrap(const ds_box *b, double *x, double *y, int32_t *ix, int32_t *iy)
{
    if (b->edge[1] == DS_EDGE_PERIODIC) {
        int32_t turns = 0;
        *y = ds_wrap_counting(*y, b->side[1], &turns);
        if (turns != 0 && b->shift != 0.0)
            *x -= (double)turns * b->shift;
        if (iy)
            *iy = (int32_t)((uint32_t)*iy + (uint32_t)turns);
    }
    if (b->edge[0] == DS_EDGE_PERIODIC) {
        if (ix)
            *x = ds_wrap_counting(*x, b->side[0], ix);
        else
            *x = ds_wrap(*x, b->side[0]);
    }
}

/* The same for any centre, as a caller gives it (psi6, g(r)): no counts. */
static inline void ds_box_wrap_any(const ds_box *b, double *x, double *y)
{
    if (b->edge[1] == DS_EDGE_PERIODIC) {
        const double turns = floor(*y / b->side[1]);
        *y = ds_wrap_any(*y, b->side[1]);
        if (b->shift != 0.0 && isfinite(turns))
            *x -= turns * b->shift;
    }
    if (b->edge[0] == DS_EDGE_PERIODIC)
        *x = ds_wrap_any(*x, b->side[0]);
}

/* ------------------------------------------------------------------ */
/* Separations                                                          */
/* ------------------------------------------------------------------ */

/* A separation along a periodic axis of side `side` taken to the nearest
 * image: into [-side/2, side/2], given |r| < 1.5 side. */
static inline double ds_nearest(double r, double side)
{
    if (r > 0.5 * side)
        r -= side;
    else if (r < -0.5 * side)
        r += side;
    return r;
}

/* A separation (*dx, *dy) of two centres in the box taken to its nearest
 * image along every periodic axis. A sheared image above or below stands
 * shift further along x, so x is taken to its nearest image after y has
 * chosen the image. Without a periodic axis nothing changes. */
static inline void ds_box_nearest(const ds_box *b, double *dx, double *dy)
{
    if (b->edge[1] == DS_EDGE_PERIODIC) {
        const double half = 0.5 * b->side[1];
        if (*dy > half) {
            *dy -= b->side[1];
            *dx -= b->shift;
        } else if (*dy < -half) {
            *dy += b->side[1];
            *dx += b->shift;
        }
    }
    if (b->edge[0] == DS_EDGE_PERIODIC) {
        if (b->shift != 0.0) /* a shifted separation may be up to 2 sides long */
            *dx -= b->side[0] * floor(*dx / b->side[0] + 0.5);
        else
            *dx = ds_nearest(*dx, b->side[0]);
    }
}

/* ds_box_nearest of a separation (*dx, *dy) and the relative velocity
 * *dvx along x of the same two disks: a disk seen through the image
 * above (the separation taken down by the height) moves shift_speed
 * faster along x, one through the image below that much slower, so the
 * relative motion of the pair is that of the images that meet. */
static inline void ds_box_nearest_moving(const ds_box *b, double *dx, double *dy, double *dvx)
{
    if (b->edge[1] == DS_EDGE_PERIODIC && b->shift_speed != 0.0) {
        const double half = 0.5 * b->side[1];
        if (*dy > half)
            *dvx -= b->shift_speed;
        else if (*dy < -half)
            *dvx += b->shift_speed;
    }
    ds_box_nearest(b, dx, dy);
}

/* ------------------------------------------------------------------ */
/* Where centres go                                                     */
/* ------------------------------------------------------------------ */

/* Where the centre of a disk of radius r may be along axis: [r, side - r]
 * between walls, [0, side) along a periodic axis (hi then side itself,
 * excluded). */
static inline void ds_box_reach(const ds_box *b, int axis, double r, double *lo, double *hi)
{
    if (b->edge[axis] == DS_EDGE_PERIODIC) {
        *lo = 0.0;
        *hi = b->side[axis];
    } else {
        *lo = r;
        *hi = b->side[axis] - r;
    }
}

/* The length a centre of radius r ranges over along axis: side - 2 r
 * between walls, side along a periodic axis. */
static inline double ds_box_span(const ds_box *b, int axis, double r)
{
    return b->edge[axis] == DS_EDGE_PERIODIC ? b->side[axis] : b->side[axis] - 2.0 * r;
}

/* The area the centre of a disk of radius r reaches (the virial
 * pressure's A). */
static inline double ds_box_area_reached(const ds_box *b, double r)
{
    return ds_box_span(b, 0, r) * ds_box_span(b, 1, r);
}

/* The length of wall the centre of a disk of radius r reaches (the wall
 * pressure's perimeter): two walls of each walls axis, each as long as
 * the other axis' span. 0 in a fully periodic box. */
static inline double ds_box_wall_reached(const ds_box *b, double r)
{
    double length = 0.0;
    if (b->edge[0] == DS_EDGE_WALLS)
        length += 2.0 * ds_box_span(b, 1, r);
    if (b->edge[1] == DS_EDGE_WALLS)
        length += 2.0 * ds_box_span(b, 0, r);
    return length;
}

/* Whether (x, y) is where the centre of a disk of radius r may be, up to
 * slack beyond a wall line (a saved state's rounding). */
static inline int ds_box_holds(const ds_box *b, double x, double y, double r, double slack)
{
    double lo, hi;
    ds_box_reach(b, 0, r, &lo, &hi);
    const int px = b->edge[0] == DS_EDGE_PERIODIC;
    if (!(x >= lo - (px ? 0.0 : slack) && (px ? x < hi : x <= hi + slack)))
        return 0;
    ds_box_reach(b, 1, r, &lo, &hi);
    const int py = b->edge[1] == DS_EDGE_PERIODIC;
    return y >= lo - (py ? 0.0 : slack) && (py ? y < hi : y <= hi + slack);
}

/* ------------------------------------------------------------------ */
/* Cell grids                                                           */
/* ------------------------------------------------------------------ */

/* The neighbour of cell c (possibly -1 or count, one past an edge) along
 * axis of a grid of count cells: its index in the grid, and the shift of
 * the image it stands for (-side, 0 or +side), or -1 past a wall. */
static inline long ds_box_cell_along(const ds_box *b, int axis, long c, long count, double *shift)
{
    *shift = 0.0;
    if (c >= 0 && c < count)
        return c;
    if (b->edge[axis] != DS_EDGE_PERIODIC)
        return -1;
    *shift = c < 0 ? -b->side[axis] : b->side[axis];
    return c < 0 ? c + count : c - count;
}

#endif
