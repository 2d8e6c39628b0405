# SPDX-License-Identifier: MIT
"""Bad arguments raise what the docstrings say, with the library's words,
and nothing crashes the interpreter whatever it is given.

The rule (python/src/convert.c): TypeError for a value of the wrong type;
disksim.ArgumentError (an Error and a ValueError) for a value refused;
NoMemoryError (an Error and a MemoryError) for more than the machine can
hold; FileError (an OSError) and FormatError (a ValueError) for files."""
import math
import random
import warnings

import numpy as np
import pytest

import disksim
from disksim import ArgumentError, Error, FileError, NoMemoryError

NAN, INF = math.nan, math.inf


def sim():
    return disksim.Sim(20, 5)


# (what, call, exception, words of the message)
BAD = [
    ("no disks", lambda: disksim.Sim(0, 5), ArgumentError, "n = 0: there must be at least one disk"),
    ("negative n", lambda: disksim.Sim(-3, 5), ArgumentError, "n = -3 must not be negative"),
    ("n beyond 2**64", lambda: disksim.Sim(10**30, 1), NoMemoryError, "cannot be held in memory"),
    ("n beyond 32 bits", lambda: disksim.Sim(2**32, 1e-3), NoMemoryError, "cannot be held in memory"),
    ("n beyond this machine", lambda: disksim.Sim(4_000_000_000, 1e-3), NoMemoryError,
     "more than the"),
    ("float n", lambda: disksim.Sim(400.0, 5), TypeError, "n must be an int"),
    ("str n", lambda: disksim.Sim("400", 5), TypeError, "n must be an int"),
    ("radius too big", lambda: disksim.Sim(1, 600), ArgumentError,
     "radius = 600 does not fit a box of 1000 x 1000"),
    ("radius too big, periodic", lambda: disksim.Sim(1, 300, boundary="periodic"), ArgumentError,
     "below a quarter of each side"),
    ("radius 0", lambda: disksim.Sim(10, 0), ArgumentError, "radius = 0 must be a number > 0"),
    ("negative radius", lambda: disksim.Sim(10, -1), ArgumentError, "radius = -1"),
    ("NaN radius", lambda: disksim.Sim(10, NAN), ArgumentError, "radius = nan"),
    ("infinite radius", lambda: disksim.Sim(10, INF), ArgumentError, "radius = inf"),
    ("huge int radius", lambda: disksim.Sim(10, 10**400), ArgumentError, "too large to be a float"),
    ("str radius", lambda: disksim.Sim(10, "5"), TypeError, "radius must be a real number"),
    ("None radius", lambda: disksim.Sim(10, None), TypeError, "radius must be a real number"),
    ("complex radius", lambda: disksim.Sim(10, 5j), TypeError, "radius must be a real number"),
    ("too many to fit", lambda: disksim.Sim(10000, 6), ArgumentError,
     "n = 10000 disks of radius 6 cannot fit in the box without overlap"),
    ("too dense for random", lambda: disksim.Sim(5000, 6), ArgumentError,
     "random placement of more than 1000 disks cannot exceed 0.54"),
    ("no lattice fits", lambda: disksim.Sim(10000, 6, placement="lattice"), ArgumentError,
     "no triangular lattice"),
    ("unknown integrator", lambda: disksim.Sim(10, 1, integrator="leapfrog"), ArgumentError,
     "integrator = 'leapfrog' is not one of 'step', 'event'"),
    ("integrator by number", lambda: disksim.Sim(10, 1, integrator=1), TypeError,
     "integrator must be a str"),
    ("unknown boundary", lambda: disksim.Sim(10, 1, boundary="torus"), ArgumentError,
     "is not one of 'walls', 'periodic'"),
    ("unknown placement", lambda: disksim.Sim(10, 1, placement="grid"), ArgumentError,
     "is not one of 'random', 'lattice'"),
    ("broad phase of the other integrator", lambda: disksim.Sim(10, 1, broadphase="cells"),
     ArgumentError, "broadphase = cells does not serve the step integrator"),
    ("box 0", lambda: disksim.Sim(10, 1, box=0), ArgumentError, "box = 0 must be > 0"),
    ("negative box", lambda: disksim.Sim(10, 1, box=-5), ArgumentError, "box = -5 must be > 0"),
    ("box too big", lambda: disksim.Sim(10, 1, box=2e9), ArgumentError, "<= 1e+09"),
    ("NaN box_y", lambda: disksim.Sim(10, 1, box_y=NAN), ArgumentError, "box_y = nan"),
    ("box_y 0", lambda: disksim.Sim(10, 1, box_y=0), ArgumentError, "box_y = 0 must be > 0"),
    ("dt 0", lambda: disksim.Sim(10, 1, dt=0), ArgumentError, "dt = 0 must be > 0"),
    ("dt too long", lambda: disksim.Sim(10, 1, dt=2), ArgumentError, "dt = 2 must be > 0 and <= 1"),
    ("infinite speed", lambda: disksim.Sim(10, 1, speed=INF), ArgumentError, "speed = inf"),
    ("negative seed", lambda: disksim.Sim(10, 1, seed=-1), ArgumentError, "seed = -1"),
    ("seed beyond 64 bits", lambda: disksim.Sim(10, 1, seed=2**64), ArgumentError,
     "seed = 18446744073709551616 is beyond 2**64 - 1"),
    ("float seed", lambda: disksim.Sim(10, 1, seed=1.5), TypeError, "seed must be an int"),
    ("three positional", lambda: disksim.Sim(10, 1, 3), TypeError, "takes 2 positional"),
    ("one positional", lambda: disksim.Sim(10), TypeError, "missing required argument 'radius'"),
    ("unknown keyword", lambda: disksim.Sim(10, 1, temperature=1), TypeError,
     "unexpected keyword argument 'temperature'"),
    ("n twice", lambda: disksim.Sim(10, 1, n=3), TypeError, "multiple values for argument 'n'"),
    ("negative steps", lambda: sim().run(-1), ArgumentError, "steps = -1 must not be negative"),
    ("steps beyond 64 bits", lambda: sim().run(2**64), ArgumentError, "beyond 2**64 - 1"),
    ("float steps", lambda: sim().run(1.0), TypeError, "steps must be an int"),
    ("no steps", lambda: sim().run(), TypeError, "steps"),
    ("positions of another n", lambda: sim().set_state(np.zeros((3, 2))), ArgumentError,
     "positions has shape (3, 2): it must be (20, 2)"),
    ("positions of 3 columns", lambda: sim().set_state(np.zeros((20, 3))), ArgumentError,
     "shape (20, 3)"),
    ("positions flat", lambda: sim().set_state(np.zeros(40)), ArgumentError, "shape (40,)"),
    ("positions of text", lambda: sim().set_state([["a", "b"]] * 20), ArgumentError,
     "positions must be an (n, 2) array of numbers"),
    ("positions None", lambda: sim().set_state(None), ArgumentError, "positions has shape ()"),
    ("complex positions", lambda: sim().set_state(np.zeros((20, 2), complex)), TypeError,
     "Cannot cast"),
    ("velocities of another n", lambda: sim().set_state(sim().positions, np.zeros((2, 2))),
     ArgumentError, "velocities has shape (2, 2)"),
    ("path None", lambda: sim().write_frame(None), TypeError, "NoneType"),
    ("path with NUL", lambda: sim().write_frame("a\0b"), ArgumentError, "NUL"),
    ("path empty", lambda: sim().write_frame(""), FileError, "No such file"),
    ("read a directory", lambda: disksim.read_frame("/"), Error, ""),
    ("read path int", lambda: disksim.read_frame(3.5), TypeError, "float"),
    ("histogram dr 0", lambda: disksim.pair_histogram(np.zeros((2, 2)), 0, 10), ArgumentError,
     "dr and the box's sides must be finite and > 0"),
    ("histogram no bins", lambda: disksim.pair_histogram(np.zeros((2, 2)), 1, 0), ArgumentError,
     "bins = 0"),
    ("histogram too many bins", lambda: disksim.pair_histogram(np.zeros((2, 2)), 1, 2**62),
     NoMemoryError, "bins needs"),
    ("histogram too long, periodic",
     lambda: disksim.pair_histogram(np.zeros((2, 2)), 10, 100, boundary="periodic"),
     ArgumentError, "bins * dr at most half the shorter side"),
    ("histogram unknown boundary",
     lambda: disksim.pair_histogram(np.zeros((2, 2)), 1, 10, boundary="open"), ArgumentError,
     "boundary = 'open'"),
    ("histogram NaN centre", lambda: disksim.pair_histogram([[NAN, 0], [1, 1]], 1, 10),
     ArgumentError, "the centres finite"),
    ("psi6 negative cutoff", lambda: disksim.local_psi6(np.zeros((2, 2)), -1), ArgumentError,
     "cutoff and the box's sides"),
    ("psi6 of a Sim, cutoff str", lambda: sim().local_psi6("x"), TypeError, "cutoff"),
    ("memory of no disks", lambda: disksim.memory_needed(0, 1), ArgumentError, "n = 0"),
    ("load a missing file", lambda: disksim.load("/nonexistent/x.ckpt"), FileError, "No such file"),
    ("load a device", lambda: disksim.load("/dev/null"), FileError, "/dev/null: not a regular"),
    ("load path None", lambda: disksim.load(None), TypeError, "NoneType"),
    ("save path int", lambda: sim().save(3.5), TypeError, "float"),
    ("save nowhere", lambda: sim().save("/nonexistent/x.ckpt"), FileError, "No such file"),
]


