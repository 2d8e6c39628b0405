/* SPDX-License-Identifier: MIT */
/*
 * disksim: what a simulation measures of itself. Energy, momentum,
 * pressures and temperature, the pressure tensor's integral, order
 * (psi6), pair counts for g(r), contacts of a packing, and transport
 * (mean-squared displacement, velocity autocorrelation). Included by
 * disk_sim.h.
 */
#ifndef DISKSIM_OBSERVE_H
#define DISKSIM_OBSERVE_H

#include "disksim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* Energy, momentum, pressure, temperature (0 for sim NULL)            */
/* ------------------------------------------------------------------ */

double ds_sim_get_kinetic_energy(const ds_sim *sim);                 /* sum of m v^2 / 2 */
void ds_sim_get_momentum(const ds_sim *sim, double *px, double *py); /* sum of m v */
uint64_t ds_sim_get_wall_count(const ds_sim *sim); /* wall reflections since the last reset */
/* Momentum handed to the walls since the last reset: sum of 2 m |v_n|. */
double ds_sim_get_wall_impulse(const ds_sim *sim);
/* Wall impulse per unit time per unit length of wall the centres reach
 * (perimeter 2 (box - 2R) + 2 (box_y - 2R); a channel's two walls,
 * 2 box), averaged since the last reset; 0 before any step. In 2D this is a force per length, the ideal
 * gas has P A = N <m v^2>/2. In a mixture each disk's impulse is over the
 * perimeter its own centre reaches, so that the partial pressures of the
 * kinds add up. A periodic box has no walls: there it is
 * ds_sim_get_virial_pressure. */
double ds_sim_get_pressure(const ds_sim *sim);
/* Pressure from the collision virial, averaged since the last reset, 0
 * before any step: P A = N kT + (1 / (2 t)) * sum over collisions of
 * r_ij . dp_i, with N kT = K the kinetic energy, r_ij joining the centres
 * (nearest image) and dp_i disk i's change of momentum. A is the area the
 * centres reach: (box - 2R) (box_y - 2R) with walls, where the virial
 * theorem makes it equal to ds_sim_get_pressure over a long run, box
 * box_y in a periodic box and box (box_y - 2R) in a channel. For a mixture with walls A is the mean of each
 * disk's (box - 2 r) (box_y - 2 r): the virial theorem weighs each kind's
 * area by its partial pressure, so this differs from ds_sim_get_pressure
 * at second order in the radii over the box; periodic, it is exact. With
 * the time step the collisions happen a little inside contact, which
 * biases it low (docs/physics.md). */
double ds_sim_get_virial_pressure(const ds_sim *sim);
/* The temperature the collisions see: with walls kT = K / N; in a
 * periodic box, where the total momentum P (total mass M) is conserved,
 * kT = K_int / (N - 1) with K_int = K - P^2 / (2 M) (0 for a single
 * disk); in a channel, which conserves P_x alone, kT = (K - P_x^2 /
 * (2 M)) / (N - 1/2). The canonical ensemble at this kT has the pressure a run
 * measures. */
double ds_sim_get_temperature(const ds_sim *sim);
/* The canonical compressibility factor Z = P A / (N kT) with kT of
 * ds_sim_get_temperature, averaged since the last reset (0 before any
 * step, 1 with no relative motion): 1 + W / (2 t N kT), W the collision
 * virial of ds_sim_get_virial_pressure, A the area the centres reach.
 * With walls it is ds_sim_get_virial_pressure A / K; periodic it is the Z
 * of the canonical ensemble at every N, which P A / K is not (high by
 * about (Z - 1) / N). Monte Carlo at the same N, A and kT gives the same
 * Z. */
double ds_sim_get_compressibility_factor(const ds_sim *sim);
/* The energy books of a granular gas (ds_sim_set_restitution,
 * ds_sim_set_drive), since the last reset: the kinetic energy the
 * collisions and wall turns took out (their restitution below 1; a TC
 * model's elastic collision takes none), and the energy a drive's kicks
 * put in; the same per unit time over the time since the reset (0 before
 * any step). In a steady state the two powers agree within their
 * fluctuations; at every step boundary the kinetic energy plus the
 * potential one is what it was at the reset less the lost and plus the
 * input energy, to rounding. (A field's floor, which sends a disk
 * resting on a wall off at the least speed of a contact time's flight,
 * puts in what it adds as negative loss.) */
double ds_sim_get_energy_lost(const ds_sim *sim);
double ds_sim_get_energy_input(const ds_sim *sim);
double ds_sim_get_power_lost(const ds_sim *sim);
double ds_sim_get_power_input(const ds_sim *sim);
/* The potential energy of the field (ds_sim_set_gravity): -sum m_i (gx
 * x_i + gy y_i), zero at the origin of the box (0 without a field). */
double ds_sim_get_potential_energy(const ds_sim *sim);
/* Zeroes the wall impulse, wall count, collision virial, energy books
 * and pressure clock (not the collision count, the time or the stress
 * integral), so a relaxation period can be discarded. */
