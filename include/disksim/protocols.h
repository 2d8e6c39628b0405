/* SPDX-License-Identifier: MIT */
/*
 * disksim: protocols, what acts on a running simulation from outside its
 * dynamics: growth (Lubachevsky-Stillinger compression), driving
 * (white-noise kicks), a thermostat (a heat bath: the canonical ensemble)
 * and a barostat (moves of the box: the isobaric ensemble). Each is set on
 * a simulation, acts as ds_sim_run goes, and is carried by checkpoints.
 * Included by disk_sim.h.
 */
#ifndef DISKSIM_PROTOCOLS_H
#define DISKSIM_PROTOCOLS_H

#include "disksim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* Growth                                                              */
/* ------------------------------------------------------------------ */

/* Growth (Lubachevsky-Stillinger compression), event-driven integrator in
 * a periodic box only (DS_ERR_ARG otherwise, err naming "integrator" or
 * "boundary"): from now on every radius grows in proportion to itself,
 * r(t) = r(now) (1 + rate (t - now)), so the ratios of a mixture stay,
 * until the area fraction reaches until_eta (0: no target), at that exact
 * time, or the reduced pressure Z (watched over windows of 2 n
 * collisions, with the temperature of the internal motion, K_int / (N -
 * 1)) passes until_z (0 means DS_JAMMED_Z; at most 1e9), whichever comes
 * first; rate 0 stops it. Past Z = 10^4 the growth slows as 10^4 / Z, so
 * the disks can rearrange near jamming (docs/physics.md). A collision
 * reflects the pair's normal velocity in the frame of their receding
 * surfaces, which adds energy: at the end of each window, and when the
 * growth stops, every velocity is scaled back to the kinetic energy of the
 * call. The masses stay. ds_sim_set_disks stops growth; so does a call
 * with other targets, which starts again from now.
 *
 * DS_ERR_ARG for a rate < 0 or not finite, a rate at which the largest
 * pair's surfaces would recede faster than 10 rms speeds (2 r_max rate >
 * 10 sqrt(2 K / M), M the total mass; so any rate > 0 with every disk at
 * rest), until_eta not 0 and not between the area fraction of now and 1,
 * until_z not 0 and not in (1, 1e9]; err names the argument ("rate",
 * "until_eta", "until_z"), its value and the limit it broke. The step in
 * which growth stops at Z is finished without it: near jamming that step
 * has many collisions (about 4 (Z - 1) sqrt(kT / (pi m)) / sigma per disk
 * per unit time). DS_ERR_NOMEM, nothing changed, without memory for the
 * growing radii. */
#define DS_JAMMED_Z 1e6
ds_status ds_sim_set_growth(ds_sim *sim, double rate, double until_eta, double until_z,
                            ds_error *err);

typedef enum ds_growth_state {
    /* "none": never grown, stopped with rate 0, ended by ds_sim_set_disks,
     * or stopped at a step's end for want of memory for the wider cells
     * it needed there (ds_sim_run then returns DS_ERR_NOMEM, see there). */
    DS_GROWTH_NONE = 0,
    DS_GROWTH_GROWING,     /* "growing" */
    DS_GROWTH_REACHED_ETA, /* "reached_eta": stopped at until_eta */
    DS_GROWTH_JAMMED,      /* "jammed": stopped when Z passed until_z */
    DS_GROWTH_STATE_COUNT
} ds_growth_state;
const char *ds_growth_state_name(ds_growth_state state); /* "none", "growing", ... */
ds_status ds_growth_state_parse(const char *name, ds_growth_state *out, ds_error *err);

ds_growth_state ds_sim_get_growth_state(const ds_sim *sim);
/* The reduced pressure Z growth measured over its last window of 2 n
 * collisions (when it jammed, the window that stopped it); 0 before its
 * first window, and for a simulation that never grew. */
double ds_sim_get_growth_z(const ds_sim *sim);

/* ------------------------------------------------------------------ */
/* Driving                                                             */
/* ------------------------------------------------------------------ */

