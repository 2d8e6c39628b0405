# SPDX-License-Identifier: MIT
# The time step's Z over the event-driven Z against dt, one line per area
# fraction, from the ratio file tools/analysis/pressure_vs_dt.sh writes (columns:
# area fraction, dt with 0 for event-driven, ratio, error):
#   gnuplot -e "data='pressure_vs_dt_ratio.dat'; N=4000" tools/analysis/plot_pressure_vs_dt.plt
# N (default 4000) is the runs' disk count, for the title. Writes
# pressure_vs_dt.png and, for print, pressure_vs_dt.pdf beside it (set
# out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too).
if (!exists("data")) data = 'pressure_vs_dt_ratio.dat'
if (!exists("out")) out = 'pressure_vs_dt.png'
if (!exists("N")) N = 4000
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out
stats data using 1 nooutput
do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 800,560 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.9in font ',9' }
    if (format eq 'svg') { set terminal svg size 800,560 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set title sprintf('The time step against event-driven dynamics: N = %d, periodic 1000 x 1000 box, lattice start', N)
    set xlabel 'time step dt (0: event-driven)'
    set ylabel 'Z(dt) / Z(event-driven)'
    set key bottom left box opaque
    set grid
    set xrange [-0.0002:0.0042]
    plot for [k = 0:STATS_blocks - 1] data index k using 2:3:4 with yerrorlines pointtype 7 \
         title sprintf("area fraction %g", word("0.1 0.3 0.5", k + 1) + 0)
    unset output
}
