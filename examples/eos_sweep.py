#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The equation of state of hard disks from Python, on every core.

Each point is one disksim.Sim: event-driven, in a periodic box of aspect
sqrt(3)/2 (1000 x 866.03), started on the triangular lattice that fits it,
as tools/analysis/eos.sh runs its points. After RELAX time units it measures
BLOCKS blocks of BLOCK time units; Z = P A / (N kT) is the mean of the
blocks' canonical Z (Sim.compressibility_factor) and its error the standard error
of that mean, computed as tools/pressure computes them, so each row is the
row tools/pressure prints for the same point (tools/analysis/plot_eos.plt can plot them).

The points run at once on a concurrent.futures pool of threads, as many as
there are cores: Sim.run releases the GIL, so threads are enough, and the
sims stay in this process (--processes uses a process pool instead). With
matplotlib (Debian: python3-matplotlib) it plots Z against the area fraction
with the virial series.

    PYTHONPATH=python python3 examples/eos_sweep.py            (after make python)
    python3 examples/eos_sweep.py --n 4096 --jobs 8 --plot eos_sweep.png
"""
import argparse
import concurrent.futures
import math
import os
import sys
import time

import disksim

HEIGHT = 1000 * math.sqrt(3) / 2
AREA_FRACTIONS = [0.1, 0.3, 0.5, 0.6, 0.65, 0.67, 0.68, 0.69, 0.7, 0.705, 0.71, 0.716, 0.72, 0.73,
                  0.75]


def point(n, eta, relax, blocks, block):
    """One point: the row tools/pressure prints for it, and (eta, Z, error)."""
    started = time.monotonic()
    radius = math.sqrt(eta * 1000 * HEIGHT / (n * math.pi))
    s = disksim.Sim(n, radius, integrator="event", boundary="periodic", placement="lattice",
                    box_y=HEIGHT)
    s.run(round(relax / s.dt))
    collisions = s.collision_count
    total = total2 = 0.0
    for _ in range(blocks):
        s.reset_observables()
        s.run(round(block / s.dt))
        z = s.compressibility_factor
        total += z
        total2 += z * z
    mean = total / blocks
    variance = total2 / blocks - mean * mean
    error = math.sqrt(variance / (blocks - 1)) if blocks > 1 and variance > 0 else 0.0
    row = "%.6g %d %s %g %s %.6f %.6f - - %d %.1f" % (
        eta, n, s.integrator, s.dt, s.boundary, mean, error, s.collision_count - collisions,
        time.monotonic() - started)
    return row, (eta, mean, error)


def series_z(eta):
    """The virial series through B10 (Clisby and McCoy 2006), as plot_eos.plt has it."""
    b = [1.0, 1.0, 0.78200443, 0.53223180, 0.33355604, 0.19884, 0.11487, 0.06499, 0.03622,
         0.01995]
    return sum(bk * (2 * eta) ** k for k, bk in enumerate(b))


def plot(results, n, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (Debian: python3-matplotlib): no plot", file=sys.stderr)
        return False
    etas = [r[0] for r in results]
    fig, ax = plt.subplots(figsize=(8, 5.5))
    x = [0.78 * k / 200 for k in range(201)]
    ax.plot(x, [series_z(e) for e in x], color="0.55", lw=2, label="virial series B2..B10")
    ax.errorbar(etas, [r[1] for r in results], yerr=[r[2] for r in results], fmt="o", ms=4,
                label="disksim: event-driven, periodic, N = %d" % n)
    ax.set_xlim(0, 0.78)
    ax.set_ylim(0, max(12, max(r[1] for r in results) + 0.5))
    ax.set_xlabel("area fraction")
    ax.set_ylabel("Z = P A / (N kT)")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left")
    fig.savefig(path, dpi=100, bbox_inches="tight")
    print("wrote %s" % path, file=sys.stderr)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=1024, help="disks per point (default 1024)")
    parser.add_argument("--relax", type=float, default=10, help="relaxation time (default 10)")
    parser.add_argument("--blocks", type=int, default=10, help="blocks per point (default 10)")
    parser.add_argument("--block", type=float, default=2, help="time per block (default 2)")
    parser.add_argument("--etas", default=",".join(map(str, AREA_FRACTIONS)),
                        help="area fractions, comma-separated (default: eos.sh's 15)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="points at a time (default: the cores, %d here)" % (os.cpu_count() or 1))
    parser.add_argument("--processes", action="store_true",
                        help="a pool of processes instead of threads")
    parser.add_argument("--plot", default="eos_sweep.png", help="the PNG (default eos_sweep.png)")
    parser.add_argument("--no-plot", action="store_true", help="print the table only")
    args = parser.parse_args()
    etas = [float(e) for e in args.etas.split(",")]
    if args.jobs < 1 or args.blocks < 2:
        parser.error("--jobs must be >= 1 and --blocks >= 2")

    pool = (concurrent.futures.ProcessPoolExecutor if args.processes
            else concurrent.futures.ThreadPoolExecutor)(max_workers=args.jobs)
    started = time.monotonic()
    with pool:
        futures = [pool.submit(point, args.n, eta, args.relax, args.blocks, args.block)
                   for eta in etas]
        # in the order of the area fractions, each as soon as it and those before are done
        results = []
        for future in futures:
            row, result = future.result()
            print(row, flush=True)
            results.append(result)
    print("%d points, %d at a time (%s): %.1f s" % (
        len(etas), args.jobs, "processes" if args.processes else "threads",
        time.monotonic() - started), file=sys.stderr)
    if not args.no_plot:
        plot(results, args.n, args.plot)


if __name__ == "__main__":
    main()
