/* SPDX-License-Identifier: MIT */
/* The event calendar: a calendar queue, and an indexed binary heap to
 * check it against (see event_queue.h).
 *
 * The calendar is built for systems much larger than the caches, where
 * every reschedule lands in a random bucket: nothing in it follows a chain
 * of links through memory.
 *
 * - Lazy deletion. A disk's time lives in the caller's memory (the
 *   integrator's disk record); rescheduling writes it there and adds a
 *   new entry. Old entries stay where they are and are recognised as
 *   stale when their bucket is drained (the disk's time is no longer in
 *   that bucket) or when they reach the top of the heap (their time is no
 *   longer the disk's). An entry whose disk was rescheduled to the very
 *   same time is as good as the new one: it names the disk at its time,
 *   whichever of the two comes first; the other is then stale.
 * - A bucket is one cache line of disk numbers (a rare full bucket spills
 *   into a pool), so draining one reads one line.
 * - For a calendar larger than the caches (ds_eq_on_soon): insertions are
 *   buffered, each one's bucket line requested at once and written some
 *   insertions later, when it has arrived; and buckets are read two ahead
 *   of their turn, their disks' times requested and the integrator told.
 *   In cache, both would be work for nothing. */
#include <math.h>
#include <stdlib.h>

#include "core/large_alloc.h"
#include "core/prefetch.h"
#include "event/event_queue.h"

#define NONE UINT32_MAX

/* Scheduled times per bucket near the front of the calendar. */
#define EVENTS_PER_BUCKET 4.0
#define BUCKET_CAP 14
/* Buffered insertions: each is written PENDING_LAG insertions after its
 * bucket line was requested. */
#define PENDING 32u
#define PENDING_LAG 16u
/* Buckets are announced (their disks' slots requested) this many ahead. */
#define SOON 2

/* Absolute bucket numbers beyond this are "never" (+infinity, or a time
 * so far ahead that it cannot be told apart from it). */
#define FAR_BUCKET ((int64_t)1 << 62)
/* The calendar's flag per disk: kept by a compaction. */
#define KEPT 1u

typedef struct bucket {
    uint16_t count; /* entries in disk[], at most BUCKET_CAP */
    uint16_t spare;
    uint32_t spill; /* pool entries beyond BUCKET_CAP, or NONE */
    uint32_t disk[BUCKET_CAP];
} bucket; /* 64 bytes: one cache line */

typedef struct pool_entry {
    uint32_t disk, next;
} pool_entry;

typedef struct heap_node {
    double time;
    uint32_t disk, spare;
} heap_node;

/* A far list entry: a disk and its time when it was listed, so that a
 * scan reads the list alone, in order, and none of the disks' records. */
typedef struct far_entry {
    double time;
    uint32_t disk, spare;
} far_entry;

typedef struct pending_insert {
    int64_t bucket;
    uint32_t disk;
} pending_insert;

struct ds_event_queue {
    ds_eq_kind kind;
    size_t n;
    char *times; /* disk i's time at times + i * stride (the caller's) */
    size_t stride;
    heap_node *heap; /* DS_EQ_HEAP: all disks; calendar: the sorted front */
    uint32_t *where; /* DS_EQ_HEAP: each disk's place in the heap */
    uint8_t *flag;   /* calendar: KEPT, set only inside heap_compact */
    size_t heap_count, heap_cap;

    /* Calendar only. Bucket b (absolute) covers [b, b+1) / inv_width and
     * lives in bucket[b & mask] while current < b < current + nbuckets. */
    bucket *bucket; /* aligned to a cache line */
    size_t nbuckets;
    uint64_t mask;
    double inv_width;
    int64_t current;   /* every time of a bucket up to this is in the heap */
    int64_t next_scan; /* current at which the far list is next scanned */
    size_t windowed;   /* entries in buckets and pending, stale ones too */
    pool_entry *pool;  /* spilled entries of full buckets */
    uint32_t pool_free;
    far_entry *far;   /* the far list: disks with times beyond the window */
    size_t far_count; /* at most n; stale entries and repeats among them */
    pending_insert pending[PENDING];
    unsigned pending_head, pending_tail;
    int64_t pending_min; /* earliest bucket among pending (or FAR_BUCKET) */
    ds_eq_soon_fn soon;
    void *soon_ctx;
    size_t lookahead; /* times kept sorted ahead (ds_eq_on_soon) */
};

