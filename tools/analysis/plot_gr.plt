# SPDX-License-Identifier: MIT
# The radial distribution function g(r) written by tools/gr, against r in
# diameters, with the ideal gas (g = 1) for reference. The title gives the
# state point from tools/gr's first line: N, the area fraction, the box
# and its boundary.
#
#   tools/gr --dr 0.5 frame_0499.txt > gr.dat
#   gnuplot -e "data='gr.dat'" tools/analysis/plot_gr.plt
#
# d is the disk diameter 2R: by default the d of tools/gr's first line (the
# largest), or set d=...; r is in units of d. Writes gr.png and, for
# print, gr.pdf beside it (set out='name.png' to change both, formats='png'
# for the PNG alone, formats='png svg' for an SVG too).

if (!exists("data")) data = 'gr.dat'
if (!exists("out")) out = 'gr.png'
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

# "# g(r) of FILE: N = 400, area fraction 0.0314, d = 10, box 1000 x 1000, walls ..."
header = system(sprintf("head -n 1 '%s'", data))
num(s) = real(s[strlen(s):] eq ',' ? s[1:strlen(s) - 1] : s)
field(key) = strstrt(header, key) ? num(word(header[strstrt(header, key) + strlen(key):], 1)) : NaN
n = field('N = ')
eta = field('area fraction ')
box = field('box ')
box_y = strstrt(header, 'box ') ? num(word(header[strstrt(header, 'box ') + 4:], 3)) : NaN
boundary = strstrt(header, 'periodic') ? 'periodic' : 'walls'
if (!exists("d")) d = field('d = ')
if (d != d) d = 1.0
state = n == n && eta == eta ? \
    sprintf('N = %d, area fraction %.4g, %s box %g x %g', n, eta, boundary, box, box_y) : data

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.67in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,600 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set title sprintf('Radial distribution function: %s', state) noenhanced
    set xlabel (d == 1.0 ? 'r' : 'r / d  (d = 2R)')
    set ylabel 'g(r)'
    set xrange [0:*]
    set yrange [0:*]
    set grid
    set key top right box opaque
    plot data using ($1 / d):2 with lines lw 2 lc rgb '#2a6fb0' title 'g(r)', \
         1 with lines dt 2 lc rgb 'black' title 'ideal gas'
    unset output
}
