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
# Writes eos.dat (rows of tools/pressure) for N disks, eos_size.dat (area
# fraction 0.70 at N/4, N and 4N, for the finite-size effect) and, with
# gnuplot, eos.png (tools/analysis/plot_eos.plt), in the current directory.
# The 17 points (tools/analysis/eos_point.sh lists them) are independent:
# -j JOBS runs JOBS of them at a time (xargs -P), default 1. About 70
# minutes on one core of the machine in README.md with the defaults;
# docs/sweeps.md has the times at -j 1 and -j 2. On a cluster,
# tools/analysis/eos.sbatch runs the same points as a Slurm job array.
#
# If a point fails, no new point starts, the sweep ends with exit status 1
# naming the point and tools/pressure's reason, and nothing is written.
#
#   sh tools/analysis/eos.sh [-j JOBS] [N] [RELAX] [BLOCKS] [BLOCK]
#   defaults:            1      16384  50     15       10
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
jobs=1
if [ "${1:-}" = -j ]; then
    jobs=${2:-}
    shift 2 || true
fi
case $jobs in
'' | *[!0-9]* | 0)
    echo "usage: sh tools/analysis/eos.sh [-j JOBS] [N] [RELAX] [BLOCKS] [BLOCK] (JOBS >= 1)" >&2
    exit 2
    ;;
esac
n=${1:-16384}
relax=${2:-50}
blocks=${3:-15}
block=${4:-10}
count=$(sh "$top/tools/analysis/eos_point.sh" --count)

dir=$(mktemp -d "${TMPDIR:-/tmp}/eos.XXXXXX")
trap 'rm -rf "$dir"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
echo "eos: $count points, N = $n, $jobs at a time" >&2
# A point that fails exits 255, which makes xargs start no other point.
# The two runs at other N go first: the one at 4 N is the longest, and
# started last it would keep one core busy while the others wait.
status=0
# shellcheck disable=SC2016 # $1 ... are the inner shell's, not ours
{ echo $((count - 1)); echo $((count - 2)); seq 0 $((count - 3)); } | xargs -P "$jobs" -I '{}' sh -c \
    'sh "$1" "$2" "$3" "$4" "$5" "$6" "$7" || exit 255' sh \
    "$top/tools/analysis/eos_point.sh" '{}' "$dir" "$n" "$relax" "$blocks" "$block" ||
    status=$?
if [ "$status" -ne 0 ]; then
    failed=""
    for err in "$dir"/point_*.dat.err; do
        [ -e "$err" ] || continue
        k=${err##*/point_}
        failed="$failed ${k%.dat.err}"
    done
    echo "eos: point(s)${failed:- unknown} failed (see above): no table written" >&2
    exit 1
fi
sh "$top/tools/analysis/eos_gather.sh" "$dir"
