/* SPDX-License-Identifier: MIT */
/* A disk's next event (event-driven integrator): the earliest of its
 * wall turn, its next cell crossing and its collisions with the disks of
 * the 3 x 3 cells around it (in a field the pairs' relative motion is
 * still straight: the records keep the falling frame, event_state.h).
 * This is the integrator's hot loop: each collision predicts both disks
 * again, each crossing and wall turn one. */
#include <math.h>

#include "core/lanes.h"
#include "event/event_state.h"

/* Disk d's earlier boundary event (x first on a tie) into *best and
 * *kind, if before *best: along each axis the edge of the disk's cell it
 * moves towards or, in a cell at a wall, the wall line r inside that edge,
 * whichever it reaches (one division, not one per kind), never before now
 * (a coordinate rounded past its edge leaves at once). Both axes go in
 * one pair of lanes (core/lanes.h), the choices made with masks: which
 * way a disk moves along each axis is a coin toss, and a branch on it was
 * mispredicted about once a prediction. */
static inline void boundary_event(const ds_events *e, const ed_disk *d, uint32_t i, double now,
                                  double *best, uint32_t *kind)
{
    const ds_cells *cells = &e->cells;
    const int walls_x = !ds_box_periodic(&e->box, 0), walls_y = !ds_box_periodic(&e->box, 1);
    /* The wall lines: R from each wall, a mixture's disk its own R. */
    const double r = e->radius ? e->radius[i] : e->one_radius;
    const double hi_x = e->box.side[0] - r, hi_y = e->box.side[1] - r;
    const ds_x2 zero = ds_x2_set1(0.0), one = ds_x2_set1(1.0);
    const ds_x2 u = ds_x2_load(&d->x), v = ds_x2_load(&d->vx); /* (x, y), (vx, vy) */
    const ds_x2 cell = ds_x2_make((double)d->column, (double)d->row);
    const ds_x2 up = ds_x2_gt(v, zero);
    /* The cells at a wall, the last one ahead or the first behind; along
     * a periodic axis none (-1). */
    const ds_x2 last = ds_x2_make(walls_x ? (double)cells->nx - 1.0 : -1.0,
                                  walls_y ? (double)cells->ny - 1.0 : -1.0);
    const ds_x2 first_cell = ds_x2_make(walls_x ? 0.0 : -1.0, walls_y ? 0.0 : -1.0);
    const ds_x2 at_wall = ds_x2_eq(cell, ds_x2_select(up, last, first_cell));
    const ds_x2 wall = ds_x2_select(up, ds_x2_make(hi_x, hi_y), ds_x2_set1(r));
    const ds_x2 edge_of_cell =
        ds_x2_mul(ds_x2_add(cell, ds_x2_and(up, one)), ds_x2_make(cells->wx, cells->wy));
    const ds_x2 edge = ds_x2_select(at_wall, wall, edge_of_cell);
    const ds_x2 moving = ds_x2_ne(v, zero);
    /* max(lag, 0) as lag > 0 ? lag : 0, a NaN giving 0 */
    const ds_x2 lag = ds_x2_max(ds_x2_div(ds_x2_sub(edge, u), ds_x2_select(moving, v, one)), zero);
    const ds_x2 t =
        ds_x2_select(moving, ds_x2_add(ds_x2_set1(now), lag), ds_x2_set1((double)INFINITY));
    const ds_x2 ty = ds_x2_high(t);
    const int y = ds_x2_first(ty) < ds_x2_first(t);
    const double first = ds_x2_first(ds_x2_min(ty, t)); /* ty < tx ? ty : tx */
    static const uint32_t kinds[4] = {EV_CELL_X, EV_WALL_X, EV_CELL_Y, EV_WALL_Y};
    const uint32_t k = kinds[2 * y + ((ds_x2_bits(at_wall) >> y) & 1)];
    const int earlier = first < *best;
    *kind = earlier ? k : *kind;
    *best = earlier ? first : *best;
}

/* The four cells of row r, across the top (up) or bottom edge of a
 * sheared box, that a disk in `column` may meet while the shear's cell
 * count stays: the image above stands shift = k w + f along (w the cell
 * width, k = shear_cell modulo the columns, 0 <= f <= w until the count
 * moves), so a partner within contact (less than w) of the disk through
 * it has its centre in columns column - k - 2 to column - k + 1; through
 * the image below, which stands -shift along, column + k - 1 to column +
 * k + 2. Each cell carries the image's shift (plus the width for each
 * time the column wrapped) and its speed. */
