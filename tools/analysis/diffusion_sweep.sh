#!/bin/sh
# SPDX-License-Identifier: MIT
# D / D_E against the area fraction (docs/physics.md, "Transport"): runs
# tools/transport at each area fraction with the same N and the same
# window in Enskog mean free times (lags 200 to 400 of 0.1 t_E: 20 to 40
# t_E), and prints one row per area fraction under two '#' lines, the
# first naming the columns (numpy.loadtxt skips them,
# numpy.genfromtxt(names=True) reads the names):
#   eta Z g_sigma D_E D_einstein D_einstein_error D_green_kubo
#   D_green_kubo_error D_over_D_E D_over_D_E_error t_c
# Usage: sh tools/analysis/diffusion_sweep.sh [TRANSPORT] [N [ETA...]]
#   (TRANSPORT: the tools/transport to run; N default 4096; the area
#    fractions default to 0.02 0.05 0.1 0.2 0.3 0.4 0.5 0.6 0.65 0.69)
#
# The sweep lives in diffusion.N<N>/ of the current directory: each area
# fraction's whole tools/transport output is kept there as eta_<ETA>.txt
# the moment it is complete, and DIR/diffusion.dat is the table of every
# area fraction the directory holds. Run again, an area fraction already
# there is not run again: its output is reused (docs/sweeps.md).
set -eu
# Where the other pieces are: in the checkout, beside this file and
# tools/transport one folder up; `make install` rewrites these two lines
# with the installed places (docs/install.md).
scripts=$(cd "$(dirname "$0")" && pwd)
transport=$scripts/../transport
case ${1:-} in
--help | -h)
    cat <<EOF
usage: ${0##*/} [TRANSPORT] [N [ETA...]]
D / D_E against the area fraction: tools/transport at each area fraction
(default 0.02 0.05 0.1 0.2 0.3 0.4 0.5 0.6 0.65 0.69) for N disks (default
4096), D over 20 to 40 Enskog mean free times, one row per area fraction on
stdout. Each run is kept in diffusion.NN/ of the current directory; run
again, the area fractions done are reused.
  --help   show this help and exit
EOF
    exit 0
    ;;
'' | *[!0-9]*) [ $# -gt 0 ] && { transport=$1; shift; } ;;
esac
n=${1:-4096}
[ $# -gt 0 ] && shift
[ $# -gt 0 ] || set -- 0.02 0.05 0.1 0.2 0.3 0.4 0.5 0.6 0.65 0.69
[ -x "$transport" ] || { echo "diffusion_sweep.sh: no program $transport (run make)" >&2; exit 2; }
case $n in
'' | *[!0-9]*) echo "diffusion_sweep.sh: N must be a whole number, got '$n'" >&2; exit 2 ;;
esac

dir=diffusion.N$n
options="--lags 401 --window 200:400 --every 10"
printf '%s\n' "diffusion sweep: transport $n ETA [--lattice above 0.54] $options" |
    sh "$scripts/sweep_dir.sh" "$dir" >/dev/null

# The row of one tools/transport output.
row() { # ETA FILE
    awk -v eta="$1" '
        /^# Z / { z = $3; g = $7; tc = $11 }
        /^# D_0 / { de = $5 }
        /^# window / {
            for (i = 1; i <= NF; ++i) {
                if ($i == "D_einstein") { e = $(i + 1); ee = $(i + 3) }
                if ($i == "D_green_kubo") { k = $(i + 1); ke = $(i + 3) }
                if ($i == "D/D_E") { r = $(i + 1); re = $(i + 3) }
            }
        }
        END { print eta, z, g, de, e, ee, k, ke, r, re, tc }' "$2"
}
header() {
    echo "# eta Z g_sigma D_E D_einstein D_einstein_error D_green_kubo D_green_kubo_error D_over_D_E D_over_D_E_error t_c"
    echo "# N = $n, periodic 1000 x 1000 box, event-driven; D over lags 200 to 400 of 0.1 t_E (tools/analysis/diffusion_sweep.sh)"
}

header
for eta in "$@"; do
    # One name for one number: 0.1, 0.10 and 1e-1 are the same point.
    eta=$(awk -v e="$eta" 'BEGIN { printf "%.10g", e }')
    out="$dir/eta_$eta.txt"
    if [ ! -s "$out" ]; then
        # Random placement stops near 0.54: denser systems start on a lattice
        # and relax for 1000 t_E (tools/transport's default then).
        start=$(awk -v e="$eta" 'BEGIN { print (e > 0.54 ? "--lattice" : "") }')
        # shellcheck disable=SC2086
        if ! "$transport" "$n" "$eta" $start $options >"$out.$$"; then
            rm -f "$out.$$"
            echo "diffusion_sweep.sh: tools/transport failed at area fraction $eta" >&2
            exit 1
        fi
        mv "$out.$$" "$out"
    fi
    row "$eta" "$out"
done
# The table of the whole directory, by area fraction.
{
    header
    for out in "$dir"/eta_*.txt; do
        [ -s "$out" ] || continue
        eta=${out##*/eta_}
        row "${eta%.txt}" "$out"
    done | sort -g
} >"$dir/diffusion.dat.$$"
mv "$dir/diffusion.dat.$$" "$dir/diffusion.dat"
