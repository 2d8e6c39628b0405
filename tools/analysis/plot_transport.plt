# SPDX-License-Identifier: MIT
# The long-time tail of the velocity autocorrelation from tools/transport:
# left, C(t)/C(0) against t/t_c on log-log axes with the mode-coupling
# line amp/t and the sound traversal time L/c; right, D(t) = (1/2) int_0^t C
# against ln t, which the 1/t tail makes a straight line.
#
#   tools/transport 65536 0.3 --interval 0.007 --lags 1000 --every 20 --blocks 8 > tail.dat
#   gnuplot -e "data='tail.dat'; tc=0.01423; amp=0.00315; ts=4.96" tools/analysis/plot_transport.plt
#
# tc is the mean free time (tools/transport prints it, "t_c"), amp the
# mode-coupling amplitude 1/(8 pi n (D + nu)) in time units, ts = L/c in
# time units (docs/physics.md derives both). The title gives the state
# point from tools/transport's first line (N, area fraction, box). Writes
# transport_tail.png and, for print, transport_tail.pdf beside it (set
# out='name.png' to change both, formats='png' for the PNG alone,
# formats='png svg' for an SVG too).

if (!exists("data")) data = 'tail.dat'
if (!exists("out")) out = 'transport_tail.png'
if (!exists("tc")) tc = 1.0
if (!exists("amp")) amp = 0.0
if (!exists("ts")) ts = 0.0

if (!exists("formats")) formats = 'png pdf'
stem = strlen(out) > 4 && out[strlen(out) - 3:] eq '.png' ? out[1:strlen(out) - 4] : out

# "# transport: N 65536 eta 0.3 periodic event seed 20260101, ..."
header = system(sprintf("sed -n '/^# transport: /{p;q;}' '%s'", data))
state = strlen(header) > 0 ? sprintf('N = %s, area fraction %s, %s 1000 x 1000 box, %s-driven', \
    word(header, 4), word(header, 6), word(header, 7), word(header, 8)) : data

do for [format in formats] {
    reset
    if (format eq 'png') { set terminal pngcairo size 1300,600 font ',11' }
    if (format eq 'pdf') { set terminal pdfcairo size 7in,3.6in font ',7' }
    if (format eq 'svg') { set terminal svg size 1300,600 font ',11' }
    set output format eq 'png' ? out : stem . '.' . format
    set multiplot layout 1,2 title sprintf('The long-time tail: %s', state) noenhanced

    set title 'Velocity autocorrelation'
    set xlabel 't / t_c  (t_c: mean free time)'
    set ylabel 'C(t) / C(0)'
    set logscale xy
    set format y '10^{%L}'
    set xrange [0.5:*]
    set yrange [1e-5:1]
    set grid
    set key bottom left Left reverse
    if (ts > 0) {
        set arrow 1 from ts / tc, 1e-5 to ts / tc, 1 nohead dt 3 lc rgb 'gray40'
        set label 1 'L/c' at ts / tc * 1.05, 0.3 tc rgb 'gray30'
    }
    # Past a few mean free times the lags are averaged in bins of 1/20 of a
    # decade (the error of a bin's mean from its lags' errors, which are
    # correlated, so it is a lower bound): one point per bin.
    binned = "< awk '!/^#/ && $2 > 0 { b = int(log($2) / log(10) * 20 + 1000); if (b != last && k) { print t / k, c / k, sqrt(e) / k; t = c = e = k = 0 } last = b; t += $2; c += $5; e += $6 * $6; k++ } END { if (k) print t / k, c / k, sqrt(e) / k }' ".data
    plot binned using 1:($2 > 0 ? $2 : 1/0):3 with yerrorbars pt 7 ps 0.5 lc rgb '#2a6fb0' \
             title 'C(t)/C(0)', \
         amp > 0 ? amp / (x * tc) : 1/0 with lines lw 2 dt 2 lc rgb '#c0392b' \
             title 'mode coupling 1/(8{/Symbol p}n(D+{/Symbol n})t)'

    unset arrow
    unset label
    set title 'D(t) = (1/2) \int_0^t C'
    set ylabel 'D(t)'
    set logscale x
    unset logscale y
    set format y '%g'
    set xrange [1:*]
    set yrange [*:*]
    set key top left Left reverse
    if (ts > 0) {
        set arrow 1 from ts / tc, graph 0 to ts / tc, graph 1 nohead dt 3 lc rgb 'gray40'
    }
    plot data using ($2):7 with lines lw 2 lc rgb '#2a6fb0' title 'D(t)', \
         data using ($2):($7 - 2 * $8) with lines lw 1 dt 2 lc rgb '#2a6fb0' title '2 standard errors', \
         data using ($2):($7 + 2 * $8) with lines lw 1 dt 2 lc rgb '#2a6fb0' notitle

    unset multiplot
    unset output
}
