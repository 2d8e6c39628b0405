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


def periodic():
    return disksim.Sim(20, 5, integrator="event", boundary="periodic")


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
     "integrator = 'leapfrog' is not one of 'step', 'event', 'chain'"),
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
    # a bool is an int to Python, but True is no count: refused as numpy does
    ("n a bool", lambda: disksim.Sim(True, 5), TypeError, "n must be an int, not bool"),
    ("seed a bool", lambda: disksim.Sim(10, 1, seed=False), TypeError,
     "seed must be an int, not bool"),
    ("steps a bool", lambda: sim().run(True), TypeError, "steps must be an int, not bool"),
    ("steps a numpy bool", lambda: sim().run(np.True_), TypeError,
     "steps must be an int, not numpy.bool"),  # numpy.bool_ before numpy 2
    ("species count a bool", lambda: disksim.Sim(2, 5, species=[(True, 5), (1, 7)]), TypeError,
     "species[0] count must be an int, not bool"),
    ("bins a bool", lambda: disksim.pair_histogram(np.zeros((2, 2)), 1, True), TypeError,
     "bins must be an int, not bool"),
    ("memory of a bool n", lambda: disksim.memory_needed(True, 1), TypeError,
     "n must be an int, not bool"),
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
     "dr = 0 must be finite and > 0"),
    ("histogram no bins", lambda: disksim.pair_histogram(np.zeros((2, 2)), 1, 0), ArgumentError,
     "bins = 0"),
    ("histogram too many bins", lambda: disksim.pair_histogram(np.zeros((2, 2)), 1, 2**62),
     NoMemoryError, "bins needs"),
    ("histogram too long, periodic",
     lambda: disksim.pair_histogram(np.zeros((2, 2)), 10, 100, boundary="periodic"),
     ArgumentError, "the range bins dr = 1000 must be at most half of each periodic side (500)"),
    ("histogram unknown boundary",
     lambda: disksim.pair_histogram(np.zeros((2, 2)), 1, 10, boundary="open"), ArgumentError,
     "boundary = 'open'"),
    ("histogram NaN centre", lambda: disksim.pair_histogram([[NAN, 0], [1, 1]], 1, 10),
     ArgumentError, "positions: centre 0 is not finite"),
    ("psi6 negative cutoff", lambda: disksim.local_psi6(np.zeros((2, 2)), -1), ArgumentError,
     "cutoff = -1 must be finite and > 0"),
    ("psi6 of a Sim, cutoff str", lambda: sim().local_psi6("x"), TypeError, "cutoff"),
    ("memory of no disks", lambda: disksim.memory_needed(0, 1), ArgumentError, "n = 0"),
    ("load a missing file", lambda: disksim.load("/nonexistent/x.ckpt"), FileError, "No such file"),
    ("load a device", lambda: disksim.load("/dev/null"), FileError, "/dev/null: not a regular"),
    ("load path None", lambda: disksim.load(None), TypeError, "NoneType"),
    ("save path int", lambda: sim().save(3.5), TypeError, "float"),
    ("save nowhere", lambda: sim().save("/nonexistent/x.ckpt"), FileError, "No such file"),
    # mixtures: the library's sentences (field 'mixture'), and what only the
    # module sees (a negative count, an array of another length)
    ("species counts short", lambda: disksim.Sim(10, 5, species=[(4, 5), (5, 7)]), ArgumentError,
     "mixture: the species' counts add up to 9, not n = 10"),
    ("species counts over", lambda: disksim.Sim(10, 5, species=[(8, 5), (5, 7)]), ArgumentError,
     "add up to more than n = 10"),
    ("negative species count", lambda: disksim.Sim(10, 5, species=[(-4, 5), (14, 7)]),
     ArgumentError, "species[0] count = -4 must not be negative"),
    ("species count beyond 64 bits", lambda: disksim.Sim(10, 5, species=[(2**64, 5)]),
     NoMemoryError, "species[0] count = 18446744073709551616 cannot be held in memory"),
    ("NaN species radius", lambda: disksim.Sim(10, 5, species=[(5, 5), (5, NAN)]), ArgumentError,
     "mixture: disk 5's radius nan is not a number > 0"),
    ("negative species mass", lambda: disksim.Sim(10, 5, species=[(5, 5), (5, 7, -1)]),
     ArgumentError, "mixture: species 1's mass -1 is not a finite number >= 0 (0 for the rule)"),
    ("species radius too big", lambda: disksim.Sim(10, 5, species=[(5, 5), (5, 600)]),
     ArgumentError, "mixture: its largest radius, 600, does not fit a box of 1000 x 1000"),
    ("species of four items", lambda: disksim.Sim(10, 5, species=[(10, 5, 1, 2)]), ArgumentError,
     "species[0] has 4 items: it must be (count, radius), (count, radius, mass), (count, "
     "radius, name) or (count, radius, mass, name)"),
    ("species name with a space", lambda: disksim.Sim(10, 5, species=[(5, 5, "a b"), (5, 7)]),
     ArgumentError, "mixture: species 0's name must be 1 to 15 printable characters without a "
     "space"),
    ("species name too long", lambda: disksim.Sim(10, 5, species=[(10, 5, "x" * 16)]),
     ArgumentError, "species 0's name must be 1 to 15 printable characters"),
    ("species names the same", lambda: disksim.Sim(10, 5, species=[(5, 5, "s"), (5, 7, "s")]),
     ArgumentError, 'mixture: species 0 and 1 are both named "s"'),
    ("species named like a default", lambda: disksim.Sim(10, 5, species=[(5, 5), (5, 7, "A")]),
     ArgumentError, 'mixture: species 0 and 1 are both named "A"'),
    ("species name with a NUL", lambda: disksim.Sim(10, 5, species=[(10, 5, "a\0b")]),
     ArgumentError, "species[0] name contains a NUL character"),
    ("species not a sequence", lambda: disksim.Sim(10, 5, species=3), TypeError,
     "species must be a sequence of (count, radius)"),
    ("species item not a tuple", lambda: disksim.Sim(10, 5, species=[5]), TypeError,
     "species[0] must be a tuple (count, radius)"),
    ("species as text", lambda: disksim.Sim(10, 5, species="ab"), TypeError,
     "species must be a sequence"),
    ("species float count", lambda: disksim.Sim(10, 5, species=[(10.0, 5)]), TypeError,
     "species[0] count must be an int"),
    ("no species", lambda: disksim.Sim(10, 5, species=[]), ArgumentError,
     "give either species (kinds, with their count) or radii per disk, not both and not neither"),
    ("species and radii", lambda: disksim.Sim(3, 5, species=[(3, 5)], radii=[5, 5, 5]),
     ArgumentError, "not both and not neither"),
    ("radii of another n", lambda: disksim.Sim(10, 5, radii=[5, 6]), ArgumentError,
     "radii has shape (2,): it must be (10,), one per disk (n)"),
    ("radii of 2 dimensions", lambda: disksim.Sim(2, 5, radii=np.ones((2, 1))), ArgumentError,
     "radii has shape (2, 1)"),
    ("radii of text", lambda: disksim.Sim(2, 5, radii=["a", "b"]), ArgumentError,
     "radii must be an (n,) array of numbers"),
    ("zero radius in radii", lambda: disksim.Sim(2, 5, radii=[5, 0]), ArgumentError,
     "mixture: disk 1's radius 0 is not a number > 0"),
    ("masses of another n", lambda: disksim.Sim(3, 5, radii=[5, 5, 5], masses=[1]), ArgumentError,
     "masses has shape (1,): it must be (3,)"),
    ("masses without radii", lambda: disksim.Sim(3, 5, masses=[1, 1, 1]), ArgumentError,
     "give either species"),
    ("masses with species", lambda: disksim.Sim(3, 5, species=[(3, 5)], masses=[1, 1, 1]),
     ArgumentError, "masses is per disk, given with radii"),
    ("infinite mass", lambda: disksim.Sim(2, 5, radii=[5, 5], masses=[1, INF]), ArgumentError,
     "mixture: disk 1's mass is not a finite number > 0"),
    ("unknown mass rule", lambda: disksim.Sim(2, 5, radii=[5, 5], mass="volume"), ArgumentError,
     "mass = 'volume' is not one of 'equal', 'area'"),
    ("mass rule not a str", lambda: disksim.Sim(2, 5, mass=1), TypeError, "mass must be a str"),
    ("mixture beyond random placement",
     lambda: disksim.Sim(4000, 6, species=[(2000, 6), (2000, 8.4)]), ArgumentError,
     "disks of radii 6 to 8.4"),
    ("memory of a bad mixture", lambda: disksim.memory_needed(10, 5, species=[(3, 5)]),
     ArgumentError, "add up to 3, not n = 10"),
    # growth, velocities, contacts: the library's sentences (2.x's module
    # derived them; the library gave a status only)
    ("growth with walls", lambda: disksim.Sim(10, 5, integrator="event").set_growth(0.1),
     ArgumentError, "boundary = walls: growth needs a periodic box"),
    ("growth with the time step", lambda: disksim.Sim(10, 5, boundary="periodic").set_growth(0.1),
     ArgumentError, "integrator = step: growth needs the event-driven integrator"),
    ("negative growth rate", lambda: periodic().set_growth(-1), ArgumentError,
     "rate = -1 must be a finite number >= 0"),
    ("NaN growth rate", lambda: periodic().set_growth(NAN), ArgumentError, "rate = nan"),
    ("until_eta passed", lambda: periodic().set_growth(0.1, until_eta=0.001), ArgumentError,
     "until_eta = 0.001 must be above the start's area fraction 0.0015708"),
    ("until_eta beyond 1", lambda: periodic().set_growth(0.1, until_eta=1.5), ArgumentError,
     "until_eta = 1.5"),
    ("until_z below 1", lambda: periodic().set_growth(0.1, until_z=0.5), ArgumentError,
     "until_z = 0.5 must be a reduced pressure > 1 and <= 1e9"),
    ("growth rate a str", lambda: periodic().set_growth("fast"), TypeError,
     "rate must be a real number"),
    ("no growth rate", lambda: periodic().set_growth(), TypeError, "rate"),
    ("scale by 0", lambda: sim().scale_velocities(0), ArgumentError,
     "factor = 0 must be finite and > 0"),
    ("scale by inf", lambda: sim().scale_velocities(INF), ArgumentError, "factor = inf"),
    ("scale beyond 1e12", lambda: sim().scale_velocities(1e20), ArgumentError,
     "factor = 1e+20 would take a velocity component from 100 to 1e+22, beyond 1e+12"),
    ("contacts gap 1", lambda: sim().contacts(gap=1.0), ArgumentError, "gap = 1 must be in [0, 1)"),
    ("contacts negative gap", lambda: sim().contacts(-1e-3), ArgumentError, "gap = -0.001"),
    ("contacts gap None", lambda: sim().contacts(None), TypeError, "gap must be a real number"),
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
             lambda: s.save("x"), lambda: s.__reduce__(), lambda: s.set_growth(1.0),
             lambda: s.scale_velocities(2.0), lambda: s.contacts(), lambda: s.rdf(10.0, 2),
             lambda: s.freud_box(), lambda: s.freud_points(), lambda: len(s)]
    calls += [lambda name=name: getattr(s, name) for name in (
        "n", "radius", "box", "box_y", "dt", "time", "steps", "integrator", "boundary",
        "placement", "broadphase", "kinetic_energy", "momentum", "pressure", "virial_pressure",
        "psi6", "collision_count", "wall_count", "wall_impulse", "pairs_tested",
        "collision_seconds", "radii", "masses", "radius_max", "area_fraction", "growth_state",
        "growth_z", "images", "unwrapped")]
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
          np.zeros((2, 2, 2)), np.zeros(5, dtype=complex), np.arange(40.0).reshape(20, 2),
          "equal", "area", [(10, 5.0), (10, 7.0)], [(20, 5.0, 2.0)], [(1, 1.0)], [(-1, 5.0)],
          [(20, NAN)], [(2**64, 1.0)], [(20,)], [(20, 5.0, 1.0, 1.0)], [("a", 1.0)], [None],
          ((3, 5.0), (17, 1.0, 0.0)), np.full(20, 5.0), np.linspace(1.0, 9.0, 20), np.ones(3),
          np.full(20, -1.0), np.full(20, INF), np.ones((20, 1)), 1e-9, 0.999, 1.5, 1e6, 2e9]
