# SPDX-License-Identifier: MIT
"""The module runs the same simulation as the disks command, and reads and
writes the same frames."""
import errno
import os
import subprocess

import numpy as np
import pytest

import disksim


def command_frames(disks, out, *options):
    """frame_0000.txt (step 0) and frame_0001.txt (after 100 steps) of
    `disks 400 5 --frames 2 OPTIONS`, as text."""
    subprocess.run([disks, "400", "5", "--frames", "2", "--quiet", "--out", str(out), *options],
                   check=True)
    return [(out / ("frame_%04d.txt" % k)).read_text() for k in (0, 1)]


def printed(positions, radius="5"):
    """The frame's text for these centres: 6 decimals, as the command prints them."""
    return "".join("%.6f %.6f %s\n" % (x, y, radius) for x, y in positions)


# The command's options and the module's arguments for the same run.
RUNS = [
    ((), {}),
    (("--integrator", "event"), {"integrator": "event"}),
    (("--periodic", "--seed", "7"), {"boundary": "periodic", "seed": 7}),
    (("--lattice", "--periodic", "--integrator", "event"),
     {"placement": "lattice", "boundary": "periodic", "integrator": "event"}),
]


@pytest.mark.parametrize("options, arguments", RUNS)
def test_the_commands_frames_are_the_modules_positions_to_the_printed_digit(
        disks_command, tmp_path, options, arguments):
    first, second = command_frames(disks_command, tmp_path, *options)
    s = disksim.Sim(400, 5, **arguments)
    assert printed(s.positions) == first
    s.run(100)
    assert printed(s.positions) == second


def test_write_frame_writes_the_commands_bytes(disks_command, tmp_path):
    command_frames(disks_command, tmp_path / "plain")
    command_frames(disks_command, tmp_path / "velo", "--velocities")
    s = disksim.Sim(400, 5)
    s.run(100)
    s.write_frame(tmp_path / "mine.txt")
    s.write_frame(str(tmp_path / "mine_v.txt"), velocities=True)
    assert (tmp_path / "mine.txt").read_bytes() == (tmp_path / "plain/frame_0001.txt").read_bytes()
    assert (tmp_path / "mine_v.txt").read_bytes() == (tmp_path / "velo/frame_0001.txt").read_bytes()


def test_read_frame_gives_back_what_was_written_to_six_decimals(tmp_path):
    s = disksim.Sim(300, 4.25, integrator="event")
    s.run(50)
    s.write_frame(tmp_path / "f.txt", velocities=True)
    f = disksim.read_frame(tmp_path / "f.txt")
    positions, radii, velocities = f  # a named tuple
    assert positions.shape == (300, 2) and velocities.shape == (300, 2) and radii.shape == (300,)
    assert positions.dtype == np.float64
    # A value printed with 6 decimals is within half a unit of the last
    # digit, 5e-7, plus the rounding of the double read back (1000 is
    # 2^10, so ~1e-13).
    assert np.abs(positions - s.positions).max() <= 5e-7 + 1e-12
    assert np.abs(velocities - s.velocities).max() <= 5e-7 + 1e-12
    assert (radii == 4.25).all()  # R is written so that it reads back exactly

    s.write_frame(tmp_path / "g.txt")
    assert disksim.read_frame(tmp_path / "g.txt").velocities is None


def test_a_malformed_frame_names_its_line(tmp_path):
    path = tmp_path / "bad.txt"
    path.write_text("# a comment\n1 2 3\n\n4 5\n")
    with pytest.raises(disksim.FormatError) as info:
        disksim.read_frame(path)
    e = info.value
    assert isinstance(e, ValueError) and isinstance(e, disksim.Error)
    assert e.line == 4 and e.status == "DS_ERR_FORMAT"
    assert "line 4" in str(e) and "expected 3 or 5 numbers" in str(e)

    path.write_text("")
    with pytest.raises(disksim.FormatError, match="empty"):
        disksim.read_frame(path)


def test_a_missing_frame_is_a_file_error_with_its_errno(tmp_path):
    with pytest.raises(disksim.FileError) as info:
        disksim.read_frame(tmp_path / "none.txt")
    assert isinstance(info.value, OSError) and info.value.errno == errno.ENOENT
    assert info.value.filename == tmp_path / "none.txt"


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full")
def test_a_frame_that_cannot_be_written_is_a_file_error():
    s = disksim.Sim(10, 1)
    with pytest.raises(disksim.FileError) as info:
        s.write_frame("/dev/full")
    assert info.value.errno == errno.ENOSPC
    with pytest.raises(disksim.FileError):
        s.write_frame("/nonexistent-directory/frame.txt")
