#!/bin/sh
# SPDX-License-Identifier: MIT
# The equation-of-state sweep's three ways of running the same points give
# the same tables, and a failed point fails the sweep loudly:
#  - tools/analysis/eos.sh -j 2 (two points at a time, xargs -P),
#  - tools/analysis/eos.sh -j 1,
#  - tools/analysis/eos.sbatch's array tasks run one by one, as Slurm would
#    run them, with SLURM_ARRAY_TASK_ID set, then its gathering step.
# A small sweep (N = 64, a second of work). The rows are compared without
# their last column, the seconds each point took. Run by make test, from
# the top directory; PRESSURE names the tools/pressure to run (make passes
# the one of its build).
# shellcheck disable=SC2015 # "A && B || fail": fail whenever A or B is false
set -eu
top=$(pwd)
PRESSURE=${PRESSURE:-$top/tools/pressure}
export PRESSURE
work=$(mktemp -d "${TMPDIR:-/tmp}/eos_sweep.XXXXXX")
trap 'rm -rf "$work"' EXIT
sweep="64 1 2 1" # N RELAX BLOCKS BLOCK
fail() {
    echo "eos_sweep: $*" >&2
    exit 1
}
table() { # DIR: both tables, without the seconds column
    awk '{ $NF = ""; print }' "$1/eos.dat" "$1/eos_size.dat"
}

mkdir "$work/j2" "$work/j1" "$work/slurm" "$work/bad"
# shellcheck disable=SC2086
(cd "$work/j2" && sh "$top/tools/analysis/eos.sh" -j 2 $sweep >out.txt 2>err.txt) ||
    fail "eos.sh -j 2 failed: $(cat "$work/j2/err.txt")"
# shellcheck disable=SC2086
(cd "$work/j1" && sh "$top/tools/analysis/eos.sh" $sweep >out.txt 2>err.txt) ||
    fail "eos.sh failed: $(cat "$work/j1/err.txt")"
count=$(sh "$top/tools/analysis/eos_point.sh" --count)
[ "$(wc -l <"$work/j2/eos.dat")" -eq 15 ] || fail "eos.dat has not 15 rows"
[ "$(wc -l <"$work/j2/eos_size.dat")" -eq 3 ] || fail "eos_size.dat has not 3 rows"
awk '$2 != 64 || $3 != "event" || $5 != "periodic" { exit 1 }' "$work/j2/eos.dat" ||
    fail "eos.dat has rows of another N or kind"
[ "$(awk '{ print $2 }' "$work/j2/eos_size.dat" | tr '\n' ' ')" = "16 64 256 " ] ||
    fail "eos_size.dat is not N/4, N, 4N"
[ "$(table "$work/j1")" = "$(table "$work/j2")" ] || fail "-j 1 and -j 2 differ"

# The Slurm tasks, one by one, then the gathering job.
k=0
while [ "$k" -lt "$count" ]; do
    # shellcheck disable=SC2086
    (cd "$work/slurm" && SLURM_ARRAY_TASK_ID=$k DISKSIM_TOP=$top \
        sh "$top/tools/analysis/eos.sbatch" task $sweep >/dev/null) || fail "task $k failed"
    k=$((k + 1))
done
(cd "$work/slurm" && DISKSIM_TOP=$top sh "$top/tools/analysis/eos.sbatch" gather >/dev/null) ||
    fail "the gathering step failed"
[ "$(table "$work/slurm")" = "$(table "$work/j2")" ] || fail "the Slurm tasks' table differs"

# A sweep whose points cannot run (N = 3: the disks do not fit) stops,
# says which point failed, and writes no table and no plot.
status=0
(cd "$work/bad" && sh "$top/tools/analysis/eos.sh" -j 2 3 1 2 1 >out.txt 2>err.txt) || status=$?
[ "$status" -ne 0 ] || fail "a failed point did not fail eos.sh"
grep -q "eos_point: point [0-9]* (N = [0-9]*, area fraction .*) failed: pressure: ." \
    "$work/bad/err.txt" || fail "the failure is not named: $(cat "$work/bad/err.txt")"
grep -q "no table written" "$work/bad/err.txt" || fail "no closing word on the failure"
! grep -q "wrote" "$work/bad/out.txt" "$work/bad/err.txt" || fail "a failed sweep wrote something"
[ ! -e "$work/bad/eos.dat" ] && [ ! -e "$work/bad/eos.png" ] || fail "a failed sweep left a table"
# and a gathering step with a missing point names it
rm "$work/slurm/eos.points/point_7.dat"
status=0
(cd "$work/slurm" && DISKSIM_TOP=$top sh "$top/tools/analysis/eos.sbatch" gather \
    >/dev/null 2>err.txt) || status=$?
[ "$status" -ne 0 ] && grep -q "point(s) 7" "$work/slurm/err.txt" ||
    fail "a gather with a point missing did not name it"
echo "eos_sweep: eos.sh -j 1, -j 2 and the Slurm tasks give the same table; failures are named"