static void sheared_row(const ds_events *e, uint32_t column, uint32_t r, int up, double sy,
                        double now, ds_ed_stencil_cells *st)
{
    const ds_cells *cells = &e->cells;
    const int64_t nx = (int64_t)cells->nx;
    double turns;
    const double shift = ds_ed_shift(e, now, &turns);
    const int64_t k = ((e->shear_cell % nx) + nx) % nx;
    const int64_t first = up ? (int64_t)column - k - 2 : (int64_t)column + k - 1;
    for (int64_t j = 0; j < 4; ++j) {
        const int64_t c = first + j;
        const int64_t wraps = c >= 0 ? c / nx : -((-c + nx - 1) / nx);
        st->cell[st->count] = ds_cells_index(cells, (uint32_t)(c - wraps * nx), r);
        st->sx[st->count] = (up ? shift : -shift) + (double)wraps * e->box.side[0];
        st->sy[st->count] = sy;
        st->su[st->count++] = up ? e->box.shift_speed : -e->box.shift_speed;
    }
}

void ds_ed_stencil(const ds_events *e, uint32_t column, uint32_t row, double now,
                   ds_ed_stencil_cells *st)
{
    const ds_cells *cells = &e->cells;
    st->count = 0;
    for (int oy = -1; oy <= 1; ++oy) {
        int64_t r = (int64_t)row + oy;
        const int across = r < 0 || r >= (int64_t)cells->ny;
        double sy = 0.0;
        r = ds_box_cell_along(&e->box, 1, (long)r, (long)cells->ny, &sy);
        if (r < 0)
            continue;
        if (across && e->lees_edwards) {
            sheared_row(e, column, (uint32_t)r, oy > 0, sy, now, st);
            continue;
        }
        for (int ox = -1; ox <= 1; ++ox) {
            int64_t c = (int64_t)column + ox;
            double sx = 0.0;
            c = ds_box_cell_along(&e->box, 0, (long)c, (long)cells->nx, &sx);
            if (c < 0)
                continue;
            st->cell[st->count] = ds_cells_index(cells, (uint32_t)c, (uint32_t)r);
            st->sx[st->count] = sx;
            st->sy[st->count] = sy;
            st->su[st->count++] = 0.0;
        }
    }
}

/* Candidates gathered from the cells before any is tested: the walk of
 * the cells and the pair tests then each run without the other's
 * unpredictable branches. */
#define GATHER_CAP 64
/* The 3 x 3 cells' slots fit at once (C99 has no static assertion). */
typedef char gather_holds_a_stencil[DS_ED_STENCIL_MAX * DS_CELL_SLOTS <= GATHER_CAP ? 1 : -1];

typedef struct predictor {
    const ds_events *e;
    const ed_disk *d;
    uint32_t self;
    double now;
    double best;
    uint32_t kind, partner_changes;
    uint32_t count;
    uint64_t tested;
    uint32_t disk[GATHER_CAP + 1]; /* + 1: room to pad to an even count */
    uint8_t image[GATHER_CAP + 1]; /* index into sx, sy */
    double sx[DS_ED_STENCIL_MAX], sy[DS_ED_STENCIL_MAX], su[DS_ED_STENCIL_MAX];
} predictor;

/* Pair times: when disk d (at time now) and disk p (at its own time, its
 * centre shifted by (sx, sy) to the image in question) come within
 * sqrt(sigma2), or +infinity. Positive b means separating: never. The
 * root is taken in the form that does not cancel (c / (-b + sqrt(disc))
 * rather than (-b - sqrt(disc)) / v2), and an approaching pair already
 * at or inside contact (c <= 0) collides now.
 *
 * Every value is computed and the answer chosen at the end: about half
 * the pairs separate, at random, and a branch on it mispredicted once
 * every other pair, which cost more than the square root and the
 * division that are now always done. With b < 0 the denominator
 * sqrt(disc) + |b| is sqrt(disc) - b > 0; otherwise the quotient is
 * discarded (it may then be an infinity or a NaN).
 *
 * Two candidates per iteration, one in each lane (core/lanes.h): a
 * disk's fields are gathered into the two lanes with one load each. Each
 * lane keeps its earliest time and that candidate's place, chosen with
 * masks: which candidate beats the best so far is a coin toss the branch
 * predictor lost a few times per prediction, each time throwing away the
 * square roots and divisions in flight. Only a collision no later than
 * the partner's own next event is kept: if the partner changes course
 * first, it is predicted again then and finds the pair itself. The two
 * lanes are merged at the end, the earlier place winning a tie, so the
 * result is that of testing the candidates one by one in order. A
 * mixture (mixed) takes each pair's contact distance, the sum of the
 * radii. */
