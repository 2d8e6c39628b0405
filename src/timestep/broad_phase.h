/* SPDX-License-Identifier: MIT */
/* The time step's broad phases: which pairs of disks overlap after a
 * move. Interchangeable behind broad_phase.c's dispatcher, all reporting
 * exactly the same pairs, each in an order of its own (SAP by x, strips
 * strip by strip, brute force by slot, the seam pass after a sweep). The
 * order matters only when a disk is in two overlapping pairs: otherwise
 * the pairs share no disk and their collisions commute to the bit
 * (docs/library.md, "What the broad phases share"):
 *
 * - DS_BROADPHASE_SAP (sap.c): the seed's sweep and prune along x, the slots kept in
 *   x order by insertion sort (insertion_sort.c);
 * - DS_BROADPHASE_STRIPS (strips.c): sweep and prune in horizontal strips;
 * - DS_BROADPHASE_BRUTE (brute_force.c): all pairs, the reference;
 * - in a periodic box the sweeps are followed by the seam pass (seam.c),
 *   which finds the pairs that touch across the box's edges.
 *
 * Private to timestep/ (and its tests). */
#ifndef DS_BROAD_PHASE_H
#define DS_BROAD_PHASE_H

#include "core/core.h"

/* The vector instructions DS_BROADPHASE_SAP's block scan and the insertion sort's
 * search for out-of-order disks use. All give the same result; the time
 * step picks the widest this CPU runs (ds_bp_widest_scan), and the tests
 * force each one the CPU has. */
typedef enum ds_scan {
    DS_SCAN_PORTABLE, /* SSE2 where the compiler targets it, plain C otherwise */
    DS_SCAN_AVX,
    DS_SCAN_AVX512
} ds_scan;

ds_scan ds_bp_widest_scan(void);

typedef struct ds_strips ds_strips;
typedef struct ds_seam ds_seam;

/* A broad phase and its state. */
typedef struct ds_bp {
    ds_broadphase kind; /* DS_BROADPHASE_SAP, DS_BROADPHASE_STRIPS or DS_BROADPHASE_BRUTE */
    ds_scan scan;
    double diameter; /* centres closer than this overlap */
    ds_box box;
    ds_strips *strips; /* DS_BROADPHASE_STRIPS only */
    ds_seam *seam;     /* a sweep in a periodic box only */
} ds_bp;

/* Called for each overlapping pair (centre distance < diameter) found,
 * with slots a != b. It may change velocities, never positions. */
typedef void (*ds_pair_fn)(ds_disks *d, size_t a, size_t b, void *ctx);

/* Sets up broad phase `kind` for world w over the placed disks d (which it
 * may reorder; slot[] is then stale until ds_disks_rebuild_slots). */
ds_status ds_bp_create(ds_bp *bp, ds_broadphase kind, const ds_world *w, ds_disks *d);
void ds_bp_destroy(ds_bp *bp);
/* A checkpoint's part of the broad phase (the strips' slots), and the
 * broad phase of a loaded state: the slots are as they were saved, so
 * nothing is sorted or laid out again. */
void ds_bp_save(const ds_bp *bp, ds_state_writer *w);
ds_status ds_bp_load(ds_bp *bp, const ds_world *w, ds_disks *d, ds_reader *r, ds_error *err);
/* Bytes broad phase w->broadphase allocates for world w. */
size_t ds_bp_bytes(const ds_world *w);

/* Brings the slots into the order the sweep needs, then reports every
 * overlapping pair exactly once, in the broad phase's own order. Returns
 * the number of narrow-phase tests. */
uint64_t ds_bp_find_pairs(ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx);

/* Insertion sort of slots [lo, hi) by x, all arrays moving together
 * (insertion_sort.c): nearly linear for the order of the step before. */
void ds_bp_insertion_sort(ds_disks *d, size_t lo, size_t hi, ds_scan scan);
/* The same order from any order (a new state): a stable merge sort,
 * O(n log n) where insertion sort could take O(n^2); without the memory
 * for it, the insertion sort. */
ds_status ds_bp_sort(ds_disks *d, ds_scan scan);

/* The parts behind the dispatcher. */
uint64_t ds_sap_find_pairs(const ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx);
uint64_t ds_brute_force_find_pairs(const ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx);

/* DS_BROADPHASE_STRIPS memory, at most, per disk: a second x, y, vx, vy, id (swapped
 * with the first after each merge), three lists of strip crossers, three
 * per-strip offset arrays (never more strips than disks). */
#define DS_STRIPS_BYTES_PER_DISK (DS_DISKS_MOVING_BYTES + 6 * sizeof(uint32_t))
ds_status ds_strips_create(ds_bp *bp, const ds_world *w, ds_disks *d);
void ds_strips_save(const ds_bp *bp, ds_state_writer *w);
ds_status ds_strips_load(ds_bp *bp, const ds_world *w, ds_disks *d, ds_reader *r, ds_error *err);
void ds_strips_destroy(ds_bp *bp);
uint64_t ds_strips_find_pairs(ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx);

ds_status ds_seam_create(ds_bp *bp, size_t n);
void ds_seam_destroy(ds_bp *bp);
uint64_t ds_seam_find_pairs(const ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx);
size_t ds_seam_bytes(size_t n);

#endif