@pytest.mark.parametrize("what, call, exception, words", BAD, ids=[b[0] for b in BAD])
def test_a_bad_argument_raises_the_documented_exception_with_the_librarys_words(
        what, call, exception, words):
    with pytest.raises(exception) as info:
        call()
    assert words in str(info.value)


def test_a_refused_parameter_names_its_field():
    with pytest.raises(ArgumentError) as info:
        disksim.Sim(10, 600)
    e = info.value
    assert e.field == "radius" and e.status == "DS_ERR_ARG"
    assert isinstance(e, ValueError) and isinstance(e, Error)
    with pytest.raises(ArgumentError) as info:
        disksim.Sim(5000, 6)
    assert info.value.status == "DS_ERR_PLACEMENT" and info.value.field == "n"


def test_the_exceptions_are_what_a_python_caller_catches():
    assert issubclass(disksim.ArgumentError, ValueError)
    assert issubclass(disksim.FormatError, ValueError)
    assert issubclass(disksim.FileError, OSError)
    assert issubclass(disksim.NoMemoryError, MemoryError)
    for e in (disksim.ArgumentError, disksim.FormatError, disksim.FileError, disksim.NoMemoryError):
        assert issubclass(e, disksim.Error)
    assert issubclass(disksim.Error, Exception) and not issubclass(disksim.Error, ValueError)
    assert disksim.Error("x").status is None and disksim.Error("x").field is None


