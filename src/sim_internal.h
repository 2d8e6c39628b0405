/* The simulation state and the internal interfaces between its parts.
 * Not installed: nothing here is part of the public API. */
#ifndef DS_SIM_INTERNAL_H
#define DS_SIM_INTERNAL_H

#include "disk_sim.h"

/* The vector instructions DS_SAP's block scan and the insertion sort's
 * search for out-of-order disks use. All give the same result; ds_create
 * picks the widest this CPU runs (ds_bp_widest_scan), and the tests force
 * each one the CPU has. */
typedef enum ds_scan {
    DS_SCAN_PORTABLE, /* SSE2 where the compiler targets it, plain C otherwise */
    DS_SCAN_AVX,
    DS_SCAN_AVX512
} ds_scan;

ds_scan ds_bp_widest_scan(void);

/* Structure of arrays, stored physically in broad-phase order (x order for
 * DS_SAP) so that the sweep reads memory front to back. id[k] is the
 * generation index of the disk in slot k; slot[i] is its inverse, valid
 * between API calls (rebuilt at the end of ds_run). Every array has one
 * element past n: DS_SAP keeps x[n] = +infinity there as a sweep sentinel. */
struct ds_sim {
    size_t n;
    double radius, box, speed, dt;
    double box_y; /* height; box is the width */
    ds_integrator integrator;
    ds_boundary boundary;
    ds_broadphase broadphase; /* resolved, never DS_AUTO */
    ds_scan scan;             /* vector instructions to use, the widest the CPU has */

    double *x, *y, *vx, *vy;
    uint32_t *id;
    uint32_t *slot;

    /* DS_SAP_STRIPS state, NULL otherwise (see broad_phase_strips.c). */
    struct ds_strips *strips;
    /* Periodic box with a sweep: the seam pass's scratch (broad_phase_seam.c). */
    struct ds_seam *seam;
    /* DS_EVENT_DRIVEN state, NULL otherwise (see event_driven.c). With it,
     * x, y, vx, vy show the disks at ds_time, refreshed after each run. */
    struct ds_events *events;

    uint64_t steps;
    ds_timer collision_timer;
    uint64_t collisions;
    uint64_t pairs_tested;

    uint64_t wall_count;
    double wall_impulse;
    double virial;                   /* sum over collisions of r_ij . dp_i since the reset */
    uint64_t observables_since_step; /* step count at the last reset */

    char radius_text[32]; /* R as written in frames, shortest round trip */
};

/* Called for each overlapping pair (centre distance < 2R) the broad phase
 * finds, with physical indices a != b. */
typedef void (*ds_pair_fn)(ds_sim *sim, size_t a, size_t b, void *ctx);

/* Broad phase: brings the arrays into the order the sweep needs (may permute
 * slots; slot[] is then stale until ds_rebuild_slots), then reports every
 * overlapping pair exactly once. Returns the number of narrow-phase tests. */
uint64_t ds_bp_find_pairs(ds_sim *sim, ds_pair_fn on_pair, void *ctx);

/* Sorts slots 0..n-1 by x with insertion sort (all arrays move together). */
void ds_bp_insertion_sort_x(ds_sim *sim);
/* The same for slots [lo, hi) only (one strip of DS_SAP_STRIPS). */
void ds_bp_insertion_sort_range(ds_sim *sim, size_t lo, size_t hi);

/* DS_SAP_STRIPS memory on top of the simulation's arrays, at most: a
 * second x, y, vx, vy, id (swapped with the first after each merge), three
 * lists of strip crossers, three per-strip offset arrays (never more strips
 * than disks). */
#define DS_STRIPS_BYTES_PER_DISK (4 * sizeof(double) + sizeof(uint32_t) + 6 * sizeof(uint32_t))

/* DS_SAP_STRIPS lifecycle (broad_phase_strips.c). */
ds_status ds_strips_create(ds_sim *sim);
void ds_strips_destroy(ds_sim *sim);
uint64_t ds_strips_find_pairs(ds_sim *sim, ds_pair_fn on_pair, void *ctx);

/* The pairs across the seams of a periodic box that the sweeps, which see
 * the box as the coordinates stand, miss (broad_phase_seam.c). */
typedef struct ds_seam ds_seam;
ds_status ds_seam_create(ds_sim *sim);
void ds_seam_destroy(ds_sim *sim);
uint64_t ds_seam_find_pairs(ds_sim *sim, ds_pair_fn on_pair, void *ctx);
size_t ds_seam_bytes(size_t n);

/* The integrators' loops: ds_run dispatches to one of them. */
void ds_ts_run(ds_sim *sim, uint64_t steps); /* time_step.c */
void ds_ed_run(ds_sim *sim, uint64_t steps); /* event_driven.c */

/* DS_EVENT_DRIVEN lifecycle (event_driven.c). ds_ed_create takes the
 * placed disks from x, y, vx, vy (it may reorder the slots). ds_ed_set
 * replaces the disk in slot k, or refuses an overlap. */
ds_status ds_ed_create(ds_sim *sim);
void ds_ed_destroy(ds_sim *sim);
ds_status ds_ed_set(ds_sim *sim, size_t k, ds_disk d);
/* Bytes the event-driven state of params would allocate. */
size_t ds_ed_bytes(size_t n, double radius, double box_x, double box_y, ds_broadphase bp);

/* Collision response (collision.c): the pair callbacks for walls and for
 * a periodic box (separation to the nearest image), and free flight with
 * wall reflection or with the periodic wrap. */
void ds_resolve_pair(ds_sim *sim, size_t a, size_t b, void *ctx);
void ds_resolve_pair_periodic(ds_sim *sim, size_t a, size_t b, void *ctx);
void ds_move_and_reflect(ds_sim *sim);
void ds_move_and_wrap(ds_sim *sim);

/* Placement: fills x, y, vx, vy in generation order. Random sequential
 * (placement.c) or a triangular lattice (placement_lattice.c), which
 * fits when its closest sites are at least 2R apart. */
ds_status ds_place_disks(ds_sim *sim, uint64_t seed);
ds_status ds_place_lattice(ds_sim *sim, uint64_t seed);
int ds_lattice_fits(size_t n, double radius, double box_x, double box_y, int periodic);

void ds_rebuild_slots(ds_sim *sim);

/* Text output (frame_io.c): formats the state with format into a buffer of
 * cap bytes and writes it to out, flushed and checked; the frame writers
 * and the trajectory writer share it. */
typedef ds_status (*ds_format_fn)(const ds_sim *sim, int velocities, char *buf, size_t cap,
                                  size_t *len);
ds_status ds_write_formatted(const ds_sim *sim, int velocities, FILE *out, size_t cap,
                             ds_format_fn format);

#define DS_TWO_PI 6.28318530717958647692

#endif
