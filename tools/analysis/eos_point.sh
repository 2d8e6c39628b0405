#!/bin/sh
# SPDX-License-Identifier: MIT
# One point of the equation-of-state sweep (tools/analysis/eos.sh runs
# them N at a time, tools/analysis/eos.sbatch one per Slurm job): point
# INDEX of the sweep for N disks, run with tools/pressure, its row written
# to DIR/points/point_INDEX.dat (complete or not at all) and printed, each
# block's Z to DIR/points/point_INDEX.blocks (tools/pressure --block-file). A
# point whose row is already there is not run again: its row is printed
# and kept (docs/sweeps.md: a sweep resumes, it never replaces a result).
#
#   sh tools/analysis/eos_point.sh INDEX DIR [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]
#   sh tools/analysis/eos_point.sh --count          (prints how many points)
#   sh tools/analysis/eos_point.sh --list [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]
#                                   (prints what each would run: the sweep's definition)
#   sh tools/analysis/eos_point.sh --name [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]
#                                   (prints the sweep's directory, eos.N16384.relax50.blocks15x10)
#   sh tools/analysis/eos_point.sh --order [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]
#                                   (prints the indices, longest point first)
#   sh tools/analysis/eos_point.sh --memory INDEX [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]
#                                   (prints the megabytes to ask Slurm for)
#
# INTEGRATOR is event (the default: the exact dynamics) or chain (event-chain
# Monte Carlo, which samples the same canonical ensemble; docs/physics.md).
# A time unit of chains is N disks' displacement at unit speed: at
# N = 16384 and 0.70, ~170 liftings per disk and 0.19 CPU seconds against
# the dynamics' ~100 collisions and 1.5 s, so a chain sweep affords longer
# RELAX and BLOCK, and needs them (docs/physics.md). A chain sweep
# has a directory of its own, eos.chain.N16384.relax..., and each line of
# its --list ends with "chain"; an event sweep's name and list are those
# of the versions before the integrator was a choice, so that their
# directories resume.
#
# The points (defaults N 16384, RELAX 50, BLOCKS 15, BLOCK 10, event):
#    0- 2  area fraction 0.1, 0.3, 0.5: relaxation 10, 20 blocks of 1
#    3-14  0.60 0.65 0.67 0.68 0.69 0.70 0.705 0.71 0.716 0.72 0.73 0.75:
#          RELAX, BLOCKS blocks of BLOCK
#   15     0.70 at N/4: relaxation 2 RELAX, 20 blocks of BLOCK
#   16     0.70 at 4 N: relaxation RELAX, 8 blocks of BLOCK/2
# 0-14 make eos.dat; 15, the 0.70 row of eos.dat and 16 make eos_size.dat
# (tools/analysis/eos_gather.sh). Every point is in a periodic box of
# aspect sqrt(3)/2 started on the lattice that fits it.
#
# On failure it says which point failed and why (tools/pressure's words),
# on stderr, and exits 1; DIR/points/point_INDEX.dat is then absent.
set -eu
# Where the other pieces are: in the checkout, tools/pressure one folder
# up; `make install` rewrites these two lines with the installed places
# (docs/install.md).
scripts=$(cd "$(dirname "$0")" && pwd)
pressure=${PRESSURE:-$scripts/../pressure}
height=866.0254037844386 # 1000 sqrt(3) / 2
count=17
high="0.60 0.65 0.67 0.68 0.69 0.70 0.705 0.71 0.716 0.72 0.73 0.75"

if [ "${1:-}" = --count ]; then
    echo "$count"
    exit 0
fi

# The integrator, the fifth of N RELAX BLOCKS BLOCK INTEGRATOR: the two
# exact ones (a fixed time step would add its bias, docs/physics.md).
integrator() { # INTEGRATOR
    case ${1:-event} in
    event | chain) echo "${1:-event}" ;;
    *)
        echo "eos_point: INTEGRATOR must be event or chain, got '$1'" >&2
        exit 2
        ;;
    esac
}

# The arguments of point $1: "N ETA RELAX BLOCKS BLOCK". Arithmetic in awk,
# so RELAX and BLOCK may be fractions (half a block of 1 is 0.5, not 0).
point() { # INDEX N RELAX BLOCKS BLOCK
    awk -v k="$1" -v n="$2" -v relax="$3" -v blocks="$4" -v block="$5" -v high="$high" 'BEGIN {
        split("0.1 0.3 0.5", low, " "); split(high, hi, " ")
        if (k >= 0 && k <= 2) print n, low[k + 1], 10, 20, 1
        else if (k >= 3 && k <= 14) print n, hi[k - 2], relax, blocks, block
        else if (k == 15) print int(n / 4), 0.70, 2 * relax, 20, block
        else if (k == 16) print 4 * n, 0.70, relax, 8, block / 2
    }'
}

# Every point, "INDEX N ETA RELAX BLOCKS BLOCK" a line, and " chain" at
# its end for event chains.
points() { # N RELAX BLOCKS BLOCK INTEGRATOR
    tail=""
    [ "$5" = event ] || tail=" $5"
    k=0
    while [ "$k" -lt "$count" ]; do
        echo "$k $(point "$k" "$1" "$2" "$3" "$4")$tail"
        k=$((k + 1))
    done
}

