/* SPDX-License-Identifier: MIT */
/*
 * disksim: a simulation. Creating it, running it, what it is and where
 * its disks are, and changing them. Included by disk_sim.h.
 */
#ifndef DISKSIM_SIM_H
#define DISKSIM_SIM_H

#include "disksim/params.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ds_sim ds_sim; /* opaque; one thread at a time */

/* One disk's centre and velocity. */
typedef struct ds_disk {
    double x, y, vx, vy;
} ds_disk;

/* ------------------------------------------------------------------ */
/* Creating and running                                                */
/* ------------------------------------------------------------------ */

/* Checks the request as ds_params_check does, allocates and places the
 * disks (mixture may be NULL: disks of one kind). On DS_OK *out owns the
 * simulation; on failure *out is NULL and err says why: a refusal of the
 * request, DS_ERR_PLACEMENT if random placement found no free spot for a
 * disk, DS_ERR_NOMEM. */
ds_status ds_sim_create(const ds_params *params, const ds_mixture *mixture, ds_sim **out,
                        ds_error *err);
void ds_sim_destroy(ds_sim *sim); /* NULL is allowed */

/* Advances simulated time by steps dt (ds_sim_step: by exactly dt). The
 * time step: move by v dt, reflect at walls, resolve overlapping pairs.
 * The event-driven integrator: every collision and wall turn inside the
 * interval in time order, then every disk shown at exactly the new time.
 * A growth set on the simulation (ds_sim_set_growth) acts as the run
 * goes. The disks do not depend on how a run is cut into calls: k steps
 * in one call, k calls of one step, or a run stopped, checkpointed and
 * loaded at any step, give the same disks to the bit. steps 0 is DS_OK
 * and does nothing.
 *
 * DS_ERR_NOMEM if the run needed memory to go on: growth, at the end of a
 * step after which its disks outgrow the event-driven integrator's cells,
 * builds wider ones, and without memory for them it stops there (its heat
 * taken out as at any stop, ds_sim_get_growth_state then DS_GROWTH_NONE)
 * and so does the run. The simulation is then as it stood at the end of
 * that step, whole (ds_sim_get_steps says which), and can be run on (at
 * the radii of then), saved or destroyed. DS_ERR_ARG for sim NULL. */
ds_status ds_sim_run(ds_sim *sim, uint64_t steps, ds_error *err);
ds_status ds_sim_step(ds_sim *sim, ds_error *err);

/* ------------------------------------------------------------------ */
/* What it is                                                          */
/* ------------------------------------------------------------------ */

/* Each returns 0 (or the enumeration's 0) for sim NULL. */
size_t ds_sim_get_count(const ds_sim *sim);         /* number of disks */
double ds_sim_get_radius(const ds_sim *sim);        /* ds_params.radius (a mixture's reference R) */
double ds_sim_get_radius_max(const ds_sim *sim);    /* the largest radius now */
double ds_sim_get_box_width(const ds_sim *sim);     /* along x */
double ds_sim_get_box_height(const ds_sim *sim);    /* along y (box_y, or box when square) */
double ds_sim_get_area_fraction(const ds_sim *sim); /* sum of pi r^2 over box box_y */
double ds_sim_get_dt(const ds_sim *sim);
double ds_sim_get_time(const ds_sim *sim);    /* simulated time = steps * dt */
uint64_t ds_sim_get_steps(const ds_sim *sim); /* steps taken since creation */
uint64_t ds_sim_get_seed(const ds_sim *sim);  /* ds_params.seed */
ds_integrator ds_sim_get_integrator(const ds_sim *sim);
ds_boundary ds_sim_get_boundary(const ds_sim *sim);
ds_placement ds_sim_get_placement(const ds_sim *sim);   /* how the disks were placed */
ds_broadphase ds_sim_get_broadphase(const ds_sim *sim); /* never DS_BROADPHASE_AUTO */

