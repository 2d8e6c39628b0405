# SPDX-License-Identifier: MIT
"""Exact checkpoints from Python: Sim.save and disksim.load, pickle and copy,
all through the library's ds_checkpoint_save / ds_checkpoint_parse. A Sim made from a
checkpoint goes on bit for bit as the saved one would have."""
import copy
import os
import pickle
import threading

import numpy as np
import pytest

import disksim


def same(a, b):
    return (np.array_equal(a.positions, b.positions) and np.array_equal(a.velocities, b.velocities)
            and a.steps == b.steps and a.collision_count == b.collision_count
            and a.wall_count == b.wall_count and a.virial_pressure == b.virial_pressure
            and a.pressure == b.pressure and a.pairs_tested == b.pairs_tested)


KINDS = [dict(integrator=i, boundary=b) for i in disksim.INTEGRATORS for b in ("walls", "periodic")]


@pytest.mark.parametrize("kind", KINDS, ids=lambda k: "%(integrator)s-%(boundary)s" % k)
def test_a_loaded_sim_goes_on_bit_for_bit(tmp_path, kind):
    s = disksim.Sim(500, 6, seed=11, **kind)
    s.run(300)
    s.reset_observables()
    s.run(200)  # accumulators mid-way, so they are part of the checkpoint
    s.save(tmp_path / "s.ckpt")
    t = disksim.load(str(tmp_path / "s.ckpt"))
    assert same(s, t)
    s.run(1000)
    t.run(1000)
    assert same(s, t)


def test_what_a_loaded_sim_knows_of_its_arguments(tmp_path):
    s = disksim.Sim(100, 4, seed=9, speed=50.0, placement="lattice", box_y=900.0,
                    integrator="event")
    s.save(tmp_path / "s.ckpt")
    t = disksim.load(tmp_path / "s.ckpt")
    assert t.params == {"n": 100, "radius": 4.0, "integrator": "event", "boundary": "walls",
                        "box": 1000.0, "box_y": 900.0, "dt": 0.001, "broadphase": s.broadphase}
    assert t.placement is None and s.placement == "lattice"
    assert "seed" not in repr(t) and "integrator='event'" in repr(t)


@pytest.mark.parametrize("how", [copy.copy, copy.deepcopy,
                                 lambda s: pickle.loads(pickle.dumps(s))])
def test_a_copy_or_a_pickle_is_an_independent_sim_that_goes_on_bit_for_bit(how):
    s = disksim.Sim(300, 6, integrator="event", boundary="periodic", seed=5)
    s.run(250)
    c = how(s)
    assert c is not s and same(s, c) and c.params == s.params
    c.run(700)
    assert c.steps == 950 and s.steps == 250  # running one leaves the other
    s.run(700)
    assert same(s, c)


def checkpoint_bytes(s):
    """What save() writes, in memory: the pickle carries the same bytes."""
    return s.__reduce__()[1][1]


COPIES = [copy.copy, copy.deepcopy, lambda s: pickle.loads(pickle.dumps(s))]
COPY_IDS = ["copy", "deepcopy", "pickle"]


def dense_lattice(integrator):
    """1024 disks at area fraction 0.8 on a lattice: above the 0.54 that
    random placement of more than 1000 disks is refused at."""
    r = (0.8 * 1e6 / (1024 * np.pi)) ** 0.5
    return disksim.Sim(1024, r, integrator=integrator, boundary="periodic", placement="lattice")


def dense_mixture(integrator):
    """A 50:50 mixture of radii r and 1.4 r at 0.6 (lattice sites are the
    larger diameter apart: 0.685 at most), whose reference radius is 1.4 r:
    as disks of that radius alone they would cover 0.795."""
    r = (0.6 * 1e6 / (512 * np.pi * (1 + 1.4**2))) ** 0.5
    return disksim.Sim(1024, 1.4 * r, species=[(512, r), (512, 1.4 * r)], mass="area",
                       integrator=integrator, boundary="periodic", placement="lattice")


@pytest.mark.parametrize("how", COPIES, ids=COPY_IDS)
@pytest.mark.parametrize("make", [dense_lattice, dense_mixture])
@pytest.mark.parametrize("integrator", disksim.INTEGRATORS)
def test_a_copy_or_a_pickle_of_any_sim_is_its_checkpoint_to_the_byte(tmp_path, how, make,
                                                                      integrator):
    # A loaded Sim's params have no placement (its checkpoint does not say):
    # the copy used to be judged as a new random placement of them, and
    # refused ("random placement of more than 1000 disks cannot exceed
    # 0.54"); a loaded mixture's, as disks of the reference radius alone.
    s = make(integrator)
    s.run(20)
    s.save(tmp_path / "s.ckpt")
    saved = (tmp_path / "s.ckpt").read_bytes()
    loaded = disksim.load(tmp_path / "s.ckpt")
    for original in (s, loaded):
        c = how(original)
        assert checkpoint_bytes(c) == checkpoint_bytes(original) == saved
        assert c.params == original.params and c.placement == original.placement
        c.run(30)  # and it goes on as the original does, which stays where it was
        assert checkpoint_bytes(original) == saved
        original.run(30)  # (the bytes now differ in collision_seconds, a wall-clock time)
        assert same(c, original)
    assert same(s, loaded)


