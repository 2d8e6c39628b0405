/* SPDX-License-Identifier: MIT */
/* The calendar queue of the event-driven integrator (event_queue.h):
 * buckets of times near the front, a sorted heap for the next few
 * (queue_heap.c), a far list beyond.
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

#include "core/prefetch.h"
#include "event/queue_parts.h"

size_t ds_eq_calendar_buckets(size_t n)
{
    /* A window of at least two mean times between a disk's events (see
     * ds_eq_build): nbuckets * EVENTS_PER_BUCKET >= 2 n. */
    size_t b = 16;
    while ((double)b * EVENTS_PER_BUCKET < 2.0 * (double)n && b < ((size_t)1 << 30))
        b <<= 1;
    return b;
}

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
        ds_qh_push(q, t, disk);
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
            ds_qh_push(q, t, disk);
    }
    q->windowed -= bk->count;
    bk->count = 0;
    while (bk->spill != NONE) {
        const uint32_t e = bk->spill;
        const double t = *time_at(q, q->pool[e].disk);
        if (bucket_of(q, t) == b)
            ds_qh_push(q, t, q->pool[e].disk);
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
            ds_qh_push(q, q->far[k].time, q->far[k].disk);
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

static void calendar_set(ds_event_queue *q, uint32_t i, double t)
{
    *time_at(q, i) = t;
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

static uint32_t calendar_first(ds_event_queue *q)
{
    for (;;) {
        while (q->heap_count < q->lookahead && (q->windowed || q->far_count))
            advance(q);
        if (q->heap_count == 0)
            return NONE;
        if (ds_qh_is_current(q, q->heap[0]))
            return ds_qh_lowest_tied(q);
        ds_qh_pop(q);
    }
}

static void calendar_build(ds_event_queue *q, double now)
{
    const size_t n = q->n;
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

const ds_eq_ops ds_eq_calendar_ops = {calendar_set, calendar_first, calendar_build};
