# SPDX-License-Identifier: MIT
# Wall pressure over the ideal-gas value against the area fraction, with the
# counting error bars, the ideal gas (1) and Henderson's hard-disk equation
# of state (1 + eta^2/8) / (1 - eta)^2.
#
#   gnuplot -e "data='pressure.dat'" tools/analysis/plot_pressure.plt
#
# data has one line per run: "R eta P/P_ideal wall_hits" (README, "Pressure
# and the ideal-gas law", shows the loop that writes it). Writes
# pressure.png (set out='name.png' to change).

if (!exists("data")) data = 'pressure.dat'
if (!exists("out")) out = 'pressure.png'

set terminal pngcairo size 900,600 font ',11'
set output out

henderson(eta) = (1.0 + eta**2 / 8.0) / (1.0 - eta)**2
# Relative counting error of a pressure built from `hits` wall hits, the
# Poisson bound of tests/test_physics.c: sqrt(4 / pi / hits).
sigma(hits) = sqrt(4.0 / pi / hits)

set title 'Hard disks, N = 2000: wall pressure against the ideal-gas law'
set xlabel 'area fraction eta = N pi R^2 / 1000^2'
set ylabel 'P A / (N <v^2>/2)'
set xrange [0:0.55]
set yrange [0.8:*]
set grid
set key top left
set samples 200

plot 1 with lines dt 2 lw 2 lc rgb '#2ca02c' title 'ideal gas', \
     henderson(x) with lines lw 2 lc rgb '#9467bd' title 'Henderson (1 + eta^2/8) / (1 - eta)^2', \
     data using 2:3:($3 * sigma($4)) with yerrorbars pt 7 ps 1 lc rgb '#d62728' \
         title 'disks, 30 time units (bars: 1 sigma)'
