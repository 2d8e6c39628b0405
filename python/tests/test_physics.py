# SPDX-License-Identifier: MIT
"""The physics through the module: what is conserved, and the pressure of
hard disks against the equation of state. Every tolerance says where it
comes from."""
import math

import numpy as np
import pytest

import disksim

EPS = np.finfo(float).eps  # 2.2e-16

INTEGRATORS = list(disksim.INTEGRATORS)  # event chains keep every velocity: trivially


def rounding_bound_on_energy(s, energy):
    """How far rounding alone can move the kinetic energy.

    A wall reflection flips the sign of a component: exact. A collision adds
    s r to one velocity and subtracts it from the other, s = approach / r^2
    (core/collide.h); in exact arithmetic that keeps v_a^2 + v_b^2. In
    floating point the relative errors of approach, r^2, s and the four
    sums are a few eps each, and each changes the pair's energy by at most
    ~2 of them times the pair's energy, which is at most the total: 10 eps E
    per collision is generous. Summing E over n disks twice (at the start
    and now) adds 2 n eps E."""
    return EPS * energy * (10 * s.collision_count + 2 * s.n)


def rounding_bound_on_momentum(s, energy):
    """How far rounding alone can move the total momentum (periodic box: no
    walls). A collision adds the same computed change to one disk and
    subtracts it from the other: only the two sums round, each by at most
    eps/2 of its result, so a component of the total moves by at most
    eps * v_max, with v_max <= sqrt(2 E) (all the energy in one disk, unit
    masses). The sum over n disks rounds by at most (n - 1) eps/2 sum |v_i|,
    and sum |v_i| <= sqrt(2 n E) (Cauchy-Schwarz); twice, start and now."""
    v_max = math.sqrt(2 * energy)
    return EPS * (s.collision_count * v_max + (s.n - 1) * math.sqrt(2 * s.n * energy))


@pytest.mark.parametrize("integrator", INTEGRATORS)
@pytest.mark.parametrize("boundary", ["walls", "periodic"])
def test_kinetic_energy_is_conserved_to_rounding(integrator, boundary):
    # Area fraction 0.2: tens of thousands of collisions in 20 time units.
    s = disksim.Sim(1000, 8, integrator=integrator, boundary=boundary)
    e0 = s.kinetic_energy
    s.run(20000)
    assert s.collision_count > 10000
    assert abs(s.kinetic_energy - e0) <= rounding_bound_on_energy(s, e0)


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_momentum_is_conserved_to_rounding_in_a_periodic_box(integrator):
    s = disksim.Sim(1000, 8, integrator=integrator, boundary="periodic", seed=3)
    e0 = s.kinetic_energy
    p0 = np.array(s.momentum)
    s.run(20000)
    assert s.collision_count > 10000
    assert np.abs(np.array(s.momentum) - p0).max() <= rounding_bound_on_momentum(s, e0)


def test_walls_change_the_momentum():
    # The other half: walls reverse components, so the momentum of a gas
    # in a box wanders (it is no conserved quantity there).
    s = disksim.Sim(400, 5)
    p0 = s.momentum
    s.run(2000)
    assert s.wall_count > 0 and s.momentum != p0


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_run_k_is_k_steps_to_the_bit(integrator):
    a = disksim.Sim(500, 6, integrator=integrator, boundary="periodic")
    b = disksim.Sim(500, 6, integrator=integrator, boundary="periodic")
    a.run(700)
    for _ in range(700):
        b.step()
    assert np.array_equal(a.positions, b.positions)
    assert np.array_equal(a.velocities, b.velocities)
    assert a.collision_count == b.collision_count and a.virial_pressure == b.virial_pressure
    assert a.steps == b.steps == 700 and a.time == b.time == 700 * a.dt


def test_reset_observables_zeroes_the_wall_tallies_not_the_collisions():
    s = disksim.Sim(400, 5)
    s.run(1000)
    collisions = s.collision_count
    assert s.wall_count > 0 and s.wall_impulse > 0 and s.pressure > 0
    s.reset_observables()
    assert s.wall_count == 0 and s.wall_impulse == 0 and s.pressure == 0
    assert s.virial_pressure == 0
    assert s.collision_count == collisions and s.time == 1.0


