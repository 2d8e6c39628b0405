/* SPDX-License-Identifier: MIT */
/* The event queue's parts (event_queue.c, queue_heap.c, calendar.c): the
 * queue's layout, its binary heap and the table each kind fills. Private
 * to event/'s queue files and their tests. */
#ifndef DS_QUEUE_PARTS_H
#define DS_QUEUE_PARTS_H

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

/* What each kind of queue does (event_queue.h's entry points). */
typedef struct ds_eq_ops {
    void (*set)(ds_event_queue *q, uint32_t i, double t);
    uint32_t (*first)(ds_event_queue *q);
    void (*build)(ds_event_queue *q, double now);
} ds_eq_ops;

struct ds_event_queue {
    ds_eq_kind kind;
    const ds_eq_ops *ops;
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

static inline double *time_at(const ds_event_queue *q, uint32_t i)
{
    return (double *)(void *)(q->times + (size_t)i * q->stride);
}

static inline int ds_qh_is_current(const ds_event_queue *q, heap_node node)
{
    return node.time == *time_at(q, node.disk);
}

/* The binary heap of (time, disk) (queue_heap.c): the indexed heap of
 * DS_EQ_HEAP, and the calendar's sorted front, which is not indexed (an
 * entry found in it is checked against its disk's time). */
void ds_qh_sift_down(ds_event_queue *q, size_t pos);
void ds_qh_push(ds_event_queue *q, double time, uint32_t disk);
void ds_qh_pop(ds_event_queue *q);
uint32_t ds_qh_lowest_tied(const ds_event_queue *q);

/* The kinds (queue_heap.c, calendar.c), and the calendar's bucket count
 * for n disks. */
extern const ds_eq_ops ds_eq_heap_ops, ds_eq_calendar_ops;
size_t ds_eq_calendar_buckets(size_t n);

#endif
