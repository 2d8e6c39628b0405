/* The event calendar of the event-driven integrator: one scheduled time per
 * disk, and which disk's time is the earliest.
 *
 * Two implementations behind one interface, as the broad phases are:
 *
 * - DS_EQ_CALENDAR, a calendar queue (Brown 1988; Paul 2007, J. Comput.
 *   Phys. 221, 615, for event-driven MD): times fall into buckets of a
 *   fixed width, the next few buckets are sorted in a small binary heap,
 *   the later ones are unsorted, and times beyond the calendar's window
 *   wait in a far list. Scheduling is O(1), finding the earliest O(1)
 *   amortised, whatever the number of disks.
 * - DS_EQ_HEAP, an indexed binary heap over all disks: O(log n) per
 *   operation, simple, and the reference the calendar is tested against.
 *
 * Not installed; used by event_driven.c and the tests. */
#ifndef DS_EVENT_QUEUE_H
#define DS_EVENT_QUEUE_H

#include <stddef.h>
#include <stdint.h>

#include "disk_sim.h"

typedef enum ds_eq_kind { DS_EQ_CALENDAR, DS_EQ_HEAP } ds_eq_kind;

typedef struct ds_event_queue ds_event_queue;

/* One disk's schedule: its time and how often it has been scheduled. */
typedef struct ds_eq_slot {
    double time;
    uint32_t seq;
    uint32_t where; /* the heap's own bookkeeping */
} ds_eq_slot;

/* A queue for disks 0..n-1 (n < 2^30), none scheduled yet. */
ds_status ds_eq_create(ds_event_queue **out, size_t n, ds_eq_kind kind);
void ds_eq_destroy(ds_event_queue *q);

/* Schedules every disk at once at times[i] (>= now, +infinity allowed),
 * replacing what was there. The calendar sizes its buckets from these
 * times: their mean distance from now is the mean time between a disk's
 * events. */
void ds_eq_build(ds_event_queue *q, const double *times, double now);

/* Reschedules disk i at time t (>= the earliest time in the queue, up to
 * rounding; +infinity allowed). */
void ds_eq_set(ds_event_queue *q, uint32_t i, double t);

/* The disk with the earliest time (ties in any order, but the same order
 * for the same calls). */
uint32_t ds_eq_first(ds_event_queue *q);

/* Every disk's schedule, indexed by disk (read-only; valid until the queue
 * is destroyed): slots[i].time is disk i's time. */
const ds_eq_slot *ds_eq_slots(const ds_event_queue *q);

static inline double ds_eq_time(const ds_event_queue *q, uint32_t i)
{
    return ds_eq_slots(q)[i].time;
}

ds_eq_kind ds_eq_kind_of(const ds_event_queue *q);

/* For a calendar larger than the caches: keeps at least `lookahead` times
 * sorted ahead of the next one (at most 64; 1 by default), reads buckets
 * ahead and calls soon(ctx, i) for a disk a couple of buckets before its
 * time joins them (some events before its turn, early enough to fetch what
 * its event will touch; a disk may be named more than once, or named and
 * then rescheduled), and buffers insertions until their bucket has been
 * fetched. soon = NULL (the default) does none of it. */
typedef void (*ds_eq_soon_fn)(void *ctx, uint32_t i);
void ds_eq_on_soon(ds_event_queue *q, ds_eq_soon_fn soon, void *ctx, unsigned lookahead);

/* Bytes a queue of n disks allocates, not counting the calendar's spill
 * pool, which holds the rare bucket that overflows and grows on demand. */
size_t ds_eq_bytes(size_t n, ds_eq_kind kind);

#endif
