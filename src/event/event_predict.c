/* SPDX-License-Identifier: MIT */
/* A disk's next event (event-driven integrator): the earliest of its
 * wall turn, its next cell crossing and its collisions with the disks of
 * the 3 x 3 cells around it. This is the integrator's hot loop: each
 * collision predicts both disks again, each crossing and wall turn one. */
#include <math.h>

#include "event/event_state.h"

#if defined(__SSE2__)
#include <emmintrin.h>

static inline __m128d load_pair(const double *a, const double *b)
{
    return _mm_loadh_pd(_mm_load_sd(a), b);
}

static inline __m128d select_pd(__m128d mask, __m128d yes, __m128d no)
{
    return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}
#endif

#if !defined(__SSE2__)
/* The boundary event of one axis: the edge of the disk's cell it moves
 * towards or, in a cell at a wall, the wall line R inside that edge,
 * whichever it reaches (one division, not one per kind). Never before now:
 * a coordinate rounded past its edge leaves at once. */
static inline void axis_event(double u, double v, uint32_t cell, uint32_t count, double width,
                              double lo, double hi, int walls, uint32_t cell_kind,
                              uint32_t wall_kind, double now, double *best, uint32_t *kind)
{
    const int up = v > 0.0;
    const int at_wall = walls & (cell == (up ? count - 1 : 0));
    const double edge = at_wall ? (up ? hi : lo) : (double)(cell + (uint32_t)up) * width;
    const double lag = (edge - u) / (v != 0.0 ? v : 1.0);
    const double t = v != 0.0 ? now + (lag > 0.0 ? lag : 0.0) : INFINITY;
    if (t < *best) {
        *best = t;
        *kind = at_wall ? wall_kind : cell_kind;
    }
}
#endif

/* Disk d's earlier boundary event (x first on a tie) into *best and
 * *kind, if before *best. On x86 both axes go in one pair of SSE2 lanes,
 * the same arithmetic as axis_event (the plain-C form, for machines
 * without SSE2: the same times to the bit), the choices made with masks:
 * which way a disk moves along each axis is a coin toss, and a branch on
 * it was mispredicted about once a prediction. */
static inline void boundary_event(const ds_events *e, const ed_disk *d, uint32_t i, double now,
                                  double *best, uint32_t *kind)
{
    const ds_cells *cells = &e->cells;
    const int walls = !e->periodic;
    /* The wall lines: R from each wall, a mixture's disk its own R. */
    const double r = e->radius ? e->radius[i] : 0.0;
    const double lo_x = e->radius ? r : e->lo_x, lo_y = e->radius ? r : e->lo_y;
    const double hi_x = e->radius ? e->box_x - r : e->hi_x;
    const double hi_y = e->radius ? e->box_y - r : e->hi_y;
#if defined(__SSE2__)
    const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
    const __m128d u = _mm_loadu_pd(&d->x), v = _mm_loadu_pd(&d->vx); /* (x, y), (vx, vy) */
    const __m128d cell = _mm_set_pd((double)d->row, (double)d->column);
    const __m128d up = _mm_cmpgt_pd(v, zero);
    const __m128d last = _mm_set_pd((double)cells->ny - 1.0, (double)cells->nx - 1.0);
    const __m128d at_wall = walls ? _mm_cmpeq_pd(cell, _mm_and_pd(up, last)) : zero;
    const __m128d wall = select_pd(up, _mm_set_pd(hi_y, hi_x), _mm_set_pd(lo_y, lo_x));
    const __m128d edge_of_cell =
        _mm_mul_pd(_mm_add_pd(cell, _mm_and_pd(up, one)), _mm_set_pd(cells->wy, cells->wx));
    const __m128d edge = select_pd(at_wall, wall, edge_of_cell);
    const __m128d moving = _mm_cmpneq_pd(v, zero);
    /* max(lag, 0) as lag > 0 ? lag : 0, a NaN giving 0 */
    const __m128d lag =
        _mm_max_pd(_mm_div_pd(_mm_sub_pd(edge, u), select_pd(moving, v, one)), zero);
    const __m128d t =
        select_pd(moving, _mm_add_pd(_mm_set1_pd(now), lag), _mm_set1_pd((double)INFINITY));
    const __m128d ty = _mm_unpackhi_pd(t, t);
    const int y = _mm_comilt_sd(ty, t);
    const double first = _mm_cvtsd_f64(_mm_min_sd(ty, t)); /* ty < tx ? ty : tx */
    static const uint32_t kinds[4] = {EV_CELL_X, EV_WALL_X, EV_CELL_Y, EV_WALL_Y};
    const uint32_t k = kinds[2 * y + ((_mm_movemask_pd(at_wall) >> y) & 1)];
    const int earlier = first < *best;
    *kind = earlier ? k : *kind;
    *best = earlier ? first : *best;
#else
    axis_event(d->x, d->vx, d->column, cells->nx, cells->wx, lo_x, hi_x, walls, EV_CELL_X,
               EV_WALL_X, now, best, kind);
    axis_event(d->y, d->vy, d->row, cells->ny, cells->wy, lo_y, hi_y, walls, EV_CELL_Y, EV_WALL_Y,
               now, best, kind);
#endif
}

