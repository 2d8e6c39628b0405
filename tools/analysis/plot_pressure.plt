# SPDX-License-Identifier: MIT
# Wall pressure over the ideal-gas value against the area fraction, with the
# counting error bars, the ideal gas (1) and Henderson's hard-disk equation
# of state (1 + eta^2/8) / (1 - eta)^2.
#
#   gnuplot -e "data='pressure.dat'" tools/analysis/plot_pressure.plt
#
# data has one line per run: "R eta P/P_ideal wall_hits" (docs/physics.md,
# "Pressure and the ideal-gas law", shows the loop that writes it); N is
# the runs' disk count (default 2000) and time their length (default 30),
# for the title. Writes pressure.png and, for print, pressure.pdf beside it
# (set out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too).

if (!exists("data")) data = 'pressure.dat'
if (!exists("out")) out = 'pressure.png'
if (!exists("N")) N = 2000
if (!exists("time")) time = 30
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

henderson(eta) = (1.0 + eta**2 / 8.0) / (1.0 - eta)**2
# Relative counting error of a pressure built from `hits` wall hits, the
# Poisson bound of tests/test_physics.c: sqrt(4 / pi / hits).
sigma(hits) = sqrt(4.0 / pi / hits)

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.67in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,600 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set title sprintf('Hard disks, N = %d in a 1000 x 1000 box with walls: wall pressure against the ideal-gas law', N)
    set xlabel 'area fraction eta = N pi R^2 / 1000^2'
    set ylabel 'P A / (N <v^2>/2)'
    set xrange [0:0.55]
    set yrange [0.8:*]
    set grid
    set key top left box opaque
    set samples 200

    plot 1 with lines dt 2 lw 2 lc rgb '#2ca02c' title 'ideal gas', \
         henderson(x) with lines lw 2 lc rgb '#9467bd' title 'Henderson (1 + eta^2/8) / (1 - eta)^2', \
         data using 2:3:($3 * sigma($4)) with yerrorbars pt 7 ps 1 lc rgb '#d62728' \
             title sprintf('disks, %g time units (bars: 1 sigma)', time)
    unset output
}
