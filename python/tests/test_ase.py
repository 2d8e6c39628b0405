# SPDX-License-Identifier: MIT
"""Sim.to_ase is what ASE reads from the library's extended XYZ frames."""
import subprocess
import sys

import numpy as np
import pytest

import disksim

ase_io = pytest.importorskip("ase.io", reason="ASE is not installed (Debian: python3-ase)")


@pytest.mark.parametrize("options, arguments", [
    ((), {}),
    (("--periodic", "--integrator", "event"), {"boundary": "periodic", "integrator": "event"}),
    (("--boundary", "channel", "--box-y", "600"), {"boundary": "channel", "box_y": 600.0}),
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
    # the file has 6 decimals: within half a unit of the last one
    assert np.abs(mine.positions - read.positions).max() <= 5e-7 + 1e-12
    assert np.abs(mine.arrays["velo"] - read.arrays["velo"]).max() <= 5e-7 + 1e-12
    assert np.array_equal(mine.arrays["radius"], read.arrays["radius"])
    assert np.array_equal(mine.cell[:], read.cell[:]) and list(mine.pbc) == list(read.pbc)
    assert mine.get_chemical_symbols() == read.get_chemical_symbols()
    assert np.array_equal(mine.get_masses(), read.get_masses())
    assert mine.info["Time"] == pytest.approx(read.info["Time"]) == 0.1
    assert (mine.positions[:, 2] == 0).all()
    assert list(mine.pbc) == [arguments.get("boundary", "walls") != "walls",
                              arguments.get("boundary") == "periodic", False]


def test_to_ase_without_ase_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "ase", None)  # import ase then raises ImportError
    with pytest.raises(ImportError, match="python3-ase"):
        disksim.Sim(3, 1).to_ase()
