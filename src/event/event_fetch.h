/* SPDX-License-Identifier: MIT */
/* Fetching ahead (event_fetch.c): the memory of events a few events
 * before they come up, for systems larger than the caches. Its state is
 * its own (ds_fetch, kept inside the integrator's state so that reaching
 * it costs nothing); the rest of the integrator calls the functions below
 * and never reads the fields. Private to event/. */
#ifndef DS_EVENT_FETCH_H
#define DS_EVENT_FETCH_H

#include <stdint.h>

/* Disks named by the calendar ahead of their events (a power of two), and
 * the size of state from which that pays (event_driven.c). */
#define DS_FETCH_AHEAD_MASK 63u
#define DS_FETCH_AHEAD_BYTES (8u << 20)
/* Times the calendar keeps sorted ahead while fetching: the disks whose
 * buckets it has read are a few events ahead of their turn. */
#define DS_FETCH_LOOKAHEAD 16

typedef struct ds_fetch {
    /* Disks whose events come up soon (the calendar's drained times), in a
     * ring; each stage walks it with a cursor of its own. */
    uint32_t ahead[DS_FETCH_AHEAD_MASK + 1];
    uint32_t ahead_tag[DS_FETCH_AHEAD_MASK + 1]; /* the event count at its last stage */
    double ahead_until[DS_FETCH_AHEAD_MASK + 1]; /* its calendar entry's end of time */
    uint32_t tail, second, third;
    uint32_t events; /* events handled, mod 2^32 */
} ds_fetch;

struct ds_events;

/* The calendar's ds_eq_on_soon callback (ctx: the ds_events), and the
 * step run before each event. */
void ds_fetch_on_soon(void *ctx, uint32_t i, double until);
void ds_fetch_ahead(struct ds_events *e);

/* The partner note. A prediction keeps, beside the partner's change count
 * (which tells a stale collision from a current one), where the partner's
 * cell is from the disk's, for fetching the cells of both disks as one
 * block. Both share one 32-bit field of the disk's record: the count in
 * the low 28 bits, the cell in the top 4, (dx + 1) + 3 (dy + 1), or
 * unknown (across a periodic edge, or no partner). The count is compared
 * mod 2^28: a stale collision would be taken for current only if its
 * partner had changed course a multiple of 2^28 (2.7 x 10^8) times before
 * it came up, where a disk changes course a few times per mean free
 * time. */
#define DS_FETCH_CHANGES_MASK 0x0fffffffu
#define DS_FETCH_CELL_SHIFT 28
#define DS_FETCH_CELL_UNKNOWN 15u

/* The note of a partner with `changes` whose cell is (partner_column,
 * partner_row), the disk's being (column, row). Without a partner the
 * disk's own cell stands in (no branch on whether a collision won: a coin
 * toss), and the note's count is unused. */
static inline uint32_t ds_fetch_note(uint32_t changes, uint32_t column, uint32_t row,
                                     uint32_t partner_column, uint32_t partner_row)
{
    const uint32_t dx = partner_column - column + 1u, dy = partner_row - row + 1u;
    const uint32_t at = dx < 3u && dy < 3u ? dx + 3u * dy : DS_FETCH_CELL_UNKNOWN;
    return (changes & DS_FETCH_CHANGES_MASK) | at << DS_FETCH_CELL_SHIFT;
}

/* Whether a partner that has changed course `changes` times since it was
 * noted as `note` is still on the predicted course. */
static inline int ds_fetch_note_current(uint32_t note, uint32_t changes)
{
    return ((changes ^ note) & DS_FETCH_CHANGES_MASK) == 0;
}

/* Where the noted partner's cell is: (dx + 1) + 3 (dy + 1), or
 * DS_FETCH_CELL_UNKNOWN. */
static inline uint32_t ds_fetch_note_cell(uint32_t note) { return note >> DS_FETCH_CELL_SHIFT; }

#endif
