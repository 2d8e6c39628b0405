#!/bin/sh
# SPDX-License-Identifier: MIT
# The plot scripts of tools/analysis/ make figures a paper can print: each
# writes a PDF beside its PNG (and an SVG when asked), and each figure
# names its state point. The text is checked in the SVG, where gnuplot
# writes it as text. The data are docs/data/ and small runs of this build.
# Run by make test, from the top; DISKS and GR name the programs of the
# build (make passes them). Skipped, saying so, without gnuplot.
# shellcheck disable=SC2015 # "A && B || fail": fail whenever A or B is false
set -eu
top=$(pwd)
DISKS=${DISKS:-$top/disks}
GR=${GR:-$top/tools/gr}
analysis=$top/tools/analysis
data=$top/docs/data
if ! command -v gnuplot >/dev/null 2>&1; then
    echo "plots: gnuplot is not installed (Debian: gnuplot-nox): the plot scripts are not checked"
    exit 0
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/plots.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() {
    echo "plots: $*" >&2
    exit 1
}
checked=0
# SCRIPT NAME SETTINGS TEXT...: SCRIPT with SETTINGS writes NAME.png and
# NAME.pdf, and with formats='svg' an SVG whose text has every TEXT.
plot() {
    script=$1 name=$2 settings=$3
    shift 3
    gnuplot -e "$settings; out='$name.png'" "$analysis/$script" 2>"$name.err" ||
        fail "$script failed: $(cat "$name.err")"
    [ -s "$name.png" ] || fail "$script wrote no $name.png"
    head -c 5 "$name.pdf" 2>/dev/null | grep -q '^%PDF-' || fail "$script wrote no PDF beside $name.png"
    gnuplot -e "$settings; out='$name.png'; formats='svg'" "$analysis/$script" 2>"$name.err" ||
        fail "$script with formats='svg' failed: $(cat "$name.err")"
    for text in "$@"; do
        grep -qF -- "$text" "$name.svg" || fail "$script: the figure does not say '$text'"
    done
    checked=$((checked + 1))
}

plot plot_rheology.plt shear_thinning "low='$data/rheo030.dat'; high='$data/rheo050.dat'; helfand_low=0.995; helfand_low_error=0.023; helfand_high=1.011; helfand_high_error=0.026" \
    "N = 1024" "area fraction 0.3" "area fraction 0.5"
plot plot_diffusion.plt diffusion "big='$data/diffusion4096.dat'; small='$data/diffusion1024.dat'" \
    "N = 4096" "N = 1024" "periodic 1000 x 1000 box"
# The jamming plot's log axis reads at 1, 2 and 5 of each decade.
plot plot_jamming.plt jamming "small='$data/jam1024.tsv'; large='$data/jam4096.tsv'" \
    "N = 1024, 20 runs" "N = 4096, 6 runs" ">0.0005<" ">0.001<" ">0.002<" ">0.005<" ">0.01<"
plot plot_transport.plt tail "data='$data/tail65536.dat'; $(sh "$analysis/tail_theory.sh" "$data/tail65536.dat")" \
    "N = 65536, area fraction 0.3"

"$DISKS" 400 5 --velocities --frames 3 --out run --quiet
"$GR" --dr 0.5 run/frame_0002.txt >gr.dat
plot plot_gr.plt gr "data='gr.dat'" "N = 400, area fraction 0.03142, walls box 1000 x 1000"
plot speed_hist.plt speeds "frame='run/frame_0002.txt'" "N = 400, area fraction 0.0314"
"$DISKS" 400 5 --frames 3 --out run --overwrite --stats stats.csv --quiet
plot plot_stats.plt stats "stats_file='stats.csv'; N=400; R=5" "disks 400 5" "area fraction 0.031"
printf '5 0.0785 1.16 2000\n8 0.2011 1.55 3000\n' >pressure.dat
plot plot_pressure.plt pressure "data='pressure.dat'; N=2000" "N = 2000 in a 1000 x 1000 box"
printf '# eta dt Z_over_Z_event error\n0.1 0 1 0.001\n0.1 0.001 0.99 0.001\n\n\n0.3 0 1 0.001\n0.3 0.001 0.98 0.001\n\n\n0.5 0 1 0.001\n0.5 0.001 0.97 0.001\n' \
    >ratio.dat
plot plot_pressure_vs_dt.plt dt "data='ratio.dat'; N=4000" "N = 4000, periodic 1000 x 1000 box"
echo "plots: $checked plot scripts write a PNG, a PDF beside it and an SVG that names the state point"
