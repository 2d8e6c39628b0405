#!/bin/sh
# SPDX-License-Identifier: MIT
# The hard-disk equation of state through melting: Z = P A / (N kT) from
# the collision virial against the area fraction, event-driven, in a
# periodic box of aspect sqrt(3)/2 (1000 x 866.03) that a triangular
# lattice of as many rows as columns fits without strain, started on that
# lattice. Each point relaxes for RELAX time units, then measures BLOCKS
# blocks of BLOCK time units; Z is their mean and its error the standard
# error of the mean (tools/pressure). One time unit is ~100 collisions per
# disk at area fraction 0.70.
#
# The sweep lives in its own directory of the current directory, named by
# its parameters: eos.N16384.relax50.blocks15x10/ with the defaults. Each
# point's row goes to DIR/points/ as it finishes; when all 17 are there,
# DIR/eos.dat (rows of tools/pressure for N disks), DIR/eos_size.dat (area
# fraction 0.70 at N/4, N and 4N, for the finite-size effect) and, with
# gnuplot, DIR/eos.png and DIR/eos.pdf (tools/analysis/plot_eos.plt). A
# sweep with other parameters has another directory; the same sweep again
# resumes: it keeps every point already done and runs the others
# (docs/sweeps.md). The 17 points (tools/analysis/eos_point.sh lists them)
# are independent: -j JOBS runs JOBS of them at a time (xargs -P), default
# 1, the longest first. About 70 minutes on one core of the machine in
# README.md with the defaults; docs/sweeps.md has the times at -j 1 and
# -j 2. On a cluster, tools/analysis/eos.sbatch runs the same points as
# Slurm jobs, in the same directory.
#
# If a point fails, no new point starts, the sweep ends with exit status 1
# naming the point and tools/pressure's reason, and no table is written;
# the points that finished are kept for the next run.
#
# INTEGRATOR chain runs every point with event-chain Monte Carlo instead
# of the dynamics (the same canonical Z, from the chains' liftings;
# docs/physics.md), in a directory of its own, eos.chain.N16384.relax...:
# a time unit of chains costs less than one of dynamics, so give it
# longer RELAX and BLOCK (docs/physics.md measures how long).
#
#   sh tools/analysis/eos.sh [-j JOBS] [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]
#   defaults:            1      16384  50     15       10      event
set -eu
# Where the other pieces are: in the checkout, the scripts beside this
# file and tools/pressure one folder up; `make install` rewrites these two
# lines with the installed places (docs/install.md).
scripts=$(cd "$(dirname "$0")" && pwd)
pressure=${PRESSURE:-$scripts/../pressure}
usage="usage: ${0##*/} [-j JOBS] [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR] (JOBS >= 1)"
case ${1:-} in
--help | -h)
    cat <<EOF
$usage
The hard-disk equation of state: 17 runs of tools/pressure (15 area
fractions at N, 0.70 at N/4 and 4N), written to the directory
eos.NN.relaxRELAX.blocksBLOCKSxBLOCK of the current directory; run again,
it keeps the points done and runs the others. INTEGRATOR is event (the
dynamics) or chain (event-chain Monte Carlo, in eos.chain.NN...).
  -j JOBS   run JOBS points at a time, the longest first (default 1)
  --help    show this help and exit
Defaults: N 16384, RELAX 50, BLOCKS 15, BLOCK 10, event. docs/sweeps.md has more.
EOF
    exit 0
    ;;
esac
jobs=1
if [ "${1:-}" = -j ]; then
    jobs=${2:-}
    shift 2 || true
fi
case $jobs in
'' | *[!0-9]* | 0)
    echo "$usage" >&2
    exit 2
    ;;
esac
n=${1:-16384}
relax=${2:-50}
blocks=${3:-15}
block=${4:-10}
integrator=${5:-event}
point="$scripts/eos_point.sh"
if [ ! -x "$pressure" ]; then
    echo "eos: $pressure is not built (run make)" >&2
    exit 1
fi
count=$(sh "$point" --count)
# The name alone first: an integrator eos_point.sh refuses stops the
# sweep here, before a directory is made.
dir=$(sh "$point" --name "$n" "$relax" "$blocks" "$block" "$integrator")
state=$(sh "$point" --list "$n" "$relax" "$blocks" "$block" "$integrator" |
    sh "$scripts/sweep_dir.sh" "$dir")
# The programs the points run, by absolute paths, and the sweep's
# arguments, for the points and for Slurm jobs that may finish this sweep
# (tools/analysis/eos.sbatch reads them).
pressure=$(cd "$(dirname "$pressure")" && pwd)/${pressure##*/}
export PRESSURE="$pressure"
printf 'scripts=%s\npressure=%s\narguments=%s %s %s %s %s\n' "$scripts" "$pressure" \
    "$n" "$relax" "$blocks" "$block" "$integrator" >"$dir/run.txt"

# The points without a result, the longest first: the 4N point is the
# longest, and started last it would keep one core busy while the others
# wait.
todo=""
for k in $(sh "$point" --order "$n" "$relax" "$blocks" "$block" "$integrator"); do
    [ -s "$dir/points/point_$k.dat" ] || todo="$todo $k"
    rm -f "$dir/points/point_$k.dat.err" # a reason from an earlier run
done
left=$(echo "$todo" | wc -w)
if [ "$state" = resume ]; then
    echo "eos: $dir: resuming, $((count - left)) of $count points done before (kept), $left to run, $jobs at a time" >&2
else
    echo "eos: $dir: $count points, N = $n, $jobs at a time" >&2
fi

trap 'exit 130' INT
trap 'exit 143' TERM
# A point that fails exits 255, which makes xargs start no other point.
status=0
if [ "$left" -gt 0 ]; then
    # shellcheck disable=SC2016 # $1 ... are the inner shell's, not ours
    for k in $todo; do echo "$k"; done | xargs -P "$jobs" -I '{}' sh -c \
        'sh "$1" "$2" "$3" "$4" "$5" "$6" "$7" "$8" || exit 255' sh \
        "$point" '{}' "$dir" "$n" "$relax" "$blocks" "$block" "$integrator" || status=$?
fi
if [ "$status" -ne 0 ]; then
    failed=""
    for err in "$dir"/points/point_*.dat.err; do
        [ -e "$err" ] || continue
        k=${err##*/point_}
        failed="$failed ${k%.dat.err}"
    done
    echo "eos: point(s)${failed:- unknown} failed (see above): no table written;" \
        "the points done are kept in $dir/points, run again to go on" >&2
    exit 1
fi
sh "$scripts/eos_gather.sh" "$dir"
