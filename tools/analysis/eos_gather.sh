#!/bin/sh
# SPDX-License-Identifier: MIT
# Gathers the points of an equation-of-state sweep (tools/analysis/eos_point.sh,
# run by tools/analysis/eos.sh or tools/analysis/eos.sbatch) from DIR into
# eos.dat (points 0 to 14) and eos_size.dat (point 15, the 0.70 row of
# eos.dat, point 16) in the current directory, then plots eos.png with
# gnuplot when it is installed (tools/analysis/plot_eos.plt).
#
#   sh tools/analysis/eos_gather.sh DIR
#
# Writes nothing and exits 1, naming them, if any point has no result.
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
if [ $# -ne 1 ]; then
    echo "usage: sh tools/analysis/eos_gather.sh DIR" >&2
    exit 2
fi
dir=$1
count=$(sh "$top/tools/analysis/eos_point.sh" --count)
missing=""
k=0
while [ "$k" -lt "$count" ]; do
    [ -s "$dir/point_$k.dat" ] || missing="$missing $k"
    k=$((k + 1))
done
if [ -n "$missing" ]; then
    echo "eos_gather: no result in $dir for point(s)$missing: eos.dat not written" >&2
    exit 1
fi
k=0
: >eos.dat.tmp
while [ "$k" -le 14 ]; do
    cat "$dir/point_$k.dat" >>eos.dat.tmp
    k=$((k + 1))
done
{
    cat "$dir/point_15.dat"
    awk '$1 == 0.7' eos.dat.tmp
    cat "$dir/point_16.dat"
} >eos_size.dat.tmp
mv eos.dat.tmp eos.dat
mv eos_size.dat.tmp eos_size.dat
echo "wrote eos.dat and eos_size.dat"
if command -v gnuplot >/dev/null 2>&1; then
    gnuplot "$top/tools/analysis/plot_eos.plt"
    echo "wrote eos.png"
fi
