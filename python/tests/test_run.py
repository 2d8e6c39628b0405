# SPDX-License-Identifier: MIT
"""Sim.run(steps=None, *, until=None, callback=None, every=1): up to a
time, and with a callback every k steps, while run(steps) stays what it
was, to the bit. No test here measures a time."""
import signal
import threading

import numpy as np
import pytest

import disksim


def state(s):
    return (s.positions, s.velocities, s.steps, s.collision_count, s.wall_count,
            s.virial_pressure, s.pressure)


def same(a, b):
    return all(np.array_equal(x, y) for x, y in zip(state(a), state(b)))


@pytest.mark.parametrize("integrator", disksim.INTEGRATORS)
def test_a_run_with_a_callback_is_the_run_without_one_to_the_bit(integrator):
    plain = disksim.Sim(300, 6, integrator=integrator, boundary="periodic", seed=2)
    called = disksim.Sim(300, 6, integrator=integrator, boundary="periodic", seed=2)
    plain.run(1000)
    seen = []
    called.run(1000, callback=lambda s: seen.append(s.positions), every=7)
    assert same(plain, called) and len(seen) == 1000 // 7
    stepped = disksim.Sim(300, 6, integrator=integrator, boundary="periodic", seed=2)
    for _ in range(1000):
        stepped.step()
    assert same(plain, stepped)


def test_the_callback_comes_at_every_multiple_of_every_of_the_step_count():
    s = disksim.Sim(50, 5)
    s.run(3)
    at = []
    s.run(20, callback=lambda t: at.append(t.steps), every=5)
    assert at == [5, 10, 15, 20] and s.steps == 23
    s.run(until=0.031, callback=lambda t: at.append(t.steps), every=5)
    assert at[4:] == [25, 30] and s.steps == 31
    got = []
    s.run(2, callback=lambda t: got.append(t))
    assert got == [s, s]  # every=1: each step, with the Sim itself


def test_a_callback_stops_the_run_by_returning_false_and_the_steps_stay():
    for stop in (False, 0, np.False_, ""):
        s = disksim.Sim(50, 5)
        s.run(100, callback=lambda t, stop=stop: stop if t.steps >= 30 else None, every=10)
        assert s.steps == 30, stop
    s = disksim.Sim(50, 5)
    s.run(100, callback=lambda t: True, every=10)  # true and None go on
    assert s.steps == 100


class Stop(Exception):
    pass


def test_a_callback_that_raises_stops_the_run_with_its_exception_and_the_steps_stay():
    s = disksim.Sim(50, 5, integrator="event")
    twin = disksim.Sim(50, 5, integrator="event")

    def fail(t):
        if t.steps == 40:
            raise Stop("at 40")

    with pytest.raises(Stop, match="at 40"):
        s.run(100, callback=fail, every=20)
    assert s.steps == 40 and not s.running
    twin.run(40)
    assert same(s, twin)
    s.run(10)  # and it goes on
    assert s.steps == 50


def test_the_callback_may_read_and_change_the_sim_and_even_run_it():
    s = disksim.Sim(50, 5, integrator="event")
    seen = []

    def look(t):
        seen.append((t.running, t.positions.shape, t.steps))
        t.scale_velocities(1.0)
        if t.steps == 10:
            t.run(5)  # the target is a step count: the outer run ends at 30 all the same

    s.run(30, callback=look, every=10)
    assert seen == [(False, (50, 2), 10), (False, (50, 2), 20), (False, (50, 2), 30)]
    assert s.steps == 30


def test_a_callback_that_closes_or_recreates_the_sim_ends_the_run():
    s = disksim.Sim(50, 5)
    with pytest.raises(disksim.Error, match="closed"):
        s.run(100, callback=lambda t: t.close(), every=10)
    s = disksim.Sim(50, 5)
    with pytest.raises(disksim.Error, match="re-created"):
        s.run(100, callback=lambda t: t.__init__(60, 5), every=10)
    assert s.n == 60 and s.steps == 0


def test_until_runs_to_the_first_step_whose_time_reaches_it():
    s = disksim.Sim(50, 5)  # dt = 0.001
    s.run(until=1.0)
    assert s.steps == 1000 and s.time == 1.0
    s.run(until=1.0015)  # between two steps: the one after
    assert s.steps == 1002
    s.run(until=0.5)  # already past: nothing
    s.run(until=-1.0)
    assert s.steps == 1002
    # 0.07 / 0.01 is 7.000000000000001 in binary: still step 7, not 8
    t = disksim.Sim(50, 5, dt=0.01)
    t.run(until=0.07)
    assert t.steps == 7
    # and the same disks as run(steps)
    u = disksim.Sim(50, 5)
    u.run(1002)
    assert same(s, u)


REFUSED = [
    (lambda s: s.run(), TypeError, "run() needs steps or until"),
    (lambda s: s.run(10, until=1.0), TypeError, "steps or until, not both"),
    (lambda s: s.run(until=float("nan")), disksim.ArgumentError, "until = nan must be a finite"),
    (lambda s: s.run(until=float("inf")), disksim.ArgumentError, "until = inf"),
    (lambda s: s.run(until=1e30), disksim.ArgumentError, "beyond 2**64 - 1 steps"),
    (lambda s: s.run(until="1"), TypeError, "until must be a real number"),
    (lambda s: s.run(10, callback=3), TypeError, "callback must be callable, not int"),
    (lambda s: s.run(10, callback=print, every=0), disksim.ArgumentError, "every = 0"),
    (lambda s: s.run(10, callback=print, every=1.5), TypeError, "every must be an int"),
    (lambda s: s.run(10, every=0), disksim.ArgumentError, "every = 0"),
    (lambda s: s.run(2**64 - 1), disksim.ArgumentError, "past 2**64 - 1"),
]


@pytest.mark.parametrize("call, exception, words", REFUSED, ids=[w for _, _, w in REFUSED])
def test_a_run_that_cannot_be_is_refused_before_any_step(call, exception, words):
    s = disksim.Sim(50, 5)
    s.step()
    with pytest.raises(exception) as info:
        call(s)
    assert words in str(info.value) and s.steps == 1


def test_every_without_a_callback_is_taken_and_does_nothing():
    s = disksim.Sim(50, 5)
    s.run(10, callback=None, every=100)
    assert s.steps == 10


def test_a_run_until_a_time_lets_other_threads_run():
    """As test_threads: another thread sees running while the run, cut by
    its callback, is inside the library."""
    s = disksim.Sim(4000, 2, integrator="event")
    started = threading.Event()
    calls = []
    worker = threading.Thread(
        target=lambda: (started.set(), s.run(until=70.0, callback=calls.append, every=10000)))
    worker.start()
    started.wait()
    seen_running = False
    while worker.is_alive() and not seen_running:
        seen_running = s.running
    worker.join()
    assert seen_running and s.steps == 70000 and len(calls) == 7


def test_a_signal_stops_a_run_with_a_callback_between_steps():
    if not hasattr(signal, "setitimer"):
        pytest.skip("no setitimer")

    def stop(signum, frame):
        raise Stop()

    s = disksim.Sim(4000, 2, integrator="event")
    calls = []
    previous = signal.signal(signal.SIGALRM, stop)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.05)
        with pytest.raises(Stop):
            s.run(until=1000.0, callback=calls.append, every=100)  # seconds of work
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    done = s.steps
    assert 0 < done < 10**6 and not s.running and len(calls) == done // 100
    s.run(10)
    assert s.steps == done + 10