static inline void test_gathered(predictor *pr, int shifted, int mixed)
{
    const ds_events *e = pr->e;
    const ed_disk *d = pr->d;
    /* An odd count is padded with the disk itself (b = 0: never); written
     * whatever the count, as a branch on it would be a coin toss. */
    pr->disk[pr->count] = pr->self;
    pr->image[pr->count] = 0;
    const ds_x2 dx = ds_x2_set1(d->x), dy = ds_x2_set1(d->y);
    const ds_x2 dvx = ds_x2_set1(d->vx), dvy = ds_x2_set1(d->vy);
    const ds_x2 now = ds_x2_set1(pr->now), sigma2 = ds_x2_set1(e->sigma2);
    const ds_x2 zero = ds_x2_set1(0.0), sign = ds_x2_set1(-0.0);
    const ds_x2 never = ds_x2_set1((double)INFINITY), two = ds_x2_set1(2.0);
    ds_x2 best = ds_x2_set1(pr->best), best_place = ds_x2_set1(-1.0);
    ds_x2 place = ds_x2_make(0.0, 1.0);
    for (uint32_t j = 0; j < pr->count; j += 2, place = ds_x2_add(place, two)) {
        const ed_disk *p0 = &e->disk[pr->disk[j]], *p1 = &e->disk[pr->disk[j + 1]];
        const ds_x2 pvx = ds_x2_load_pair(&p0->vx, &p1->vx),
                    pvy = ds_x2_load_pair(&p0->vy, &p1->vy);
        const ds_x2 lag = ds_x2_sub(now, ds_x2_load_pair(&p0->t, &p1->t));
        ds_x2 rx = ds_x2_add(ds_x2_load_pair(&p0->x, &p1->x), ds_x2_mul(pvx, lag));
        ds_x2 ry = ds_x2_add(ds_x2_load_pair(&p0->y, &p1->y), ds_x2_mul(pvy, lag));
        if (shifted) {
            rx = ds_x2_add(rx, ds_x2_load_pair(&pr->sx[pr->image[j]], &pr->sx[pr->image[j + 1]]));
            ry = ds_x2_add(ry, ds_x2_load_pair(&pr->sy[pr->image[j]], &pr->sy[pr->image[j + 1]]));
        } else { /* the same sum with a zero shift, to the bit */
            rx = ds_x2_add(rx, zero);
            ry = ds_x2_add(ry, zero);
        }
        rx = ds_x2_sub(rx, dx);
        ry = ds_x2_sub(ry, dy);
        /* A sheared image's speed (0 elsewhere: the same difference). */
        const ds_x2 ivx =
            shifted
                ? ds_x2_add(pvx, ds_x2_load_pair(&pr->su[pr->image[j]], &pr->su[pr->image[j + 1]]))
                : pvx;
        const ds_x2 vx = ds_x2_sub(ivx, dvx), vy = ds_x2_sub(pvy, dvy);
        const ds_x2 b = ds_x2_add(ds_x2_mul(rx, vx), ds_x2_mul(ry, vy));
        ds_x2 contact2 = sigma2;
        if (mixed) {
            const ds_x2 sigma =
                ds_x2_add(ds_x2_set1(e->radius[pr->self]),
                          ds_x2_load_pair(&e->radius[pr->disk[j]], &e->radius[pr->disk[j + 1]]));
            contact2 = ds_x2_mul(sigma, sigma);
        }
        const ds_x2 c = ds_x2_sub(ds_x2_add(ds_x2_mul(rx, rx), ds_x2_mul(ry, ry)), contact2);
        const ds_x2 disc = ds_x2_sub(ds_x2_mul(b, b),
                                     ds_x2_mul(ds_x2_add(ds_x2_mul(vx, vx), ds_x2_mul(vy, vy)), c));
        const ds_x2 den = ds_x2_add(ds_x2_sqrt(ds_x2_max(disc, zero)), ds_x2_andnot(sign, b));
        const ds_x2 t = ds_x2_add(now, ds_x2_div(ds_x2_max(c, zero), den));
        const ds_x2 ok = ds_x2_and(ds_x2_lt(b, zero), ds_x2_gt(disc, zero));
        const ds_x2 time = ds_x2_select(ok, t, never);
        const ds_x2 partner_next = ds_x2_load_pair(&p0->next, &p1->next);
        const ds_x2 take = ds_x2_and(ds_x2_lt(time, best), ds_x2_le(time, partner_next));
        best = ds_x2_select(take, time, best);
        best_place = ds_x2_select(take, place, best_place);
    }
    pr->tested += pr->count;
    if (pr->count == 0)
        return;
    pr->count = 0;
    /* The earlier lane wins, the earlier place on a tie. A lane's best
     * starts at pr->best and only a strictly earlier time replaces it, so
     * a lane that found nothing (place -1) ties only with another such.
     * Whether anything was found is a coin toss (a collision before the
     * disk's wall or cell edge, or not): chosen with masks and
     * conditional moves, not a branch. Lane 0 holds the answer. */
    const ds_x2 best1 = ds_x2_high(best);
    const ds_x2 place1 = ds_x2_high(best_place);
    const ds_x2 second = ds_x2_or(ds_x2_lt(best1, best),
                                  ds_x2_and(ds_x2_eq(best1, best), ds_x2_lt(place1, best_place)));
    const ds_x2 chosen = ds_x2_select(second, place1, best_place);
    const int found = ds_x2_first(chosen) >= 0.0;
    const uint32_t k = pr->disk[(uint32_t)ds_x2_first(ds_x2_max(chosen, zero))];
    const uint32_t changes = e->disk[k].changes;
    pr->best = ds_x2_first(ds_x2_select(second, best1, best));
    const uint32_t keep = (uint32_t)found - 1u; /* all ones if nothing was found */
    pr->kind = (k & ~keep) | (pr->kind & keep);
    pr->partner_changes = (changes & ~keep) | (pr->partner_changes & keep);
}