class Labelled(disksim.Sim):
    """A subclass with an attribute of its own, defined here so pickle finds it."""


def test_a_subclass_pickles_as_itself_with_its_attributes():
    s = Labelled(50, 3)
    s.label = "run 7"
    t = pickle.loads(pickle.dumps(s))
    assert type(t) is Labelled and t.label == "run 7" and same(s, t)


def test_a_damaged_checkpoint_is_a_format_error_never_a_crash(tmp_path):
    s = disksim.Sim(40, 5, integrator="event")
    s.run(50)
    s.save(tmp_path / "s.ckpt")
    data = (tmp_path / "s.ckpt").read_bytes()
    restore, (cls, checkpoint, params), _ = s.__reduce__()
    assert checkpoint == data  # the pickle carries the file's bytes
    for where in [0, 8, 20, len(data) // 2, len(data) - 1]:
        damaged = bytearray(data)
        damaged[where] ^= 0x5A
        (tmp_path / "bad.ckpt").write_bytes(bytes(damaged))
        with pytest.raises(disksim.FormatError):
            disksim.load(tmp_path / "bad.ckpt")
        with pytest.raises(disksim.FormatError):
            restore(cls, bytes(damaged), params)
    for length in [0, 7, 40, len(data) - 1]:
        (tmp_path / "short.ckpt").write_bytes(data[:length])
        with pytest.raises(disksim.FormatError) as info:
            disksim.load(tmp_path / "short.ckpt")
        assert str(tmp_path / "short.ckpt") in str(info.value)
    s.write_frame(tmp_path / "frame.txt")
    with pytest.raises(disksim.FormatError):
        disksim.load(tmp_path / "frame.txt")  # a frame is no checkpoint
    with pytest.raises(TypeError):
        restore(int, data, params)
    # arguments that are not the checkpoint's (any it says of itself)
    for wrong in (dict(n=41), dict(box=900.0), dict(box_y=900.0), dict(dt=0.002),
                  dict(integrator="step"), dict(boundary="periodic"), dict(seed=1),
                  dict(placement="lattice")):
        with pytest.raises(disksim.ArgumentError, match="not the checkpoint's"):
            restore(cls, data, dict(params, **wrong))


def test_a_length_field_beyond_the_file_is_a_format_error_not_no_memory(tmp_path):
    # The payload's length (bytes 32..40) forged to 2^42: the file is
    # truncated, which python.md says is a FormatError; the library used to
    # allocate what the header announced first and report no memory.
    s = disksim.Sim(40, 5)
    s.save(tmp_path / "s.ckpt")
    data = bytearray((tmp_path / "s.ckpt").read_bytes())
    data[32:40] = (1 << 42).to_bytes(8, "little")
    (tmp_path / "long.ckpt").write_bytes(bytes(data))
    with pytest.raises(disksim.FormatError, match="truncated"):
        disksim.load(tmp_path / "long.ckpt")


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full")
def test_a_checkpoint_that_cannot_be_written_is_a_file_error():
    with pytest.raises(disksim.FileError):
        disksim.Sim(10, 1).save("/dev/full")


def test_a_checkpoint_is_read_from_a_regular_file_only():
    # ds_checkpoint_load reads to the end of the file, which /dev/zero never has
    with pytest.raises(disksim.FileError, match="not a regular file"):
        disksim.load("/dev/zero")
    with pytest.raises(disksim.FileError, match="not a regular file"):
        disksim.load("/")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no named pipes")
def test_a_named_pipe_is_refused_without_waiting_for_a_writer(tmp_path):
    # Opening a named pipe for reading waits for a writer: load() must not
    # open it that way. The load runs in a thread so that a regression fails
    # here instead of hanging the suite: after the guard's time a writer
    # opens and closes the pipe, which lets a blocked open() go on.
    fifo = tmp_path / "c.ckpt"
    os.mkfifo(fifo)
    outcome = []

    def load():
        try:
            outcome.append(disksim.load(fifo))
        except Exception as e:  # judged below, in the test's own thread
            outcome.append(e)

    reader = threading.Thread(target=load, daemon=True)
    reader.start()
    reader.join(timeout=20)  # a hang guard, not a timing: the refusal is immediate
    blocked = reader.is_alive()
    if blocked:
        os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        reader.join(timeout=20)
    assert not blocked, "disksim.load blocked in open() on a named pipe with no writer"
    assert isinstance(outcome[0], disksim.FileError), outcome
    assert "not a regular file" in str(outcome[0])
