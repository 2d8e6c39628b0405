# SPDX-License-Identifier: MIT
"""The module's face: names, defaults, docstrings, repr, parameters."""
import inspect
import pydoc

import numpy as np
import pytest

import disksim

PUBLIC = [name for name in disksim.__all__]


def test_everything_public_has_a_docstring():
    assert disksim.__doc__ and "Sim" in disksim.__doc__
    for name in PUBLIC:
        thing = getattr(disksim, name)
        if callable(thing):
            assert thing.__doc__ and len(thing.__doc__) > 40, name
    for name, member in vars(disksim.Sim).items():
        if not name.startswith("_") or name in ("__enter__", "__exit__"):
            assert member.__doc__, name


def test_help_reads_like_the_header():
    text = pydoc.render_doc(disksim.Sim, renderer=pydoc.plaintext)
    for words in ("N hard disks of one radius", "'event': exact event-driven", "run(self, /, steps=None, *, until=None, callback=None, every=1)",
                  "virial_pressure", "Pressure from the collision virial", "releases the GIL",
                  "species     [(count, radius), ...]", "mass        the rule for the masses",
                  "set_growth(self, /, rate, until_eta=0.0, until_z=0.0)",
                  "Lubachevsky-Stillinger", "contacts(self, /, gap=0.0001)", "growth_state"):
        assert words in text, words


def test_the_signature_is_introspectable_and_its_defaults_are_the_librarys():
    parameters = inspect.signature(disksim.Sim).parameters
    assert list(parameters)[:2] == ["n", "radius"]
    assert parameters["seed"].default == disksim.DEFAULT_SEED == 20260101
    assert parameters["seed"].kind is inspect.Parameter.KEYWORD_ONLY
    assert list(parameters)[-4:] == ["species", "radii", "masses", "mass"]
    s = disksim.Sim(400, 5)
    defaults = {k: p.default for k, p in parameters.items() if k not in ("n", "radius")}
    assert {k: v for k, v in s.params.items() if k not in ("n", "radius")} == defaults
    assert (s.box, s.box_y, s.dt, s.integrator, s.boundary, s.placement) == (
        1000.0, 1000.0, 0.001, "step", "walls", "random")
    assert s.broadphase in disksim.BROADPHASES and s.broadphase != "auto"


def test_the_names_are_the_librarys():
    assert disksim.INTEGRATORS == ("step", "event", "chain")
    assert disksim.BOUNDARIES == ("walls", "periodic", "channel")
    assert disksim.PLACEMENTS == ("random", "lattice")
    assert set(disksim.BROADPHASES) == {"sap", "brute", "strips", "auto", "cells"}
    assert disksim.MASS_RULES == ("equal", "area")
    assert disksim.GROWTH_STATES == ("none", "growing", "reached_eta", "jammed")
    assert disksim.THERMOSTATS == ("none", "andersen", "isokinetic")
    assert disksim.JAMMED_Z == 1e6
    assert disksim.VELOCITY_MAX == 1e12
    assert disksim.__version__ == disksim.library_version


def test_3_0_names_z_the_compressibility_factor():
    # 3.0: Sim.compressibility is compressibility_factor, as the library's
    # ds_sim_get_compressibility_factor (Z, not the compressibility kappa).
    s = disksim.Sim(100, 5, boundary="periodic")
    s.run(200)
    assert s.compressibility_factor > 1.0
    assert not hasattr(s, "compressibility")


def test_a_refusal_carries_the_librarys_field_value_and_limit():
    with pytest.raises(disksim.ArgumentError) as info:
        disksim.Sim(400, 600.0)
    e = info.value
    assert (e.status, e.field, e.value, e.limit) == ("DS_ERR_ARG", "radius", 600.0, 500.0)
    assert str(e).startswith("radius = 600 does not fit a box of 1000 x 1000")
    with pytest.raises(disksim.ArgumentError) as info:
        disksim.Sim(10, 5, integrator="exact")
    assert info.value.field == "integrator" and info.value.value is None
    assert str(info.value) == "integrator = 'exact' is not one of 'step', 'event', 'chain'"


def test_params_recreate_the_same_simulation():
    s = disksim.Sim(300, 4, seed=9, integrator="event", boundary="periodic", box_y=800.0,
                    speed=50.0)
    s.run(100)
    t = disksim.Sim(**s.params)
    t.run(100)
    assert np.array_equal(s.positions, t.positions)
    assert t.box_y == 800.0 and s.params["box_y"] == 800.0
    assert disksim.Sim(3, 1).params["box_y"] is None


def test_repr_shows_what_differs_from_the_defaults_and_the_time():
    s = disksim.Sim(400, 5, integrator="event", seed=3)
    s.run(5)
    assert repr(s) == "<disksim.Sim(400, 5.0, seed=3, integrator='event') at t = 0.005 after 5 steps>"
    assert repr(disksim.Sim(1, 1)) == "<disksim.Sim(1, 1.0) at t = 0.0 after 0 steps>"


def test_memory_needed_is_the_librarys_and_grows_with_n():
    small, big = disksim.memory_needed(1000, 1), disksim.memory_needed(100000, 1)
    assert 0 < small < big and big > 100000 * 32  # at least x, y, vx, vy a disk


def test_a_sim_is_a_context_manager():
    with disksim.Sim(10, 1) as s:
        s.run(3)
    assert s.closed


def test_len_of_a_sim_is_its_number_of_disks_and_a_sim_is_always_true():
    s = disksim.Sim(400, 5)
    assert len(s) == s.n == 400
    assert len(disksim.Sim(7, 5, species=[(3, 5), (4, 7)])) == 7
    s.close()
    with pytest.raises(disksim.Error, match="closed"):
        len(s)  # as s.n
    assert s  # truth is not length: `if s:` never raises


def test_sim_can_be_subclassed():
    class Mine(disksim.Sim):
        def area_fraction(self):
            return self.n * np.pi * self.radius**2 / (self.box * self.box_y)

    assert abs(Mine(100, 10).area_fraction() - 100 * np.pi * 100 / 1e6) < 1e-15


def test_histogram_and_psi6_of_a_sim_are_the_functions_of_its_arrays():
    s = disksim.Sim(500, 8, boundary="periodic", integrator="event")
    s.run(200)
    counts = s.pair_histogram(1.0, 100)
    assert counts.dtype == np.uint64 and counts.shape == (100,)
    assert np.array_equal(counts, disksim.pair_histogram(s.positions, 1.0, 100,
                                                          boundary="periodic"))
    assert counts[:16].sum() == 0 and counts.sum() > 0  # no pair closer than 2R = 16
    z = s.local_psi6()
    assert np.array_equal(z, disksim.local_psi6(s.positions, 1.4 * 16, boundary="periodic"))
    assert abs(abs(z.mean()) - s.psi6) < 1e-12
