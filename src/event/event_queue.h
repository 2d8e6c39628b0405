/* SPDX-License-Identifier: MIT */
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

/* A queue for disks 0..n-1 (n < 2^30), none scheduled yet. Disk i's
 * time lives in the caller's memory, at times + i * stride bytes (the
 * integrator keeps it in the disk's record, on the line an event reads
 * anyway): the queue reads it there and ds_eq_set writes it. The calendar
 * keeps no copy of it and no count of schedules: an entry is current
 * while its time is still the disk's time, so an entry left by a
 * reschedule is recognised as stale by the disk's own time. */
ds_status ds_eq_create(ds_event_queue **out, size_t n, ds_eq_kind kind, double *times,
                       size_t stride);
void ds_eq_destroy(ds_event_queue *q);

/* Schedules every disk at once at its time as it stands in the caller's
 * memory (>= now, +infinity allowed), replacing what was there. The
 * calendar sizes its buckets from these times: their mean distance from
 * now is the mean time between a disk's events. */
void ds_eq_build(ds_event_queue *q, double now);

/* Reschedules disk i at time t (>= the earliest time in the queue, up to
 * rounding; +infinity allowed), writing t into the caller's memory. */
void ds_eq_set(ds_event_queue *q, uint32_t i, double t);

/* The disk with the earliest time; of disks with the same time, the
 * lowest numbered. The order is a function of the times alone, the same
 * for the calendar and the heap, whatever the history of the queue. */
uint32_t ds_eq_first(ds_event_queue *q);

/* Disk i's scheduled time. */
double ds_eq_time(const ds_event_queue *q, uint32_t i);

ds_eq_kind ds_eq_kind_of(const ds_event_queue *q);

/* For a calendar larger than the caches: keeps at least `lookahead` times
 * sorted ahead of the next one (at most 64; 1 by default), reads buckets
 * ahead and calls soon(ctx, i, until) for a disk a couple of buckets
 * before its time joins them (some events before its turn, early enough to
 * fetch what its event will touch; a disk may be named more than once, or
 * named and then rescheduled), and buffers insertions until their bucket
 * has been fetched. until is the end of the naming entry's bucket: a disk
 * whose time is at or past it was named by a stale entry, and is named
 * again by its new bucket unless that was read already. soon = NULL (the
 * default) does none of it. */
typedef void (*ds_eq_soon_fn)(void *ctx, uint32_t i, double until);
void ds_eq_on_soon(ds_event_queue *q, ds_eq_soon_fn soon, void *ctx, unsigned lookahead);

/* Bytes a queue of n disks allocates, not counting the calendar's spill
 * pool, which holds the rare bucket that overflows and grows on demand. */
size_t ds_eq_bytes(size_t n, ds_eq_kind kind);

#endif
