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
# fraction 0.70 at several N, for the finite-size effect) and, with
# gnuplot, eos.png (tools/analysis/plot_eos.plt). About 70 minutes on one core of the
# machine in README.md, with the defaults.
#
#   sh tools/analysis/eos.sh [N] [RELAX] [BLOCKS] [BLOCK]    (run from the top directory)
#   defaults:       16384  50     15       10
set -eu
n=${1:-16384}
relax=${2:-50}
blocks=${3:-15}
block=${4:-10}
height=866.0254037844386 # 1000 sqrt(3) / 2
run() { # N ETA RELAX BLOCKS BLOCK
    tools/pressure "$1" "$2" --periodic --lattice --box-y "$height" \
        --relax "$3" --blocks "$4" --block "$5"
}
: > eos.dat
for eta in 0.1 0.3 0.5; do
    run "$n" "$eta" 10 20 1 | tee -a eos.dat
done
for eta in 0.60 0.65 0.67 0.68 0.69 0.70 0.705 0.71 0.716 0.72 0.73 0.75; do
    run "$n" "$eta" "$relax" "$blocks" "$block" | tee -a eos.dat
done
# The same point at a quarter and at four times N (shorter for the large one).
: > eos_size.dat
run $((n / 4)) 0.70 $((2 * relax)) 20 "$block" | tee -a eos_size.dat
awk '$1 == 0.7' eos.dat >> eos_size.dat
run $((4 * n)) 0.70 "$relax" 8 "$((block / 2))" | tee -a eos_size.dat
if command -v gnuplot >/dev/null 2>&1; then
    gnuplot tools/analysis/plot_eos.plt && echo "wrote eos.png"
fi
