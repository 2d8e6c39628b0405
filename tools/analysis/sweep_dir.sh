#!/bin/sh
# SPDX-License-Identifier: MIT
# The directory of one sweep (docs/sweeps.md): the sweeps of
# tools/analysis/ keep each sweep in a directory named by its parameters
# (eos.N16384.relax50.blocks15x10, diffusion.N4096, jamming.N1024), with
# one file per point, so that two sweeps with other parameters never share
# a file, and the same sweep started again goes on where it stopped: a
# point whose result is there is kept, never run again or replaced.
#
#   sh tools/analysis/sweep_dir.sh DIR < DEFINITION
#
# DEFINITION is the text that says what the sweep's points run (for the
# equation of state, the lines of eos_point.sh --list). A new DIR is made
# with it as DIR/sweep.txt and "new" is printed; a DIR that holds the same
# DIR/sweep.txt is the same sweep, and "resume" is printed. Anything else
# is refused, exit status 1, naming the first line that differs: the
# directory belongs to another sweep (the scripts changed what a point
# runs, or the directory is no sweep's), and mixing them would mix results.
set -eu
if [ $# -ne 1 ]; then
    echo "usage: sh tools/analysis/sweep_dir.sh DIR < DEFINITION" >&2
    exit 2
fi
dir=$1
definition=$(cat)
if [ -z "$definition" ]; then
    echo "sweep_dir: no definition on stdin for $dir" >&2
    exit 2
fi
# mkdir without -p succeeds for one caller only: two sweeps started at once
# with the same parameters do not both write the definition.
if mkdir "$dir" 2>/dev/null; then
    printf '%s\n' "$definition" >"$dir/sweep.txt.$$"
    mv "$dir/sweep.txt.$$" "$dir/sweep.txt"
    echo new
    exit 0
fi
if [ ! -d "$dir" ]; then
    echo "sweep_dir: cannot make the directory $dir" >&2
    exit 1
fi
if [ ! -f "$dir/sweep.txt" ]; then
    echo "sweep_dir: $dir exists but is no sweep's directory (it has no sweep.txt): move it away or run elsewhere" >&2
    exit 1
fi
if [ "$(cat "$dir/sweep.txt")" != "$definition" ]; then
    first=$(printf '%s\n' "$definition" | awk -v f="$dir/sweep.txt" '
        { if ((getline old < f) <= 0) old = "nothing"; else old = "\"" old "\"" }
        old != "\"" $0 "\"" { printf "line %d is %s there, \"%s\" here", NR, old, $0; found = 1; exit }
        END { if (!found) printf "it has more lines than this sweep" }')
    echo "sweep_dir: $dir holds a sweep of other points ($first):" \
        "refusing to mix them; move $dir away to start this sweep afresh" >&2
    exit 1
fi
echo resume
