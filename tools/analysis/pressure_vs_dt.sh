#!/bin/sh
# SPDX-License-Identifier: MIT
# The time step's bias, measured: Z = P A / (N kT) from the collision virial
# for the event-driven integrator and for the time step at several dt, at
# several area fractions, in a periodic box (no walls, so no wall term).
# Writes pressure_vs_dt.dat (the rows of tools/pressure), the ratios to the
# event-driven Z in pressure_vs_dt_ratio.dat (both with a '#' line naming
# the columns) and, with gnuplot, pressure_vs_dt.png and .pdf. About 3
# minutes on one core.
#
#   sh tools/analysis/pressure_vs_dt.sh [N]          (default N = 4000; run from the top)
set -eu
n=${1:-4000}
out=pressure_vs_dt.dat
# The columns, in a '#' line that numpy.loadtxt skips and
# numpy.genfromtxt(names=True) reads.
echo "# eta N integrator dt boundary Z_virial Z_virial_error Z_walls Z_walls_error collisions seconds" > "$out"
for eta in 0.1 0.3 0.5; do
    tools/pressure "$n" "$eta" --periodic --lattice --relax 10 --blocks 20 >> "$out"
    for dt in 0.0005 0.001 0.002 0.004; do
        tools/pressure "$n" "$eta" --periodic --lattice --relax 10 --blocks 20 \
            --integrator step --dt "$dt" >> "$out"
    done
done
cat "$out"
# For the plot: per area fraction (blocks two blank lines apart), dt (0 for
# the event-driven row, which comes first) and Z / Z_event with its error.
awk 'BEGIN { print "# eta dt Z_over_Z_event error" }
     /^#/ { next }
     $3 == "event" { if (blocks++) printf "\n\n"; z0 = $6; e0 = $7; print $1, 0, 1, e0 / z0; next }
     { print $1, $4, $6 / z0, sqrt($7 * $7 + e0 * e0 * $6 * $6 / (z0 * z0)) / z0 }' \
    "$out" > pressure_vs_dt_ratio.dat
if command -v gnuplot >/dev/null 2>&1; then
    gnuplot -e "data='pressure_vs_dt_ratio.dat'; N=$n" tools/analysis/plot_pressure_vs_dt.plt &&
        echo "wrote pressure_vs_dt.png and pressure_vs_dt.pdf"
fi