static size_t bucket_count(size_t n)
{
    /* A window of at least two mean times between a disk's events (see
     * ds_eq_build): nbuckets * EVENTS_PER_BUCKET >= 2 n. */
    size_t b = 16;
    while ((double)b * EVENTS_PER_BUCKET < 2.0 * (double)n && b < ((size_t)1 << 30))
        b <<= 1;
    return b;
}

size_t ds_eq_bytes(size_t n, ds_eq_kind kind)
{
    const size_t bytes = sizeof(ds_event_queue);
    if (kind == DS_EQ_HEAP)
        return bytes + n * (sizeof(heap_node) + sizeof(uint32_t));
    return bytes + (n + 4096) * sizeof(heap_node) + bucket_count(n) * sizeof(bucket) +
           n * (sizeof(pool_entry) + sizeof(far_entry) + sizeof(uint8_t));
}

static inline double *time_at(const ds_event_queue *q, uint32_t i)
{
    return (double *)(void *)(q->times + (size_t)i * q->stride);
}

double ds_eq_time(const ds_event_queue *q, uint32_t i) { return *time_at(q, i); }

ds_status ds_eq_create(ds_event_queue **out, size_t n, ds_eq_kind kind, double *times,
                       size_t stride)
{
    if (out)
        *out = NULL;
    if (!out || n == 0 || n >= ((size_t)1 << 30) || !times || stride < sizeof(double))
        return DS_ERR_ARG;
    ds_event_queue *q = calloc(1, sizeof *q);
    if (!q)
        return DS_ERR_NOMEM;
    q->kind = kind;
    q->n = n;
    q->times = (char *)times;
    q->stride = stride;
    /* The calendar's heap also holds stale entries, until compacted. */
    q->heap_cap = kind == DS_EQ_HEAP ? n : n + 4096;
    q->heap = malloc(q->heap_cap * sizeof *q->heap);
    int failed = !q->heap;
    if (kind == DS_EQ_HEAP) {
        q->where = malloc(n * sizeof *q->where);
        failed = failed || !q->where;
    } else {
        q->flag = calloc(n, sizeof *q->flag);
        q->nbuckets = bucket_count(n);
        q->mask = q->nbuckets - 1;
        q->bucket = ds_large_alloc(q->nbuckets * sizeof(bucket));
        q->pool = malloc(n * sizeof *q->pool);
        q->far = malloc(n * sizeof *q->far);
        failed = failed || !q->flag || !q->bucket || !q->pool || !q->far;
    }
    if (failed) {
        ds_eq_destroy(q);
        return DS_ERR_NOMEM;
    }
    q->inv_width = 1.0;
    q->lookahead = 1;
    *out = q;
    return DS_OK;
}

void ds_eq_destroy(ds_event_queue *q)
{
    if (!q)
        return;
    free(q->heap);
    free(q->where);
    free(q->flag);
    free(q->bucket);
    free(q->pool);
    free(q->far);
    free(q);
}

ds_eq_kind ds_eq_kind_of(const ds_event_queue *q) { return q->kind; }

void ds_eq_on_soon(ds_event_queue *q, ds_eq_soon_fn soon, void *ctx, unsigned lookahead)
{
    q->soon = soon;
    q->soon_ctx = ctx;
    q->lookahead = lookahead < 1 ? 1 : lookahead > 64 ? 64 : lookahead;
}

/* ------------------------------------------------------------------ */
/* Binary heap of (time, disk)                                           */
/* ------------------------------------------------------------------ */

/* DS_EQ_HEAP keeps each disk's heap position; the calendar's heap is not
 * indexed (an entry found in it is checked against the disk's time). The
 * heap orders by time alone; ties are settled by disk in ds_eq_first. */

