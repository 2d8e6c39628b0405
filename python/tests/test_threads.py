# SPDX-License-Identifier: MIT
"""Threads: run() releases the GIL, a Sim per thread gives the same results
as one after another, and a Sim used from two threads refuses instead of
racing. No test here measures a time: `tools/analysis/eos.sh -j` and
docs/sweeps.md are where speed is measured."""
import concurrent.futures
import signal
import threading

import numpy as np
import pytest

import disksim

SEEDS = [1, 2, 3, 4]


def simulate(seed):
    s = disksim.Sim(600, 6, seed=seed, integrator="event", boundary="periodic")
    s.run(3000)
    return s.positions, s.velocities, s.collision_count, s.virial_pressure


def test_threads_with_a_sim_each_give_what_one_after_another_gives():
    alone = [simulate(seed) for seed in SEEDS]
    with concurrent.futures.ThreadPoolExecutor(max_workers=len(SEEDS)) as pool:
        together = list(pool.map(simulate, SEEDS))
    for (p, v, c, z), (p2, v2, c2, z2) in zip(alone, together):
        assert np.array_equal(p, p2) and np.array_equal(v, v2) and c == c2 and z == z2
    # and the seeds do make different simulations
    assert not np.array_equal(alone[0][0], alone[1][0])


def test_run_lets_other_threads_run_and_a_sim_in_use_refuses_them():
    """If run() held the GIL, this thread could not execute a line while the
    other is inside run(), so it could never see s.running true: seeing it
    shows the GIL released. Using the Sim then raises Error (it would race
    the library otherwise); s.running itself never raises."""
    s = disksim.Sim(4000, 2, integrator="event")
    started = threading.Event()

    def work():
        started.set()
        s.run(70000)  # long enough (~0.5 s) to be caught inside

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    seen_running = refused = None
    while worker.is_alive() and refused is None:
        if s.running:
            seen_running = True
            try:
                s.positions
            except disksim.Error as e:
                refused = e
    worker.join()
    assert seen_running and refused is not None
    assert "in use by another thread" in str(refused)
    assert not s.running and s.steps == 70000  # and the Sim is whole afterwards
    s.step()
    assert s.steps == 70001 and s.positions.shape == (4000, 2)


class Stop(Exception):
    pass


def test_a_signal_stops_a_long_run_between_steps_and_the_sim_stays_whole():
    """Ctrl-C is SIGINT's KeyboardInterrupt; any handler that raises works the
    same way: run() takes signals between its chunks of steps."""
    if not hasattr(signal, "setitimer"):
        pytest.skip("no setitimer")

    def stop(signum, frame):
        raise Stop()

    s = disksim.Sim(4000, 2, integrator="event")
    previous = signal.signal(signal.SIGALRM, stop)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.05)
        with pytest.raises(Stop):
            s.run(10**6)  # seconds of work: the signal comes long before the end
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    done = s.steps
    assert 0 < done < 10**6 and not s.running
    s.run(10)  # and it goes on from where it stopped
    assert s.steps == done + 10
