# SPDX-License-Identifier: MIT
# Makes animation.gif from frame_0000.txt, frame_0001.txt, ... in the
# current directory: `gnuplot animate_disk.plt` or, inside gnuplot,
# load "animate_disk.plt". Disks are drawn to scale (column 3 is R) in a
# square 1000x1000 view. Set `frames` first to override the count.
if (!exists("frames")) {
    files = system("ls frame_[0-9][0-9][0-9][0-9].txt 2>/dev/null | wc -l") + 0
    frames = files
}
if (frames < 1) { print "animate_disk.plt: no frame_NNNN.txt files here"; exit }
if (!exists("output")) output = "animation.gif"
set terminal gif animate delay 4 size 600,600 optimize
set output output
set size square
set xrange [0:1000]
set yrange [0:1000]
unset key
set xtics 200
set ytics 200
do for [k = 0:frames - 1] {
    set title sprintf("frame %04d", k)
    plot sprintf("frame_%04d.txt", k) using 1:2:3 with circles fill solid 0.6 lc rgb "#2a6fb0"
}
unset output