static inline void heap_place(ds_event_queue *q, size_t pos, heap_node node)
{
    q->heap[pos] = node;
    if (q->kind == DS_EQ_HEAP)
        q->where[node.disk] = (uint32_t)pos;
}

static void sift_up(ds_event_queue *q, size_t pos)
{
    const heap_node node = q->heap[pos];
    while (pos > 0) {
        const size_t parent = (pos - 1) / 2;
        if (!(node.time < q->heap[parent].time))
            break;
        heap_place(q, pos, q->heap[parent]);
        pos = parent;
    }
    heap_place(q, pos, node);
}

static void sift_down(ds_event_queue *q, size_t pos)
{
    const heap_node node = q->heap[pos];
    const size_t count = q->heap_count;
    for (;;) {
        size_t child = 2 * pos + 1;
        if (child >= count)
            break;
        /* The earlier child, without a branch on which: a coin toss. */
        const size_t right = child + 1 < count ? child + 1 : child;
        child += q->heap[right].time < q->heap[child].time;
        if (!(q->heap[child].time < node.time))
            break;
        heap_place(q, pos, q->heap[child]);
        pos = child;
    }
    heap_place(q, pos, node);
}

static void heap_pop(ds_event_queue *q)
{
    const heap_node last = q->heap[--q->heap_count];
    if (q->heap_count) {
        heap_place(q, 0, last);
        sift_down(q, 0);
    }
}

static int is_current(const ds_event_queue *q, heap_node node)
{
    return node.time == *time_at(q, node.disk);
}

/* The calendar's heap is full of stale entries: keeps one current entry
 * per disk (KEPT marks the disks kept) and heapifies again. */
static void heap_compact(ds_event_queue *q)
{
    size_t kept = 0;
    for (size_t k = 0; k < q->heap_count; ++k) {
        const heap_node node = q->heap[k];
        if (is_current(q, node) && !(q->flag[node.disk] & KEPT)) {
            q->flag[node.disk] |= KEPT;
            q->heap[kept++] = node;
        }
    }
    for (size_t k = 0; k < kept; ++k)
        q->flag[q->heap[k].disk] &= (uint8_t)~KEPT;
    q->heap_count = kept;
    for (size_t pos = kept / 2; pos-- > 0;)
        sift_down(q, pos);
}

static void heap_push(ds_event_queue *q, double time, uint32_t disk)
{
    if (q->heap_count == q->heap_cap)
        heap_compact(q);
    const heap_node node = {time, disk, 0};
    heap_place(q, q->heap_count++, node);
    sift_up(q, q->heap_count - 1);
}

/* ------------------------------------------------------------------ */
/* Calendar                                                             */
/* ------------------------------------------------------------------ */

static int64_t bucket_of(const ds_event_queue *q, double t)
{
    const double b = t * q->inv_width;
    /* Times are >= 0 (now is the origin of the integrator's clock, up to
     * rounding): truncation is floor, and a hair below 0 is bucket 0. */
    return b < (double)FAR_BUCKET ? (int64_t)b : FAR_BUCKET;
}

static void reinsert_all(ds_event_queue *q);

/* Adds an entry for disk to bucket b (current < b < current + nbuckets).
 * Returns 0, or 1 if the spill pool ran out and the whole calendar was
 * rebuilt from the slots instead (which discards every stale entry, so the
 * pool, one entry per disk, then always suffices). */
static int bucket_add(ds_event_queue *q, int64_t b, uint32_t disk)
{
    bucket *bk = &q->bucket[(uint64_t)b & q->mask];
    if (bk->count < BUCKET_CAP) {
        bk->disk[bk->count++] = disk;
    } else {
        if (q->pool_free == NONE) {
            reinsert_all(q);
            return 1;
        }
        const uint32_t e = q->pool_free;
        q->pool_free = q->pool[e].next;
        q->pool[e].disk = disk;
        q->pool[e].next = bk->spill;
        bk->spill = e;
    }
    ++q->windowed;
    return 0;
}