case ${1:-} in
--list)
    shift
    how=$(integrator "${5:-}")
    points "${1:-16384}" "${2:-50}" "${3:-15}" "${4:-10}" "$how"
    exit 0
    ;;
--name)
    shift
    how=$(integrator "${5:-}")
    prefix=eos
    [ "$how" = event ] || prefix=eos.$how
    echo "$prefix.N${1:-16384}.relax${2:-50}.blocks${3:-15}x${4:-10}"
    exit 0
    ;;
--order)
    # The cost of a point is its collisions: N nu T / 2, with nu the
    # collisions per disk per unit time, nu ~ (Z - 1) / sigma, Z from
    # Henderson's equation of state (1 + eta^2 / 8) / (1 - eta)^2 and the
    # diameter sigma ~ sqrt(eta / N) at a fixed box; each costs ~log N (the
    # event queue). So cost ~ T N^1.5 log N (Z - 1) / sqrt(eta), good
    # enough to put the longest first (docs/sweeps.md compares it with the
    # seconds the points took). Chains are ordered the same way: their
    # liftings per unit grow with Z as the collisions do.
    shift
    how=$(integrator "${5:-}")
    points "${1:-16384}" "${2:-50}" "${3:-15}" "${4:-10}" "$how" | awk '{
        n = $2; eta = $3; t = $4 + $5 * $6
        z = (1 + eta * eta / 8) / ((1 - eta) * (1 - eta))
        printf "%s %.6e\n", $1, t * n ^ 1.5 * log(n + 1) * (z - 1) / sqrt(eta)
    }' | sort -k2,2gr -k1,1n | awk '{ print $1 }'
    exit 0
    ;;
--memory)
    # What the point's simulation allocates (ds_params_memory, through
    # tools/pressure --memory) and a quarter more, plus 64 MB for the
    # program itself, the shell and awk: the peak resident size measured
    # was the estimate plus 2 to 6 MB (docs/sweeps.md).
    shift
    [ $# -ge 1 ] || { echo "usage: eos_point.sh --memory INDEX [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]" >&2; exit 2; }
    how=$(integrator "${6:-}")
    # shellcheck disable=SC2046 # the point's five words become $1 .. $5
    set -- $(point "$1" "${2:-16384}" "${3:-50}" "${4:-15}" "${5:-10}")
    [ $# -eq 5 ] || { echo "eos_point: INDEX must be 0 to $((count - 1))" >&2; exit 2; }
    bytes=$("$pressure" "$1" "$2" --periodic --lattice --box-y "$height" --integrator "$how" \
        --memory) || exit 1
    awk -v b="$bytes" 'BEGIN { m = b * 1.25 / 1048576; printf "%d\n", (m == int(m) ? m : int(m) + 1) + 64 }'
    exit 0
    ;;
esac

if [ $# -lt 2 ]; then
    echo "usage: sh tools/analysis/eos_point.sh INDEX DIR [N] [RELAX] [BLOCKS] [BLOCK] [INTEGRATOR]" >&2
    exit 2
fi
index=$1
dir=$2
case $index in
'' | *[!0-9]*) index=-1 ;;
esac
if [ "$index" -lt 0 ] || [ "$index" -ge "$count" ]; then
    echo "eos_point: INDEX must be 0 to $((count - 1)), got '$1'" >&2
    exit 2
fi
how=$(integrator "${7:-}")
# shellcheck disable=SC2046 # the point's five words become $1 .. $5
set -- $(point "$index" "${3:-16384}" "${4:-50}" "${5:-15}" "${6:-10}")
note=""
[ "$how" = event ] || note=", event chains"
what="point $index (N = $1, area fraction $2, relaxation $3, $4 blocks of $5$note)"
out="$dir/points/point_$index.dat"
if [ -s "$out" ]; then
    echo "eos_point: $what: done before, kept ($out)" >&2
    cat "$out"
    exit 0
fi
if [ ! -x "$pressure" ]; then
    echo "eos_point: $what: $pressure is not built (run make)" >&2
    exit 1
fi
mkdir -p "$dir/points"
# The partial files carry this process's id: a point started twice at once
# (a Slurm job run again while the first still runs) writes two, not one.
tmp="$out.$$"
# Each block's Z beside the row, DIR/points/point_INDEX.blocks: whether
# neighbouring blocks are independent, which the row's error assumes.
blocks="$dir/points/point_$index.blocks"
if ! "$pressure" "$1" "$2" --periodic --lattice --box-y "$height" --integrator "$how" \
    --relax "$3" --blocks "$4" --block "$5" --block-file "$blocks.$$" >"$tmp" 2>"$out.err"; then
    echo "eos_point: $what failed: $(cat "$out.err")" >&2
    rm -f "$tmp" "$blocks.$$"
    exit 1
fi
mv "$blocks.$$" "$blocks"
mv "$tmp" "$out"
rm -f "$out.err"
cat "$out"
