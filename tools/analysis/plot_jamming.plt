# SPDX-License-Identifier: MIT
# The jamming area fraction of the 50:50 mixture of radius ratio 1.4
# against the growth rate, every run a point, from the tables of
# tools/analysis/jamming.sh, with the values of O'Hern et al. 2003 (0.842)
# and the densest amorphous packings of Schreck, O'Hern and Silbert 2011
# (0.853).
#
#   sh tools/analysis/jamming.sh 1024 "0.1 0.03 0.01 0.003" "1 2 3 4 5" jam1024.tsv
#   sh tools/analysis/jamming.sh 4096 "0.1 0.01" "1 2 3" jam4096.tsv
#   gnuplot -e "small='jam1024.tsv'; large='jam4096.tsv'" tools/analysis/plot_jamming.plt
#
# Writes jamming.png (set out='name.png' to change).

if (!exists("small")) small = 'jam1024.tsv'
if (!exists("large")) large = 'jam4096.tsv'
if (!exists("out")) out = 'jamming.png'

set terminal pngcairo size 900,600 font ',11'
set output out
set title 'Jamming of a 50:50 mixture of radius ratio 1.4 (Z > 10^6)'
# The x axis is the dimensionless rate: how fast a small disk's surface
# moves, rate * r, over the speed 100, with r of the row's N from the
# area fraction 0.5 the runs start at (tools/analysis/jamming.sh).
r(n) = sqrt(0.5e6 / (pi * n * 1.48))
set xlabel 'growth rate x small radius / speed'
set ylabel 'area fraction at jamming'
set logscale x
set xrange [0.0002:0.015]
set yrange [0.835:0.86]
set grid
set key bottom left

plot 0.842 with lines dt 2 lc rgb 'black' title "O'Hern et al. 2003: 0.842", \
     0.853 with lines dt 3 lc rgb 'gray40' title 'Schreck et al. 2011: up to 0.853', \
     small using ($2 * r($1) / 100):4 with points pt 7 ps 1.2 lc rgb '#2a6fb0' title 'N = 1024', \
     large using ($2 * r($1) / 100):4 with points pt 5 ps 1.2 lc rgb '#c0392b' title 'N = 4096'