/* Appends disk, at time t, to the far list: one sequential write, no
 * look-up. A disk rescheduled while listed is listed again; its entries
 * left with other times are stale, and are dropped where every stale
 * entry is: the bucket they are filed into, or the heap. A full list is
 * rebuilt from the times with the whole calendar (returns 1 then). */
static int far_add(ds_event_queue *q, uint32_t disk, double t)
{
    if (q->far_count == q->n) {
        reinsert_all(q);
        return 1;
    }
    q->far[q->far_count++] = (far_entry){t, disk, 0};
    return 0;
}

/* Files disk at time t, writing its bucket at once. */
static int file_at(ds_event_queue *q, uint32_t disk, double t)
{
    const int64_t b = bucket_of(q, t);
    if (b <= q->current) {
        heap_push(q, t, disk);
        return 0;
    }
    if (b - q->current < (int64_t)q->nbuckets)
        return bucket_add(q, b, disk);
    return far_add(q, disk, t);
}

static void update_pending_min(ds_event_queue *q)
{
    q->pending_min = FAR_BUCKET;
    for (unsigned k = q->pending_head; k != q->pending_tail; ++k)
        if (q->pending[k % PENDING].bucket < q->pending_min)
            q->pending_min = q->pending[k % PENDING].bucket;
}

/* Writes the oldest buffered insertion into its bucket. */
static int write_pending(ds_event_queue *q)
{
    const pending_insert p = q->pending[q->pending_head++ % PENDING];
    --q->windowed; /* counted again by bucket_add */
    if (bucket_add(q, p.bucket, p.disk))
        return 1;
    if (p.bucket == q->pending_min)
        update_pending_min(q);
    return 0;
}

static void flush_pending(ds_event_queue *q)
{
    while (q->pending_head != q->pending_tail)
        if (write_pending(q))
            return;
}

/* Puts every disk back from its time, dropping every stale entry. */
static void reinsert_all(ds_event_queue *q)
{
    for (size_t b = 0; b < q->nbuckets; ++b) {
        q->bucket[b].count = 0;
        q->bucket[b].spill = NONE;
    }
    for (size_t e = 0; e < q->n; ++e)
        q->pool[e].next = e + 1 < q->n ? (uint32_t)(e + 1) : NONE;
    q->pool_free = 0;
    q->far_count = 0;
    q->windowed = 0;
    q->heap_count = 0;
    q->pending_head = q->pending_tail = 0;
    q->pending_min = FAR_BUCKET;
    for (size_t i = 0; i < q->n; ++i)
        file_at(q, (uint32_t)i, *time_at(q, (uint32_t)i)); /* no stale entries: fits */
}

/* Entries of the far list a scan looks ahead by. */
#define FAR_AHEAD 16

/* Moves the far list's entries whose times now fall inside the window
 * into it, keeping the rest in order. Scanning every nbuckets/2 buckets is
 * early enough: a time goes to the far list only when at least nbuckets
 * ahead of current. An entry is filed by its own time, whether or not it
 * is still its disk's: a stale one is dropped when its bucket is drained,
 * as any stale bucket entry. (Filing by the disk's present time instead
 * read a random record line per entry: ~1 per collision at 10^5 disks.) */
static void scan_far(ds_event_queue *q)
{
    q->next_scan = q->current + (int64_t)(q->nbuckets / 2);
    const size_t count = q->far_count;
    size_t kept = 0;
    for (size_t k = 0; k < count; ++k) {
        /* The bucket line of an entry some entries ahead: filing into
         * random buckets is where a scan waits (perf at 10^6 disks). */
        if (k + FAR_AHEAD < count)
            ds_prefetch(&q->bucket[(uint64_t)bucket_of(q, q->far[k + FAR_AHEAD].time) & q->mask]);
        const far_entry f = q->far[k];
        if (bucket_of(q, f.time) - q->current < (int64_t)q->nbuckets) {
            /* In the window now: never back to this list, which the loop
             * is rewriting, and a rebuild replaces the list outright. */
            if (file_at(q, f.disk, f.time))
                return;
        } else {
            q->far[kept++] = f;
        }
    }
    q->far_count = kept;
}

