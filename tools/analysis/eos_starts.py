#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Relaxation of the hard-disk pressure from two sides (docs/physics.md).

N disks at area fraction ETA in the periodic 1000 x 866.03 box of the
equation-of-state sweep (tools/analysis/eos.sh), started either on the
triangular lattice (ordered, the sweep's start) or melted: the lattice at
area fraction 0.60, where it melts within a few time units, run 20 time
units with the dynamics, then compressed by Lubachevsky-Stillinger growth
to ETA over about 25 time units. It prints |psi6| on arrival, which
says how disordered the start is: at 0.72, 0.09 with 16384 disks, 0.06
to 0.41 with 4096 (by seed), 0.55 to 0.66 with 1024, which order during
the compression already. Or started from the
positions an earlier run saved (FILE.npy, from --save, the velocities
drawn afresh at the default speed), to continue a run or hand it from
one integrator to the other. Then the integrator
(chain: event-chain Monte Carlo, event: the dynamics) runs BLOCKS blocks
of BLOCK time units; each block prints one line,

    time Z psi6 cpu_seconds

Z the canonical compressibility factor over the block (the chains'
liftings, or the collision virial at the canonical temperature), psi6 the
global |psi6| at its end, cpu_seconds the process's CPU time so far. A
pressure relaxed from both starts is the equilibrium one of this box;
until then the two runs' Z approach it from either side.

    PYTHONPATH=python python3 tools/analysis/eos_starts.py ETA lattice|melted|FILE.npy \\
        [--integrator chain|event] [--n N] [--blocks B] [--block T] [--seed S] [--save FILE.npy]
"""
import argparse
import math
import sys
import time

import numpy as np

import disksim

BOX = 1000.0
BOX_Y = 866.0254037844386  # sqrt(3)/2: the 128 x 128 lattice fits unstrained
MELT_ETA = 0.60


def radius_at(n, eta):
    return math.sqrt(eta * BOX * BOX_Y / (n * math.pi))


def melted(n, eta, seed):
    """A disordered configuration at eta: a lattice melted at 0.60 and grown."""
    s = disksim.Sim(n, radius_at(n, MELT_ETA), integrator="event", boundary="periodic",
                    placement="lattice", box=BOX, box_y=BOX_Y, dt=1.0, seed=seed)
    s.run(20)
    print(f"# melted: psi6 {abs(s.psi6):.3f} at {MELT_ETA} after 20 time units")
    # radii grow as r (1 + rate t): to eta in ~25 time units
    rate = (math.sqrt(eta / MELT_ETA) - 1.0) / 25.0
    s.set_growth(rate, until_eta=eta)
    while s.growth_state == "growing":
        s.run(1)
    if s.growth_state != "reached_eta":
        sys.exit(f"eos_starts: growth ended {s.growth_state} at {s.area_fraction:.4f}")
    print(f"# grown: psi6 {abs(s.psi6):.3f} at {s.area_fraction:.4f}, time {s.time:.0f}")
    return s.positions, s.radii[0]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("eta", type=float)
    p.add_argument("start", help="lattice, melted, or a .npy of positions")
    p.add_argument("--integrator", default="chain", choices=["chain", "event"])
    p.add_argument("--n", type=int, default=16384)
    p.add_argument("--blocks", type=int, default=100)
    p.add_argument("--block", type=int, default=10)
    p.add_argument("--seed", type=int, default=20260101)
    p.add_argument("--save", help="write the last positions to this .npy")
    a = p.parse_args()
    if a.blocks < 1 or a.block < 1:
        p.error("--blocks and --block must be at least 1")
    r = radius_at(a.n, a.eta)
    kw = dict(integrator=a.integrator, boundary="periodic", placement="lattice", box=BOX,
              box_y=BOX_Y, dt=1.0, seed=a.seed)
    if a.start == "lattice":
        s = disksim.Sim(a.n, r, **kw)
    else:
        if a.start == "melted":
            pos, grown = melted(a.n, a.eta, a.seed)
            print(f"# melted at {MELT_ETA}, grown to radius {grown:.9f} (lattice's {r:.9f})")
        else:
            pos = np.load(a.start)
        # one part in 1e9 of a radius clears contacts that the growth or a
        # file's rounding left at exactly touching; eta moves by 2e-9
        s = disksim.Sim(a.n, r * (1.0 - 1e-9), **kw)
        s.set_state(pos)
    print(f"# N {a.n} eta {s.area_fraction:.6f} start {a.start} integrator {a.integrator} "
          f"block {a.block} seed {a.seed}")
    print("# time Z psi6 cpu_seconds", flush=True)
    for _ in range(a.blocks):
        s.reset_observables()
        s.run(a.block)
        print(f"{s.time:.1f} {s.compressibility_factor:.6f} {abs(s.psi6):.4f} "
              f"{time.process_time():.1f}", flush=True)
        if a.save:
            np.save(a.save, s.positions)


if __name__ == "__main__":
    try:
        main()
    except (OSError, ValueError, disksim.Error) as e:  # a bad file, N or area fraction
        sys.exit(f"eos_starts: {e}")
