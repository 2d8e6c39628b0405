#!/bin/sh
# SPDX-License-Identifier: MIT
# Jamming of the 50:50 mixture of radius ratio 1.4: compressed from area
# fraction 0.5 (random start, periodic, event-driven) at each growth rate
# until Z passes 10^6, for each seed; one row per run under a '#' line
# naming the columns (numpy.loadtxt skips it):
#   N rate seed area_fraction Z contacts_per_disk rattler_fraction seconds
# Usage: sh tools/analysis/jamming.sh N "RATES" "SEEDS" [OUT.tsv]
# e.g.   sh tools/analysis/jamming.sh 1024 "0.1 0.03 0.01 0.003" "1 2 3 4 5" jam1024.tsv
# The rows of the runs asked for go to OUT.tsv, or to stdout without it.
#
# The sweep lives in jamming.N<N>/ of the current directory: each run's
# row is kept there as rate<RATE>.seed<SEED>.tsv the moment the run ends,
# and DIR/jamming.tsv is the table of every run the directory holds. Run
# again, with the same or other rates and seeds, a run already there is
# not run again: its row is reused (docs/sweeps.md). Each run's frames go
# to a temporary directory, removed after it.
set -eu
# Where the other pieces are: in the checkout, beside this file and disks
# two folders up; `make install` rewrites these two lines with the
# installed places (docs/install.md).
scripts=$(cd "$(dirname "$0")" && pwd)
disks=${DISKS:-$scripts/../../disks}
case ${1:-} in
--help | -h)
    cat <<EOF
usage: ${0##*/} N "RATES" "SEEDS" [OUT.tsv]
Jamming of the 50:50 mixture of radius ratio 1.4 in N disks: a growth run
from area fraction 0.5 to Z = 10^6 for each rate and seed, one row per run
on stdout or in OUT.tsv. Each run is kept in jamming.NN/ of the current
directory; run again, the runs done are reused.
  --help   show this help and exit
EOF
    exit 0
    ;;
esac
n=${1:?usage: jamming.sh N RATES SEEDS [OUT.tsv]}
rates=${2:?usage: jamming.sh N RATES SEEDS [OUT.tsv]}
seeds=${3:?usage: jamming.sh N RATES SEEDS [OUT.tsv]}
out=${4:-}
[ -x "$disks" ] || { echo "jamming.sh: $disks not found: run make first" >&2; exit 1; }
case $n in
'' | *[!0-9]*) echo "jamming.sh: N must be a whole number, got '$n'" >&2; exit 2 ;;
esac
# R of the small disks for area fraction 0.5: pi N R^2 (1 + 1.4^2) / 2 = 0.5 10^6.
r=$(awk -v n="$n" 'BEGIN { printf "%.10g", sqrt(0.5e6 / (3.14159265358979 * n * 1.48)) }')
dir=jamming.N$n
run="disks $n $r --mixture 1.4:0.5 --periodic --integrator event --grow RATE --seed SEED --frames 10000 --steps-per-frame 1000"
printf 'jamming sweep: %s\n' "$run" | sh "$scripts/sweep_dir.sh" "$dir" >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
header="# N	rate	seed	area_fraction	Z	contacts_per_disk	rattler_fraction	seconds"
echo "$header" >"$tmp/rows"
for rate in $rates; do
    # One name for one number: 0.1, 0.10 and 1e-1 are the same rate.
    rate=$(awk -v r="$rate" 'BEGIN { printf "%.10g", r }')
    for seed in $seeds; do
        row="$dir/rate$rate.seed$seed.tsv"
        if [ ! -s "$row" ]; then
            start=$(date +%s)
            # One frame per time unit, up to 10^4: the growth ends the run when it jams.
            if ! "$disks" "$n" "$r" --mixture 1.4:0.5 --periodic --integrator event \
                --grow "$rate" --seed "$seed" --frames 10000 --steps-per-frame 1000 \
                --out "$tmp/run" --overwrite >"$tmp/log"; then
                echo "jamming.sh: the run N = $n, rate $rate, seed $seed failed" >&2
                exit 1
            fi
            end=$(date +%s)
            # "area fraction F, jammed at Z = Z in frame ...; C contacts per disk, rattlers K (P%)"
            awk -v n="$n" -v rate="$rate" -v seed="$seed" -v s=$((end - start)) '
                /^area fraction .*jammed at Z/ {
                    gsub(/[,;()%]/, " ")
                    for (i = 1; i <= NF; ++i) {
                        if ($i == "fraction") f = $(i + 1)
                        if ($i == "Z" && $(i + 1) == "=") z = $(i + 2)
                        if ($i == "contacts") c = $(i - 1)
                        if ($i == "rattlers") p = $(i + 2)
                    }
                    printf "%s\t%s\t%s\t%s\t%s\t%s\t%.4f\t%s\n", n, rate, seed, f, z, c, p / 100, s
                    found = 1
                }
                END { if (!found) { print "jamming.sh: no jam in the run" > "/dev/stderr"; exit 1 } }
            ' "$tmp/log" >"$row.$$"
            mv "$row.$$" "$row"
            rm -rf "$tmp/run"
        fi
        cat "$row" >>"$tmp/rows"
    done
done
# The table of the whole directory: the fastest rate first, then by seed.
{
    echo "$header"
    for row in "$dir"/rate*.seed*.tsv; do
        [ -s "$row" ] && cat "$row"
    done | sort -t '	' -k2,2gr -k3,3n
} >"$dir/jamming.tsv.$$"
mv "$dir/jamming.tsv.$$" "$dir/jamming.tsv"
if [ -n "$out" ]; then
    mv "$tmp/rows" "$out"
else
    cat "$tmp/rows"
fi
