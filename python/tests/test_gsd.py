# SPDX-License-Identifier: MIT
"""GSD files, read back by the gsd package (Debian: python3-gsd), hold
what the simulation says: every frame the command's --gsd writes and
every frame Python's Writer writes, field by field (the step, the 2D box,
the kinds' names and ids, masses, diameters, positions to float32
rounding, images, velocities and the logged observables). A file cut
short never reads as whole; an interrupted run keeps a GSD file of
exactly its frames, and a killed one restarted ends with the uninterrupted
run's; a Writer appending goes on with its file; a pipe is refused."""
import os
import signal
import subprocess
import time

import numpy as np
import pytest

import disksim

gsd_hoomd = pytest.importorskip("gsd.hoomd", reason="gsd is not installed (Debian: python3-gsd)")

# The observables logged under log/disksim/, as Sim names them.
LOGGED = {
    "time": lambda s: s.time,
    "kinetic_energy": lambda s: s.kinetic_energy,
    "px": lambda s: s.momentum[0],
    "py": lambda s: s.momentum[1],
    "collisions": lambda s: s.collision_count,
    "wall_reflections": lambda s: s.wall_count,
    "pressure": lambda s: s.pressure,
    "virial_pressure": lambda s: s.virial_pressure,
    "psi6": lambda s: s.psi6,
    "area_fraction": lambda s: s.area_fraction,
    "shear_offset": lambda s: s.shear_offset,
}


def expected(s):
    """What a frame of s must hold, taken from s now."""
    box = np.array([s.box, s.box_y])
    periodic = np.array([s.boundary != "walls", s.boundary == "periodic"])
    image = np.round((s.unwrapped - s.positions) / box).astype(np.int32)
    return {
        "step": s.steps, "box": box, "periodic": periodic, "n": s.n,
        "types": list(s.kind_names), "typeid": s.kinds.copy(), "mass": s.masses,
        "diameter": 2 * s.radii, "positions": s.positions, "image": image,
        "velocities": s.velocities, "log": {k: get(s) for k, get in LOGGED.items()},
    }


def check_frame(frame, want):
    c, p = frame.configuration, frame.particles
    assert c.step == want["step"]
    assert c.dimensions == 2
    # HOOMD's 2D box: Lz = 0, no tilt; float32 as the schema stores it.
    assert np.array_equal(c.box, np.float32([*want["box"], 0, 0, 0, 0]))
    assert p.N == want["n"]
    assert p.types == want["types"]
    assert np.array_equal(p.typeid, want["typeid"])
    assert np.array_equal(p.mass, np.float32(want["mass"]))
    assert np.array_equal(p.diameter, np.float32(want["diameter"]))
    # Centred on the origin as HOOMD has it: x - L/2 correctly rounded to
    # float32 in [-L/2, L/2); where rounding reached +L/2 on a periodic
    # axis, -L/2 with one more image.
    half = np.float32(want["box"]) / 2
    centred = np.float32(want["positions"] - want["box"] / 2)
    wrapped = (centred >= half) & want["periodic"]
    assert np.array_equal(p.position[:, :2], np.where(wrapped, -half, centred))
    assert ((p.position[:, :2] >= -half) & (p.position[:, :2] < half)).all()
    assert np.array_equal(p.image[:, :2], want["image"] + wrapped)
    assert (p.position[:, 2] == 0).all() and (p.image[:, 2] == 0).all()
    assert np.array_equal(p.velocity[:, :2], np.float32(want["velocities"]))
    assert (p.velocity[:, 2] == 0).all()
    assert set(frame.log) == {"disksim/" + k for k in LOGGED}
    for name, value in want["log"].items():
        got = frame.log["disksim/" + name]
        assert got.shape == (1,)
        if name in ("collisions", "wall_reflections"):
            assert got.dtype == np.uint64 and got[0] == value, name
        else:  # the very doubles the library's getters return
            assert got.dtype == np.float64, name
            assert got[0] == value or (np.isnan(got[0]) and np.isnan(value)), name