void ds_ed_stencil(const ds_events *e, uint32_t column, uint32_t row, ds_ed_stencil_cells *st)
{
    const ds_cells *cells = &e->cells;
    st->count = 0;
    for (int oy = -1; oy <= 1; ++oy) {
        int64_t r = (int64_t)row + oy;
        double sy = 0.0;
        if (r < 0 || r >= (int64_t)cells->ny) {
            if (!e->periodic)
                continue;
            sy = r < 0 ? -e->box_y : e->box_y;
            r = r < 0 ? r + cells->ny : r - cells->ny;
        }
        for (int ox = -1; ox <= 1; ++ox) {
            int64_t c = (int64_t)column + ox;
            double sx = 0.0;
            if (c < 0 || c >= (int64_t)cells->nx) {
                if (!e->periodic)
                    continue;
                sx = c < 0 ? -e->box_x : e->box_x;
                c = c < 0 ? c + cells->nx : c - cells->nx;
            }
            st->cell[st->count] = ds_cells_index(cells, (uint32_t)c, (uint32_t)r);
            st->sx[st->count] = sx;
            st->sy[st->count++] = sy;
        }
    }
}

/* Candidates gathered from the cells before any is tested: the walk of
 * the cells and the pair tests then each run without the other's
 * unpredictable branches. */
#define GATHER_CAP 64
/* The 3 x 3 cells' slots fit at once (C99 has no static assertion). */
typedef char gather_holds_nine_cells[9 * DS_CELL_SLOTS <= GATHER_CAP ? 1 : -1];

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
    double sx[9], sy[9];
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
 * discarded (it may then be an infinity or a NaN). On x86 the choice is
 * written with SSE2 masks: in plain C the compiler moves the square root
 * and the division back under a branch of its own. */
#if defined(__SSE2__)
/* Two candidates per iteration, lane by lane the same arithmetic as the
 * plain-C pair_time below (so the same times to the bit): a disk's fields
 * are gathered into the two lanes with one load each. Each lane keeps its
 * earliest time and that candidate's place, chosen with masks: which
 * candidate beats the best so far is a coin toss the branch predictor
 * lost a few times per prediction, each time throwing away the square
 * roots and divisions in flight. The two lanes are merged at the end,
 * the earlier place winning a tie, as in the plain-C loop. A mixture
 * (mixed) takes each pair's contact distance, the sum of the radii. */