/* The four forms, each compiled with its constants: one kind of disk is
 * the hot loop as it was. */
static void test_candidates(predictor *pr)
{
    if (pr->e->radius)
        test_gathered(pr, 1, 1);
    else
        test_gathered(pr, 1, 0);
}

static void test_unshifted(predictor *pr)
{
    if (pr->e->radius)
        test_gathered(pr, 0, 1);
    else
        test_gathered(pr, 0, 0);
}

/* Appends the disks of `count` consecutive slots, image 0. Empty slots
 * are written but not counted: no branch per slot. The disk itself may be
 * among them: against itself b = 0, so its pair time is +infinity. */
static inline void gather_slots(predictor *pr, const uint32_t *slot, int count, uint32_t empty)
{
    uint32_t n = pr->count;
    /* A cell's disks fill its slots from the first (cells.h): its four
     * slots are copied at once, and the count moves on past its disks.
     * How many there are comes from the mask of its empty slots. */
    static const uint8_t filled[16] = {4, 3, 3, 2, 3, 2, 2, 1, 3, 2, 2, 1, 2, 1, 1, 0};
    for (int k = 0; k < count; k += DS_CELL_SLOTS) {
        const ds_u4 v = ds_u4_load(slot + k);
        ds_u4_store(pr->disk + n, v);
        n += filled[ds_u4_equal_bits(v, empty)];
    }
    pr->count = n;
}

/* Appends the disks of one cell with the given image: its slots, then its
 * overflow list (a dilute gas's large cells only). */
static void gather_cell(predictor *pr, const ds_cells *cells, uint32_t cell, uint8_t image)
{
    const uint32_t *slot = ds_cells_slots(cells, cell);
    if (pr->count + DS_CELL_SLOTS > GATHER_CAP)
        test_candidates(pr);
    const uint32_t from = pr->count;
    gather_slots(pr, slot, DS_CELL_SLOTS, cells->empty);
    for (uint32_t j = from; j < pr->count; ++j)
        pr->image[j] = image;
    if (slot[DS_CELL_SLOTS - 1] == cells->empty)
        return;
    for (uint32_t k = ds_cells_overflow(cells, cell); k != cells->empty; k = cells->next[k]) {
        if (pr->count == GATHER_CAP)
            test_candidates(pr);
        pr->image[pr->count] = image;
        pr->disk[pr->count++] = k;
    }
}

