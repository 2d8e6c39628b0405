# SPDX-License-Identifier: MIT
# The jamming area fraction of the 50:50 mixture of radius ratio 1.4
# against the growth rate, every run a point, from the tables of
# tools/analysis/jamming.sh, with the values of O'Hern et al. 2003 (0.842)
# and the densest amorphous packings of Schreck, O'Hern and Silbert 2011
# (0.853). The key gives each table's N and runs (from its rows).
#
#   sh tools/analysis/jamming.sh 1024 "0.1 0.03 0.01 0.003" "1 2 3 4 5" jam1024.tsv
#   sh tools/analysis/jamming.sh 4096 "0.1 0.01" "1 2 3" jam4096.tsv
#   gnuplot -e "small='jam1024.tsv'; large='jam4096.tsv'" tools/analysis/plot_jamming.plt
#
# Writes jamming.png and, for print, jamming.pdf beside it (set
# out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too).

if (!exists("small")) small = 'jam1024.tsv'
if (!exists("large")) large = 'jam4096.tsv'
if (!exists("out")) out = 'jamming.png'
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

# Each table's N (column 1) and number of runs, for the key.
stats small using 1 nooutput
n_small = int(STATS_min); runs_small = STATS_records
stats large using 1 nooutput
n_large = int(STATS_min); runs_large = STATS_records

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.67in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,600 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set title "Jamming of a 50:50 mixture of radius ratio 1.4 (Z > 10^6)\ncompressed from area fraction 0.5, periodic box, event-driven"
    # The x axis is the dimensionless rate: how fast a small disk's surface
    # moves, rate * r, over the speed 100, with r of the row's N from the
    # area fraction 0.5 the runs start at (tools/analysis/jamming.sh).
    r(n) = sqrt(0.5e6 / (pi * n * 1.48))
    set xlabel 'growth rate x small radius / speed'
    set ylabel 'area fraction at jamming'
    set logscale x
    set xrange [0.0002:0.015]
    # Labels at 1, 2 and 5 of each decade, written as numbers: with only
    # the decades labelled, the axis read 0.001 and 0.01 and nothing else.
    set xtics (0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01) format '%g'
    set mxtics 10
    set yrange [0.835:0.862]
    set grid xtics ytics
    # Above the data and the 0.853 line, in the top right corner.
    set key top right box opaque
    plot 0.842 with lines dt 2 lc rgb 'black' title "O'Hern et al. 2003: 0.842", \
         0.853 with lines dt 3 lc rgb 'gray40' title 'Schreck et al. 2011: up to 0.853', \
         small using ($2 * r($1) / 100):4 with points pt 7 ps 1.2 lc rgb '#2a6fb0' \
             title sprintf('N = %d, %d runs', n_small, runs_small), \
         large using ($2 * r($1) / 100):4 with points pt 5 ps 1.2 lc rgb '#c0392b' \
             title sprintf('N = %d, %d runs', n_large, runs_large)
    unset output
}