/* White-noise driving (random kicks; van Noije and Ernst 1998), which
 * holds a granular gas (ds_sim_set_restitution) in a steady state: from
 * now on, at the end of every step, each velocity component of every
 * disk changes by a Gaussian number of variance strength dt, the kicks'
 * mass-weighted mean taken out so that the total momentum stays. The
 * velocities diffuse at S = strength (box units^2 per time^3), and energy
 * goes in at sum over the disks of m_i S (1 - m_i / M) per unit time, (N
 * - 1) m S for N equal masses (ds_sim_get_power_input). The kicks are the
 * noise integrated over a step (Euler-Maruyama): dt must be short beside
 * the mean free time for them to be white noise (docs/physics.md). Both
 * integrators. The numbers come from a stream of the simulation's seed
 * of the drive's own (no number of the placement's), drawn in generation
 * order; checkpoints carry the stream, so a loaded run kicks as the saved
 * one would have; set again, the strength changes and the stream goes
 * on. 0 stops the drive.
 *
 * DS_ERR_ARG (field "strength", value and limit) for a strength < 0, not
 * finite or above DS_DRIVE_MAX, or while a growth grows (err naming
 * "growth": growth takes out the heat its collisions add, and would take
 * the drive's), or (field "integrator") with event chains, which take no
 * kicks; DS_ERR_NOMEM, nothing changed, without memory for the kicks (16
 * bytes a disk twice). */
#define DS_DRIVE_MAX 1e24
ds_status ds_sim_set_drive(ds_sim *sim, double strength, ds_error *err);
double ds_sim_get_drive(const ds_sim *sim); /* the strength; 0 without a drive or for NULL */

/* ------------------------------------------------------------------ */
/* Thermostat: the canonical ensemble (NVT)                            */
/* ------------------------------------------------------------------ */

/* Temperature is an energy, kT, in the units of params.h (mass length^2
 * / time^2): in two dimensions a disk of mass m has mean kinetic energy
 * kT, m <v^2> / 2 = kT, so disks of mass 1 all at speed v (random
 * placement's start) have kT = v^2 / 2: the default speed 100 is kT =
 * 5000. */
typedef enum ds_thermostat {
    /* "none": no heat bath: molecular dynamics at constant energy. */
    DS_THERMOSTAT_NONE = 0,
    /* "andersen": Andersen's stochastic collisions with a heat bath: each
     * disk, at the times of a Poisson process of rate collision_rate,
     * gets a velocity drawn afresh from Maxwell-Boltzmann at kT with its
     * own mass (each component normal with variance kT / m), from the
     * simulation's seed. The event-driven integrator redraws at the exact
     * times, the time step at the end of the step each falls in (a step
     * sees velocities only at its boundaries: the same law as a redraw at
     * each step's end with probability 1 - exp(-collision_rate dt)).
     * Exact canonical sampling: the kinetic energy is Gamma(n, kT)
     * distributed in any box (the momentum is not conserved). */
    DS_THERMOSTAT_ANDERSEN,
    /* "isokinetic": at the end of every step every velocity is scaled so
     * that the kinetic temperature (ds_sim_get_temperature's rule, from
     * the velocities) is kT; a run that nothing heats (elastic collisions
     * keep the energy) is scaled at the first step's end, then only when
     * rounding has moved it by 1e-12. For driven systems; not a canonical
     * ensemble of velocities. */
    DS_THERMOSTAT_ISOKINETIC,
    DS_THERMOSTAT_COUNT
} ds_thermostat;
const char *ds_thermostat_name(ds_thermostat kind); /* "none", "andersen", "isokinetic" */
ds_status ds_thermostat_parse(const char *name, ds_thermostat *out, ds_error *err);

