#!/bin/sh
# SPDX-License-Identifier: MIT
# The equation-of-state sweep (docs/sweeps.md): its ways of running the
# same points give the same tables, no sweep loses another's results, and
# a failed point fails the sweep loudly:
#  - tools/analysis/eos.sh -j 2 and -j 1 give the same tables, in the
#    directory named by the sweep's parameters, with a '#' line naming
#    the columns that numpy.loadtxt skips and numpy.genfromtxt reads;
#  - with INTEGRATOR chain, the same points run by event chains in a
#    directory of their own, each point's blocks kept beside its row, and
#    plot_eos.plt draws them beside the dynamics' (chains=);
#  - a second sweep with other parameters in the same directory keeps
#    both results; the same sweep again resumes: it keeps every point done
#    and runs only the missing ones; a directory whose points differ is
#    refused, untouched;
#  - tools/analysis/eos.sbatch under a stand-in for Slurm (tests/slurm/:
#    its sbatch runs each job at once as slurmd would, from a spooled copy
#    of the script, with Slurm's variables and none of the submitting
#    shell's) submits one job per point, the longest first, each asking
#    the memory tools/pressure --memory gives plus the margin, and a
#    gathering job after them; the tables equal eos.sh's; the documented
#    rerun commands work; a second submission submits only the missing
#    points, and is refused while jobs of the first are queued.
# A small sweep (N = 64, a second of work). The rows are compared without
# their last column, the seconds each point took. Run by make test, from
# the top directory; PRESSURE names the tools/pressure to run (make passes
# the one of its build).
# shellcheck disable=SC2015 # "A && B || fail": fail whenever A or B is false
set -eu
top=$(pwd)
PRESSURE=${PRESSURE:-$top/tools/pressure}
export PRESSURE
python=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d "${TMPDIR:-/tmp}/eos_sweep.XXXXXX")
trap 'rm -rf "$work"' EXIT
analysis=$top/tools/analysis
sweep="64 1 2 1" # N RELAX BLOCKS BLOCK
name=eos.N64.relax1.blocks2x1
other="64 1 2 0.5" # another sweep: blocks of half the length
other_name=eos.N64.relax1.blocks2x0.5
fail() {
    echo "eos_sweep: $*" >&2
    exit 1
}
table() { # DIR: both tables, without the seconds column
    awk '!/^#/ { $NF = ""; print }' "$1/eos.dat" "$1/eos_size.dat"
}
eos() { # DIR ARGS...: eos.sh in DIR, its output in DIR/out.txt and DIR/err.txt
    eos_dir=$1
    shift
    (cd "$eos_dir" && sh "$analysis/eos.sh" "$@" >out.txt 2>err.txt)
}

mkdir "$work/j2" "$work/j1" "$work/slurm" "$work/bad"
# shellcheck disable=SC2086
eos "$work/j2" -j 2 $sweep || fail "eos.sh -j 2 failed: $(cat "$work/j2/err.txt")"
# shellcheck disable=SC2086
eos "$work/j1" $sweep || fail "eos.sh failed: $(cat "$work/j1/err.txt")"
count=$(sh "$analysis/eos_point.sh" --count)
[ -d "$work/j2/$name" ] || fail "eos.sh wrote no directory $name: $(ls "$work/j2")"
[ "$(grep -vc '^#' "$work/j2/$name/eos.dat")" -eq 15 ] || fail "eos.dat has not 15 rows"
[ "$(grep -vc '^#' "$work/j2/$name/eos_size.dat")" -eq 3 ] || fail "eos_size.dat has not 3 rows"
awk '!/^#/ && ($2 != 64 || $3 != "event" || $5 != "periodic") { exit 1 }' "$work/j2/$name/eos.dat" ||
    fail "eos.dat has rows of another N or kind"
[ "$(awk '!/^#/ { print $2 }' "$work/j2/$name/eos_size.dat" | tr '\n' ' ')" = "16 64 256 " ] ||
    fail "eos_size.dat is not N/4, N, 4N"
