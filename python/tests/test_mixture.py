# SPDX-License-Identifier: MIT
"""Mixtures from Python: Sim(..., species=...) or radii= and masses= per
disk, through ds_sim_create. The radii and masses come back as given,
and an event-driven periodic run with unequal masses conserves energy and
momentum to rounding (the bounds below say how much rounding)."""
import math
import pickle

import numpy as np
import pytest

import disksim

EPS = np.finfo(float).eps  # 2.2e-16


def binary(n=200, r=6.0, **kw):
    """A 50:50 mixture of radii r and 1.4 r, the usual glass former."""
    return disksim.Sim(n, r, species=[(n // 2, r), (n - n // 2, 1.4 * r)], **kw)


def test_a_binary_mixtures_radii_come_back_in_generation_order():
    s = binary(200, 6.0)
    radii = s.radii
    assert radii.shape == (200,) and radii.dtype == np.float64
    assert np.all(radii[:100] == 6.0) and np.all(radii[100:] == 6.0 * 1.4)
    assert s.radius == 6.0 and s.radius_max == 6.0 * 1.4
    assert np.all(s.masses == 1.0)  # mass='equal', the default
    eta = 100 * math.pi * (6.0**2 + (6.0 * 1.4)**2) / 1e6
    assert abs(s.area_fraction - eta) < 1e-12
    radii[:] = 0.0  # a copy: changing it changes nothing
    assert s.radii[0] == 6.0


def test_each_disk_knows_its_species_through_a_run_and_a_checkpoint():
    s = binary(200, 6.0, integrator="event", boundary="periodic", seed=3)
    want = np.repeat(np.arange(2, dtype=np.uint32), 100)
    assert s.kinds.dtype == np.uint32 and np.array_equal(s.kinds, want)
    assert s.kind_names == ("A", "B")
    s.run(200)  # the cells' sorts move the slots; the kinds go with them
    back = pickle.loads(pickle.dumps(s))
    assert np.array_equal(back.kinds, want) and back.kind_names == ("A", "B")
    one = disksim.Sim(10, 5.0)
    assert np.array_equal(one.kinds, np.zeros(10, np.uint32))
    assert one.kind_names == ("A",)


def test_a_species_may_be_named_and_keeps_its_name():
    s = disksim.Sim(30, 5.0, species=[(10, 5.0, "small"), (20, 7.0, 2.5, "big")],
                    integrator="event", boundary="periodic")
    assert s.kind_names == ("small", "big")
    assert s.params["species"] == ((10, 5.0, "small"), (20, 7.0, 2.5, "big"))
    assert "species=((10, 5.0, 'small'), (20, 7.0, 2.5, 'big'))" in repr(s)
    assert np.array_equal(s.masses, [1.0] * 10 + [2.5] * 20)  # the rule, then the given
    s.run(100)
    back = pickle.loads(pickle.dumps(s))  # through a checkpoint, which keeps the names
    assert back.kind_names == ("small", "big") and np.array_equal(back.kinds, s.kinds)
    assert disksim.Sim(**s.params).kind_names == ("small", "big")


def test_mass_area_weighs_each_disk_as_its_area():
    s = binary(200, 6.0, mass="area")
    assert np.allclose(s.masses, (s.radii / s.radius)**2, rtol=2 * EPS, atol=0)
    assert s.masses[0] == 1.0 and abs(s.masses[-1] - 1.96) < 1e-15
    # a species' own mass overrides the rule
    t = disksim.Sim(10, 5.0, species=[(5, 5.0, 3.0), (5, 7.0)], mass="area")
    assert np.all(t.masses[:5] == 3.0) and np.allclose(t.masses[5:], 1.96, rtol=EPS)


def test_radii_and_masses_per_disk_are_the_disks_own():
    radii = np.linspace(3.0, 9.0, 50)
    masses = np.arange(1.0, 51.0)
    s = disksim.Sim(50, 5.0, radii=radii, masses=masses, integrator="event")
    assert np.array_equal(s.radii, radii) and np.array_equal(s.masses, masses)
    radii[0] = 100.0  # the arguments were copied
    assert s.radii[0] == 3.0
    p = s.params
    assert np.array_equal(p["radii"], np.linspace(3.0, 9.0, 50)) and p["species"] is None
    p["radii"][0] = 100.0  # and params gives copies
    assert s.params["radii"][0] == 3.0
    # radii by rule
    t = disksim.Sim(50, 5.0, radii=np.linspace(3.0, 9.0, 50), mass="area")
    assert np.allclose(t.masses, (t.radii / 5.0)**2, rtol=2 * EPS)


def test_every_disk_is_inside_the_box_at_its_own_radius_and_none_overlap():
    for boundary in ("walls", "periodic"):
        s = binary(400, 6.0, boundary=boundary, integrator="event", seed=4)
        s.set_state(s.positions)  # the library checks inside and apart
        if boundary == "walls":
            x, r = s.positions, s.radii[:, None]
            assert np.all(x >= r) and np.all(x <= 1000.0 - r)


def test_one_kind_is_the_plain_simulation_to_the_bit():
    a = disksim.Sim(400, 5.0, integrator="event")
    b = disksim.Sim(400, 5.0, integrator="event", species=[(400, 5.0)], mass="area")
    a.run(500)
    b.run(500)
    assert np.array_equal(a.positions, b.positions)
    assert np.array_equal(a.velocities, b.velocities)


def test_params_and_repr_recreate_the_mixture():
    s = binary(100, 6.0, mass="area", seed=2, integrator="event")
    assert s.params["species"] == ((50, 6.0), (50, 6.0 * 1.4)) and s.params["mass"] == "area"
    assert "species=((50, 6.0), (50, %r)), mass='area'" % (6.0 * 1.4) in repr(s)
    s.run(100)
    t = disksim.Sim(**s.params)
    t.run(100)
    assert np.array_equal(s.positions, t.positions)
    assert "species" not in repr(disksim.Sim(10, 1))


def test_memory_needed_takes_the_mixture_too():
    plain = disksim.memory_needed(1000, 5.0)
    mixed = disksim.memory_needed(1000, 5.0, species=[(500, 5.0), (500, 7.0)])
    assert mixed > plain  # the radii and masses arrays


def test_a_mixture_goes_to_ase_with_each_disks_radius():
    pytest.importorskip("ase")
    s = binary(20, 6.0)
    atoms = s.to_ase()
    assert np.array_equal(atoms.get_array("radius"), s.radii)
    assert atoms.cell[2][2] == 2 * s.radius_max


# ---------------------------------------------------------------------------
# Conservation with unequal masses


def conservation_run():
    # Masses 1 and 1.96 (by area), area fraction 0.2, event-driven and
    # periodic: no wall changes a momentum, and ~40,000 collisions.
    s = disksim.Sim(1000, 6.0, species=[(500, 6.0), (500, 8.4)], mass="area",
                    integrator="event", boundary="periodic", seed=3)
    return s


def test_energy_is_conserved_to_rounding_with_unequal_masses():
    """The bound: a collision changes the velocities by 2 m_b / (m_a + m_b)
    (dv . n) n and the opposite momentum (core/collide.h), which keeps the
    pair's energy exactly; in floating point the factors, the product and
    the four sums round by a few eps each, each moving the pair's energy by
    at most ~2 eps of it, which is at most the total E: 20 eps E per
    collision is generous. Summing m v^2 over n disks, twice (start, now),
    rounds by 4 n eps E at most."""
    s = conservation_run()
    e0 = s.kinetic_energy
    s.run(10000)
    assert s.collision_count > 20000
    bound = EPS * e0 * (20 * s.collision_count + 4 * s.n)
    assert abs(s.kinetic_energy - e0) <= bound
    assert bound / e0 < 1e-9  # a bound that says something


def test_momentum_is_conserved_to_rounding_with_unequal_masses():
    """The bound: in exact arithmetic m_a dv_a = -m_b dv_b = dp, with
    |dp| <= 2 mu |v_a - v_b| <= 4 P, P = sqrt(2 m_max E) the most momentum
    one disk can hold. The factors 2 m / (m_a + m_b), the product and the
    sums round by ~3 eps of dp and eps/2 of each new velocity (times its
    mass, at most P): 16 eps P per collision is generous. The total sums n
    products m v, each rounding eps/2, and rounds (n - 1) eps/2 of
    sum m |v| <= sqrt(2 M E) (Cauchy-Schwarz, M the total mass): 2 n eps
    sqrt(2 M E) for the start and now."""
    s = conservation_run()
    e0, m = s.kinetic_energy, s.masses
    p0 = np.array(s.momentum)
    s.run(10000)
    assert s.collision_count > 20000
    big_p = math.sqrt(2 * m.max() * e0)
    bound = EPS * (16 * s.collision_count * big_p + 2 * s.n * math.sqrt(2 * m.sum() * e0))
    assert np.abs(np.array(s.momentum) - p0).max() <= bound
    assert bound / math.sqrt(2 * m.sum() * e0) < 1e-9
    # and the momentum is the sum of m v over the disks
    assert np.allclose(np.array(s.momentum), (m[:, None] * s.velocities).sum(0), rtol=0,
                       atol=bound)
