# SPDX-License-Identifier: MIT
# Speed histogram of one frame written with `disks --velocities`, against the
# 2D Maxwell-Boltzmann (Rayleigh) density with the frame's own <v^2>.
#
#   gnuplot -e "frame='run/frame_0499.txt'" tools/analysis/speed_hist.plt
#
# Writes speed_hist.png and, for print, speed_hist.pdf beside it (set
# out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too). Optional: bins (default 40), vmax
# (right edge of the plot, default 4 sigma), v0 (the initial speed, drawn
# as a marker; default 100, 0 hides it), early (a second, earlier frame
# drawn as an outline, to show the relaxation), box and box_y (the box, for
# the area fraction of the title; default 1000 x box).
#
# Rayleigh density with sigma^2 = <v^2>/2 (each velocity component normal
# with variance sigma^2): f(v) = v / sigma^2 * exp(-v^2 / (2 sigma^2)).
# The histogram is normalised to a density (count / (N * bin width)), so
# the two curves share the axes with no fitted factor.

if (!exists("frame")) frame = 'frame_0499.txt'
if (!exists("out")) out = 'speed_hist.png'
if (!exists("bins")) bins = 40
if (!exists("v0")) v0 = 100.0
if (!exists("box")) box = 1000.0
if (!exists("box_y")) box_y = box
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

speed(vx, vy) = sqrt(vx**2 + vy**2)
stats frame using ($4**2 + $5**2) nooutput
n = STATS_records
sigma2 = STATS_mean / 2.0
stats frame using (pi * $3**2) nooutput
eta = STATS_sum / (box * box_y)
if (!exists("vmax")) vmax = 4.0 * sqrt(sigma2)
width = vmax / bins
bin(v) = width * (floor(v / width) + 0.5)
rayleigh(v) = v / sigma2 * exp(-v**2 / (2.0 * sigma2))

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.67in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,600 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set title sprintf("%s: N = %d, area fraction %.3g (box %g x %g)\n%d speeds against Rayleigh, sigma^2 = <v^2>/2 = %.4g", \
        frame, n, eta, box, box_y, n, sigma2) noenhanced
    set xlabel 'speed'
    set ylabel 'probability density'
    set xrange [0:vmax]
    set yrange [0:*]
    set samples 400
    set style fill solid 0.5 border lc rgb '#1f77b4'
    set grid
    # Right of the initial speed's spike and under its label.
    set key at graph 0.98, graph 0.86 right top box opaque samplen 2
    if (v0 > 0) {
        set arrow 1 from v0, graph 0 to v0, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
        set label 1 sprintf("every speed at t = 0 (%g)", v0) at v0, graph 0.95 offset 1,0 tc rgb '#7f7f7f'
    }
    plot frame using (bin(speed($4, $5))):(1.0 / (n * width)) smooth frequency with boxes \
             lc rgb '#1f77b4' title 'simulation', \
         rayleigh(x) with lines lw 3 lc rgb '#d62728' title 'Rayleigh (2D Maxwell)', \
         (exists("early") ? early : frame) using (bin(speed($4, $5))):(exists("early") ? 1.0 / (n * width) : NaN) \
             smooth frequency with histeps lw 2 lc rgb '#ff7f0e' \
             title (exists("early") ? sprintf("earlier: %s", early) : "") noenhanced
    unset output
}