[ "$(table "$work/j1/$name")" = "$(table "$work/j2/$name")" ] || fail "-j 1 and -j 2 differ"
if command -v gnuplot >/dev/null 2>&1; then
    for f in eos.png eos.pdf; do
        [ -s "$work/j2/$name/$f" ] || fail "eos.sh with gnuplot wrote no $f"
    done
    head -c 5 "$work/j2/$name/eos.pdf" | grep -q '^%PDF-' || fail "eos.pdf is not a PDF"
fi

# The tables load with numpy: loadtxt skips the '#' lines, the columns
# are found by the names of the first, and genfromtxt(names=True) reads
# the same names and values.
if "$python" -c 'import numpy' 2>/dev/null; then
    "$python" - "$work/j2/$name/eos.dat" "$work/j2/$name/eos_size.dat" <<'EOF' ||
import sys
import numpy as np
for path, rows in zip(sys.argv[1:], (15, 3)):
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    columns = [names.index(c) for c in ("eta", "N", "Z_virial", "Z_virial_error", "collisions")]
    table = np.loadtxt(path, usecols=columns)
    assert table.shape == (rows, 5), (path, table.shape)
    named = np.genfromtxt(path, names=True, dtype=None, encoding=None)
    assert list(named.dtype.names) == names, (path, named.dtype.names)
    assert np.array_equal(named["Z_virial"], table[:, 2]), path
    assert (table[:, 2] > 1).all() and (table[:, 3] >= 0).all(), path
EOF
        fail "the tables do not load with numpy.loadtxt and genfromtxt"
else
    echo "eos_sweep: $python has no numpy (Debian: python3-numpy): the tables' loading is not checked"
fi

# Another sweep in the same directory keeps both; the first's points are
# not touched (their seconds column is marked, which a rerun would reset).
marked="$work/j2/$name/points/point_3.dat"
awk '{ $NF = "99999.9"; print }' "$marked" >"$marked.new" && mv "$marked.new" "$marked"
# shellcheck disable=SC2086
eos "$work/j2" -j 2 $other || fail "a second sweep failed: $(cat "$work/j2/err.txt")"
[ -s "$work/j2/$other_name/eos.dat" ] && [ -s "$work/j2/$name/eos.dat" ] ||
    fail "two sweeps in one directory did not keep both tables: $(ls "$work/j2")"
[ "$(awk '{ print $NF }' "$marked")" = 99999.9 ] || fail "the second sweep touched the first's points"
[ "$(table "$work/j2/$other_name")" != "$(table "$work/j2/$name")" ] ||
    fail "the two sweeps' tables are the same"

# The same sweep again resumes: a missing point is run, the others kept.
rm "$work/j2/$name/points/point_7.dat"
# shellcheck disable=SC2086
eos "$work/j2" -j 2 $sweep || fail "a resumed sweep failed: $(cat "$work/j2/err.txt")"
grep -q "resuming, $((count - 1)) of $count points done before (kept), 1 to run" "$work/j2/err.txt" ||
    fail "the resumed sweep did not say what it kept: $(cat "$work/j2/err.txt")"
[ "$(awk '{ print $NF }' "$marked")" = 99999.9 ] || fail "the resumed sweep ran a point done before"
[ -s "$work/j2/$name/points/point_7.dat" ] || fail "the resumed sweep did not run the missing point"
[ "$(table "$work/j2/$name")" = "$(table "$work/j1/$name")" ] || fail "the resumed sweep's table differs"
grep -q "99999.9" "$work/j2/$name/eos.dat" || fail "the resumed sweep's table is not of the kept points"

