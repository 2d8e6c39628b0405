/* SPDX-License-Identifier: MIT */
/* The event queue's binary heap of (time, disk): the whole queue of
 * DS_EQ_HEAP, indexed by disk (the reference the calendar is tested
 * against), and the calendar's sorted front, not indexed. The heap orders
 * by time alone; ties are settled by disk in ds_qh_lowest_tied. */
#include "event/queue_parts.h"

static inline void heap_place(ds_event_queue *q, size_t pos, heap_node node)
{
    q->heap[pos] = node;
    if (q->where)
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

void ds_qh_sift_down(ds_event_queue *q, size_t pos)
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

void ds_qh_pop(ds_event_queue *q)
{
    const heap_node last = q->heap[--q->heap_count];
    if (q->heap_count) {
        heap_place(q, 0, last);
        ds_qh_sift_down(q, 0);
    }
}

/* The calendar's heap is full of stale entries: keeps one current entry
 * per disk (KEPT marks the disks kept) and heapifies again. */
static void heap_compact(ds_event_queue *q)
{
    size_t kept = 0;
    for (size_t k = 0; k < q->heap_count; ++k) {
        const heap_node node = q->heap[k];
        if (ds_qh_is_current(q, node) && !(q->flag[node.disk] & KEPT)) {
            q->flag[node.disk] |= KEPT;
            q->heap[kept++] = node;
        }
    }
    for (size_t k = 0; k < kept; ++k)
        q->flag[q->heap[k].disk] &= (uint8_t)~KEPT;
    q->heap_count = kept;
    for (size_t pos = kept / 2; pos-- > 0;)
        ds_qh_sift_down(q, pos);
}

void ds_qh_push(ds_event_queue *q, double time, uint32_t disk)
{
    if (q->heap_count == q->heap_cap)
        heap_compact(q);
    const heap_node node = {time, disk, 0};
    heap_place(q, q->heap_count++, node);
    sift_up(q, q->heap_count - 1);
}

/* Equal times come in the order of their disks, whatever the order they
 * were filed in: the order of events is then a function of the times
 * alone, not of the queue's history, so a queue built afresh from the
 * same times (a restarted run) gives the same events in the same order.
 * The heap orders by time only (a second key in its comparisons cost 5
 * to 9% per collision); here, the entries tied with the top (current
 * ones) are looked for and the lowest disk among them taken. They form a
 * subtree at the top (a parent is never later than its children), walked
 * depth first; nearly always the top's two children are later and that
 * is all it costs. The calendar's entry of a disk taken from inside the
 * heap goes stale when its disk is rescheduled, and is dropped when it
 * reaches the top. */
uint32_t ds_qh_lowest_tied(const ds_event_queue *q)
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
        if (h[k].disk < best && (q->where || ds_qh_is_current(q, h[k])))
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

/* ------------------------------------------------------------------ */
/* DS_EQ_HEAP: every disk in the heap, at its place                     */
/* ------------------------------------------------------------------ */

static void heap_set(ds_event_queue *q, uint32_t i, double t)
{
    double *time = time_at(q, i);
    const double old = *time;
    *time = t;
    q->heap[q->where[i]].time = t;
    if (t < old) /* equal: the same place, the disk ties with itself */
        sift_up(q, q->where[i]);
    else
        ds_qh_sift_down(q, q->where[i]);
}

static uint32_t heap_first(ds_event_queue *q) { return ds_qh_lowest_tied(q); }

static void heap_build(ds_event_queue *q, double now)
{
    (void)now;
    const size_t n = q->n;
    for (size_t i = 0; i < n; ++i) {
        const heap_node node = {*time_at(q, (uint32_t)i), (uint32_t)i, 0};
        heap_place(q, i, node);
    }
    q->heap_count = n;
    for (size_t pos = n / 2; pos-- > 0;)
        ds_qh_sift_down(q, pos);
}

const ds_eq_ops ds_eq_heap_ops = {heap_set, heap_first, heap_build};
