# SPDX-License-Identifier: MIT
# D / D_E against the area fraction from tools/analysis/diffusion_sweep.sh
# (one table per N), with Enskog's value 1 and the converged Sonine
# factor 1.027 of the dilute gas for reference. The key gives each table's
# N (from its '#' lines) and sits below the curves, in the corner they
# leave empty.
#
#   sh tools/analysis/diffusion_sweep.sh tools/transport 4096     # diffusion.N4096/diffusion.dat
#   sh tools/analysis/diffusion_sweep.sh tools/transport 1024     # diffusion.N1024/diffusion.dat
#   gnuplot -e "big='diffusion.N4096/diffusion.dat'; small='diffusion.N1024/diffusion.dat'" \
#       tools/analysis/plot_diffusion.plt
#
# Writes diffusion.png and, for print, diffusion.pdf beside it (set
# out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too).

if (!exists("big")) big = 'd4096.dat'
if (!exists("small")) small = 'd1024.dat'
if (!exists("out")) out = 'diffusion.png'
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

# The N of a table: "N = 4096" in its '#' lines.
n_of(file) = system(sprintf("sed -n 's/^#.*N = \\([0-9][0-9]*\\).*/\\1/p' '%s' | head -n 1", file))
n_big = n_of(big)
n_small = n_of(small)

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.67in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,600 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set title "Self-diffusion of hard disks over Enskog's D_E\nperiodic 1000 x 1000 box, event-driven; D from 20 to 40 mean free times"
    set xlabel 'area fraction'
    set ylabel 'D / D_E'
    set xrange [0:0.72]
    set grid
    # Below the curves at low density: D / D_E >= 1 there.
    set key bottom left box opaque
    plot big using 1:9:10 with yerrorlines pt 7 lw 2 lc rgb '#2a6fb0' title sprintf('N = %s', n_big), \
         small using 1:9:10 with yerrorlines pt 5 lw 1 dt 2 lc rgb '#c0392b' title sprintf('N = %s', n_small), \
         1 with lines lc rgb 'black' title 'Enskog D_E', \
         1.027 with lines dt 3 lc rgb 'gray40' title 'dilute, all Sonine terms'
    unset output
}
