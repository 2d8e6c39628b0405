#!/bin/sh
# SPDX-License-Identifier: MIT
# Compares two builds of the library in one process (2.x or 3.x each):
#
#   tools/benchmark/ab.sh REV_A REV_B [N [ROUNDS [event|step|seed|chain]]]
#
# builds libdisksim.a at two git revisions (or "." for the working tree as
# it is), gives every global symbol of each an A_ or B_ prefix (objcopy),
# links both into one program (tools/benchmark/ab_events.c) and times N disks
# (default 10^6) in ROUNDS (default 21) alternating rounds: event-driven at
# area fraction 0.5, ~10^6 collisions a round (event, the default); the
# time step at area fraction 0.1 (step); the seed case (seed, N unused); or
# event chains at area fraction 0.70, periodic, ns of CPU per lifting (chain). Two separate runs a minute apart differ here
# by 10% and more; within one process the rounds see the same machine.
# The same build against itself gave 1.01 and 1.04 (quartiles 0.96 to 1.08)
# at 10^6 over 21 rounds: nothing under ~5% stands out from the noise.
set -eu
[ $# -ge 2 ] || { echo "usage: $0 REV_A REV_B [N [ROUNDS]]" >&2; exit 2; }
top=$(git rev-parse --show-toplevel)
work=$(mktemp -d)
trap 'rm -rf "$work"; git -C "$top" worktree prune' EXIT INT TERM

# Each side's library and its own headers (2.x's or 3.0's: ab_events.c
# speaks both), so that a release can be timed against the last one.
lib() { # side revision
    if [ "$2" = "." ]; then
        make -s -C "$top" libdisksim.a
        cp "$top/libdisksim.a" "$work/$1.a"
        cp -r "$top/include" "$work/include$1"
    else
        git -C "$top" worktree add --detach -q "$work/tree$1" "$2"
        make -s -C "$work/tree$1" libdisksim.a
        cp "$work/tree$1/libdisksim.a" "$work/$1.a"
        cp -r "$work/tree$1/include" "$work/include$1"
    fi
}
lib A "$1"
lib B "$2"
nm -g --defined-only "$work/A.a" "$work/B.a" | awk 'NF == 3 { print $3 }' | sort -u >"$work/symbols"
for side in A B; do
    awk -v p="${side}_" '{ print $1, p $1 }' "$work/symbols" >"$work/$side.map"
    objcopy --redefine-syms="$work/$side.map" "$work/$side.a" "$work/${side}_renamed.a"
    cc -std=c99 -O2 -I"$work/include$side" -DAB_SIDE="${side}_" -c "$top/tools/benchmark/ab_events.c" \
        -o "$work/$side.o"
done
cc -std=c99 -O2 -DAB_MAIN "$top/tools/benchmark/ab_events.c" "$work/A.o" "$work/B.o" \
    "$work/A_renamed.a" "$work/B_renamed.a" -lm -o "$work/ab"
"$work/ab" "${3:-1000000}" "${4:-21}" "${5:-event}"