void ds_sim_reset_observables(ds_sim *sim);
/* The time integral of the pressure tensor times the area since
 * ds_sim_create (ds_sim_reset_observables leaves it; a checkpoint carries
 * it, and one of format version 1, which did not, starts it at 0 at the
 * load), components s[0] xx, s[1] yy, s[2] xy:
 *   s_ab = int sum_i m_i v_i,a v_i,b dt + sum over collisions of
 *          (r_i - r_j)_a dp_i,b,
 * the kinetic part integrated exactly between velocity changes (with the
 * time step: over each step at the velocities it starts with), the
 * collisions' part their impulses, r_i - r_j the nearest image. Wall
 * impulses are not in it. The mean pressure tensor over a stretch is the
 * change of s over A times its duration, A the area of
 * ds_sim_get_virial_pressure, whose pressure is (s_xx + s_yy) / (2 A t)
 * since creation. Its increments are the Helfand moments of the shear
 * viscosity: eta = lim <(s_xy(t0 + t) - s_xy(t0))^2> / (2 A kT t), and the
 * same with (s_xx - s_yy) / 2 (observe/observables.c says why). Each
 * ds_sim_run sums the kinetic tensor afresh from the disks (so that
 * whatever set them between runs is in it): runs split into other
 * ds_sim_run calls agree to rounding, the same calls to the bit.
 * DS_ERR_ARG if sim or s is NULL. */
ds_status ds_sim_get_stress_integral(const ds_sim *sim, double s[3], ds_error *err);

/* ------------------------------------------------------------------ */
/* Order: bond-orientational order psi6                                */
/* ------------------------------------------------------------------ */

/* Per-disk bond-orientational order of the n centres (x[j], y[j]):
 *   psi6_j = (1/n_j) sum_k exp(6 i theta_jk)  ->  re[j] + i im[j],
 * over the n_j disks k whose centres are closer than cutoff to j's (a
 * coincident centre is no bond), theta_jk the angle of the bond j -> k from
 * the x axis. 0 for a disk with no neighbour. |psi6_j| = 1 for six
 * neighbours at multiples of 60 degrees; arg(psi6_j) / 6 is then the
 * lattice's orientation. The box is [0, box_x] x [0, box_y]; with
 * DS_BOUNDARY_PERIODIC separations are minimum images (centres anywhere,
 * wrapped), which is unique only if cutoff < min(box_x, box_y) / 2. O(n)
 * with a cell grid allocated inside. n = 0 is DS_OK and reads and writes
 * nothing (the pointers may then be NULL). DS_ERR_ARG if, with n > 0, a
 * pointer is NULL, or if box_x, box_y or cutoff is not finite and
 * positive, a centre is not finite, boundary is unknown, or a periodic
 * cutoff is not below half the shorter side; DS_ERR_NOMEM if the grid
 * cannot be allocated. */
ds_status ds_psi6_local(size_t n, const double *x, const double *y, double box_x, double box_y,
                        ds_boundary boundary, double cutoff, double *re, double *im, ds_error *err);
/* Global order |(1/N) sum_j psi6_j| of the disks at ds_sim_get_time into
 * *psi6, in the sim's box and boundary, with cutoff 1.4 d (d = 2R: past
 * the first shell of neighbours, short of the dense liquid's first
 * minimum of g(r), 1.55 d at area fraction 0.70, and of a crystal's
 * second shell; a mixture's pair 1.4 times its own contact distance).
 * Near 1 for a crystal of one orientation, O(1/sqrt N) for a liquid; a
 * lattice sparser than 1.4 d has no bonds and gives 0. DS_ERR_ARG (*psi6
 * NaN) if sim or psi6 is NULL or a periodic box is narrower than 2.8
 * d_max (field "box" or "box_y"); DS_ERR_NOMEM. */
ds_status ds_sim_get_psi6(const ds_sim *sim, double *psi6, ds_error *err);

/* Pair separations for the radial distribution function g(r): counts[b]
 * (b < bins) receives the number of pairs j < k of the n centres whose
 * distance lies in [b dr, (b + 1) dr), nearest image with
 * DS_BOUNDARY_PERIODIC (then bins dr must be at most half the shorter
 * side, as a second image could be as close beyond it; centres anywhere,
 * wrapped). With walls the box only sizes the cell grid that makes this
 * O(n) at a fixed density. g(r) of bin b is counts[b] over the pairs an
 * ideal gas of the same n in the same area A would have there, n (n - 1)
 * / 2 * pi (r1^2 - r0^2) / A (tools/gr prints it). DS_ERR_ARG if a
 * pointer is NULL (x, y with n > 0), bins is 0, dr or a side is not
 * finite and positive, a centre is not finite, boundary is unknown, or a
 * periodic range is too long; DS_ERR_NOMEM if the grid cannot be
 * allocated. */
