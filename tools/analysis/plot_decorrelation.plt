# SPDX-License-Identifier: MIT
# Decorrelation per CPU second: the integrated autocorrelation time, in
# CPU seconds, of |psi6| and of Z for each algorithm at area fractions
# 0.70 and 0.72 (tools/analysis/decorrelation.sh writes the data).
#
#   gnuplot -e "data='decorrelation.d/tau.txt'; out='docs/decorrelation.png'" \
#       tools/analysis/plot_decorrelation.plt
#
# data has the lines of tools/decorrelation, ECMC, EDMD with Andersen's
# bath and EDMD at 0.70, then the same at 0.72. Filled points: runs at
# least 50 tau long; open points: shorter runs, whose tau is a lower
# bound.

if (!exists("data")) data = 'decorrelation.d/tau.txt'
if (!exists("out")) out = 'decorrelation.png'

set terminal pngcairo size 1000,450 font ',11'
set output out
set multiplot layout 1,2
set logscale y
set format y '10^{%L}'
set xrange [-0.6:2.6]
set xtics ('ECMC' 0, "EDMD +\nAndersen" 1, 'EDMD' 2)
set ylabel 'tau_{int} (CPU seconds)'
set key bottom right font ',9'
set bmargin 4
set offsets 0, 0, graph 0.1, graph 0.1
set grid ytics
x(row) = row - 3 * floor(row / 3.0) + (row >= 3 ? 0.12 : -0.12)
long(run, value) = run >= 50 ? value : 1/0
short(run, value) = run < 50 ? value : 1/0
do for [panel = 0:1] {
    col = panel ? 10 : 6
    runs = panel ? 16 : 14
    set title (panel ? 'pressure Z (over each sample)' : 'global order |psi_6|')
    if (panel) { unset key }
    plot data using (x($0)):(long(column(runs), column(col))):(column(col + 1)) \
             every ::0::2 with yerrorbars pt 7 lc 1 title 'area fraction 0.70', \
         '' using (x($0)):(short(column(runs), column(col))):(column(col + 1)) \
             every ::0::2 with yerrorbars pt 6 lc 1 title '0.70, run < 50 tau: lower bound', \
         '' using (x($0 + 3)):(long(column(runs), column(col))):(column(col + 1)) \
             every ::3::5 with yerrorbars pt 5 lc 2 title 'area fraction 0.72', \
         '' using (x($0 + 3)):(short(column(runs), column(col))):(column(col + 1)) \
             every ::3::5 with yerrorbars pt 4 lc 2 title '0.72, run < 50 tau: lower bound'
}
unset multiplot