@pytest.mark.parametrize("options, arguments", [
    ((), {}),
    (("--periodic", "--integrator", "event"), {"boundary": "periodic", "integrator": "event"}),
    (("--boundary", "channel", "--box-y", "600"), {"boundary": "channel", "box_y": 600.0}),
    (("--mixture", "1.4:0.5", "--mass", "area", "--periodic"),
     {"species": [(200, 5), (200, 7)], "mass": "area", "boundary": "periodic"}),
])
def test_every_frame_of_the_commands_gsd_is_the_simulations(disks_command, tmp_path, options,
                                                             arguments):
    path = tmp_path / "run.gsd"
    subprocess.run([disks_command, "400", "5", "--frames", "6", "--steps-per-frame", "500",
                    "--quiet", "--out", str(tmp_path), "--gsd", str(path), *options], check=True)
    s = disksim.Sim(400, 5, **arguments)  # the command's run, step for step
    with gsd_hoomd.open(path, "rb") as trajectory:
        assert len(trajectory) == 6
        assert trajectory.file.schema == "hoomd" and trajectory.file.schema_version == (1, 4)
        for k, frame in enumerate(trajectory):
            if k > 0:
                s.run(500)
            check_frame(frame, expected(s))
    if "boundary" in arguments:  # t = 2.5: disks crossed the periodic sides
        assert np.abs(expected(s)["image"]).max() > 0


def test_a_writer_writes_what_the_simulation_says_of_named_kinds(tmp_path):
    s = disksim.Sim(60, 6.0, species=[(40, 6.0, "small"), (20, 8.5, "large_ones")],
                    mass="area", boundary="periodic", integrator="event", box=400.0,
                    box_y=300.0)
    wants = []
    with disksim.Writer(tmp_path / "w.gsd") as w:
        assert w.format == "gsd" and not w.closed
        for k in range(5):
            if k == 3:  # diameters change between frames: growth
                s.set_growth(0.05, until_eta=0.6)
            if k > 0:
                s.run(700)
            w.write(s)
            wants.append(expected(s))
        assert w.frames == 5
    assert w.closed
    with gsd_hoomd.open(tmp_path / "w.gsd", "rb") as trajectory:
        assert len(trajectory) == 5
        for frame, want in zip(trajectory, wants):
            check_frame(frame, want)
        assert trajectory[0].particles.types == ["small", "large_ones"]
        assert set(trajectory[0].particles.mass) == {1.0, np.float32((8.5 / 6.0) ** 2)}
        assert trajectory[4].particles.diameter[0] > 12.0  # grown
    assert np.abs(wants[-1]["image"]).max() > 0


def test_later_frames_leave_out_what_frame_0_has(tmp_path):
    s = disksim.Sim(50, 5.0)
    with disksim.Writer(tmp_path / "w.gsd") as w:
        for _ in range(3):
            w.write(s)
            s.run(10)
    import gsd.fl
    with gsd.fl.open(str(tmp_path / "w.gsd"), "rb") as f:
        for name in ("particles/types", "particles/mass", "particles/diameter",
                     "particles/image", "configuration/box"):
            assert f.chunk_exists(0, name) and not f.chunk_exists(2, name), name
        for name in ("particles/position", "particles/velocity", "log/disksim/time"):
            assert f.chunk_exists(2, name), name


