# SPDX-License-Identifier: MIT
# Energy and wall pressure against time, from the CSV of `disks --stats`.
#
#   gnuplot -e "stats_file='stats.csv'; N=2000; R=3" tools/analysis/plot_stats.plt
#
# Writes energy_pressure.png and, for print, energy_pressure.pdf beside it
# (set out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too). Variables, all optional: stats_file,
# N and R (the run's disk count and radius, for the title's state point and
# the dense-gas reference curve), box (default 1000), out, formats.
#
# Top: relative energy drift (E - E0) / E0, which collisions conserve
# exactly up to rounding. Bottom: the pressure averaged since t = 0 (the
# CSV's column), the pressure of each frame interval (from the change of
# the accumulated impulse), the ideal-gas value N <v^2>/2 / A = E / A with
# A = (box - 2R)^2, and Henderson's hard-disk equation of state
# P A / N kT = (1 + eta^2/8) / (1 - eta)^2, eta = N pi R^2 / box^2.

if (!exists("stats_file")) stats_file = 'stats.csv'
if (!exists("out")) out = 'energy_pressure.png'
if (!exists("N")) N = 2000
if (!exists("R")) R = 3.0
if (!exists("box")) box = 1000.0

if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

set datafile separator ','

# Columns: 1 frame, 2 time, 3 kinetic_energy, 4 px, 5 py, 6 collisions,
# 7 wall_reflections, 8 pressure (averaged since t = 0).
# Rows are selected by their time column, not by record number, so the
# header line cannot shift them.
stats stats_file using ($2 == 0 ? $3 : NaN) nooutput
E0 = STATS_min
stats stats_file using 3 nooutput
E_mean = STATS_mean

area = (box - 2.0*R)**2
eta = N * pi * R**2 / box**2
ideal = E_mean / area
henderson = ideal * (1.0 + eta**2/8.0) / (1.0 - eta)**2

# The pressure is 0 by definition at t = 0 (no time has passed): not drawn.
# Pressure over one frame interval: the accumulated impulse is P * t *
# perimeter, so its increment over the interval, per time and perimeter,
# is (P_k t_k - P_{k-1} t_{k-1}) / (t_k - t_{k-1}).
interval_p(p, t) = (d = (t > prev_t) ? (p*t - prev_pt) / (t - prev_t) : NaN, \
                    prev_pt = p*t, prev_t = t, d)

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,700 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,5.4in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,700 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set datafile separator ','
    prev_pt = 0.0
    prev_t = 0.0
    set multiplot layout 2,1 title sprintf("disks %d %g: energy and wall pressure\narea fraction %.3f, box %g x %g with walls", N, R, eta, box, box)

    set ylabel '(E - E_0) / E_0'
    set format y '%.0e'
    set xlabel ''
    # Room above the data for the key: a fifth of the height.
    set offsets 0, 0, graph 0.25, 0
    set key top right
    set grid
    plot stats_file using 2:(($3 - E0) / E0) with lines lw 2 lc rgb '#1f77b4' \
         title 'kinetic energy'

    set ylabel 'P (impulse / time / length)'
    set format y '%g'
    set xlabel 'time'
    # The frame intervals scatter over the whole range: the key goes in a
    # band above them.
    set offsets 0, 0, graph 0.6, 0
    set key top right
    plot stats_file using 2:(interval_p($8, $2)) with points pt 7 ps 0.3 \
             lc rgb '#bbbbbb' title 'each frame interval', \
         stats_file using 2:($2 > 0 ? $8 : NaN) with lines lw 2 lc rgb '#d62728' \
             title 'average since t = 0', \
         ideal with lines dt 2 lw 2 lc rgb '#2ca02c' title sprintf('ideal gas N<v^2>/2A = %.3g', ideal), \
         henderson with lines dt 4 lw 2 lc rgb '#9467bd' \
             title sprintf('hard disks, Henderson (eta = %.3f) = %.3g', eta, henderson)

    unset multiplot
    unset output
}
