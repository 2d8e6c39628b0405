# SPDX-License-Identifier: MIT
"""The canonical and isobaric ensembles from Python: Sim.set_thermostat
(ds_sim_set_thermostat) and Sim.set_barostat (ds_sim_set_barostat), their
properties, refusals with the library's fields, and checkpoints and
pickles that carry them bit for bit; the physics itself is the C tests'
(tests/test_thermostat.c, tests/test_barostat.c)."""
import copy
import math
import pickle

import numpy as np
import pytest

import disksim
from disksim import ArgumentError


def fluid(n=100, eta=0.3, **kw):
    r = math.sqrt(eta * 1e6 / (n * math.pi))
    return disksim.Sim(n, r, boundary="periodic", placement="lattice", **kw)


def test_the_thermostats_are_the_librarys():
    assert disksim.THERMOSTATS == ("none", "andersen", "isokinetic")
    s = fluid()
    assert (s.thermostat, s.thermostat_kt) == ("none", 0.0)
    assert (s.barostat_pressure, s.barostat_acceptance) == (0.0, 0.0)


# The integrators that change velocities: event chains refuse a bath.
BATHED = [i for i in disksim.INTEGRATORS if i != "chain"]


@pytest.mark.parametrize("integrator", BATHED)
def test_andersen_holds_the_kinetic_energy_at_n_kt_on_average(integrator):
    # K is Gamma(n, kT): mean n kT with a standard deviation sqrt(n) kT,
    # samples 0.1 apart (2 redraws a disk at nu = 20) nearly independent:
    # 400 of them hold the mean to sqrt(100 / 400) kT = 0.5 kT, and the run
    # starts at 5000 per disk, twice the bath's.
    s = fluid(integrator=integrator, dt=0.01)
    s.set_thermostat("andersen", kt=2500.0, collision_rate=20.0)
    assert (s.thermostat, s.thermostat_kt, s.temperature) == ("andersen", 2500.0, 2500.0)
    s.run(100)
    energies = []
    for _ in range(400):
        s.run(10)
        energies.append(s.kinetic_energy)
    assert abs(np.mean(energies) / 2500.0 - s.n) < 5 * 0.5 * 1.05


def test_isokinetic_scales_to_its_temperature_at_each_step():
    s = fluid(integrator="event")
    s.set_thermostat("isokinetic", kt=1000.0)
    s.run(3)
    px, py = s.momentum
    internal = s.kinetic_energy - (px * px + py * py) / (2 * s.n)
    assert abs(internal / (s.n - 1) / 1000.0 - 1) < 1e-12


def test_a_barostat_moves_the_box_and_its_area_fraction():
    s = fluid(integrator="event")
    s.set_thermostat("andersen")
    s.set_barostat(50.0, every=1, aspect=True)
    eta = s.area_fraction
    s.run(200)
    assert s.barostat_pressure == 50.0 and 0 < s.barostat_acceptance < 1
    # far above the fluid's pressure at 0.3 (beta P sigma^2 near 1): it
    # compresses, the box with it
    assert s.area_fraction > eta and s.box < 1000.0 and s.box_y < 1000.0
    assert s.area_fraction == pytest.approx(s.n * math.pi * s.radius**2 / (s.box * s.box_y))
    s.set_barostat(0.0)
    assert s.barostat_pressure == 0.0


def same(a, b):
    return (np.array_equal(a.positions, b.positions) and np.array_equal(a.velocities, b.velocities)
            and a.box == b.box and a.box_y == b.box_y)


@pytest.mark.parametrize("how", ["save", "pickle", "copy"])
def test_a_checkpoint_carries_the_ensemble_and_goes_on_bit_for_bit(tmp_path, how):
    a = fluid(integrator="event")
    a.set_thermostat("andersen", kt=4000.0, collision_rate=30.0)
    a.set_barostat(2.0, every=2, aspect=True)
    a.run(300)
    if how == "save":
        a.save(tmp_path / "c.ckpt")
        b = disksim.load(tmp_path / "c.ckpt")
    elif how == "pickle":
        b = pickle.loads(pickle.dumps(a))
    else:
        b = copy.copy(a)
    assert (b.thermostat, b.thermostat_kt, b.barostat_pressure) == ("andersen", 4000.0, 2.0)
    a.run(500)
    b.run(500)
    assert same(a, b) and a.barostat_acceptance == b.barostat_acceptance


@pytest.mark.parametrize("call, field", [
    (lambda s: s.set_thermostat("hot"), "kind"),
    (lambda s: s.set_thermostat("andersen", kt=-1.0), "kt"),
    (lambda s: s.set_thermostat("andersen", kt=math.nan), "kt"),
    (lambda s: s.set_thermostat("andersen", collision_rate=-1.0), "collision_rate"),
    (lambda s: s.set_thermostat("isokinetic", collision_rate=2.0), "collision_rate"),
    (lambda s: s.set_barostat(-1.0), "pressure"),
    (lambda s: s.set_barostat(math.inf), "pressure"),
    (lambda s: s.set_barostat(1.0, max_step=2.0), "max_step"),
    (lambda s: s.set_barostat(1.0, every=-1), "every"),
])
def test_a_refusal_names_the_keyword_at_fault(call, field):
    with pytest.raises(ArgumentError) as e:
        call(fluid())
    assert e.value.field == field


def test_event_chains_take_a_barostat_and_refuse_a_bath():
    s = fluid(integrator="chain")
    with pytest.raises(ArgumentError, match="needs an integrator with velocities") as e:
        s.set_thermostat("andersen")
    assert e.value.field == "integrator"
    s.set_barostat(50.0, every=1)
    eta = s.area_fraction
    s.run(200)
    assert s.area_fraction != eta and s.barostat_acceptance > 0.0


def test_the_barostat_moves_a_periodic_box_only():
    with pytest.raises(ArgumentError, match="periodic box only") as e:
        disksim.Sim(10, 5).set_barostat(1.0)
    assert e.value.field == "boundary"


def test_the_arguments_are_checked_for_their_types():
    s = fluid()
    with pytest.raises(TypeError):
        s.set_thermostat(1)
    with pytest.raises(TypeError):
        s.set_barostat("high")
