# SPDX-License-Identifier: MIT
# The hard-disk equation of state: Z against area fraction from
# tools/analysis/eos.sh (eos.dat: columns eta N integrator dt boundary Z error ...),
# with the virial series through B10 (Clisby and McCoy 2006) and the
# published points of Li et al. 2022 and Engel et al. 2013.
#   cd eos.N16384.relax50.blocks15x10 && gnuplot CHECKOUT/tools/analysis/plot_eos.plt
#       (tools/analysis/eos_gather.sh runs it in the sweep's directory; the N in
#        the legend is the data's, and the title says which integrator made
#        them, from eos.dat's third column)
# chains='FILE' draws beside them the rows of a sweep with the other
# integrator, any of its points (event chains beside the dynamics, for
# docs/eos.png: the rows of eos.chain.N16384.../points/point_*.dat):
#   gnuplot -e "chains='../eos.chain.N16384.relax200.blocks15x100/chains.dat'" CHECKOUT/tools/analysis/plot_eos.plt
# Writes eos.png and, for print, eos.pdf (set out='name.png' to change
# both, formats='png' for the PNG alone, formats='png svg' for an SVG too).
if (!exists("out")) out = 'eos.png'
if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out
# Reduced virial coefficients B_k / B_2^(k-1), k = 2..10, in powers of 2 eta.
b2 = 1.0; b3 = 0.78200443; b4 = 0.53223180; b5 = 0.33355604; b6 = 0.19884
b7 = 0.11487; b8 = 0.06499; b9 = 0.03622; b10 = 0.01995
series(e) = (x = 2*e, 1 + b2*x + b3*x**2 + b4*x**3 + b5*x**4 + b6*x**5 + b7*x**6 + b8*x**7 + b9*x**8 + b10*x**9)
$ref << EOD
0.670 9.362
0.698 10.318
0.700 10.306
0.716 10.073
0.720 10.069
EOD
# Which integrator made eos.dat (its third column, event or chain), for
# the title.
integrator = system("awk '!/^#/ { print $3; exit }' eos.dat")
made_by = integrator eq 'chain' ? 'event chains' : 'event-driven'
other = integrator eq 'chain' ? 'event-driven' : 'event chains'
# The N of the runs, from the data (column 2), for the legend: eos.dat has
# one N, eos_size.dat three (N/4, N, 4N).
stats "eos.dat" using 2 nooutput
n = int(STATS_min)
stats "eos_size.dat" using 2 nooutput
n_small = int(STATS_min); n_large = int(STATS_max)
# The whole range: to Z = 12, or above the highest point if higher.
stats "eos.dat" using ($6 + $7) nooutput
z_top = STATS_max + 0.3 > 12 ? STATS_max + 0.3 : 12
# The inset's range of Z: every point inside its range of area fraction,
# with its error bar and the published values, and a margin.
inset_lo = 0.665; inset_hi = 0.755
in_inset(x) = (x >= inset_lo && x <= inset_hi)
stats "eos.dat" using (in_inset($1) ? $6 - $7 : NaN) nooutput
z_lo = STATS_min < 9.362 ? STATS_min : 9.362
stats "eos.dat" using (in_inset($1) ? $6 + $7 : NaN) nooutput
z_hi = STATS_max > 10.318 ? STATS_max : 10.318
stats "eos_size.dat" using (in_inset($1) ? $6 - $7 : NaN) nooutput
z_lo = STATS_min < z_lo ? STATS_min : z_lo
stats "eos_size.dat" using (in_inset($1) ? $6 + $7 : NaN) nooutput
z_hi = STATS_max > z_hi ? STATS_max : z_hi
if (exists("chains")) {
    stats chains using 2 nooutput
    n_chains = int(STATS_min)
    stats chains using (in_inset($1) ? $6 - $7 : NaN) nooutput
    z_lo = STATS_min < z_lo ? STATS_min : z_lo
    stats chains using (in_inset($1) ? $6 + $7 : NaN) nooutput
    z_hi = STATS_max > z_hi ? STATS_max : z_hi
}
# The other integrator's points, as the tails of the two plot commands
# (macros: empty without chains=).
chains_style = 'using 1:6:7 pt 13 ps 1 lc rgb "#9467bd"'
chains_main = exists("chains") ? sprintf(', "%s" %s with yerrorbars title "disksim, %s, N = %d"', \
                                         chains, chains_style, other, n_chains) : ''
chains_inset = exists("chains") ? sprintf(', "%s" %s with yerrorlines', chains, chains_style) : ''
margin = 0.08 * (z_hi - z_lo)
do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 900,640 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,5in font ',9' }
    if (format eq 'svg') { set terminal svg size 900,640 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set multiplot
    # The whole range.
    set xlabel "area fraction {/Symbol h}"
    set ylabel "Z = P A / (N kT)"
    # The state of disksim's runs (tools/analysis/eos_point.sh) in the title,
    # their N in the key, which sits under the curve, clear of it.
    set title sprintf("Hard disks, %s, in a periodic 1000 x 866.03 box, from a lattice", \
                      exists("chains") ? made_by . ' and ' . other : made_by)
    set key bottom right
    set grid
    set xrange [0:0.78]
    set yrange [0:z_top]
    plot series(x) with lines lw 2 lc rgb "#888888" title "virial series B_2..B_{10}", \
         $ref using 1:2 with points pt 6 ps 2 lw 2 lc rgb "#d62728" title "Li 2022 (< 0.70), Engel 2013", \
         "eos.dat" using 1:6:7 with yerrorbars pt 7 ps 1 lc rgb "#1f77b4" title sprintf("disksim%s, N = %d", exists("chains") ? ', ' . made_by : '', n), \
         "eos_size.dat" using 1:6:7 with yerrorbars pt 5 ps 0.8 lc rgb "#2ca02c" title sprintf("disksim at 0.70, N = %d, %d, %d", n_small, n, n_large) \
         @chains_main
    # The melting region, enlarged: the loop between 0.70 and 0.72.
    set origin 0.09, 0.40
    set size 0.55, 0.50
    set object 1 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb "white" fillstyle solid noborder
    unset title
    unset xlabel
    unset ylabel
    unset key
    set xrange [inset_lo:inset_hi]
    set yrange [z_lo - margin:z_hi + margin]
    set xtics 0.02
    set ytics autofreq
    plot $ref using 1:2 with points pt 6 ps 2 lw 2 lc rgb "#d62728", \
         "eos.dat" using 1:6:7 with yerrorlines pt 7 ps 1 lc rgb "#1f77b4", \
         "eos_size.dat" using 1:6:7 with yerrorbars pt 5 ps 0.8 lc rgb "#2ca02c" \
         @chains_inset
    unset multiplot
    unset output
}
