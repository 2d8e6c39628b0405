#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/migrate/disksim3.py on a program written for disksim 2.1
# (tests/migrate/program_2x.c): moved to 3.0, it builds against this
# library without a warning and prints, to the byte, what it printed
# built against 2.1.0 (tests/migrate/program_2x.out: 3.0 computes the
# same trajectories). A second run changes nothing; the calls it cannot
# finish alone (tests/migrate/by_hand_2x.c) are each named at their line.
#   sh tests/migrate.sh [LIBRARY] (default libdisksim.a)
set -eu
lib=${1:-libdisksim.a}
python=${PYTHON:-/usr/bin/python3}
tool=tools/migrate/disksim3.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "migrate: $*" >&2; exit 1; }

cp tests/migrate/program_2x.c tests/migrate/by_hand_2x.c "$work/"
"$python" "$tool" "$work/program_2x.c" 2>"$work/notes"
[ ! -s "$work/notes" ] || { cat "$work/notes" >&2; fail "notes on a program it can move alone"; }
# shellcheck disable=SC2086
${CC:-cc} -std=c99 -Wall -Werror ${CFLAGS:-} -Iinclude -o "$work/program" "$work/program_2x.c" "$lib" ${LDFLAGS:-} -lm ||
    fail "the moved program does not build against 3.0"
"$work/program" >"$work/out" || fail "the moved program failed"
cmp -s "$work/out" tests/migrate/program_2x.out || {
    diff "$work/out" tests/migrate/program_2x.out >&2 || true
    fail "the moved program prints otherwise than under 2.1.0"
}

cp "$work/program_2x.c" "$work/once.c"
"$python" "$tool" "$work/program_2x.c" 2>"$work/notes"
cmp -s "$work/program_2x.c" "$work/once.c" || fail "a second run changed the file"
[ ! -s "$work/notes" ] || fail "a second run made notes"

"$python" "$tool" "$work/by_hand_2x.c" 2>"$work/notes"
for expect in "by_hand_2x.c:8: ds_radius_of" "by_hand_2x.c:9: ds_mass_of" \
    "by_hand_2x.c:10: ds_get_radii with radii and masses" "by_hand_2x.c:11: ds_psi6" \
    "by_hand_2x.c:12: ds_frame_error's .line is ds_error's .index"; do
    grep -qF "$expect" "$work/notes" || { cat "$work/notes" >&2; fail "no note '$expect'"; }
done
"$python" "$tool" --frobnicate 2>/dev/null && fail "an unknown option was taken"
"$python" "$tool" "$work/no such file.c" 2>"$work/notes" && fail "a missing file was taken"
grep -qF "no such file.c: No such file or directory" "$work/notes" || fail "no message for a missing file"
echo "migrate: a 2.1 program moved to 3.0 prints what it printed under 2.1.0; the by-hand calls are named"
