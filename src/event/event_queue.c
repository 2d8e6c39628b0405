/* SPDX-License-Identifier: MIT */
/* The event queue's entry points (event_queue.h), dispatched to its kind:
 * the calendar (calendar.c) or the indexed heap (queue_heap.c). */
#include <stdlib.h>

#include "core/large_alloc.h"
#include "event/queue_parts.h"

size_t ds_eq_bytes(size_t n, ds_eq_kind kind)
{
    const size_t bytes = sizeof(ds_event_queue);
    if (kind == DS_EQ_HEAP)
        return bytes + n * (sizeof(heap_node) + sizeof(uint32_t));
    return bytes + (n + 4096) * sizeof(heap_node) + ds_eq_calendar_buckets(n) * sizeof(bucket) +
           n * (sizeof(pool_entry) + sizeof(far_entry) + sizeof(uint8_t));
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
    q->ops = kind == DS_EQ_HEAP ? &ds_eq_heap_ops : &ds_eq_calendar_ops;
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
        q->nbuckets = ds_eq_calendar_buckets(n);
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

void ds_eq_set(ds_event_queue *q, uint32_t i, double t) { q->ops->set(q, i, t); }
uint32_t ds_eq_first(ds_event_queue *q) { return q->ops->first(q); }
void ds_eq_build(ds_event_queue *q, double now) { q->ops->build(q, now); }
