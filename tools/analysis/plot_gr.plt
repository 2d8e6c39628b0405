# SPDX-License-Identifier: MIT
# The radial distribution function g(r) written by tools/gr, against r in
# diameters, with the ideal gas (g = 1) for reference.
#
#   tools/gr --dr 0.5 frame_0499.txt > gr.dat
#   gnuplot -e "data='gr.dat'; d=16.45" tools/analysis/plot_gr.plt
#
# d is the disk diameter 2R (gr prints it in its first line, "# ... d = ");
# without it r is in box units. Writes gr.png (set out='name.png' to change).

if (!exists("data")) data = 'gr.dat'
if (!exists("out")) out = 'gr.png'
if (!exists("d")) d = 1.0

set terminal pngcairo size 900,600 font ',11'
set output out

set title 'Radial distribution function'
set xlabel (d == 1.0 ? 'r' : 'r / d  (d = 2R)')
set ylabel 'g(r)'
set xrange [0:*]
set yrange [0:*]
set grid
set key top right

plot data using ($1 / d):2 with lines lw 2 lc rgb '#2a6fb0' title 'g(r)', \
     1 with lines dt 2 lc rgb 'black' title 'ideal gas'
