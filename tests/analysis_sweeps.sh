#!/bin/sh
# SPDX-License-Identifier: MIT
# The diffusion and jamming sweeps (docs/sweeps.md) lose nothing: each
# keeps its runs in a directory named by its parameters, two sweeps with
# other parameters in one directory keep both, the same sweep again reuses
# every run it has (and runs the ones asked for that it lacks), and the
# tables load with numpy.loadtxt, their '#' lines skipped and named.
# Small sweeps, about two seconds. Run by make test, from the top; DISKS
# and TRANSPORT name the programs of the build (make passes them).
# shellcheck disable=SC2015 # "A && B || fail": fail whenever A or B is false
set -eu
top=$(pwd)
DISKS=${DISKS:-$top/disks}
TRANSPORT=${TRANSPORT:-$top/tools/transport}
export DISKS
python=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d "${TMPDIR:-/tmp}/analysis_sweeps.XXXXXX")
trap 'rm -rf "$work"' EXIT
analysis=$top/tools/analysis
fail() {
    echo "analysis_sweeps: $*" >&2
    exit 1
}
# FILE COLUMNS ROWS: numpy.loadtxt reads ROWS rows of the named COLUMNS,
# found by the names of the first '#' line, and genfromtxt(names=True)
# reads the same names.
loads() {
    if [ -z "$numpy" ]; then return 0; fi
    "$python" - "$@" <<'EOF' || fail "$1 does not load with numpy.loadtxt: $(head -n 3 "$1")"
import sys
import numpy as np
path, columns, rows = sys.argv[1], sys.argv[2].split(), int(sys.argv[3])
with open(path) as f:
    names = f.readline().lstrip("#").split()
table = np.loadtxt(path, usecols=[names.index(c) for c in columns], ndmin=2)
assert table.shape == (rows, len(columns)), table.shape
named = np.genfromtxt(path, names=True, dtype=None, encoding=None, ndmin=1)
assert list(named.dtype.names) == names, named.dtype.names
assert np.array_equal(named[columns[0]], table[:, 0])
EOF
}
numpy=yes
"$python" -c 'import numpy' 2>/dev/null || {
    numpy=""
    echo "analysis_sweeps: $python has no numpy (Debian: python3-numpy): the tables' loading is not checked"
}

# --- diffusion: N = 32 at 0.1 and 0.3, then N = 24 at 0.1 in the same place
cd "$work"
sh "$analysis/diffusion_sweep.sh" "$TRANSPORT" 32 0.1 0.3 >d32.dat 2>err.txt ||
    fail "diffusion_sweep.sh failed: $(cat err.txt)"
sh "$analysis/diffusion_sweep.sh" "$TRANSPORT" 24 0.1 >d24.dat 2>err.txt ||
    fail "a second diffusion sweep failed: $(cat err.txt)"
[ -s diffusion.N32/eta_0.1.txt ] && [ -s diffusion.N32/eta_0.3.txt ] && [ -s diffusion.N24/eta_0.1.txt ] ||
    fail "the two diffusion sweeps did not keep their runs: $(ls -R)"
[ "$(grep -vc '^#' d32.dat)" -eq 2 ] && [ "$(grep -vc '^#' d24.dat)" -eq 1 ] ||
    fail "the diffusion tables do not have a row per area fraction"
grep -q '^# .*N = 32' d32.dat || fail "the diffusion table does not say its N"
loads d32.dat "eta Z D_E D_over_D_E D_over_D_E_error t_c" 2
# The same N again, with one area fraction more: the run at 0.1 is reused
# (a line added to its output survives), 0.2 is run.
echo "# kept" >>diffusion.N32/eta_0.1.txt
sh "$analysis/diffusion_sweep.sh" "$TRANSPORT" 32 0.1 0.2 >again.dat 2>err.txt ||
    fail "the resumed diffusion sweep failed: $(cat err.txt)"
tail -n 1 diffusion.N32/eta_0.1.txt | grep -qx "# kept" || fail "the resumed diffusion sweep ran 0.1 again"
[ "$(grep -v '^#' again.dat | head -n 1)" = "$(grep -v '^#' d32.dat | head -n 1)" ] ||
    fail "the resumed diffusion sweep's row at 0.1 differs"
[ "$(awk '!/^#/ { print $1 }' diffusion.N32/diffusion.dat | tr '\n' ' ')" = "0.1 0.2 0.3 " ] ||
    fail "diffusion.N32/diffusion.dat is not the table of every run: $(cat diffusion.N32/diffusion.dat)"
loads diffusion.N32/diffusion.dat "eta D_over_D_E" 3

# --- jamming: N = 24, rate 0.3, seeds 1 2 into jam.tsv; then seeds 2 3
sh "$analysis/jamming.sh" 24 0.3 "1 2" jam.tsv 2>err.txt || fail "jamming.sh failed: $(cat err.txt)"
[ "$(grep -vc '^#' jam.tsv)" -eq 2 ] || fail "jam.tsv has not 2 rows: $(cat jam.tsv)"
loads jam.tsv "N rate seed area_fraction Z contacts_per_disk" 2
kept=jamming.N24/rate0.3.seed2.tsv
[ -s "$kept" ] || fail "jamming.sh kept no row per run: $(ls -R)"
awk 'BEGIN { FS = OFS = "\t" } { $NF = 99999; print }' "$kept" >"$kept.new" && mv "$kept.new" "$kept"
sh "$analysis/jamming.sh" 24 0.30 "2 3" jam.tsv 2>err.txt || fail "the second jamming sweep failed: $(cat err.txt)"
[ "$(awk '!/^#/ { print $3 ":" $NF }' jam.tsv | tr '\n' ' ')" = "2:99999 $(awk '!/^#/ && $3 == 3 { print 3 ":" $NF }' jam.tsv) " ] ||
    fail "the second jamming sweep did not reuse the run of seed 2: $(cat jam.tsv)"
[ "$(grep -vc '^#' jamming.N24/jamming.tsv)" -eq 3 ] ||
    fail "jamming.N24/jamming.tsv is not the table of the three runs: $(cat jamming.N24/jamming.tsv)"
loads jamming.N24/jamming.tsv "rate seed area_fraction" 3
# Another N in the same place keeps both.
sh "$analysis/jamming.sh" 16 0.3 1 >/dev/null 2>err.txt || fail "jamming.sh at N = 16 failed: $(cat err.txt)"
[ -s jamming.N16/rate0.3.seed1.tsv ] && [ "$(grep -vc '^#' jamming.N24/jamming.tsv)" -eq 3 ] ||
    fail "a jamming sweep at another N did not keep both"
echo "analysis_sweeps: diffusion and jamming sweeps keep, reuse and table their runs"