static inline void test_gathered(predictor *pr, int shifted, int mixed)
{
    const ds_events *e = pr->e;
    const ed_disk *d = pr->d;
    /* An odd count is padded with the disk itself (b = 0: never); written
     * whatever the count, as a branch on it would be a coin toss. */
    pr->disk[pr->count] = pr->self;
    pr->image[pr->count] = 0;
    const __m128d dx = _mm_set1_pd(d->x), dy = _mm_set1_pd(d->y);
    const __m128d dvx = _mm_set1_pd(d->vx), dvy = _mm_set1_pd(d->vy);
    const __m128d now = _mm_set1_pd(pr->now), sigma2 = _mm_set1_pd(e->sigma2);
    const __m128d zero = _mm_setzero_pd(), sign = _mm_set1_pd(-0.0);
    const __m128d never = _mm_set1_pd((double)INFINITY), two = _mm_set1_pd(2.0);
    __m128d best = _mm_set1_pd(pr->best), best_place = _mm_set1_pd(-1.0);
    __m128d place = _mm_set_pd(1.0, 0.0);
    for (uint32_t j = 0; j < pr->count; j += 2, place = _mm_add_pd(place, two)) {
        const ed_disk *p0 = &e->disk[pr->disk[j]], *p1 = &e->disk[pr->disk[j + 1]];
        const __m128d pvx = load_pair(&p0->vx, &p1->vx), pvy = load_pair(&p0->vy, &p1->vy);
        const __m128d lag = _mm_sub_pd(now, load_pair(&p0->t, &p1->t));
        __m128d rx = _mm_add_pd(load_pair(&p0->x, &p1->x), _mm_mul_pd(pvx, lag));
        __m128d ry = _mm_add_pd(load_pair(&p0->y, &p1->y), _mm_mul_pd(pvy, lag));
        if (shifted) {
            rx = _mm_add_pd(rx, load_pair(&pr->sx[pr->image[j]], &pr->sx[pr->image[j + 1]]));
            ry = _mm_add_pd(ry, load_pair(&pr->sy[pr->image[j]], &pr->sy[pr->image[j + 1]]));
        } else {
            rx = _mm_add_pd(rx, zero);
            ry = _mm_add_pd(ry, zero);
        }
        rx = _mm_sub_pd(rx, dx);
        ry = _mm_sub_pd(ry, dy);
        const __m128d vx = _mm_sub_pd(pvx, dvx), vy = _mm_sub_pd(pvy, dvy);
        const __m128d b = _mm_add_pd(_mm_mul_pd(rx, vx), _mm_mul_pd(ry, vy));
        __m128d contact2 = sigma2;
        if (mixed) {
            const __m128d sigma =
                _mm_add_pd(_mm_set1_pd(e->radius[pr->self]),
                           load_pair(&e->radius[pr->disk[j]], &e->radius[pr->disk[j + 1]]));
            contact2 = _mm_mul_pd(sigma, sigma);
        }
        const __m128d c = _mm_sub_pd(_mm_add_pd(_mm_mul_pd(rx, rx), _mm_mul_pd(ry, ry)), contact2);
        const __m128d disc = _mm_sub_pd(
            _mm_mul_pd(b, b), _mm_mul_pd(_mm_add_pd(_mm_mul_pd(vx, vx), _mm_mul_pd(vy, vy)), c));
        const __m128d den = _mm_add_pd(_mm_sqrt_pd(_mm_max_pd(disc, zero)), _mm_andnot_pd(sign, b));
        const __m128d t = _mm_add_pd(now, _mm_div_pd(_mm_max_pd(c, zero), den));
        const __m128d ok = _mm_and_pd(_mm_cmplt_pd(b, zero), _mm_cmpgt_pd(disc, zero));
        const __m128d time = select_pd(ok, t, never);
        /* keep_if_earlier (below), lane by lane. */
        const __m128d partner_next = load_pair(&p0->next, &p1->next);
        const __m128d take = _mm_and_pd(_mm_cmplt_pd(time, best), _mm_cmple_pd(time, partner_next));
        best = select_pd(take, time, best);
        best_place = select_pd(take, place, best_place);
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
     * conditional moves, not a branch. */
    const __m128d best1 = _mm_unpackhi_pd(best, best);
    const __m128d place1 = _mm_unpackhi_pd(best_place, best_place);
    const __m128d second =
        _mm_or_pd(_mm_cmplt_sd(best1, best),
                  _mm_and_pd(_mm_cmpeq_sd(best1, best), _mm_cmplt_sd(place1, best_place)));
    const __m128d chosen = select_pd(second, place1, best_place);
    const int found = _mm_comige_sd(chosen, zero);
    const uint32_t k = pr->disk[(uint32_t)_mm_cvtsd_f64(_mm_max_sd(chosen, zero))];
    const uint32_t changes = e->disk[k].changes;
    pr->best = _mm_cvtsd_f64(select_pd(second, best1, best));
    const uint32_t keep = (uint32_t)found - 1u; /* all ones if nothing was found */
    pr->kind = (k & ~keep) | (pr->kind & keep);
    pr->partner_changes = (changes & ~keep) | (pr->partner_changes & keep);
}
#else
/* Keeps candidate k (time t) if it beats the best so far. Only a
 * collision no later than the partner's own next event is kept: if the
 * partner changes course first, it is predicted again then and finds the
 * pair itself. */
static inline void keep_if_earlier(predictor *pr, uint32_t k, double t)
{
    if (t < pr->best && t <= pr->e->disk[k].next) {
        pr->best = t;
        pr->kind = k;
        pr->partner_changes = pr->e->disk[k].changes;
    }
}

/* The time at which disk d (at time now) and disk p (at its own time,
 * its centre shifted by (sx, sy) to the image in question) come within
 * sqrt(sigma2), or +infinity: the plain-C form of test_gathered's SSE2
 * lanes above, for machines without SSE2. */
static inline double pair_time(const ed_disk *d, const ed_disk *p, double now, double sx, double sy,
                               double sigma2)
{
    const double lag = now - p->t;
    const double rx = p->x + p->vx * lag + sx - d->x, ry = p->y + p->vy * lag + sy - d->y;
    const double vx = p->vx - d->vx, vy = p->vy - d->vy;
    const double b = rx * vx + ry * vy;
    const double c = rx * rx + ry * ry - sigma2;
    const double disc = b * b - (vx * vx + vy * vy) * c;
    const double t = now + (c > 0.0 ? c : 0.0) / (sqrt(disc > 0.0 ? disc : 0.0) + fabs(b));
    return b < 0.0 && disc > 0.0 ? t : INFINITY;
}

static inline void test_gathered(predictor *pr, int shifted, int mixed)
{
    const double *radius = pr->e->radius;
    for (uint32_t j = 0; j < pr->count; ++j) {
        const uint32_t k = pr->disk[j];
        const double sx = shifted ? pr->sx[pr->image[j]] : 0.0;
        const double sy = shifted ? pr->sy[pr->image[j]] : 0.0;
        const double sigma = mixed ? radius[pr->self] + radius[k] : 0.0;
        const double sigma2 = mixed ? sigma * sigma : pr->e->sigma2;
        keep_if_earlier(pr, k, pair_time(pr->d, &pr->e->disk[k], pr->now, sx, sy, sigma2));
    }
    pr->tested += pr->count;
    pr->count = 0;
}
#endif

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
#if defined(__SSE2__)
    /* A cell's disks fill its slots from the first (cells.h): its four
     * slots are copied at once, and the count moves on past its disks.
     * How many there are comes from the mask of its empty slots. */
    static const uint8_t filled[16] = {4, 3, 3, 2, 3, 2, 2, 1, 3, 2, 2, 1, 2, 1, 1, 0};
    const __m128i none = _mm_set1_epi32((int)empty);
    for (int k = 0; k < count; k += DS_CELL_SLOTS) {
        const __m128i v = _mm_loadu_si128((const __m128i *)(const void *)(slot + k));
        _mm_storeu_si128((__m128i *)(void *)(pr->disk + n), v);
        n += filled[_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(v, none)))];
    }
#else
    for (int k = 0; k < count; k += 4) {
        pr->disk[n] = slot[k];
        n += slot[k] != empty;
        pr->disk[n] = slot[k + 1];
        n += slot[k + 1] != empty;
        pr->disk[n] = slot[k + 2];
        n += slot[k + 2] != empty;
        pr->disk[n] = slot[k + 3];
        n += slot[k + 3] != empty;
    }
#endif
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
    boundary_event(e, d, i, now, &best, &kind);
    ds_ed_stencil_cells st;
    ds_ed_stencil(e, d->column, d->row, &st);
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
        ds_ed_stencil(e, d->column, d->row, &st);
        for (uint32_t c = 0; c < st.count; ++c) {
            pr.sx[c] = st.sx[c];
            pr.sy[c] = st.sy[c];
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