/* The time disk d (at time now) and disk p (at its own time, its centre
 * shifted by (sx, sy)) come into contact while their contact distance
 * grows, s0 (1 + rate (t - from)) at time t, or +infinity. With r the
 * separation at now, v the relative velocity, sigma the contact distance
 * and a = s0 rate its growth speed: |r + v tau| = sigma + a tau, the
 * quadratic (v^2 - a^2) tau^2 + 2 (r.v - sigma a) tau + r^2 - sigma^2 = 0
 * (b, c as for fixed radii with b taken in the growing frame). Already in
 * contact and closing in that frame (b < 0): now. Faster growth than
 * approach (v^2 < a^2) always meets. The root in the form that does not
 * cancel, as pair_time. */
static double growing_pair_time(const ed_disk *d, const ed_disk *p, double now, double sx,
                                double sy, double s0, const ds_ed_law *g)
{
    const double lag = now - p->t;
    const double rx = p->x + p->vx * lag + sx - d->x, ry = p->y + p->vy * lag + sy - d->y;
    const double vx = p->vx - d->vx, vy = p->vy - d->vy;
    const double sigma = s0 * (1.0 + g->rate * (now - g->from)), a = s0 * g->rate;
    const double b = rx * vx + ry * vy - sigma * a;
    const double c = rx * rx + ry * ry - sigma * sigma;
    const double quad = vx * vx + vy * vy - a * a;
    if (c <= 0.0)
        return b < 0.0 ? now : INFINITY;
    const double disc = b * b - quad * c;
    if (quad > 0.0 && !(b < 0.0 && disc > 0.0))
        return INFINITY;
    const double den = sqrt(disc > 0.0 ? disc : 0.0) - b;
    return den > 0.0 ? now + c / den : INFINITY;
}

/* ds_ed_predict with growing radii (periodic: cell crossings only), in
 * plain C: the cells around the disk, their slots and overflow lists. */
double ds_ed_predict_growing(ds_events *e, uint32_t i)
{
    ed_disk *const d = &e->disk[i];
    const ds_cells *cells = &e->cells;
    const double now = d->t;
    double best = INFINITY;
    uint32_t kind = EV_NONE, partner_changes = 0;
    if (e->falls)
        ds_ed_boundary_falling(e, d, i, now, &best, &kind);
    else
        boundary_event(e, d, i, now, &best, &kind);
    ds_ed_stencil_cells st;
    ds_ed_stencil(e, d->column, d->row, now, &st);
    uint64_t tested = 0;
    for (uint32_t c = 0; c < st.count; ++c) {
        const uint32_t *slot = ds_cells_slots(cells, st.cell[c]);
        for (int j = 0; j < DS_CELL_SLOTS + 1; ++j) {
            /* The four slots, then the overflow list behind them. */
            uint32_t k = j < DS_CELL_SLOTS ? slot[j]
                         : slot[DS_CELL_SLOTS - 1] != cells->empty
                             ? ds_cells_overflow(cells, st.cell[c])
                             : cells->empty;
            for (; k != cells->empty; k = j < DS_CELL_SLOTS ? cells->empty : cells->next[k]) {
                if (k == i)
                    continue;
                ++tested;
                const double t = growing_pair_time(d, &e->disk[k], now, st.sx[c], st.sy[c],
                                                   e->radius[i] + e->radius[k], &e->law);
                if (t < best && t <= e->disk[k].next) {
                    best = t;
                    kind = k;
                    partner_changes = e->disk[k].changes;
                }
            }
        }
    }
    e->tested += tested;
    d->partner = kind;
    const ed_disk *p = &e->disk[kind < cells->empty ? kind : i];
    d->partner_changes = ds_fetch_note(partner_changes, d->column, d->row, p->column, p->row);
    return best;
}

/* Long: the integrator's hot loop in one piece. Split into its interior
 * and edge paths (as two inlined helpers) it ran 5 to 7% slower per
 * collision at 10^5 disks (tools/benchmark/ab.sh, three rounds of 11)
 * though it executed 2.5% fewer instructions (callgrind): the layout of
 * the code, not its work. */
