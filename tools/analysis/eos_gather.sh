#!/bin/sh
# SPDX-License-Identifier: MIT
# Gathers the points of an equation-of-state sweep (tools/analysis/eos_point.sh,
# run by tools/analysis/eos.sh or tools/analysis/eos.sbatch) from
# DIR/points/ into DIR/eos.dat (points 0 to 14) and DIR/eos_size.dat (point
# 15, the 0.70 row of eos.dat, point 16), then plots DIR/eos.png and
# DIR/eos.pdf with gnuplot when it is installed (tools/analysis/plot_eos.plt).
#
#   sh tools/analysis/eos_gather.sh DIR
#
# The tables are the rows of tools/pressure under a '#' line naming the
# columns, which numpy.loadtxt skips and numpy.genfromtxt(names=True) reads:
#   eta N integrator dt boundary Z_virial Z_virial_error Z_walls Z_walls_error collisions seconds
# Writes nothing and exits 1, naming them, if any point has no result. The
# tables come from the points alone: gathering again writes them the same.
set -eu
# Where the other pieces are: in the checkout, beside this file; `make
# install` rewrites this line with the installed scripts' directory.
scripts=$(cd "$(dirname "$0")" && pwd)
if [ $# -ne 1 ]; then
    echo "usage: sh tools/analysis/eos_gather.sh DIR" >&2
    exit 2
fi
dir=$1
count=$(sh "$scripts/eos_point.sh" --count)
missing=""
k=0
while [ "$k" -lt "$count" ]; do
    [ -s "$dir/points/point_$k.dat" ] || missing="$missing $k"
    k=$((k + 1))
done
if [ -n "$missing" ]; then
    echo "eos_gather: no result in $dir/points for point(s)$missing: eos.dat not written" >&2
    exit 1
fi
header="# eta N integrator dt boundary Z_virial Z_virial_error Z_walls Z_walls_error collisions seconds"
k=0
{
    echo "$header"
    echo "# ${dir##*/}: N disks at 15 area fractions (tools/analysis/eos.sh)"
    while [ "$k" -le 14 ]; do
        cat "$dir/points/point_$k.dat"
        k=$((k + 1))
    done
} >"$dir/eos.dat.tmp"
{
    echo "$header"
    echo "# ${dir##*/}: area fraction 0.70 at N/4, N and 4N (tools/analysis/eos.sh)"
    cat "$dir/points/point_15.dat"
    awk '!/^#/ && $1 == 0.7' "$dir/eos.dat.tmp"
    cat "$dir/points/point_16.dat"
} >"$dir/eos_size.dat.tmp"
mv "$dir/eos.dat.tmp" "$dir/eos.dat"
mv "$dir/eos_size.dat.tmp" "$dir/eos_size.dat"
echo "wrote $dir/eos.dat and $dir/eos_size.dat"
if command -v gnuplot >/dev/null 2>&1; then
    (cd "$dir" && gnuplot "$scripts/plot_eos.plt")
    echo "wrote $dir/eos.png and $dir/eos.pdf"
fi