ds_status ds_pair_histogram(size_t n, const double *x, const double *y, double box_x, double box_y,
                            ds_boundary boundary, double dr, size_t bins, uint64_t *counts,
                            ds_error *err);

/* The contacts of a packing at ds_sim_get_time: pairs whose centres are
 * closer than (r_i + r_j) (1 + gap), gap >= 0 (a jammed packing's
 * contacts are what its pressure keeps a hair apart: at Z = 10^6 they are
 * 1e-6 to 1e-4 of their contact distance apart, and gap 1e-4 counts 4.00
 * per disk of 1024 where 1e-3 counts 1.5% more; docs/physics.md).
 * Rattlers, disks with fewer than 3 contacts (which a disk in the plane
 * needs to be held), are removed, and removed again as their removal
 * leaves others with fewer, until none is left. */
typedef struct ds_contacts {
    size_t pairs;            /* contacts between the disks that are left */
    size_t rattlers;         /* disks removed */
    double per_disk;         /* contacts per disk left, 2 pairs / (n - rattlers); 0 if none */
    double rattler_fraction; /* rattlers / n */
} ds_contacts;
/* DS_ERR_ARG for NULL or a gap not in [0, 1); DS_ERR_NOMEM. O(n). */
ds_status ds_sim_get_contacts(const ds_sim *sim, double gap, ds_contacts *out, ds_error *err);

/* ------------------------------------------------------------------ */
/* Transport: displacement and velocity correlations                   */
/* ------------------------------------------------------------------ */

/* An accumulator of the mean-squared displacement and the velocity
 * autocorrelation of n disks with multiple time origins, fed one sample
 * at a time:
 *   msd[k]  = < |r_i(t0 + k h) - r_i(t0)|^2 >,
 *   vacf[k] = < v_i(t0) . v_i(t0 + k h) >,
 * for lags k < lags, averaged over the n disks and every time origin t0
 * seen with lag k. h is the caller's interval between samples (the
 * accumulator never sees time: the samples must be equally spaced); every
 * origin_every-th sample, starting with the first, is an origin (1: every
 * sample; more saves work when samples are closer than the dynamics
 * decorrelates). r must be unwrapped (ds_sim_get_unwrapped) and the disks
 * in the same order in every sample. Memory: 4 n ceil(lags /
 * origin_every) doubles; work per sample: that many multiply-adds. */
typedef struct ds_transport ds_transport; /* opaque */

/* A new accumulator into *out. DS_ERR_ARG if out is NULL, n is 0, lags is
 * below 2 or origin_every is 0; DS_ERR_NOMEM without memory for it. */
ds_status ds_transport_create(size_t n, size_t lags, size_t origin_every, ds_transport **out,
                              ds_error *err);
void ds_transport_destroy(ds_transport *tr); /* NULL is fine */
/* One sample: unwrapped centres xy[2 i], xy[2 i + 1] and velocities
 * v[2 i], v[2 i + 1] of disk i < n. DS_ERR_ARG (nothing added) if a
 * pointer is NULL or a value is not finite. */
ds_status ds_transport_add(ds_transport *tr, const double *xy, const double *v, ds_error *err);
/* The sample of sim at ds_sim_get_time: ds_sim_get_unwrapped and the
 * velocities, in generation order. DS_ERR_ARG if a pointer is NULL or
 * ds_sim_get_count(sim) is not the accumulator's n; DS_ERR_NOMEM. */
ds_status ds_transport_sample(ds_transport *tr, const ds_sim *sim, ds_error *err);
size_t ds_transport_get_lags(const ds_transport *tr); /* 0 for NULL */
/* The averages so far, each array of ds_transport_get_lags values (any
 * of them may be NULL): msd, vacf, and origins[k], how many origins have
 * been seen with lag k (a lag not yet reached has msd and vacf 0).
 * DS_ERR_ARG if tr is NULL. */
ds_status ds_transport_get(const ds_transport *tr, double *msd, double *vacf, uint64_t *origins,
                           ds_error *err);
/* The self-diffusion coefficient over the window of lags [from, to]
 * (interval h between samples), two ways that agree up to the sampling
 * noise and the O(h^2) error of the trapezoids:
 *   Einstein:    (msd[to] - msd[from]) / (4 (to - from) h), the slope of
 *                msd / 4 in two dimensions;
 *   Green-Kubo:  the mean over the window of D(t) = (1/2) int_0^t vacf,
 *                both integrals by trapezoids on the samples.
 * In two dimensions d msd / dt = 4 D(t) exactly, so the two are the same
 * average of D(t), which for a fluid of disks grows like ln t (the 1/t
 * tail of the autocorrelation, docs/physics.md): quote the window. Either
 * pointer may be NULL. DS_ERR_ARG if tr is NULL, h is not finite and
 * positive, from >= to, to >= lags, or no origin has reached lag to. */
ds_status ds_transport_get_diffusion(const ds_transport *tr, double interval, size_t from,
                                     size_t to, double *einstein, double *green_kubo,
                                     ds_error *err);

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_OBSERVE_H */
