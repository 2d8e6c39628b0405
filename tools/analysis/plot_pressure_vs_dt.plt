# SPDX-License-Identifier: MIT
# The time step's Z over the event-driven Z against dt, one line per area
# fraction, from the ratio file tools/analysis/pressure_vs_dt.sh writes (columns:
# area fraction, dt with 0 for event-driven, ratio, error):
#   gnuplot -e "data='pressure_vs_dt_ratio.dat'" tools/analysis/plot_pressure_vs_dt.plt
if (!exists("data")) data = 'pressure_vs_dt_ratio.dat'
set terminal pngcairo size 800,560 font ",11"
set output 'pressure_vs_dt.png'
set xlabel 'time step dt (0: event-driven)'
set ylabel 'Z(dt) / Z(event-driven)'
set key bottom left
set grid
set xrange [-0.0002:0.0042]
stats data using 1 nooutput
plot for [k = 0:STATS_blocks - 1] data index k using 2:3:4 with yerrorlines pointtype 7 \
     title sprintf("area fraction %g", word("0.1 0.3 0.5", k + 1) + 0)