/* A heat bath of that kind at temperature kt from now on (until set
 * again), for any integrator that has velocities, in any box; kind
 * DS_THERMOSTAT_NONE removes it. kt 0 means the temperature of now
 * (ds_sim_get_temperature, the bath's if one is set). collision_rate is
 * Andersen's, collisions with the bath per disk per unit time; 0 means
 * 0.1 sqrt(kT) / sigma (sigma the largest diameter: a disk of mass 1
 * meets the bath about once in the time it crosses ten diameters at its
 * thermal speed); the isokinetic thermostat takes none (0). While a heat
 * bath is set, ds_sim_get_temperature is its kT, and the virial pressure
 * and Z take it (the canonical ones: for two disks in a periodic box Z =
 * (1 + A / (A - pi sigma^2)) / 2 exactly). Set again, the bath goes on
 * with the same stream of random numbers: a run is the same to the bit
 * however it is cut into calls and checkpoints.
 *
 * DS_ERR_ARG (err naming the argument, its value and its limit) for sim
 * NULL, a kind that is no ds_thermostat, an integrator without
 * velocities (field "integrator"), a growth that is growing (field
 * "thermostat": growth takes its own heat out), kt < 0 or not finite, kt
 * 0 with the disks at rest, a kt at which a disk could pass
 * DS_VELOCITY_MAX (Andersen's draws reach 8.58 sqrt(kT / m), the
 * isokinetic's a disk holding the whole energy, sqrt(2 n kT / m)),
 * collision_rate < 0 or not finite, or not 0 for the isokinetic kind.
 * DS_ERR_NOMEM, nothing changed. */
ds_status ds_sim_set_thermostat(ds_sim *sim, ds_thermostat kind, double kt, double collision_rate,
                                ds_error *err);
/* The kind set (DS_THERMOSTAT_NONE without, and for sim NULL) and its kT
 * (0 without). */
ds_thermostat ds_sim_get_thermostat(const ds_sim *sim);
double ds_sim_get_thermostat_temperature(const ds_sim *sim);

/* ------------------------------------------------------------------ */
/* Barostat: the isobaric ensemble (NPT)                               */
/* ------------------------------------------------------------------ */

/* The limits of ds_sim_set_barostat's pressure and max_step. */
#define DS_BAROSTAT_MAX_PRESSURE 1e9
#define DS_BAROSTAT_MAX_STEP 1.0

/* Monte Carlo moves of the box at reduced pressure pressure = beta P
 * sigma^2 (sigma the largest diameter, Engel et al. 2013: the hexatic
 * phase of one kind of disk lies near 9.2), in a periodic box only, from
 * now on; pressure 0 removes it. At the end of every step whose count is
 * a multiple of every (0 means 10) the area makes a random-walk move, ln
 * A by d uniform in [-max_step, max_step] (0 means 1 / (4 n), at most
 * DS_BAROSTAT_MAX_STEP), both sides scaled by exp(d / 2) and every centre
 * with them (velocities and image counts kept), accepted with probability
 * min(1, exp(-beta P (A' - A) + (n + 1) d)) unless a pair would come
 * closer than contact (or the largest disk would pass a quarter of a
 * side, or a side 1e9); with aspect nonzero it then moves the aspect too,
 * ln(width / height) by a d of the same law at fixed area, accepted
 * unless a pair would overlap (for a crystal, whose box must find its own
 * shape: a fluid's box has nothing to hold its aspect and drifts until a
 * side is four times the largest radius). An ideal gas's area is then
 * Gamma(n + 1, 1 / (beta P)) distributed: <A> = (n + 1) / (beta P), and
 * the mean area fraction is the canonical one at the same pressure.
 * Temperature does not enter (hard disks have no potential energy), so
 * it samples the isobaric ensemble with any integrator, with a heat
 * bath or without. The time step's disks overlap a little at a step's
 * end (it sees each collision after it happens): a move is refused for a
 * pair it brings closer than contact that was not, which leaves the time
 * step's own O(dt) error. The event-driven integrator builds its state
 * again for each move accepted (O(n)), the time step its broad phase.
 * The box's sides (ds_sim_get_box_width, _height) and the area fraction
 * follow the moves; frames do not carry the box (extended XYZ's Lattice
 * does). Set again, the moves go on with the same stream of random
 * numbers (the simulation's seed), and the acceptance counts afresh.
 *
 * DS_ERR_ARG (err naming the argument, its value and its limit) for sim
 * NULL, a box that is not periodic (field "boundary"), an integrator
 * that cannot rescale its box (field "integrator"), a growth that is
 * growing (field "pressure"), pressure < 0, not finite or above
 * DS_BAROSTAT_MAX_PRESSURE, max_step < 0, not finite or above
 * DS_BAROSTAT_MAX_STEP. DS_ERR_NOMEM, nothing changed; ds_sim_run returns
 * DS_ERR_NOMEM at the end of a step whose move found no memory for its
 * new state (the move not made, the run stopped there). */