def test_degraded_physics_is_a_runtime_warning_in_the_librarys_words():
    with pytest.warns(RuntimeWarning, match="pass through each other"):
        disksim.Sim(400, 0.1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(RuntimeWarning):
            disksim.Sim(400, 0.1)


def test_a_closed_sim_refuses_everything_and_says_so():
    s = disksim.Sim(10, 1)
    s.close()
    s.close()  # again: nothing
    assert s.closed and not s.running and "closed" in repr(s)
    calls = [lambda: s.step(), lambda: s.run(1), lambda: s.positions, lambda: s.velocities,
             lambda: s.set_state(np.zeros((10, 2))), lambda: s.write_frame("x"),
             lambda: s.to_ase(), lambda: s.reset_observables(), lambda: s.pair_histogram(1, 2),
             lambda: s.local_psi6(), lambda: s.params, lambda: s.__enter__(),
             lambda: s.save("x"), lambda: s.__reduce__()]
    calls += [lambda name=name: getattr(s, name) for name in (
        "n", "radius", "box", "box_y", "dt", "time", "steps", "integrator", "boundary",
        "placement", "broadphase", "kinetic_energy", "momentum", "pressure", "virial_pressure",
        "psi6", "collision_count", "wall_count", "wall_impulse", "pairs_tested",
        "collision_seconds")]
    for call in calls:
        with pytest.raises(Error, match="this Sim is closed"):
            call()


def test_a_sim_that_was_never_initialised_refuses_too():
    s = disksim.Sim.__new__(disksim.Sim)
    with pytest.raises(Error, match="closed"):
        s.run(1)
    assert "closed" in repr(s)


def test_a_second_init_replaces_the_simulation_and_a_failed_one_keeps_it():
    s = disksim.Sim(10, 1)
    s.__init__(20, 2, integrator="event")
    assert s.n == 20 and s.integrator == "event"
    with pytest.raises(ArgumentError):
        s.__init__(0, 2)
    assert s.n == 20


class Evil:
    """A number that closes the Sim while it is being converted."""

    def __init__(self, s, value):
        self.s, self.value = s, value

    def __index__(self):
        self.s.close()
        return self.value

    __float__ = lambda self: float(self.__index__())  # noqa: E731

    def __array__(self, dtype=None):
        self.s.close()
        return np.zeros((self.s_n, 2))


def test_an_argument_that_closes_the_sim_meanwhile_is_no_crash():
    s = disksim.Sim(10, 1)
    with pytest.raises(Error, match="closed"):
        s.run(Evil(s, 5))
    s = disksim.Sim(10, 1)
    with pytest.raises(Error, match="closed"):
        s.pair_histogram(Evil(s, 1), 4)
    s = disksim.Sim(10, 1)
    evil = Evil(s, 0)
    evil.s_n = 10
    with pytest.raises(Error, match="closed"):
        s.set_state(evil)


# Values for the fuzz: of every type and every awkward size.
VALUES = [0, 1, 2, 3, 7, 20, 400, -1, -2**63, 2**31, 2**32, 2**64, 10**30, True, None, 0.0, -0.0,
          1e-300, 0.5, 5.0, 49.9, 1e9, 1e300, NAN, INF, -INF, 5j, "", "a", "walls", "periodic",
          "event", "step", "lattice", "random", "cells", "sap", "auto", "brute", "strips", b"x",
          "\0", [], [[1, 2]], [[1, 2], [3, 4]], object(), np.float64(3), np.int32(4),
          np.zeros((20, 2)), np.full((20, 2), NAN), np.ones((20, 2)) * 500, np.zeros((0, 2)),
          np.zeros((2, 2, 2)), np.zeros(5, dtype=complex), np.arange(40.0).reshape(20, 2)]
SIM_KEYWORDS = ["seed", "integrator", "boundary", "placement", "box", "box_y", "dt", "speed",
                "broadphase", "bogus"]
OK_SIZES = [1, 2, 3, 20]  # fuzzed Sims are small, so the fuzz stays fast


def fuzz_call(rng, s, tmp_path):
    pick = rng.choice
    target = rng.randrange(11)
    if target == 0:
        kwargs = {k: pick(VALUES) for k in rng.sample(SIM_KEYWORDS, rng.randrange(4))}
        # A valid n and radius half the time, so the keywords get judged too.
        n = pick(OK_SIZES) if rng.random() < 0.5 else pick(VALUES)
        radius = pick([1.0, 5.0]) if rng.random() < 0.5 else pick(VALUES)
        t = disksim.Sim(n, radius, **kwargs)
        t.run(pick([0, 1, 10]))
        return t.positions
    if target == 1:
        v = pick(VALUES)
        if isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= 1000:
            return s.run(v)  # larger valid counts would only take long
        if not isinstance(v, (int, np.integer)) or isinstance(v, bool):
            return s.run(v)
        if v < 0 or v >= 2**64:
            return s.run(v)
        return None
    if target == 2:
        return s.set_state(pick(VALUES), pick(VALUES))
    if target == 3:
        # velocities is read by its truth, as Python's flags are (an array
        # has none: numpy's own ValueError, not the module's to judge)
        return s.write_frame(pick([tmp_path / "f.txt", pick(VALUES)]),
                             velocities=pick([False, True, 0, 1, None, "", "x"]))
    if target == 4:
        return disksim.read_frame(pick([tmp_path / "f.txt", pick(VALUES)]))
    if target == 5:
        return disksim.pair_histogram(pick(VALUES), pick(VALUES), pick([1, 10, pick(VALUES)]),
                                      boundary=pick(["walls", "periodic", pick(VALUES)]))
    if target == 6:
        return disksim.local_psi6(pick(VALUES), pick(VALUES), box=pick([1000.0, pick(VALUES)]))
    if target == 7:
        return s.pair_histogram(pick(VALUES), pick([1, 10, pick(VALUES)]))
    if target == 8:
        return s.save(pick([tmp_path / "s.ckpt", pick(VALUES)]))
    if target == 9:
        return disksim.load(pick([tmp_path / "s.ckpt", tmp_path / "f.txt", pick(VALUES)]))
    return disksim.memory_needed(pick(VALUES), pick(VALUES))


def test_two_thousand_random_calls_raise_or_succeed_and_never_crash(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # paths such as "a" or b"x" are written here
    rng = random.Random(26)
    s = disksim.Sim(20, 5, integrator="event")
    outcomes = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        for _ in range(2000):
            try:
                fuzz_call(rng, s, tmp_path)
                outcome = "ok"
            except (TypeError, Error) as e:  # the documented ones (Error covers the rest)
                outcome = type(e).__name__
            except MemoryError as e:  # numpy's own, for a huge array request
                outcome = type(e).__name__
            outcomes[outcome] = outcomes.get(outcome, 0) + 1
    # The fuzz reached both sides: calls that ran and calls that were refused.
    assert outcomes.get("ok", 0) > 200 and outcomes.get("ArgumentError", 0) > 200
    assert outcomes.get("TypeError", 0) > 200 and outcomes.get("FileError", 0) > 0
    # and the Sim it hammered is still a working simulation
    s.run(10)
    assert s.positions.shape == (20, 2)