def test_a_file_cut_short_never_reads_as_whole(disks_command, tmp_path):
    for frames in (4, 40):  # the first index block, and one moved to the end
        path = tmp_path / "whole.gsd"
        subprocess.run([disks_command, "30", "5", "--frames", str(frames), "--quiet", "--out",
                        str(tmp_path / str(frames)), "--gsd", str(path), "--periodic"],
                       check=True)
        data = path.read_bytes()
        for cut in range(0, len(data), max(1, len(data) // 300)):
            (tmp_path / "cut.gsd").write_bytes(data[:cut])
            with pytest.raises((RuntimeError, OSError, ValueError)):
                with gsd_hoomd.open(tmp_path / "cut.gsd", "rb") as trajectory:
                    for frame in trajectory:
                        frame.particles.position, frame.log


def test_an_interrupted_run_keeps_a_gsd_of_exactly_its_frames(disks_command, tmp_path):
    run = subprocess.Popen([disks_command, "200", "5", "--frames", "10000", "--quiet",
                            "--out", str(tmp_path / "out"), "--gsd", str(tmp_path / "t.gsd")])
    deadline = time.monotonic() + 60
    while not (tmp_path / "out" / "frame_0005.txt").exists() and time.monotonic() < deadline:
        time.sleep(0.01)
    run.send_signal(signal.SIGINT)
    assert run.wait(60) == -signal.SIGINT
    frames = len(list((tmp_path / "out").glob("frame_*.txt")))  # frames.json beside them
    assert frames >= 6
    with gsd_hoomd.open(tmp_path / "t.gsd", "rb") as trajectory:
        assert len(trajectory) == frames
        last = disksim.read_frame(tmp_path / "out" / ("frame_%04d.txt" % (frames - 1)))
        # the frame file's six decimals against float32 of x - 500 (half
        # a float32 unit below 512: 2^-16, within 500 2^-24)
        got = trajectory[-1].particles.position[:, :2].astype(np.float64) + 500.0
        assert np.abs(got - last.positions).max() <= 5e-7 + 500 * 2.0**-24


def test_the_command_refuses_a_pipe_for_gsd(disks_command, tmp_path):
    done = subprocess.run([disks_command, "10", "5", "--frames", "2", "--quiet", "--out",
                           str(tmp_path), "--gsd", "/dev/stdout"], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    assert done.returncode == 1
    assert "cannot write --gsd /dev/stdout" in done.stderr and "pipe" in done.stderr
    assert done.stdout == "" and not list(tmp_path.iterdir())


def test_a_writer_of_each_format_and_its_refusals(tmp_path):
    s = disksim.Sim(20, 5.0)
    for format in disksim.FORMATS:
        with disksim.Writer(tmp_path / ("w." + format), format) as w:
            w.write(s)
            w.write(s)
        assert w.frames == 2 and w.closed
    text = (tmp_path / "w.frame").read_text().splitlines()
    assert len(text) == 40  # two frames of 20 lines, one after the other
    w.close()  # again: nothing
    with pytest.raises(disksim.Error, match="closed"):
        w.write(s)
    with pytest.raises(disksim.ArgumentError, match="'pdb' is not one of"):
        disksim.Writer(tmp_path / "x", "pdb")
    with pytest.raises(TypeError):
        disksim.Writer(tmp_path / "x").write("not a Sim")
    with pytest.raises(disksim.FileError) as raised:
        disksim.Writer(tmp_path / "missing" / "x.gsd")
    assert raised.value.filename == tmp_path / "missing" / "x.gsd"
    s.close()
    with disksim.Writer(tmp_path / "y.gsd") as w, pytest.raises(disksim.Error, match="closed"):
        w.write(s)


def test_a_writer_appending_goes_on_with_its_file(tmp_path):
    s = disksim.Sim(30, 5.0, boundary="periodic")
    wants = []
    for session in range(3):  # a new file, then two more sessions appending to it
        with disksim.Writer(tmp_path / "a.gsd", append=session > 0) as w:
            for _ in range(2):
                w.write(s)
                wants.append(expected(s))
                s.run(400)
    with gsd_hoomd.open(tmp_path / "a.gsd", "rb") as trajectory:
        assert len(trajectory) == 6
        for frame, want in zip(trajectory, wants):
            check_frame(frame, want)
    with disksim.Writer(tmp_path / "a.xyz", "xyz", append=True) as w:  # none there: made
        w.write(s)
    with disksim.Writer(tmp_path / "a.xyz", "xyz", append=True) as w:
        w.write(s)
    assert (tmp_path / "a.xyz").read_text().count("Lattice=") == 2
    (tmp_path / "other.gsd").write_text("not a GSD file\n")
    with pytest.raises(disksim.FormatError, match="not a GSD file of this library's chunks"):
        disksim.Writer(tmp_path / "other.gsd", append=True)


def test_a_restart_goes_on_with_the_runs_gsd_file(disks_command, tmp_path):
    # The run killed (SIGKILL) two frames after its checkpoint at frame 10,
    # restarted with nothing but --restart: its GSD file ends up holding
    # the uninterrupted run's frames, chunk for chunk.
    common = ["200", "5", "--frames", "20", "--steps-per-frame", "2000", "--quiet"]
    subprocess.run([disks_command, *common, "--out", str(tmp_path / "a"), "--gsd",
                    str(tmp_path / "a.gsd")], check=True)
    run = subprocess.Popen([disks_command, *common, "--out", str(tmp_path / "b"), "--gsd",
                            str(tmp_path / "b.gsd"), "--checkpoint", str(tmp_path / "c.ckpt"),
                            "--checkpoint-every", "5"])
    deadline = time.monotonic() + 120
    while not (tmp_path / "b" / "frame_0012.txt").exists() and time.monotonic() < deadline:
        time.sleep(0.001)
    run.kill()
    run.wait(60)
    with gsd_hoomd.open(tmp_path / "b.gsd", "rb") as killed:
        assert len(killed) > 11  # frames past the checkpoint's, to be taken out
    subprocess.run([disks_command, "--restart", str(tmp_path / "c.ckpt"), "--quiet"], check=True)
    with gsd_hoomd.open(tmp_path / "a.gsd", "rb") as a, gsd_hoomd.open(tmp_path / "b.gsd",
                                                                       "rb") as b:
        assert len(a) == len(b) == 20
        for fa, fb in zip(a, b):
            assert fa.configuration.step == fb.configuration.step
            for name in ("position", "velocity", "image", "typeid", "mass", "diameter"):
                assert np.array_equal(getattr(fa.particles, name), getattr(fb.particles, name))
            for key, value in fa.log.items():
                assert np.array_equal(value, fb.log[key], equal_nan=True), key
