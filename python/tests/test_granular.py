# SPDX-License-Identifier: MIT
"""Granular gases from Python: Sim.set_restitution, set_contact_time,
set_gravity and set_drive (the library's ds_sim_set_*), their properties
and the energy books, refusals raised with the library's reasons, and
pickles and checkpoints that go on bit for bit as the C tests check."""
import pickle

import numpy as np
import pytest

import disksim


def channel(integrator="event", n=150, seed=4):
    return disksim.Sim(n, 5.0, integrator=integrator, boundary="channel", box=300.0,
                       seed=seed)


@pytest.mark.parametrize("integrator", ["step", "event"])
def test_the_rules_read_back_as_set(integrator):
    s = channel(integrator)
    assert (s.restitution, s.wall_restitution, s.gravity, s.drive) == (1.0, 1.0, (0.0, 0.0), 0.0)
    # the default contact time: 1e-4 of 2 R / speed
    assert s.contact_time == pytest.approx(1e-4 * 10.0 / 100.0, rel=1e-15)
    s.set_restitution(0.8)
    assert (s.restitution, s.wall_restitution) == (0.8, 1.0)
    s.set_restitution(0.8, wall_restitution=0.5)
    s.set_contact_time(1e-3)
    s.set_gravity(0.0, -50.0)
    s.set_drive(100.0)
    assert (s.wall_restitution, s.contact_time, s.gravity, s.drive) == (0.5, 1e-3, (0.0, -50.0),
                                                                         100.0)


@pytest.mark.parametrize("integrator", ["step", "event"])
def test_the_energy_books_balance(integrator):
    s = channel(integrator)
    s.set_restitution(0.7, 0.7)
    s.set_gravity(0.0, -100.0)
    s.set_drive(5e4)
    e0 = s.kinetic_energy + s.potential_energy
    s.run(300)
    assert s.energy_lost > 0.0 and s.energy_input > 0.0
    e = s.kinetic_energy + s.potential_energy
    # the event-driven run keeps the books to rounding; the time step's
    # field moves the disks by Euler steps, which do not conserve energy
    if integrator == "event":
        assert e - e0 == pytest.approx(s.energy_input - s.energy_lost, abs=1e-9 * e0)
    assert s.power_lost == pytest.approx(s.energy_lost / s.time, rel=1e-15)
    assert s.power_input == pytest.approx(s.energy_input / s.time, rel=1e-15)
    s.reset_observables()
    assert s.energy_lost == 0.0 and s.energy_input == 0.0


def test_refusals_carry_the_library_reasons():
    s = channel()
    with pytest.raises(disksim.ArgumentError) as e:
        s.set_restitution(1.5)
    assert e.value.field == "restitution" and e.value.value == 1.5 and e.value.limit == 1.0
    with pytest.raises(disksim.ArgumentError) as e:
        s.set_restitution(0.5, wall_restitution=0.0)
    assert e.value.field == "wall_restitution"
    with pytest.raises(disksim.ArgumentError) as e:
        s.set_gravity(1.0, -10.0)  # along the channel's periodic x
    assert e.value.field == "gx"
    with pytest.raises(disksim.ArgumentError) as e:
        s.set_gravity(0.0, float("nan"))
    assert e.value.field == "gy"
    with pytest.raises(disksim.ArgumentError) as e:
        s.set_drive(-1.0)
    assert e.value.field == "strength"
    with pytest.raises(disksim.ArgumentError) as e:
        s.set_contact_time(-1.0)
    assert e.value.field == "contact_time"
    with pytest.raises(TypeError):
        s.set_restitution("high")
    assert (s.restitution, s.gravity, s.drive) == (1.0, (0.0, 0.0), 0.0)


@pytest.mark.parametrize("integrator", ["step", "event"])
def test_a_granular_run_pickles_and_goes_on_bit_for_bit(integrator, tmp_path):
    s = channel(integrator)
    s.set_restitution(0.8, 0.9)
    s.set_gravity(0.0, -80.0)
    s.set_drive(2e4)
    s.run(200)
    t = pickle.loads(pickle.dumps(s))
    s.save(tmp_path / "c.state")
    u = disksim.load(tmp_path / "c.state")
    for other in (t, u):
        assert (other.restitution, other.gravity, other.drive) == (0.8, (0.0, -80.0), 2e4)
    for sim in (s, t, u):
        sim.run(150)
    for other in (t, u):
        assert np.array_equal(s.positions, other.positions)
        assert np.array_equal(s.velocities, other.velocities)
        assert s.energy_lost == other.energy_lost and s.energy_input == other.energy_input