# A directory of the same name holding other points (what an older
# version of the scripts ran) is refused and left as it was.
sed 's/^3 64 0.60 /3 64 0.61 /' "$work/j2/$name/sweep.txt" >"$work/sweep.txt"
cp "$work/sweep.txt" "$work/j2/$name/sweep.txt"
before=$(cat "$work/j2/$name"/points/*.dat | cksum)
status=0
# shellcheck disable=SC2086
eos "$work/j2" $sweep || status=$?
[ "$status" -eq 1 ] && grep -q "holds a sweep of other points" "$work/j2/err.txt" ||
    fail "a directory of other points was not refused: $(cat "$work/j2/err.txt")"
[ "$(cat "$work/j2/$name"/points/*.dat | cksum)" = "$before" ] || fail "a refused sweep changed points"

# Slurm, through the stand-in: submit, which runs every job at once. The
# jobs must run the tools/pressure the sweep was submitted with, which
# they learn from the sweep's directory: here a wrapper that counts calls.
export FAKE_SLURM="$work/slurm-state"
slurm_path="$top/tests/slurm:$PATH"
mkdir "$work/bin"
printf '#!/bin/sh\necho "$*" >>"%s"\nexec "%s" "$@"\n' "$work/pressure.calls" "$PRESSURE" \
    >"$work/bin/pressure"
chmod +x "$work/bin/pressure"
PRESSURE=$work/bin/pressure
submit() { # ARGS...: eos.sbatch submit in $work/slurm, output in $work/slurm/submit.txt
    (cd "$work/slurm" && PATH=$slurm_path sh "$analysis/eos.sbatch" submit "$@" >submit.txt 2>&1)
}
# shellcheck disable=SC2086
submit $sweep || fail "eos.sbatch submit failed: $(cat "$work/slurm/submit.txt")"
dir="$work/slurm/$name"
[ "$(table "$dir")" = "$(table "$work/j1/$name")" ] ||
    fail "the Slurm jobs' table differs: $(cat "$dir"/points/slurm-*.out "$dir"/slurm-*-gather.out 2>&1)"
[ "$(grep -vc -- --memory "$work/pressure.calls")" -eq "$count" ] ||
    fail "the Slurm jobs did not run the tools/pressure of the submission ($PRESSURE)"
# One single-task array job per point, in the order of eos_point.sh
# --order (the longest first: the 4N point), each asking its memory; the
# gathering job depends on all of them.
# shellcheck disable=SC2086
order=$(sh "$analysis/eos_point.sh" --order $sweep | tr '\n' ' ')
[ "$(sed -n 's/.* --array=\([0-9]*\) .*/\1/p' "$FAKE_SLURM/submitted" | tr '\n' ' ')" = "$order" ] ||
    fail "the tasks were not submitted longest first ($order): $(cat "$FAKE_SLURM/submitted")"
[ "${order%% *}" = 16 ] || fail "the 4N point is not the first of the order: $order"
for k in $order; do
    # shellcheck disable=SC2046,SC2086
    set -- $(sh "$analysis/eos_point.sh" --list $sweep | awk -v k="$k" '$1 == k')
    bytes=$("$PRESSURE" "$2" "$3" --periodic --lattice --box-y 866.0254037844386 --memory)
    mb=$(awk -v b="$bytes" 'BEGIN { m = b * 1.25 / 1048576; print (m == int(m) ? m : int(m) + 1) + 64 }')
    grep -q -- "--array=$k --mem=${mb}M " "$FAKE_SLURM/submitted" ||
        fail "task $k does not ask for ${mb}M (ds_memory_needed $bytes bytes, plus a quarter and 64 MB)"
done
# The margin where it shows, at N = 16384: 4N needs 16.5 MB, and asks 85 MB.
bytes=$("$PRESSURE" 65536 0.70 --periodic --lattice --box-y 866.0254037844386 --memory)
mb=$(sh "$analysis/eos_point.sh" --memory 16 16384 50 15 10)
[ "$(awk -v b="$bytes" -v mb="$mb" 'BEGIN { print (mb - 64 >= b * 1.25 / 1048576 && mb - 65 < b * 1.25 / 1048576) }')" = 1 ] ||
    fail "point 16 at N = 16384 asks ${mb} MB for $bytes bytes, not a quarter more and 64 MB"
jobs=$(awk '/--array=/ { print $1 }' "$FAKE_SLURM/submitted" | tr '\n' ':')
grep -q -- "--dependency=afterok:${jobs%:} .* gather $dir\$" "$FAKE_SLURM/submitted" ||
    fail "the gathering job does not wait for every task: $(tail -n 1 "$FAKE_SLURM/submitted")"

# The documented rerun of one task, typed in the results directory, and
# of the gathering job: they run as Slurm runs them, with nothing from
# this shell (no PRESSURE, no checkout path).
rm "$dir/points/point_7.dat" "$dir/eos.dat"
: >"$work/pressure.calls"
(cd "$work/slurm" && env -u PRESSURE PATH="$slurm_path" sbatch --array=7 --mem=70M \
    "$analysis/eos.sbatch" task "$name" >/dev/null &&
    env -u PRESSURE PATH="$slurm_path" sbatch "$analysis/eos.sbatch" gather "$name" >/dev/null)
[ -s "$dir/points/point_7.dat" ] && [ -s "$dir/eos.dat" ] && [ -s "$work/pressure.calls" ] ||
    fail "the documented rerun did not work: $(cat "$work/slurm"/slurm-*.out)"
[ "$(table "$dir")" = "$(table "$work/j1/$name")" ] || fail "the rerun's table differs"

# Submitted again, only the missing points go, the longest first.
rm "$dir/points/point_7.dat" "$dir/points/point_16.dat"
: >"$FAKE_SLURM/submitted"
# shellcheck disable=SC2086
submit $sweep || fail "a second submission failed: $(cat "$work/slurm/submit.txt")"
[ "$(sed -n 's/.* --array=\([0-9]*\) .*/\1/p' "$FAKE_SLURM/submitted" | tr '\n' ' ')" = "16 7 " ] ||
    fail "a second submission did not submit just points 16 and 7: $(cat "$FAKE_SLURM/submitted")"
grep -q "2 of $count points submitted" "$work/slurm/submit.txt" ||
    fail "the second submission did not say what it submitted: $(cat "$work/slurm/submit.txt")"
[ "$(table "$dir")" = "$(table "$work/j1/$name")" ] || fail "the second submission's table differs"
# ... and is refused while a job of the last one waits in the queue.
awk '{ print $NF }' "$dir/slurm-jobs.txt" >"$FAKE_SLURM/queued"
: >"$FAKE_SLURM/submitted"
status=0
# shellcheck disable=SC2086
submit $sweep || status=$?
[ "$status" -eq 1 ] && grep -q "still queued or running" "$work/slurm/submit.txt" &&
    [ ! -s "$FAKE_SLURM/submitted" ] ||
    fail "a submission while jobs are queued was not refused: $(cat "$work/slurm/submit.txt")"
rm "$FAKE_SLURM/queued"

# The same sweep with event chains: a directory of its own beside the
# dynamics' (whose name and points are those before the integrator was a
# choice, so that old directories resume), every row made by chains, and
# each point's blocks beside its row, as many as it runs, whose mean is the
# row's Z (to the six decimals both are printed with, and the rounding of
# each block: 1e-6).
mkdir "$work/chain"
# shellcheck disable=SC2086
eos "$work/chain" $sweep chain || fail "eos.sh with chains failed: $(cat "$work/chain/err.txt")"
chain_dir="$work/chain/eos.chain.N64.relax1.blocks2x1"
[ -s "$chain_dir/eos.dat" ] || fail "the chain sweep wrote no $chain_dir/eos.dat: $(ls "$work/chain")"
awk '!/^#/ && ($2 != 64 || $3 != "chain" || $5 != "periodic") { exit 1 }' "$chain_dir/eos.dat" ||
    fail "the chain sweep's eos.dat has rows not made by chains"
[ "$(sh "$analysis/eos_point.sh" --name $sweep)" = "$name" ] &&
    [ "$(sh "$analysis/eos_point.sh" --name $sweep event)" = "$name" ] ||
    fail "the dynamics' sweep is no longer named $name"
[ "$(sh "$analysis/eos_point.sh" --list $sweep event)" = "$(cat "$work/j1/$name/sweep.txt")" ] ||
    fail "the dynamics' points are listed differently from before"
for k in 0 8 16; do
    row="$chain_dir/points/point_$k.dat"
    # shellcheck disable=SC2086
    blocks=$(sh "$analysis/eos_point.sh" --list $sweep chain | awk -v k="$k" '$1 == k { print $5 }')
    awk -v z="$(awk '{ print $6 }' "$row")" -v b="$blocks" '{ s += $1; n++ }
        END { exit !(n == b && (s / n - z) ^ 2 < 2e-6 ^ 2) }' "$chain_dir/points/point_$k.blocks" ||
        fail "point $k's blocks are not its row's: $(cat "$chain_dir/points/point_$k.blocks") against $(cat "$row")"
done
if command -v gnuplot >/dev/null 2>&1; then
    # The chains drawn beside the dynamics, named in the legend and title.
    (cd "$work/j1/$name" && gnuplot -e "chains='$chain_dir/eos.dat'; out='both.png'; formats='svg'" \
        "$analysis/plot_eos.plt") 2>"$work/chain/plot.err" ||
        fail "plot_eos.plt with chains= failed: $(cat "$work/chain/plot.err")"
    grep -q "disksim, event chains, N = 64" "$work/j1/$name/both.svg" &&
        grep -q "event-driven and event chains" "$work/j1/$name/both.svg" ||
        fail "the plot with chains= does not name them"
fi
# An integrator the sweep does not run is refused before anything is made.
status=0
# shellcheck disable=SC2086
eos "$work/chain" $sweep step || status=$?
[ "$status" -eq 2 ] && grep -q "INTEGRATOR must be event or chain, got 'step'" "$work/chain/err.txt" ||
    fail "an integrator step was not refused: $status $(cat "$work/chain/err.txt")"
[ ! -e "$work/chain/eos.step.N64.relax1.blocks2x1" ] && [ "$(ls "$work/chain" | grep -c '^eos\.')" -eq 1 ] ||
    fail "a refused integrator left a directory: $(ls "$work/chain")"

# A sweep whose points cannot run (N = 3: the disks do not fit) stops,
# says which point failed, and writes no table and no plot.
status=0
eos "$work/bad" -j 2 3 1 2 1 || status=$?
[ "$status" -ne 0 ] || fail "a failed point did not fail eos.sh"
grep -q "eos_point: point [0-9]* (N = [0-9]*, area fraction .*) failed: pressure: ." \
    "$work/bad/err.txt" || fail "the failure is not named: $(cat "$work/bad/err.txt")"
grep -q "no table written" "$work/bad/err.txt" || fail "no closing word on the failure"
! grep -q "wrote" "$work/bad/out.txt" "$work/bad/err.txt" || fail "a failed sweep wrote something"
[ ! -e "$work/bad/eos.N3.relax1.blocks2x1/eos.dat" ] && [ ! -e "$work/bad/eos.N3.relax1.blocks2x1/eos.png" ] ||
    fail "a failed sweep left a table"
# and a gathering step with a missing point names it
rm "$dir/points/point_7.dat"
status=0
(cd "$work/slurm" && env -u PRESSURE sh "$analysis/eos.sbatch" gather "$name" >/dev/null 2>err.txt) ||
    status=$?
[ "$status" -ne 0 ] && grep -q "point(s) 7" "$work/slurm/err.txt" ||
    fail "a gather with a point missing did not name it"
echo "eos_sweep: eos.sh -j 1, -j 2 and Slurm jobs give the same table; sweeps keep, resume or refuse; failures are named"