/* Requests the times of bucket b's disks and tells the integrator, with
 * the end of the bucket's time: an entry is current only while its
 * disk's time is before it. The rare entries spilled past a full bucket
 * are named too: a disk left unnamed there may have been named by a
 * stale entry of an earlier bucket, whose end it is past. */
static void announce(ds_event_queue *q, int64_t b)
{
    const bucket *bk = &q->bucket[(uint64_t)b & q->mask];
    ds_prefetch(&q->bucket[(uint64_t)(b + SOON) & q->mask]);
    const double until = (double)(b + 1) / q->inv_width;
    for (unsigned k = 0; k < bk->count; ++k) {
        ds_prefetch(time_at(q, bk->disk[k]));
        q->soon(q->soon_ctx, bk->disk[k], until);
    }
    for (uint32_t e = bk->spill; e != NONE; e = q->pool[e].next)
        q->soon(q->soon_ctx, q->pool[e].disk, until);
}

/* Moves bucket b's current entries into the heap and empties it. */
static void drain(ds_event_queue *q, int64_t b)
{
    bucket *bk = &q->bucket[(uint64_t)b & q->mask];
    for (unsigned k = 0; k < bk->count; ++k) {
        const uint32_t disk = bk->disk[k];
        const double t = *time_at(q, disk);
        if (bucket_of(q, t) == b)
            heap_push(q, t, disk);
    }
    q->windowed -= bk->count;
    bk->count = 0;
    while (bk->spill != NONE) {
        const uint32_t e = bk->spill;
        const double t = *time_at(q, q->pool[e].disk);
        if (bucket_of(q, t) == b)
            heap_push(q, t, q->pool[e].disk);
        bk->spill = q->pool[e].next;
        q->pool[e].next = q->pool_free;
        q->pool_free = e;
        --q->windowed;
    }
}

/* With nothing in the window, moves current to just before the far list's
 * earliest time instead of walking empty buckets. */
static void jump_to_far(ds_event_queue *q)
{
    double first = INFINITY;
    for (size_t k = 0; k < q->far_count; ++k)
        if (q->far[k].time < first)
            first = q->far[k].time;
    const int64_t b = bucket_of(q, first);
    if (b >= FAR_BUCKET) {
        /* Only "never" is left (every disk at rest): the heap takes them
         * all, and current moves to the far end so that the heap holds
         * every time (an earlier one set later goes straight to it) until
         * the next ds_eq_build. */
        q->current = FAR_BUCKET;
        for (size_t k = 0; k < q->far_count; ++k)
            heap_push(q, q->far[k].time, q->far[k].disk);
        q->far_count = 0;
        return;
    }
    if (b - 1 > q->current)
        q->current = b - 1;
    scan_far(q);
}

static void advance(ds_event_queue *q)
{
    if (q->windowed == 0) {
        jump_to_far(q);
        if (q->windowed == 0)
            return;
    }
    ++q->current;
    if (q->pending_min <= q->current + SOON)
        flush_pending(q);
    if (q->current >= q->next_scan)
        scan_far(q);
    if (q->soon)
        announce(q, q->current + SOON);
    drain(q, q->current);
}

/* ------------------------------------------------------------------ */
/* The interface                                                        */
/* ------------------------------------------------------------------ */

void ds_eq_set(ds_event_queue *q, uint32_t i, double t)
{
    double *time = time_at(q, i);
    if (q->kind == DS_EQ_HEAP) {
        const double old = *time;
        *time = t;
        q->heap[q->where[i]].time = t;
        if (t < old) /* equal: the same place, the disk ties with itself */
            sift_up(q, q->where[i]);
        else
            sift_down(q, q->where[i]);
        return;
    }
    *time = t;
    if (q->soon) {
        const int64_t b = bucket_of(q, t);
        if (b > q->current && b - q->current < (int64_t)q->nbuckets) {
            /* Larger than the caches: request the bucket's line now,
             * write the entry later. */
            ds_prefetch(&q->bucket[(uint64_t)b & q->mask]);
            q->pending[q->pending_tail++ % PENDING] = (pending_insert){b, i};
            ++q->windowed;
            if (b < q->pending_min)
                q->pending_min = b;
            if (q->pending_tail - q->pending_head > PENDING_LAG)
                write_pending(q);
            return;
        }
    }
    file_at(q, i, t); /* the heap, the far list, or (in cache) its bucket at once */
}