/* The seed's timing measure, summed over all steps. The time step:
 * seconds spent sorting, pruning, testing and resolving disk-disk pairs.
 * The event-driven integrator: seconds spent processing events
 * (collisions, wall turns, cell crossings and their predictions), not
 * showing the disks at ds_sim_get_time afterwards. */
double ds_sim_get_collision_seconds(const ds_sim *sim);
uint64_t ds_sim_get_collision_count(const ds_sim *sim); /* disk-disk collisions resolved */
uint64_t ds_sim_get_pairs_tested(const ds_sim *sim);    /* narrow-phase distance tests */

/* ------------------------------------------------------------------ */
/* The disks                                                           */
/* ------------------------------------------------------------------ */

/* Disk i, in generation order (i < n; out of range gives all zeros). */
ds_disk ds_sim_get_disk(const ds_sim *sim, size_t i);
/* Every disk at once: out[i] = disk i for i < ds_sim_get_count(sim).
 * DS_ERR_ARG if sim or out is NULL. The arrays below work alike: each
 * holds ds_sim_get_count(sim) entries (two per disk for images and
 * unwrapped centres), in generation order, whatever order the integrator
 * keeps internally. */
ds_status ds_sim_get_disks(const ds_sim *sim, ds_disk *out, ds_error *err);
/* Each disk's radius and mass (disks of one kind: ds_params.radius and
 * 1; a growth's radii as grown by now). */
ds_status ds_sim_get_radii(const ds_sim *sim, double *radii, ds_error *err);
ds_status ds_sim_get_masses(const ds_sim *sim, double *masses, ds_error *err);
/* Each disk's kind: its species' index in the mixture (0 without
 * species). ds_sim_get_kind_count says how many kinds there are (1
 * without species) and ds_sim_get_kind_name the name of kind k (the
 * species' name, or "A", "B", ...; NULL for k out of range or sim NULL). */
ds_status ds_sim_get_kinds(const ds_sim *sim, uint32_t *kinds, ds_error *err);
size_t ds_sim_get_kind_count(const ds_sim *sim);
const char *ds_sim_get_kind_name(const ds_sim *sim, size_t k);
/* Periodic images: image[2 i] and image[2 i + 1] are how many times disk
 * i has crossed the box along x and along y since it was placed (+1 each
 * time it leaves through the far edge, -1 through 0), so that its
 * unwrapped centre is x + image[2 i] box, y + image[2 i + 1] box_y
 * (LAMMPS' ix iy, OVITO's periodic image); all 0 with walls.
 * ds_sim_set_disk keeps the disk's counts, ds_sim_set_disks sets them all
 * to 0 (a new state starts in the box), checkpoints carry them. The
 * counts wrap past 2^31 crossings. */
ds_status ds_sim_get_images(const ds_sim *sim, int32_t *image, ds_error *err);
/* Unwrapped centres: xy[2 i], xy[2 i + 1] = x + ix box, y + iy box_y
 * (ds_sim_get_images), each one rounding of the sum from the exact image
 * sum; with walls the centres themselves; in a sheared box x + ix box +
 * iy ds_sim_get_shear_offset (protocols.h). A free disk's unwrapped centre
 * is x0 + v t up to the rounding of its flight: within (s + 2) eps (box +
 * |x0 + v t|) after s steps of the time step or s events of the
 * event-driven integrator (eps = DBL_EPSILON). */
ds_status ds_sim_get_unwrapped(const ds_sim *sim, double *xy, ds_error *err);

/* Two centres closer than (r_i + r_j)(1 - DS_CONTACT_TOLERANCE) overlap;
 * closer than r_i + r_j by less is contact, up to the rounding of the
 * coordinates. */
#define DS_CONTACT_TOLERANCE 1e-9
/* The fastest velocity component a disk may have (ds_sim_set_disk,
 * ds_sim_set_disks, ds_sim_scale_velocities, checkpoints): faster, an
 * event-driven step might never end. */
#define DS_VELOCITY_MAX 1e12

