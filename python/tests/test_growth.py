# SPDX-License-Identifier: MIT
"""Compression from Python: Sim.set_growth (ds_sim_set_growth), growth_state,
growth_z, scale_velocities and contacts(), and checkpoints of mixtures and
of growing runs, which go on bit for bit as the C tests check."""
import copy
import pickle

import numpy as np
import pytest

import disksim

EPS = np.finfo(float).eps


def binary(n=64, seed=3, eta=0.5):
    """A 50:50 mixture of radii 1:1.4 at area fraction eta, event-driven in
    a periodic box (where growth runs)."""
    r = (eta * 1e6 / (np.pi * (n // 2) * (1 + 1.4**2))) ** 0.5
    return disksim.Sim(n, r, species=[(n // 2, r), (n - n // 2, 1.4 * r)], integrator="event",
                       boundary="periodic", placement="lattice", seed=seed)


def grow(s, until_eta, rate=None, most=100000):
    rate = rate if rate is not None else 0.02 * 100.0 / (2 * s.radius)  # 2% of a diameter a unit
    s.set_growth(rate, until_eta=until_eta)
    steps = 0
    while s.growth_state == "growing" and steps < most:
        s.run(100)
        steps += 100
    return rate


def test_a_growth_to_until_eta_reaches_it_with_the_energy_of_the_start():
    s = binary(64)
    e0, r0 = s.kinetic_energy, s.radii
    assert s.growth_state == "none" and s.growth_z == 0.0
    grow(s, 0.75)
    assert s.growth_state == "reached_eta"
    # stopped at its exact time: the area fraction is the target to rounding
    assert abs(s.area_fraction - 0.75) < 1e-12
    # the radii grew in proportion: the mixture's ratio stays
    assert np.allclose(s.radii / r0, s.radii[0] / r0[0], rtol=1e-12, atol=0)
    # the library scales the velocities back when growth stops: one scaling
    # of n velocities, ~1e-16 each
    assert abs(s.kinetic_energy / e0 - 1) < 1e-12
    assert s.growth_z > 1  # windows were measured on the way: a dense liquid's Z
    s.run(100)  # and it runs on as any mixture, disks inside and apart
    assert s.growth_state == "reached_eta" and abs(s.area_fraction - 0.75) < 1e-12
    s.set_state(s.positions)  # which the library checks; and which ends growth
    assert s.growth_state == "none"


def test_rate_zero_stops_growth_where_it_is():
    s = binary(64)
    s.set_growth(1.0)
    s.run(50)
    assert s.growth_state == "growing"
    s.set_growth(0.0)
    eta = s.area_fraction
    s.run(50)
    assert s.growth_state == "none" and s.area_fraction == eta


def test_scale_velocities_scales_the_energy_by_its_square():
    s = binary(64)
    e0, v0 = s.kinetic_energy, s.velocities
    s.scale_velocities(0.5)
    assert np.array_equal(s.velocities, v0 * 0.5)
    assert abs(s.kinetic_energy / (0.25 * e0) - 1) < 1e-15


def test_contacts_of_a_lattice_are_its_coordination_number():
    # ds_sim_get_contacts's own case: 64 disks on the 8 x 8 triangular
    # lattice, diameters 1e-6 short of the spacing: six contacts each within
    # a gap of 1e-5, none within 1e-7 (all rattlers).
    spacing = 1000.0 / 8
    s = disksim.Sim(64, 0.5 * spacing / (1 + 1e-6), boundary="periodic", placement="lattice",
                    box_y=1000.0 * 3**0.5 / 2)
    c = s.contacts(gap=1e-5)
    assert isinstance(c, disksim.Contacts) and tuple(c) == (3 * 64, 0, 6.0, 0.0)
    assert (c.pairs, c.rattlers, c.per_disk, c.rattler_fraction) == (192, 0, 6.0, 0.0)
    none = s.contacts(1e-7)
    assert none.pairs == 0 and none.rattlers == 64 and none.rattler_fraction == 1.0
    assert s.contacts() == s.contacts(gap=1e-4)  # the header's gap for jammed packings


# ---------------------------------------------------------------------------
# Checkpoints of mixtures and of growing runs


def same(a, b):
    return (np.array_equal(a.positions, b.positions) and np.array_equal(a.velocities, b.velocities)
            and np.array_equal(a.radii, b.radii) and np.array_equal(a.masses, b.masses)
            and a.steps == b.steps and a.collision_count == b.collision_count
            and a.growth_state == b.growth_state and a.growth_z == b.growth_z
            and a.virial_pressure == b.virial_pressure
            # the library sums pi r^2 in another order after a load (the
            # broad phase's order), so with every radius the same to the bit
            # the sum may differ by rounding: n eps of it at most
            and abs(a.area_fraction - b.area_fraction) <= a.n * EPS * a.area_fraction)


@pytest.mark.parametrize("integrator", disksim.INTEGRATORS)
@pytest.mark.parametrize("boundary", ["walls", "periodic"])
def test_a_saved_mixture_loads_and_goes_on_bit_for_bit(tmp_path, integrator, boundary):
    s = disksim.Sim(300, 6.0, species=[(150, 6.0), (150, 8.4, 3.0)], mass="area",
                    integrator=integrator, boundary=boundary, seed=11)
    s.run(300)
    s.save(tmp_path / "m.ckpt")
    t = disksim.load(tmp_path / "m.ckpt")
    assert same(s, t) and t.masses[-1] == 3.0
    s.run(500)
    t.run(500)
    assert same(s, t)


def test_a_growing_run_saved_and_loaded_goes_on_bit_for_bit(tmp_path):
    # The C test's case: the thermostat's windows and the growth's clock
    # are in the checkpoint.
    s = binary(200, seed=5)
    s.set_growth(0.5, until_eta=0.7)
    s.run(30)
    assert s.growth_state == "growing"
    s.save(tmp_path / "g.ckpt")
    t = disksim.load(tmp_path / "g.ckpt")
    c = copy.deepcopy(s)
    p = pickle.loads(pickle.dumps(s))
    assert same(s, t) and same(s, c) and same(s, p)
    for sim in (s, t, c, p):
        sim.run(300)
    assert same(s, t) and same(s, c) and same(s, p)
    assert s.radii[0] > t.params["radius"]  # it did grow
    assert p.params == s.params and "species" not in t.params


# ---------------------------------------------------------------------------
# Refusals, in the library's words, with the field it names


def test_growth_is_refused_where_it_cannot_run():
    cases = [
        (dict(), "integrator", r"integrator = step: growth needs the event-driven integrator"),
        (dict(integrator="event"), "boundary", "boundary = walls: growth needs a periodic box"),
        (dict(boundary="periodic"), "integrator", "integrator = step: growth needs"),
    ]
    for kw, field, words in cases:
        with pytest.raises(disksim.ArgumentError, match=words) as info:
            disksim.Sim(10, 5.0, **kw).set_growth(0.1)
        assert info.value.field == field
        assert info.value.value is None and info.value.limit is None


def test_a_growth_faster_than_the_disks_move_is_refused():
    # 10 disks of R = 5 at the speed of 100: the largest pair's surfaces
    # recede at 2 x 5 x rate, at most 10 x 100, so rate <= 100.
    s = disksim.Sim(10, 5.0, integrator="event", boundary="periodic")
    with pytest.raises(disksim.ArgumentError, match="rate = 200 is too fast") as info:
        s.set_growth(200.0)
    # The library's numbers: the rate refused and the fastest it takes (the
    # rms speed, 100 to rounding once the mean velocity is taken out).
    assert (info.value.field, info.value.value) == ("rate", 200.0)
    assert info.value.limit == pytest.approx(100.0, rel=1e-12)
    assert s.growth_state == "none"
    s.set_growth(100.0)
    assert s.growth_state == "growing"