/* Equal times come in the order of their disks, whatever the order they
 * were filed in: the order of events is then a function of the times
 * alone, not of the queue's history, so a queue built afresh from the
 * same times (a restarted run) gives the same events in the same order.
 * The heap orders by time only (a second key in its comparisons cost 5
 * to 9% per collision); here, the entries tied with the top (current
 * ones) are looked for and the lowest disk among them
 * taken. They form a subtree at the top (a parent is never later than
 * its children), walked depth first; nearly always the top's two
 * children are later and that is all it costs. The calendar's entry of a
 * disk taken from inside the heap goes stale when its disk is
 * rescheduled, and is dropped when it reaches the top. */
static uint32_t lowest_tied(const ds_event_queue *q)
{
    const heap_node *h = q->heap;
    const size_t count = q->heap_count;
    const double t = h[0].time;
    if (!((count > 1 && h[1].time == t) || (count > 2 && h[2].time == t)))
        return h[0].disk;
    uint32_t best = h[0].disk;
    size_t stack[64], depth = 0; /* pending right children: at most the heap's depth */
    size_t k = 0;
    for (;;) {
        if (h[k].disk < best && (q->kind == DS_EQ_HEAP || is_current(q, h[k])))
            best = h[k].disk;
        const size_t left = 2 * k + 1, right = left + 1;
        const int go_left = left < count && h[left].time == t;
        if (right < count && h[right].time == t) {
            if (go_left)
                stack[depth++] = right;
            else
                k = right;
        }
        if (go_left)
            k = left;
        else if (!(right < count && h[right].time == t)) {
            if (depth == 0)
                break;
            k = stack[--depth];
        }
    }
    return best;
}

uint32_t ds_eq_first(ds_event_queue *q)
{
    if (q->kind == DS_EQ_HEAP)
        return lowest_tied(q);
    for (;;) {
        while (q->heap_count < q->lookahead && (q->windowed || q->far_count))
            advance(q);
        if (q->heap_count == 0)
            return NONE;
        if (is_current(q, q->heap[0]))
            return lowest_tied(q);
        heap_pop(q);
    }
}

void ds_eq_build(ds_event_queue *q, double now)
{
    const size_t n = q->n;
    if (q->kind == DS_EQ_HEAP) {
        for (size_t i = 0; i < n; ++i) {
            const heap_node node = {*time_at(q, (uint32_t)i), (uint32_t)i, 0};
            heap_place(q, i, node);
        }
        q->heap_count = n;
        for (size_t pos = n / 2; pos-- > 0;)
            sift_down(q, pos);
        return;
    }
    /* Bucket width: the times ahead are spread over about the mean time
     * between one disk's events, tau, so near the front n / tau of them
     * fall in each unit of time. */
    double sum = 0.0;
    size_t finite = 0;
    for (size_t i = 0; i < n; ++i) {
        const double t = *time_at(q, (uint32_t)i);
        if (isfinite(t)) {
            sum += t > now ? t - now : 0.0;
            ++finite;
        }
    }
    const double tau = finite ? sum / (double)finite : 0.0;
    const double width = tau > 0.0 ? EVENTS_PER_BUCKET * tau / (double)n : 1.0;
    /* Keep absolute bucket numbers of times near now far below FAR_BUCKET. */
    q->inv_width = fmin(1.0 / width, 1e15 / fmax(now, 1.0));
    q->current = bucket_of(q, now);
    q->next_scan = q->current + (int64_t)(q->nbuckets / 2);
    reinsert_all(q);
}