def test_a_crystal_is_ordered_and_a_gas_is_not():
    # psi6 is near 1 for a lattice of one orientation, O(1/sqrt N) for a gas.
    crystal = disksim.Sim(1024, 14, placement="lattice", boundary="periodic",
                          box_y=1000 * math.sqrt(3) / 2)
    assert crystal.psi6 > 0.99
    gas = disksim.Sim(1024, 3)
    gas.run(1000)
    assert gas.psi6 < 5 / math.sqrt(1024)
    z = crystal.local_psi6()
    assert z.dtype == np.complex128 and np.allclose(np.abs(z), 1)


def series_z(eta):
    """Z of hard disks from the virial series through B10 (Clisby and
    McCoy 2006; the reduced coefficients B_k / B_2^(k-1) in powers of
    2 eta, as tools/analysis/plot_eos.plt has them). At eta = 0.3 the terms
    fall by ~3 a step and the next one would add ~1e-4."""
    b = [1.0, 1.0, 0.78200443, 0.53223180, 0.33355604, 0.19884, 0.11487, 0.06499, 0.03622,
         0.01995]
    return sum(bk * (2 * eta) ** k for k, bk in enumerate(b))


@pytest.mark.parametrize("integrator", ["event", "chain"])
def test_the_exact_samplers_z_at_area_fraction_0_3_is_the_virial_series(integrator):
    # 1024 disks, periodic, on the lattice that fits a box of aspect
    # sqrt(3)/2, as tools/analysis/eos.sh runs its points; the event-driven
    # dynamics and the event chains, which sample the same ensemble (a
    # chain's time unit moves the disks as far in all as the dynamics').
    n, eta = 1024, 0.3
    height = 1000 * math.sqrt(3) / 2
    radius = math.sqrt(eta * 1000 * height / (n * math.pi))
    s = disksim.Sim(n, radius, integrator=integrator, boundary="periodic", placement="lattice",
                    box_y=height)
    s.run(round(2 / s.dt))  # relaxation: ~5 collisions per disk melt the lattice
    z = []
    for _ in range(80):  # blocks of 5 time units, ~12 collisions per disk each
        s.reset_observables()
        s.run(round(5 / s.dt))
        z.append(s.compressibility_factor)
    mean = np.mean(z)
    # The standard error of the mean of the blocks: honest when the blocks
    # are independent, and blocks of 1, 5 and 10 time units gave the same
    # error (0.0009) here, so they are. Four of them: a good run fails with
    # probability 6e-5. Plus the finite-size shift of Z, O(1/N): measured
    # +0.0047 +- 0.0023 at N = 256 (1.2 / N) with P A / K, of which the
    # temperature's (Z - 1) / N = 0.0041 is gone from the canonical Z, so
    # 2 / N bounds it at 1024.
    error = np.std(z, ddof=1) / math.sqrt(len(z))
    assert error < 0.005  # the measurement itself is sharp enough to mean something
    reference = series_z(eta)
    assert abs(reference - 2.0632) < 1e-4
    assert abs(mean - reference) <= 4 * error + 2.0 / n
    # Henderson's equation of state, (1 + eta^2 / 8) / (1 - eta)^2, agrees.
    assert abs(mean - (1 + eta**2 / 8) / (1 - eta) ** 2) <= 4 * error + 2.0 / n


def test_compressibility_is_the_virial_over_the_temperature_the_collisions_see():
    # Z = 1 + W / (2 t N kT): the same collision virial as virial_pressure
    # (P A = K + W / (2 t)), over N kT instead of K. With walls kT = K / N,
    # so the two agree; periodic, with the momentum conserved, kT = K_int /
    # (N - 1). Both are a few roundings from one another, hence 1e-12.
    for boundary in ("walls", "periodic"):
        s = disksim.Sim(64, 20.0, integrator="event", boundary=boundary)
        s.run(2000)
        px, py = s.momentum
        k = s.kinetic_energy
        kt = k / 64 if boundary == "walls" else (k - (px * px + py * py) / (2 * 64)) / 63
        assert s.temperature == pytest.approx(kt, rel=1e-12)
        area = (s.box - 2 * s.radius) ** 2 if boundary == "walls" else s.box * s.box_y
        naive = s.virial_pressure * area / k
        assert s.compressibility_factor - 1 == pytest.approx((naive - 1) * k / (64 * kt),
                                                             rel=1e-12)
        assert naive > 1.1  # the virial part is large enough for the check to bite
