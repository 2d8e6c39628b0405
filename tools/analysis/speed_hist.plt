# SPDX-License-Identifier: MIT
# Speed histogram of one frame written with `disks --velocities`, against the
# 2D Maxwell-Boltzmann (Rayleigh) density with the frame's own <v^2>.
#
#   gnuplot -e "frame='run/frame_0499.txt'" tools/analysis/speed_hist.plt
#
# Writes speed_hist.png (set out='name.png' to change). Optional: bins
# (default 40), vmax (right edge of the plot, default 4 sigma), v0 (the
# initial speed, drawn as a marker; default 100, 0 hides it), early (a
# second, earlier frame drawn as an outline, to show the relaxation).
#
# Rayleigh density with sigma^2 = <v^2>/2 (each velocity component normal
# with variance sigma^2): f(v) = v / sigma^2 * exp(-v^2 / (2 sigma^2)).
# The histogram is normalised to a density (count / (N * bin width)), so
# the two curves share the axes with no fitted factor.

if (!exists("frame")) frame = 'frame_0499.txt'
if (!exists("out")) out = 'speed_hist.png'
if (!exists("bins")) bins = 40
if (!exists("v0")) v0 = 100.0

set terminal pngcairo size 900,600 font ',11'
set output out

speed(vx, vy) = sqrt(vx**2 + vy**2)
stats frame using ($4**2 + $5**2) nooutput
n = STATS_records
sigma2 = STATS_mean / 2.0
if (!exists("vmax")) vmax = 4.0 * sqrt(sigma2)
width = vmax / bins
bin(v) = width * (floor(v / width) + 0.5)
rayleigh(v) = v / sigma2 * exp(-v**2 / (2.0 * sigma2))

set title sprintf("%s: %d speeds against Rayleigh, sigma^2 = <v^2>/2 = %.4g", frame, n, sigma2) noenhanced
set xlabel 'speed'
set ylabel 'probability density'
set xrange [0:vmax]
set yrange [0:*]
set samples 400
set style fill solid 0.5 border lc rgb '#1f77b4'
set grid
set key center right
if (v0 > 0) set arrow from v0, graph 0 to v0, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
if (v0 > 0) set label sprintf("every speed at t = 0 (%g)", v0) at v0, graph 0.95 offset 1,0 tc rgb '#7f7f7f'

plot frame using (bin(speed($4, $5))):(1.0 / (n * width)) smooth frequency with boxes \
         lc rgb '#1f77b4' title 'simulation', \
     rayleigh(x) with lines lw 3 lc rgb '#d62728' title 'Rayleigh (2D Maxwell-Boltzmann)', \
     (exists("early") ? early : frame) using (bin(speed($4, $5))):(exists("early") ? 1.0 / (n * width) : NaN) \
         smooth frequency with histeps lw 2 lc rgb '#ff7f0e' \
         title (exists("early") ? sprintf("earlier: %s", early) : "") noenhanced
