#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs into a temporary stage the way a distribution package is built
# (make install DESTDIR=stage PREFIX=/usr), checks every installed file (the
# manual pages rendered by man without a warning, the documentation, the
# analysis commands disks-* answering --help, each with its man page), then
# builds examples/minimal.c and the README's library example against the
# staged copy through pkg-config, once with the shared and once with the
# static library, runs them, and checks that make uninstall removes it all.
# Last, an install under a prefix of its own, where the installed sweeps run
# small sweeps (and the Slurm one through tests/slurm/'s stand-in), finding
# their helpers and programs where make install put them.
set -euo pipefail
cd "$(dirname "$0")/.."
tree=$(pwd)

headers="include/disk_sim.h $(ls include/disksim/*.h)"
version=$(sed -n 's/^#define DS_VERSION_STRING "\(.*\)"/\1/p' include/disksim/base.h)
major=$(sed -n 's/^#define DS_VERSION_MAJOR \([0-9]*\).*/\1/p' include/disksim/base.h)
stage=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$stage" "$work"' EXIT
fail() { echo "install check: $*" >&2; exit 1; }

make -s install DESTDIR="$stage" PREFIX=/usr

analysis="disks-gr disks-pressure disks-transport disks-eos disks-eos-slurm disks-diffusion disks-jamming"
for f in usr/bin/disks usr/lib/libdisksim.a "usr/lib/libdisksim.so.$version" \
         usr/include/disk_sim.h $(ls include/disksim/*.h | sed 's|^|usr/|') \
         usr/lib/pkgconfig/disksim.pc \
         usr/share/man/man1/disks.1 usr/share/man/man3/disk_sim.3 \
         usr/share/disksim/animate_disk.plt usr/share/disksim/eos_point.sh \
         usr/share/disksim/eos_gather.sh usr/share/disksim/sweep_dir.sh \
         $(for c in $analysis; do echo "usr/bin/$c usr/share/man/man1/$c.1"; done); do
    [ -f "$stage/$f" ] || fail "missing $f"
done
# Every installed command answers --help (exit status 0, its usage on
# stdout; the programs of tools/ still call themselves gr, pressure and
# transport there), and has its manual page; no command is installed
# without one.
for c in $analysis; do
    out=$("$stage/usr/bin/$c" --help) || fail "installed $c --help failed"
    echo "$out" | grep -q "^usage: " || fail "installed $c --help gives no usage: $out"
done
for c in "$stage"/usr/bin/*; do
    [ -f "$stage/usr/share/man/man1/${c##*/}.1" ] || fail "${c##*/} is installed without a man page"
done
# The documentation where a package puts it, the manual with its pictures.
doc=usr/share/doc/disksim
for f in README.md CHANGELOG.md LICENSE docs/*.md docs/*.png; do
    cmp -s "$f" "$stage/$doc/$f" || fail "$f is not installed as $doc/$f"
done
[ "$(readlink "$stage/usr/lib/libdisksim.so.$major")" = "libdisksim.so.$version" ] ||
    fail "libdisksim.so.$major does not point to libdisksim.so.$version"
[ "$(readlink "$stage/usr/lib/libdisksim.so")" = "libdisksim.so.$major" ] ||
    fail "libdisksim.so does not point to libdisksim.so.$major"
readelf -d "$stage/usr/lib/libdisksim.so.$version" | grep -q "SONAME.*\[libdisksim.so.$major\]" ||
    fail "soname is not libdisksim.so.$major"
if [ -x tools/render ]; then
    [ -x "$stage/usr/bin/disks-render" ] || fail "tools/render is built but not installed"
    [ -f "$stage/usr/share/man/man1/disks-render.1" ] || fail "disks-render is installed without its man page"
fi
grep -q '^\.I /usr/share/disksim/animate_disk\.plt$' "$stage/usr/share/man/man1/disks.1" ||
    fail "installed disks.1 does not name /usr/share/disksim/animate_disk.plt"
groff -man -Tutf8 -ww -z "$stage/usr/share/man/man1/disks.1" 2>&1 | { ! grep .; } ||
    fail "installed disks.1 has groff warnings"
# Each installed manual page as man shows it: no warning from man or groff.
for page in "$stage"/usr/share/man/man*/*; do
    out=$(man -l --warnings "$page" 2>&1 >/dev/null) || fail "man -l $page failed: $out"
    [ -z "$out" ] || fail "man -l ${page#"$stage"/} warns: $out"
done
"$stage/usr/bin/disks" --version | grep -qx "disks $version" || fail "installed disks --version"

# The shared library exports exactly the functions of the public headers.
nm -D --defined-only "$stage/usr/lib/libdisksim.so.$version" | awk '$2 == "T" { print $3 }' |
    sort > "$work/exported"
# shellcheck disable=SC2086
sed -n '/^[a-z]/s/^[^(]*[ *]\(ds_[a-z0-9_]*\)(.*/\1/p' $headers | sort > "$work/declared"
diff -u "$work/declared" "$work/exported" || fail "libdisksim.so exports differ from the public headers"

# Only the staged copy is visible to pkg-config, with paths under the stage.
export PKG_CONFIG_LIBDIR="$stage/usr/lib/pkgconfig" PKG_CONFIG_PATH=""
export PKG_CONFIG_SYSROOT_DIR="$stage"
[ "$(pkg-config --modversion disksim)" = "$version" ] || fail "disksim.pc version"
grep -qx 'prefix=/usr' "$stage/usr/lib/pkgconfig/disksim.pc" || fail "disksim.pc prefix"
grep -qx 'Libs.private: -lm' "$stage/usr/lib/pkgconfig/disksim.pc" || fail "disksim.pc Libs.private"
grep -qx 'License: MIT' "$stage/usr/lib/pkgconfig/disksim.pc" || fail "disksim.pc names no License: MIT"
pkg-config --validate disksim || fail "pkg-config --validate disksim"
grep -qx 'MIT License' LICENSE 2>/dev/null || fail "LICENSE is not the MIT licence"

# The library example of the README, as a reader would copy it.
awk '/^## Use the library/ { on = 1; next } /^## / { on = 0 }
     on && /^```c/ { code = 1; next } code && /^```/ { exit } code' README.md > "$work/readme.c"
[ -s "$work/readme.c" ] || fail "no C example under README's \"## Use the library\""

for prog in examples/minimal.c "$work/readme.c"; do
    name=$(basename "$prog" .c)
    # Shared: the program records libdisksim.so.MAJOR and finds it at run time.
    # shellcheck disable=SC2046
    cc -std=c99 -Wall -Wextra -Werror -o "$work/$name-shared" "$prog" \
        $(pkg-config --cflags --libs disksim)
    readelf -d "$work/$name-shared" | grep -q "NEEDED.*\[libdisksim.so.$major\]" ||
        fail "$name-shared does not link libdisksim.so.$major"
    LD_LIBRARY_PATH="$stage/usr/lib" "$work/$name-shared" > "$work/$name-shared.out"
    # Static: --static adds Libs.private (-lm) for a fully static program.
    # shellcheck disable=SC2046
    cc -std=c99 -Wall -Wextra -Werror -static -o "$work/$name-static" "$prog" \
        $(pkg-config --cflags --libs --static disksim)
    "$work/$name-static" > "$work/$name-static.out"
    for out in "$work/$name-shared.out" "$work/$name-static.out"; do
        grep -q "collision" "$out" || fail "$(basename "$out" .out) printed no collision time"
    done
    echo "install check: $prog built against the staged copy, shared and static: OK"
done

make -s uninstall DESTDIR="$stage" PREFIX=/usr
left=$(find "$stage" ! -type d)
[ -z "$left" ] || fail "make uninstall left: $left"

# The installed sweeps, run: under a prefix of their own (no DESTDIR, so the
# paths make install writes into them are real), from another directory.
prefix="$work/prefix"
unset PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR # the build's pkg-config again, not the stage's
make -s install PREFIX="$prefix"
mkdir "$work/run"
(
    cd "$work/run"
    export PATH="$prefix/bin:$PATH"
    disks-eos -j 2 64 1 2 1 >eos.out 2>&1 || fail "installed disks-eos failed: $(cat eos.out)"
    [ "$(grep -vc '^#' eos.N64.relax1.blocks2x1/eos.dat)" -eq 15 ] || fail "installed disks-eos wrote no eos.dat"
    disks-diffusion 32 0.1 >d.dat 2>&1 || fail "installed disks-diffusion failed: $(cat d.dat)"
    [ "$(grep -vc '^#' d.dat)" -eq 1 ] || fail "installed disks-diffusion wrote no row: $(cat d.dat)"
    disks-jamming 16 0.3 1 >j.tsv 2>&1 || fail "installed disks-jamming failed: $(cat j.tsv)"
    [ "$(grep -vc '^#' j.tsv)" -eq 1 ] || fail "installed disks-jamming wrote no row: $(cat j.tsv)"
    # Slurm through the stand-in, whose jobs run the spooled copy of the
    # installed disks-eos-slurm with nothing of this environment.
    mkdir slurm && cd slurm
    FAKE_SLURM="$work/slurm-state" PATH="$tree/tests/slurm:$PATH" \
        disks-eos-slurm submit 64 1 2 1 >submit.out 2>&1 ||
        fail "installed disks-eos-slurm submit failed: $(cat submit.out)"
    cmp -s eos.N64.relax1.blocks2x1/eos.dat ../eos.N64.relax1.blocks2x1/eos.dat ||
        [ "$(awk '!/^#/ { $NF = ""; print }' eos.N64.relax1.blocks2x1/eos.dat)" = \
          "$(awk '!/^#/ { $NF = ""; print }' ../eos.N64.relax1.blocks2x1/eos.dat)" ] ||
        fail "installed disks-eos-slurm's jobs did not give disks-eos's table: $(cat submit.out)"
) || exit 1
make -s uninstall PREFIX="$prefix"
left=$(find "$prefix" ! -type d)
[ -z "$left" ] || fail "make uninstall left: $left"
echo "install check: layout, analysis commands, pkg-config, shared and static examples, installed sweeps, uninstall: OK"
