# SPDX-License-Identifier: MIT
# D / D_E against the area fraction from tools/analysis/diffusion_sweep.sh
# (one table per N), with Enskog's value 1 and the converged Sonine
# factor 1.027 of the dilute gas for reference.
#
#   sh tools/analysis/diffusion_sweep.sh tools/transport 4096 > d4096.dat
#   sh tools/analysis/diffusion_sweep.sh tools/transport 1024 > d1024.dat
#   gnuplot -e "big='d4096.dat'; small='d1024.dat'" tools/analysis/plot_diffusion.plt
#
# Writes diffusion.png (set out='name.png' to change).

if (!exists("big")) big = 'd4096.dat'
if (!exists("small")) small = 'd1024.dat'
if (!exists("out")) out = 'diffusion.png'

set terminal pngcairo size 900,600 font ',11'
set output out
set title 'Self-diffusion over Enskog, D measured from 20 to 40 mean free times'
set xlabel 'area fraction'
set ylabel 'D / D_E'
set xrange [0:0.72]
set grid
set key top right

plot big using 1:9:10 with yerrorlines pt 7 lw 2 lc rgb '#2a6fb0' title 'N = 4096', \
     small using 1:9:10 with yerrorlines pt 5 lw 1 dt 2 lc rgb '#c0392b' title 'N = 1024', \
     1 with lines lc rgb 'black' title 'Enskog D_E', \
     1.027 with lines dt 3 lc rgb 'gray40' title 'dilute, all Sonine terms'