/* Replaces disk i at ds_sim_get_time. DS_ERR_ARG (field "disk", index i)
 * if i >= n, a value is not finite, a velocity component exceeds
 * DS_VELOCITY_MAX in magnitude (value and limit in err), or the centre is
 * outside the box: [r, box - r] x [r, box_y - r] with walls, r the disk's
 * own radius (ds_sim_get_radii: R with one kind of disk, each disk's own
 * in a mixture), [0, box) x [0, box_y) in a periodic box. The time step
 * does not check overlaps (its next step resolves them); the event-driven
 * integrator refuses a centre that overlaps another (see
 * DS_CONTACT_TOLERANCE) with DS_ERR_OVERLAP, the state unchanged: exact
 * dynamics has no meaning for overlapping hard disks. Moving many disks
 * one by one can fail where the new state is fine (a disk's new place
 * overlaps a disk not yet moved): use ds_sim_set_disks. The disk's
 * periodic image counts stay (ds_sim_get_images). */
ds_status ds_sim_set_disk(ds_sim *sim, size_t i, ds_disk d, ds_error *err);

/* Replaces every disk at once: disks[i] becomes disk i, for i below
 * ds_sim_get_count(sim). The whole new state is checked before anything
 * changes: DS_ERR_ARG for a disk ds_sim_set_disk would refuse as a value
 * (or sim or disks NULL), DS_ERR_OVERLAP if two disks overlap (see
 * DS_CONTACT_TOLERANCE; with either integrator: this is a state to start
 * from); err says which disk (index) and why. On DS_OK the integrator
 * starts afresh from the new state (the event-driven one predicts every
 * event again); the time, the step count and the observables'
 * accumulators go on; the periodic image counts start again at 0 (the new
 * centres are in the box, so ds_sim_get_unwrapped starts from them). A
 * growth (ds_sim_set_growth) ends: the radii stay as grown by now,
 * ds_sim_get_growth_state says DS_GROWTH_NONE and ds_sim_get_growth_z 0
 * (a growth that had reached its target or jammed is forgotten too), and
 * the velocities are the ones given, not scaled back as the end of a
 * growth otherwise scales them. */
ds_status ds_sim_set_disks(ds_sim *sim, const ds_disk *disks, ds_error *err);

/* Every velocity times factor, at ds_sim_get_time: a thermostat's step,
 * or a compression taking out its heat. DS_ERR_ARG, changing nothing, for
 * a factor not > 0 and finite, or one that takes a velocity component
 * past DS_VELOCITY_MAX (err gives the factor and the largest it may be). */
ds_status ds_sim_scale_velocities(ds_sim *sim, double factor, ds_error *err);

/* ------------------------------------------------------------------ */
/* Granular rules: restitution, the TC model, a field                  */
/* ------------------------------------------------------------------ */

/* The coefficients of normal restitution of disk-disk collisions (disks)
 * and of wall turns (walls), each in (0, 1], from ds_sim_get_time on;
 * both 1 (elastic) when a simulation is created. A pair of masses m_i,
 * m_j colliding with relative normal velocity u = (v_j - v_i) . n < 0 (n
 * from i to j) leaves with -e u: v_i changes by (1 + e) m_j / (m_i + m_j)
 * u n and v_j by the opposite momentum, and the kinetic energy falls by
 * (1 - e^2) m_i m_j / (m_i + m_j) u^2 / 2. A wall turns a disk's normal
 * velocity v_n into -e v_n, taking (1 - e^2) m v_n^2 / 2 and receiving
 * (1 + e) m |v_n| of momentum (ds_sim_get_wall_impulse). e = 1 is the
 * elastic collision to the bit. The energy taken is in
 * ds_sim_get_energy_lost.
 *
 * With e < 1 the event-driven integrator follows the TC model (Luding
 * and McNamara 1998): a collision of a disk with a disk or a wall within
 * the contact time (ds_sim_set_contact_time) after that disk's previous
 * collision is elastic, so a run can never take infinitely many
 * collisions in a finite time (the inelastic collapse) and every step
 * ends (docs/physics.md says what the model changes). The time step
 * applies e to every collision: it resolves a pair once a step at most
 * and cannot collapse. A growth's collisions are its own (elastic in
 * the frame of the receding surfaces).
 *
 * DS_ERR_ARG (err naming "restitution" or "wall_restitution", the value
 * and the limit) for a coefficient not in (0, 1], or for e < 1 while a
 * growth grows (ds_sim_set_growth), or (field "integrator") for e < 1
 * with event chains, which have no dynamics; DS_ERR_NOMEM, nothing changed,
 * without memory for each disk's time of last collision (the
 * event-driven integrator's, 8 bytes a disk). */
