# SPDX-License-Identifier: MIT
"""Sim.to_ase is what ASE reads from the library's extended XYZ frames:
every array and info field, for the command's trajectory and for
Python's Writer, with walls, periodic and in a channel, for a mixture of
named kinds whose masses go by area."""
import subprocess
import sys

import numpy as np
import pytest

import disksim

ase_io = pytest.importorskip("ase.io", reason="ASE is not installed (Debian: python3-ase)")

# The file has 6 decimals: a number read back is within half a unit of the
# last one of what to_ase holds, plus the double's own rounding.
SIX_DECIMALS = 5e-7 + 1e-12


def assert_same_atoms(mine, read):
    """to_ase's Atoms against ASE's reading of the file, field by field."""
    assert sorted(mine.arrays) == sorted(read.arrays)
    assert np.array_equal(mine.numbers, read.numbers)
    assert mine.get_chemical_symbols() == read.get_chemical_symbols()
    assert set(mine.get_chemical_symbols()) == {"X"}
    assert np.abs(mine.positions - read.positions).max() <= SIX_DECIMALS
    assert (mine.positions[:, 2] == 0).all() and (read.positions[:, 2] == 0).all()
    for exact in ("type", "radius", "mass", "masses"):
        assert np.array_equal(mine.arrays[exact], read.arrays[exact]), exact
    for decimals in ("velo", "momenta"):
        assert np.abs(mine.arrays[decimals] - read.arrays[decimals]).max() <= SIX_DECIMALS
    if "map_shift" in mine.arrays:
        assert mine.arrays["map_shift"].dtype == read.arrays["map_shift"].dtype
        assert np.array_equal(mine.arrays["map_shift"], read.arrays["map_shift"])
    # ASE's own accessors: masses and velocities are the disks'.
    assert np.array_equal(mine.get_masses(), read.get_masses())
    masses = mine.get_masses()[:, None]
    assert np.abs(mine.get_velocities() - read.get_velocities()).max() <= \
        (SIX_DECIMALS / masses).max()
    assert np.abs(mine.get_velocities() - mine.arrays["velo"]).max() <= 1e-12 * np.abs(
        mine.arrays["velo"]).max()
    assert np.array_equal(mine.cell[:], read.cell[:]) and list(mine.pbc) == list(read.pbc)
    assert mine.info.keys() == read.info.keys() == {"Time"}
    assert abs(mine.info["Time"] - read.info["Time"]) <= SIX_DECIMALS


@pytest.mark.parametrize("options, arguments", [
    ((), {}),
    (("--periodic", "--integrator", "event"), {"boundary": "periodic", "integrator": "event"}),
    (("--boundary", "channel", "--box-y", "600"), {"boundary": "channel", "box_y": 600.0}),
    (("--mixture", "1.4:0.5", "--mass", "area", "--periodic"),
     {"species": [(200, 5), (200, 7)], "mass": "area", "boundary": "periodic"}),
])
def test_to_ase_is_what_ase_reads_from_the_commands_trajectory(disks_command, tmp_path, options,
                                                                arguments):
    trajectory = tmp_path / "t.xyz"
    subprocess.run([disks_command, "400", "5", "--frames", "2", "--quiet", "--out", str(tmp_path),
                    "--trajectory", str(trajectory), *options], check=True)
    read = ase_io.read(trajectory, index=-1)
    s = disksim.Sim(400, 5, **arguments)
    s.run(100)
    mine = s.to_ase()
    assert_same_atoms(mine, read)
    assert mine.info["Time"] == pytest.approx(0.1)
    boundary = arguments.get("boundary", "walls")
    assert list(mine.pbc) == [boundary != "walls", boundary == "periodic", False]
    assert ("map_shift" in mine.arrays) == (boundary != "walls")


@pytest.mark.parametrize("boundary", disksim.BOUNDARIES)
def test_to_ase_is_what_ase_reads_from_a_writer_of_named_kinds(tmp_path, boundary):
    s = disksim.Sim(40, 4.0, species=[(25, 4.0, "small"), (15, 6.5, "big")], mass="area",
                    boundary=boundary, box=300.0, box_y=220.0)
    s.run(3000)  # t = 3: at speeds near 100 many disks cross a periodic side
    with disksim.Writer(tmp_path / "n.xyz", "xyz") as w:
        w.write(s)
    read = ase_io.read(tmp_path / "n.xyz")
    mine = s.to_ase()
    assert_same_atoms(mine, read)
    assert list(read.arrays["type"]) == ["small"] * 25 + ["big"] * 15
    assert np.array_equal(read.get_masses(), s.masses)
    assert set(s.masses[25:]) == {(6.5 / 4.0) ** 2}
    if boundary != "walls":
        image = np.round((s.unwrapped - s.positions) / [s.box, s.box_y]).astype(int)
        assert np.array_equal(read.arrays["map_shift"][:, :2], image)
        assert (read.arrays["map_shift"][:, 2] == 0).all()
        assert np.abs(image).max() > 0  # the images were put to the test


def test_to_ase_without_ase_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "ase", None)  # import ase then raises ImportError
    with pytest.raises(ImportError, match="python3-ase"):
        disksim.Sim(3, 1).to_ase()