SIM_KEYWORDS = ["seed", "integrator", "boundary", "placement", "box", "box_y", "dt", "speed",
                "broadphase", "bogus", "species", "radii", "masses", "mass"]
REFUSED = [-1, NAN, INF, -INF, "x", None, 5j]
MIXTURE = {"species": [[(10, 5.0), (10, 7.0)], [(20, 5.0, 2.0)], [(5, 3.0), (15, 6.0)]],
           "radii": [np.full(20, 5.0), np.linspace(1.0, 9.0, 20)],
           "masses": [np.arange(1.0, 21.0), np.full(20, 0.5)], "mass": ["equal", "area"]}
OK_SIZES = [1, 2, 3, 20]  # fuzzed Sims are small, so the fuzz stays fast


def fuzz_call(rng, s, g, tmp_path):
    pick = rng.choice
    target = rng.randrange(15)
    if target == 0:
        kwargs = {k: pick(VALUES) for k in rng.sample(SIM_KEYWORDS, rng.randrange(4))}
        # a valid mixture a third of the time, so the rest gets judged with it
        if rng.random() < 0.3:
            kwargs.update({k: pick(MIXTURE[k]) for k in rng.sample(list(MIXTURE), 2)})
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
    if target == 10:
        # growth on a Sim where it runs (g) or not (s), then a few steps
        # Rates from a list: a rate that grows a radius much faster than the
        # disks move (rate R >> speed, 1e6 here) jams within a step, whose
        # collisions then take minutes (issue note); the refused ones all.
        t = pick([g, g, s])
        args = [pick([0.0, 0.5, 5.0] + REFUSED)]
        args += [pick([0.0, 0.3, 0.6, pick(VALUES)]) for _ in range(rng.randrange(3))]
        t.set_growth(*args)
        t.run(pick([0, 1, 5]))
        return t.growth_state, t.growth_z
    if target == 11:
        # a valid factor and its inverse (the energy stays), or a refused one
        t, factor = pick([g, s]), pick([0.5, 2.0, 0, 1e20, 1e300] + REFUSED)
        t.scale_velocities(factor)
        return t.scale_velocities(1 / factor)
    if target == 12:
        return pick([g, s]).contacts(*[pick([1e-4, pick(VALUES)])][:rng.randrange(2)])
    if target == 13:
        t = pick([g, s])
        return t.radii, t.masses, t.radius_max, t.area_fraction, t.growth_state, t.params
    kwargs = {k: pick(MIXTURE[k] + [pick(VALUES)]) for k in rng.sample(list(MIXTURE), 2)}
    return disksim.memory_needed(pick([20, pick(VALUES)]), pick([5.0, pick(VALUES)]), **kwargs)


