# SPDX-License-Identifier: MIT
# The plots of docs/physics.md's granular gases, from the tables of
# tools/analysis/granular.py:
#
#   PYTHONPATH=python python3 tools/analysis/granular.py haff 0.9 20 2000 > haff_090.dat
#   PYTHONPATH=python python3 tools/analysis/granular.py haff 0.95 20 2000 > haff_095.dat
#   gnuplot -e "what='haff'; data='haff_090.dat haff_095.dat'" tools/analysis/plot_granular.plt
#   PYTHONPATH=python python3 tools/analysis/granular.py barometric > barometric.dat
#   gnuplot -e "what='barometric'; data='barometric.dat'" tools/analysis/plot_granular.plt
#
# haff: the measured T over Haff's law T0 / (1 + t / tau)^2 of each table,
# with its standard error, against t / tau (on T / T0 itself the points sit
# on the law and hide the few per cent); the tables' first line gives e. barometric: the time-averaged disks per unit
# height against the barometric law with the measured m g / kT, on a log
# scale (the law is a straight line; the first and last bins hold less,
# since a centre keeps R from the walls). Writes granular_WHAT.png and, for
# print, the PDF beside it (set out='name.png' to change both, formats='png'
# for the PNG alone).

if (!exists("what")) what = 'haff'
if (!exists("data")) data = what eq 'haff' ? 'haff_090.dat haff_095.dat' : 'barometric.dat'
if (!exists("out")) out = 'granular_' . what . '.png'
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

# "# e 0.9, n 2000, area fraction 0.05, 20 seeds: ..." -> "e = 0.9"
label(file) = (h = system(sprintf("head -n 1 '%s'", file)), 'e = ' . word(h, 3)[1:strlen(word(h, 3)) - 1])
colours = "#2a6fb0 #c0392b #27864a"

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.67in font ',9' }
    set output format eq 'png' ? out : stem . '.' . format
    set grid
    if (what eq 'haff') {
        set title "Free cooling at area fraction 0.05: T over Haff's law T_0 / (1 + t / tau)^2"
        set xlabel 't / tau'
        set ylabel 'T / T_{Haff}'
        set yrange [0.98:1.05]
        set key top left box opaque
        plot for [i = 1:words(data)] word(data, i) using 1:3:4 \
                 with yerrorlines pt 7 ps 0.8 lc rgb word(colours, i) title label(word(data, i)), \
             1 with lines dt 2 lw 2 lc rgb 'black' title "Haff's law"
    } else {
        set title 'A dilute elastic gas under gravity: the barometric profile'
        set yrange [0.3:3]
        set xlabel 'y'
        set ylabel 'disks per unit height'
        set logscale y
        set key top right box opaque
        plot data using 1:2 with points pt 7 ps 0.8 lc rgb word(colours, 1) title 'measured', \
             data using 1:3 with lines lw 2 lc rgb 'black' title 'n_0 exp(-m g y / kT)'
    }
    unset output
}
