# SPDX-License-Identifier: MIT
# Shear thinning: the apparent viscosity of a sheared flow over Enskog's
# at rest, against the reduced rate gamma_dot t_c (t_c the measured mean
# free time), at two area fractions, from tools/rheology's lines (columns
# eta N rate viscosity error temperature slope slope_error reduced_rate
# eta_enskog; each table's first row, its smallest rate, gives the eta_E
# at rest: a strong shear changes the structure and Z), with the Helfand
# viscosity of tools/transport at rest at each (helfand_low, helfand_high
# and their errors, over Enskog's) as bands on the left.
#
#   (for rate in 0.055 0.11 0.27 0.55 1.1 2.7 5.5; do tools/rheology 1024 0.3 $rate | tail -n 1; done) > rheo030.dat
#   (for rate in 0.2 0.4 1 2 4 10 20; do tools/rheology 1024 0.5 $rate --lattice | tail -n 1; done) > rheo050.dat
#   gnuplot -e "low='rheo030.dat'; high='rheo050.dat'; helfand_low=1.05; helfand_low_error=0.02; \
#       helfand_high=1.1; helfand_high_error=0.03" tools/analysis/plot_rheology.plt
#
# Writes shear_thinning.png and, for print, shear_thinning.pdf beside it
# (set out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too).

if (!exists("low")) low = 'rheo030.dat'
if (!exists("high")) high = 'rheo050.dat'
if (!exists("out")) out = 'shear_thinning.png'
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

# The area fraction and N of a table: its first row's first two columns.
first(file, col) = system(sprintf("awk '!/^#/ { print $%d; exit }' '%s'", col, file))
eta_low = first(low, 1)
eta_high = first(high, 1)
n_low = first(low, 2)
enskog_low = first(low, 10) + 0
enskog_high = first(high, 10) + 0

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,4.67in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,600 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set title sprintf("Shear thinning of hard disks: Lees-Edwards flow, isokinetic thermostat\nN = %s, periodic 1000 x 1000 box, event-driven", n_low)
    set xlabel 'reduced shear rate: rate x t_c' noenhanced
    set ylabel 'viscosity / Enskog eta_E at rest' noenhanced
    set logscale x
    set grid
    set key bottom left box opaque
    if (exists("helfand_low")) {
        set object 1 rect from graph 0, first helfand_low - helfand_low_error to graph 1, first helfand_low + helfand_low_error fc rgb '#2a6fb0' fs transparent solid 0.15 noborder behind
        set object 2 rect from graph 0, first helfand_high - helfand_high_error to graph 1, first helfand_high + helfand_high_error fc rgb '#c0392b' fs transparent solid 0.15 noborder behind
        set label 1 'shaded: Helfand viscosity at rest, one standard error' at graph 0.35, graph 0.45 noenhanced
    }
    plot low using 9:($4 / enskog_low):($5 / enskog_low) with yerrorlines pt 7 lw 2 lc rgb '#2a6fb0' title sprintf('area fraction %s', eta_low), \
         high using 9:($4 / enskog_high):($5 / enskog_high) with yerrorlines pt 5 lw 2 lc rgb '#c0392b' title sprintf('area fraction %s', eta_high), \
         1 with lines lc rgb 'black' title 'Enskog eta_E' noenhanced
    unset output
}
