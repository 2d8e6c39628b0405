#!/bin/sh
# SPDX-License-Identifier: MIT
# D / D_E against the area fraction (docs/physics.md, "Transport"): runs
# tools/transport at each area fraction with the same N and the same
# window in Enskog mean free times (lags 200 to 400 of 0.1 t_E: 20 to 40
# t_E), and prints one row per area fraction:
#   eta Z g(sigma) D_E D_einstein error D_green_kubo error D/D_E error t_c
# Usage: sh tools/analysis/diffusion_sweep.sh [TRANSPORT [N [ETA...]]]
set -eu
transport=${1:-tools/transport}
n=${2:-4096}
[ $# -gt 2 ] && shift 2 || set -- 0.02 0.05 0.1 0.2 0.3 0.4 0.5 0.6 0.65 0.69
[ -x "$transport" ] || { echo "diffusion_sweep.sh: no program $transport (run make)" >&2; exit 2; }
echo "# eta Z g(sigma) D_E D_einstein error D_green_kubo error D/D_E error t_c   (N = $n)"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for eta in "$@"; do
    # Random placement stops near 0.54: denser systems start on a lattice
    # and relax for 1000 t_E (tools/transport's default then).
    start=$(awk -v e="$eta" 'BEGIN { print (e > 0.54 ? "--lattice" : "") }')
    # shellcheck disable=SC2086
    if ! "$transport" "$n" "$eta" $start --lags 401 --window 200:400 --every 10 > "$out"; then
        echo "diffusion_sweep.sh: tools/transport failed at area fraction $eta" >&2
        exit 1
    fi
    awk -v eta="$eta" '
        /^# Z / { z = $3; g = $7; tc = $11 }
        /^# D_0 / { de = $5 }
        /^# window / {
            for (i = 1; i <= NF; ++i) {
                if ($i == "D_einstein") { e = $(i + 1); ee = $(i + 3) }
                if ($i == "D_green_kubo") { k = $(i + 1); ke = $(i + 3) }
                if ($i == "D/D_E") { r = $(i + 1); re = $(i + 3) }
            }
        }
        END { print eta, z, g, de, e, ee, k, ke, r, re, tc }' "$out"
done