double ds_ed_predict(ds_events *e, uint32_t i)
{
    if (e->law.rate > 0.0)
        return ds_ed_predict_growing(e, i);
    ed_disk *const d = &e->disk[i];
    const ds_cells *cells = &e->cells;
    const uint32_t empty = cells->empty;
    predictor pr;
    pr.e = e;
    pr.d = d;
    pr.self = i;
    pr.now = d->t;
    pr.best = INFINITY;
    pr.kind = EV_NONE;
    pr.partner_changes = 0;
    pr.count = 0;
    pr.tested = 0;
    /* In a field, parabolas and both edges of the cell (falling.c); the
     * straight flights' test stays apart so that it is inlined as it was
     * (callgrind: the event loop took 1.1% more instructions with the branch
     * inside it, as many as before without). */
    if (e->falls)
        ds_ed_boundary_falling(e, d, i, pr.now, &pr.best, &pr.kind);
    else
        boundary_event(e, d, i, pr.now, &pr.best, &pr.kind);

    if (ds_ed_interior(cells, d)) {
        /* Away from the edges of the grid (nearly every disk of a large
         * system): three rows of three cells, twelve consecutive slots
         * each, no shifts, no wrap. */
        const uint32_t cell = ds_cells_index(cells, d->column - 1u, d->row - 1u);
        const uint32_t *row0 = ds_cells_slots(cells, cell);
        const uint32_t *row1 = row0 + (size_t)cells->nx * DS_CELL_SLOTS;
        const uint32_t *row2 = row1 + (size_t)cells->nx * DS_CELL_SLOTS;
        /* 36 slots fit the gathering at once (GATHER_CAP), written out
         * row by row: no loop to leave, no check between the rows. */
        gather_slots(&pr, row0, 3 * DS_CELL_SLOTS, empty);
        gather_slots(&pr, row1, DS_CELL_SLOTS, empty);
        const uint32_t own = pr.count; /* where the disk's own cell begins */
        gather_slots(&pr, row1 + DS_CELL_SLOTS, DS_CELL_SLOTS, empty);
        const uint32_t own_end = pr.count;
        gather_slots(&pr, row1 + 2 * DS_CELL_SLOTS, DS_CELL_SLOTS, empty);
        gather_slots(&pr, row2, 3 * DS_CELL_SLOTS, empty);
        /* The disk itself is among its own cell's disks (unless in its
         * overflow list): the last candidate takes its place, one
         * candidate fewer to test. Not found, the spare entry at
         * GATHER_CAP takes the copy instead, and nothing changes. Only
         * the cell's own entries are looked at: past them, what the
         * gathering has not written since is left from before. */
        uint32_t at = GATHER_CAP;
        for (uint32_t k = own; k < own + DS_CELL_SLOTS; ++k)
            at = k < own_end && pr.disk[k] == i ? k : at;
        const uint32_t found = at != GATHER_CAP;
        pr.disk[at] = pr.disk[pr.count - found];
        pr.count -= found;
        /* Overflow lists (a dilute gas's large cells only): one branch for
         * all nine cells, none of them full in a dense system. */
        const uint32_t last = DS_CELL_SLOTS - 1;
        const uint32_t mid = last + DS_CELL_SLOTS, end = last + 2 * DS_CELL_SLOTS;
        if ((row0[last] != empty) | (row0[mid] != empty) | (row0[end] != empty) |
            (row1[last] != empty) | (row1[mid] != empty) | (row1[end] != empty) |
            (row2[last] != empty) | (row2[mid] != empty) | (row2[end] != empty))
            for (uint32_t r = 0; r < 3; ++r)
                for (uint32_t c = 0; c < 3; ++c) {
                    const uint32_t full = cell + r * cells->nx + c;
                    if (ds_cells_slots(cells, full)[last] == empty)
                        continue;
                    for (uint32_t k = ds_cells_overflow(cells, full); k != empty;
                         k = cells->next[k]) {
                        if (pr.count == GATHER_CAP)
                            test_unshifted(&pr);
                        pr.disk[pr.count++] = k;
                    }
                }
        test_unshifted(&pr);
        pr.tested -= 1u - found; /* the disk itself, if it was tested */
    } else {
        ds_ed_stencil_cells st;
        ds_ed_stencil(e, d->column, d->row, pr.now, &st);
        for (uint32_t c = 0; c < st.count; ++c) {
            pr.sx[c] = st.sx[c];
            pr.sy[c] = st.sy[c];
            pr.su[c] = st.su[c];
            gather_cell(&pr, cells, st.cell[c], (uint8_t)c);
        }
        test_candidates(&pr);
        /* The disk itself, once per image of its own cell. */
        for (uint32_t c = 0; c < st.count; ++c)
            pr.tested -= st.cell[c] == ds_cells_index(cells, d->column, d->row);
    }
    e->tested += pr.tested;
    d->partner = pr.kind;
    /* The partner's count and cell (event_fetch.h); without a partner, the
     * disk's own record stands in. */
    const ed_disk *p = &e->disk[pr.kind < empty ? pr.kind : i];
    d->partner_changes = ds_fetch_note(pr.partner_changes, d->column, d->row, p->column, p->row);
    return pr.best;
}
