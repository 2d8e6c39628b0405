#!/bin/sh
# SPDX-License-Identifier: MIT
# Jamming of the 50:50 mixture of radius ratio 1.4: compressed from area
# fraction 0.5 (random start, periodic, event-driven) at each growth rate
# until Z passes 10^6, for each seed; one row per run:
#   N rate seed area_fraction Z contacts_per_disk rattler_fraction seconds
# Usage: sh tools/analysis/jamming.sh N "RATES" "SEEDS" [OUT.tsv]
# e.g.   sh tools/analysis/jamming.sh 1024 "0.1 0.03 0.01 0.003" "1 2 3 4 5" jam1024.tsv
# Run from the top of the checkout after `make`; each run's frames go to a
# temporary directory, removed after it.
set -eu
n=${1:?usage: jamming.sh N RATES SEEDS [OUT.tsv]}
rates=${2:?usage: jamming.sh N RATES SEEDS [OUT.tsv]}
seeds=${3:?usage: jamming.sh N RATES SEEDS [OUT.tsv]}
out=${4:-/dev/stdout}
disks=${DISKS:-./disks}
[ -x "$disks" ] || { echo "jamming.sh: $disks not found: run make first" >&2; exit 1; }
# R of the small disks for area fraction 0.5: pi N R^2 (1 + 1.4^2) / 2 = 0.5 10^6.
r=$(awk -v n="$n" 'BEGIN { printf "%.10g", sqrt(0.5e6 / (3.14159265358979 * n * 1.48)) }')
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ "$out" = /dev/stdout ] || : > "$out"
printf '# N\trate\tseed\tarea_fraction\tZ\tcontacts_per_disk\trattler_fraction\tseconds\n' >> "$out"
for rate in $rates; do
    for seed in $seeds; do
        start=$(date +%s)
        # One frame per time unit, up to 10^4: the growth ends the run when it jams.
        if ! "$disks" "$n" "$r" --mixture 1.4:0.5 --periodic --integrator event \
            --grow "$rate" --seed "$seed" --frames 10000 --steps-per-frame 1000 \
            --out "$tmp/run" --overwrite > "$tmp/log"; then
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
        ' "$tmp/log" >> "$out"
        rm -rf "$tmp/run"
    done
done