ds_status ds_sim_set_barostat(ds_sim *sim, double pressure, uint64_t every, double max_step,
                              int aspect, ds_error *err);
/* The reduced pressure set (0 without a barostat, and for sim NULL), and
 * the fraction of its area moves accepted since it was set (0 before the
 * first): about a third to a half is a good step. */
double ds_sim_get_barostat_pressure(const ds_sim *sim);
double ds_sim_get_barostat_acceptance(const ds_sim *sim);

/* ------------------------------------------------------------------ */
/* Shear: Lees-Edwards boundaries                                       */
/* ------------------------------------------------------------------ */

/* The largest strain a shear may put in per step, |rate| dt: a heat bath
 * acts at the ends of steps, and the profile must not run away between
 * them. */
#define DS_SHEAR_MAX_STRAIN_PER_STEP 1.0

/* Shears the box at rate = dv_x / dy (per unit time; negative shears the
 * other way) from now on, with Lees and Edwards' boundaries (1972): the
 * box periodic along both axes, the images above moving at +rate H
 * along x (H the height), those below at -rate H. A disk that leaves
 * through the top comes in at the bottom shifted by the images' offset
 * (ds_sim_get_shear_shift) and rate H slower along x (and the reverse);
 * pairs across the top or bottom meet as their images do. The disks take
 * the profile's velocity, rate (y - H / 2) along x, added to theirs (set
 * again, the change of it), so that the flow starts from its steady
 * profile. Rate 0 stops the images where they stand. The viscous heat
 * the shear puts in is for a thermostat to take out: the isokinetic one
 * (ds_sim_set_thermostat) then scales the peculiar velocities, the
 * velocity less the profile's, which are also what ds_sim_get_temperature
 * and the kinetic part of the pressure tensor's xy component
 * (ds_sim_get_stress_integral) take; its xx component keeps the
 * velocities as they are. In the shear flow's steady state the
 * viscosity is -P_xy / rate.
 *
 * Image counts under shear: the unwrapped centre of a disk is (x + ix W +
 * iy ds_sim_get_shear_offset, y + iy H), continuous in time (W the
 * width).
 *
 * Event-driven integrator only. DS_ERR_ARG (err naming the argument, its
 * value and its limit) for sim NULL, rate not finite, |rate| dt above
 * DS_SHEAR_MAX_STRAIN_PER_STEP or |rate| H above DS_VELOCITY_MAX / 4 (a
 * disk crossing would outrun the speed limit), a box not periodic along
 * both axes (field "boundary"), an integrator that cannot shear (field
 * "integrator"), Andersen's heat bath (field "thermostat": its draws
 * know no profile; use the isokinetic one), a barostat (field
 * "barostat") or a growth that is growing (field "growth"); a field
 * cannot be, as it needs walls across it (ds_sim_set_gravity).
 * DS_ERR_NOMEM, nothing changed. */
ds_status ds_sim_set_shear(ds_sim *sim, double rate, ds_error *err);
/* The rate set (0 without a shear, and for sim NULL). */
double ds_sim_get_shear(const ds_sim *sim);
/* The images' offset along x at the present time: the image above
 * stands shift along (in [0, W)), the one below -shift; offset is the
 * same unwrapped (shift plus whole widths), for the image counts. 0
 * without shear. */
double ds_sim_get_shear_shift(const ds_sim *sim);
double ds_sim_get_shear_offset(const ds_sim *sim);

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_PROTOCOLS_H */
