/* SPDX-License-Identifier: MIT */
/* Flights in a field (event-driven integrator): where a falling disk
 * meets its cell's edges and the walls. Its records keep the falling frame
 * (event_state.h), in which pairs fly straight, so only what is fixed in
 * the box needs a parabola: along each axis the centre's distance to an
 * edge is p + w tau + b tau^2 / 2, and its next wall or cell event is the
 * first root at which that distance reaches zero going down. Both edges of
 * the cell count along each axis: a disk thrown up may fall back before it
 * reaches the edge above. */
#include <math.h>

#include "event/event_state.h"

/* The first tau >= 0 at which a distance p + w tau + b tau^2 / 2 to an
 * edge reaches 0 while falling (leaving through the edge), or +infinity.
 * The roots in the forms that do not cancel, as the pair times' (2 p /
 * (sqrt(disc) - w) for w < 0, (w + sqrt(disc)) / -b for w >= 0):
 * - b = 0: straight, -p / w if it moves out (w < 0), never before now;
 * - at or past the edge (p <= 0, rounding) and moving out: now; moving
 *   in, it leaves again only if pulled back (b < 0), when it is back at
 *   the edge, or at the top of its arc if it never got in (disc < 0);
 * - inside (p > 0): pulled out (b < 0) it always leaves; pushed in (b >
 *   0), only if it reaches the edge before it turns (disc >= 0). */
static double leaving_time(double p, double w, double b)
{
    if (b == 0.0)
        return w < 0.0 ? fmax(-p / w, 0.0) : INFINITY;
    const double disc = w * w - 2.0 * b * p;
    if (p <= 0.0) {
        if (w < 0.0)
            return 0.0;
        return b < 0.0 ? (w + sqrt(fmax(disc, 0.0))) / -b : INFINITY;
    }
    if (w < 0.0)
        return disc >= 0.0 ? 2.0 * p / (sqrt(disc) - w) : INFINITY;
    return b < 0.0 ? (w + sqrt(disc)) / -b : INFINITY;
}

/* Along axis a of the box, for a disk of radius r at u (in the box, not the
 * frame) moving at v with acceleration g in cell c of count cells of width
 * wc: the time (from now) it leaves, and whether through a wall line. A
 * cell at a wall has the wall line (r inside the box's edge) for its edge
 * on that side; a periodic axis has none. */
static double leaving_along(const ds_events *e, int a, double r, double u, double v, double g,
                            uint32_t c, uint32_t cells, double wc, int *at_wall)
{
    const int walls = !ds_box_periodic(&e->box, a);
    const int wall_lo = walls && c == 0, wall_hi = walls && c + 1u == cells;
    const double lo = wall_lo ? r : (double)c * wc;
    const double hi = wall_hi ? e->box.side[a] - r : (double)(c + 1u) * wc;
    const double t_lo = leaving_time(u - lo, v, g), t_hi = leaving_time(hi - u, -v, -g);
    *at_wall = t_hi < t_lo ? wall_hi : wall_lo;
    return fmin(t_lo, t_hi);
}

void ds_ed_boundary_falling(const ds_events *e, const ed_disk *d, uint32_t i, double now,
                            double *best, uint32_t *kind)
{
    const double r = e->radius ? e->radius[i] : e->one_radius;
    double x, y, vx, vy;
    ds_ed_lab_at(e, d, now, &x, &y, &vx, &vy);
    int wall_x = 0, wall_y = 0;
    const double tx =
        leaving_along(e, 0, r, x, vx, e->field[0], d->column, e->cells.nx, e->cells.wx, &wall_x);
    const double ty =
        leaving_along(e, 1, r, y, vy, e->field[1], d->row, e->cells.ny, e->cells.wy, &wall_y);
    /* x first on a tie, as the lanes' */
    const int along_y = ty < tx;
    const double first = now + (along_y ? ty : tx);
    if (!(first < *best))
        return;
    *best = first;
    *kind = along_y ? (wall_y ? EV_WALL_Y : EV_CELL_Y) : (wall_x ? EV_WALL_X : EV_CELL_X);
}
