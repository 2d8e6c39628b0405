#!/bin/sh
# SPDX-License-Identifier: MIT
# Decorrelation per CPU second (docs/performance.md): tools/decorrelation
# for EDMD, EDMD with Andersen's bath and ECMC at area fractions 0.70 and
# 0.72, one run at a time, then docs/decorrelation.png.
#
#   make tools/decorrelation
#   tools/analysis/decorrelation.sh [OUT [N [SECONDS [RELAX]]]]
#
# OUT (default decorrelation.d) gets one summary line per run in
# OUT/tau.txt (the columns of tools/analysis/decorrelation.c) and each
# run's series in OUT/ALGO_ETA.txt; SECONDS CPU seconds of sampling per
# run (default 45) after RELAX of relaxation (default 15), N disks
# (default 4096). The bath's rate is 0.5 collisions per disk per time unit,
# about 1% of a disk's collisions at these densities.
set -eu
out=${1:-decorrelation.d}
n=${2:-4096}
seconds=${3:-45}
relax=${4:-15}
mkdir -p "$out"
: > "$out/tau.txt"
for eta in 0.70 0.72; do
    for run in "ecmc 1" "andersen 0.5" "edmd 0.5"; do
        set -- $run
        DS_DECORRELATION_SERIES="$out/$1_$eta.txt" \
            tools/decorrelation "$1" "$eta" "$n" "$seconds" "$2" "$relax" 0.5 >> "$out/tau.txt"
        tail -n 1 "$out/tau.txt"
    done
done
if command -v gnuplot > /dev/null; then
    gnuplot -e "data='$out/tau.txt'; out='docs/decorrelation.png'" tools/analysis/plot_decorrelation.plt
fi
