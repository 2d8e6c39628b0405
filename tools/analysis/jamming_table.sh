#!/bin/sh
# SPDX-License-Identifier: MIT
# The table of docs/physics.md from the rows of tools/analysis/jamming.sh:
# for each N and rate, the runs, the area fraction at jamming (mean, the
# sample standard deviation of the runs, lowest and highest), the contacts
# per disk left and the rattler fraction (means).
# Usage: sh tools/analysis/jamming_table.sh jam1024.tsv [jam4096.tsv ...]
set -eu
[ $# -ge 1 ] || { echo "usage: jamming_table.sh TABLE.tsv..." >&2; exit 2; }
echo "| N | rate | runs | area fraction at Z = 10^6 | spread (sd) | lowest, highest | contacts per disk | rattlers |"
echo "|---|---|---|---|---|---|---|---|"
awk -F '\t' '
    /^#/ { next }
    {
        k = $1 SUBSEP $2
        if (!(k in n)) order[++keys] = k
        n[k]++; s[k] += $4; ss[k] += $4 * $4; c[k] += $6; r[k] += $7
        if (!(k in lo) || $4 < lo[k]) lo[k] = $4
        if (!(k in hi) || $4 > hi[k]) hi[k] = $4
    }
    END {
        for (i = 1; i <= keys; ++i) {
            k = order[i]; split(k, p, SUBSEP)
            m = s[k] / n[k]
            sd = n[k] > 1 ? sqrt((ss[k] - n[k] * m * m) / (n[k] - 1)) : 0
            printf "| %s | %s | %d | %.4f | %.4f | %.4f, %.4f | %.3f | %.3f |\n",
                p[1], p[2], n[k], m, sd, lo[k], hi[k], c[k] / n[k], r[k] / n[k]
        }
    }' "$@"