ds_status ds_sim_set_restitution(ds_sim *sim, double disks, double walls, ds_error *err);
double ds_sim_get_restitution(const ds_sim *sim);      /* disk-disk; 1 for NULL */
double ds_sim_get_wall_restitution(const ds_sim *sim); /* disk-wall; 1 for NULL */

/* The TC model's contact time t_c, in simulated time (> 0 and finite, or
 * 0 for the default): DS_CONTACT_TIME_DEFAULT times 2 R / speed, the time
 * a disk of ds_params.radius takes to cross its diameter at the initial
 * speed. A disk resting on a wall under a field (ds_sim_set_gravity)
 * bounces about once per t_c, so a bed of such disks costs about n / t_c
 * events per unit time. DS_ERR_ARG (field "contact_time") for another
 * value. */
#define DS_CONTACT_TIME_DEFAULT 1e-4
ds_status ds_sim_set_contact_time(ds_sim *sim, double contact_time, ds_error *err);
double ds_sim_get_contact_time(const ds_sim *sim); /* as resolved; 0 for NULL */

/* A uniform field: from ds_sim_get_time on every disk accelerates by (gx,
 * gy) (box units per time squared; gravity of magnitude g is (0, -g)),
 * and has the potential energy -m (gx x + gy y) (ds_sim_get_potential_energy).
 * The event-driven integrator flies parabolas: pairs collide at the times
 * of their straight relative motion (both fall alike), walls and its
 * cells' edges are met at the roots of quadratics; the kinetic plus the
 * potential energy of an elastic run is conserved to rounding. The time
 * step adds g dt to every velocity at the start of each step. A disk
 * that a field presses against a wall is sent off no slower than g_n t_c
 * / 2 (the speed of a flight lasting the contact time: a disk resting on
 * the floor, which hard disks cannot hold still, hops once per t_c at
 * most). DS_ERR_ARG (field "gx" or "gy") for a component not finite, of
 * magnitude beyond DS_GRAVITY_MAX, or other than 0 along a periodic axis
 * (the disks would fall for ever), or (field "integrator") for a field
 * with event chains, which have no dynamics; (0, 0) turns the field off. */
#define DS_GRAVITY_MAX 1e12
ds_status ds_sim_set_gravity(ds_sim *sim, double gx, double gy, ds_error *err);
void ds_sim_get_gravity(const ds_sim *sim, double *gx, double *gy); /* (0, 0) for NULL */

/* ------------------------------------------------------------------ */
/* A caller's notes                                                     */
/* ------------------------------------------------------------------ */

/* A text the caller keeps with the simulation, which checkpoints carry
 * and give back on load (the disks command records its run's settings
 * there, so that --restart goes on with them): up to DS_METADATA_MAX
 * bytes, copied. "" (or NULL) clears it. DS_ERR_ARG, changing nothing,
 * for a longer text; DS_ERR_NOMEM without memory for the copy. The
 * library does not read it. */
#define DS_METADATA_MAX 65536
ds_status ds_sim_set_metadata(ds_sim *sim, const char *text, ds_error *err);
/* The text, "" if none was set (NULL for sim NULL); valid until the next
 * ds_sim_set_metadata or ds_sim_destroy. */
const char *ds_sim_get_metadata(const ds_sim *sim);

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_SIM_H */