def test_two_thousand_random_calls_raise_or_succeed_and_never_crash(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # paths such as "a" or b"x" are written here
    rng = random.Random(26)
    s = disksim.Sim(20, 5, integrator="event")
    g = disksim.Sim(20, 5, integrator="event", boundary="periodic",
                    species=[(10, 5.0), (10, 7.0)], mass="area")
    outcomes = {}
    eta0 = g.area_fraction
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        for _ in range(2000):
            try:
                fuzz_call(rng, s, g, tmp_path)
                outcome = "ok"
            except (TypeError, Error) as e:  # the documented ones (Error covers the rest)
                outcome = type(e).__name__
            except MemoryError as e:  # numpy's own, for a huge array request
                outcome = type(e).__name__
            outcomes[outcome] = outcomes.get(outcome, 0) + 1
    # The fuzz reached both sides: calls that ran and calls that were refused.
    assert outcomes.get("ok", 0) > 200 and outcomes.get("ArgumentError", 0) > 200
    assert outcomes.get("TypeError", 0) > 200 and outcomes.get("FileError", 0) > 0
    # and the Sims it hammered are still working simulations
    s.run(10)
    g.run(10)
    assert s.positions.shape == (20, 2) and g.radii.shape == (20,)
    assert g.area_fraction > eta0  # and the fuzz's growth did grow it
