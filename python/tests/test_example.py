# SPDX-License-Identifier: MIT
"""examples/eos_sweep.py: its rows are tools/pressure's for the same points,
and it plots when matplotlib is there."""
import os
import subprocess
import sys

import pytest

import disksim
from conftest import TOP

EXAMPLE = os.path.join(TOP, "examples", "eos_sweep.py")
SWEEP = ["--n", "64", "--relax", "1", "--blocks", "3", "--block", "0.5", "--etas", "0.3,0.7,0.75"]


def run_example(*options):
    # the disksim this suite imports, wherever it is (in place or installed)
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(disksim.__file__)))
    return subprocess.run([sys.executable, EXAMPLE, *SWEEP, *options], env=env, check=True,
                          capture_output=True, text=True)


def without_seconds(rows):
    return [row.rsplit(" ", 1)[0] for row in rows.splitlines()]


def test_the_examples_rows_are_tools_pressures():
    pressure = os.environ.get("DISKSIM_PRESSURE") or os.path.join(TOP, "tools", "pressure")
    if not os.access(pressure, os.X_OK):
        pytest.skip("no tools/pressure at %s (run make first)" % pressure)
    mine = run_example("--no-plot", "--jobs", "2").stdout
    theirs = "".join(subprocess.run(
        [pressure, "64", eta, "--periodic", "--lattice", "--box-y", "866.0254037844386",
         "--relax", "1", "--blocks", "3", "--block", "0.5"], check=True, capture_output=True,
        text=True).stdout for eta in ("0.3", "0.7", "0.75"))
    assert without_seconds(mine) == without_seconds(theirs)
    assert len(without_seconds(mine)) == 3


def test_the_example_plots_with_matplotlib(tmp_path):
    pytest.importorskip("matplotlib", reason="matplotlib is not installed (python3-matplotlib)")
    out = run_example("--plot", str(tmp_path / "z.png"), "--processes")
    assert (tmp_path / "z.png").stat().st_size > 1000 and "wrote" in out.stderr
