#!/bin/sh
# SPDX-License-Identifier: MIT
# The Python module's packaging (docs/python.md#install), offline, the way
# a user with Debian's packages does it: pip from a venv made with
# --system-site-packages, --no-build-isolation --no-index. On a copy of
# the checkout's files (what git tracks, and new files it does not
# ignore), so that nothing an earlier build left behind can stand in for
# a missing source:
#  - `pip install .` at the top, then `import disksim` from another
#    directory imports the installed copy, in the venv's site-packages,
#    with py.typed and its stubs, and runs; `pip install ./python`
#    (disksim 2.x's way) installs the same;
#  - `pip wheel .` makes a wheel holding the module, py.typed and the
#    stubs, and the licence;
#  - the sdist (python3 -m build --sdist --no-isolation) holds every
#    source and header of the library and the module, LICENSE and
#    README.md, and nothing under build/; a wheel built from it alone, in
#    a directory with no checkout around it, installs and imports;
#  - the installed package is typed: mypy's stubtest finds its stubs in
#    agreement with it, and mypy --strict passes a script using it
#    correctly and flags a misspelled integrator name;
#  - the copy is left as it was: no file outside build/ added, changed or
#    removed (2.x's sdist copied the library's 39 sources into python/src/).
# Every build compiles the library, seconds each: .ci/run runs this, and
# `make python-packaging` by hand, not make test. From the top directory;
# PYTHON names the Python (default /usr/bin/python3, Debian's).
# shellcheck disable=SC2015 # "A && B || fail": fail whenever A or B is false
set -eu
top=$(pwd)
python=${PYTHON:-/usr/bin/python3}
work=$(mktemp -d "${TMPDIR:-/tmp}/python_packaging.XXXXXX")
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH # the installed copy, not one built in place
fail() {
    echo "python_packaging: $*" >&2
    exit 1
}

need() { # MODULE PACKAGE
    "$python" -c "import $1" 2>/dev/null || fail "$python lacks $1 (Debian: $2)"
}
need ensurepip python3-venv
need wheel python3-wheel
need build python3-build
need mypy python3-mypy
need numpy python3-numpy

# The copy, and what it holds before any build.
src=$work/disksim
mkdir "$src" "$work/elsewhere" "$work/empty"
git -C "$top" ls-files -z --cached --others --exclude-standard |
    (cd "$top" && tar --null --files-from=- --ignore-failed-read -cf -) | tar -xf - -C "$src"
[ -f "$src/include/disk_sim.h" ] || fail "no checkout of disksim at $top"
snapshot() {
    (cd "$src" && find . -path ./build -prune -o -type f -exec sha256sum {} + | LC_ALL=C sort -k 2)
}
snapshot >"$work/before"
version=$(cat "$src"/include/*.h "$src"/include/*/*.h 2>/dev/null |
    sed -n 's/^#define DS_VERSION_STRING "\(.*\)"/\1/p')
[ -n "$version" ] || fail "no DS_VERSION_STRING in include/"

"$python" -m venv --system-site-packages "$work/env"
env=$work/env/bin
offline="--no-build-isolation --no-index --disable-pip-version-check"
run() { # LOG COMMAND...: COMMAND, its output in $work/LOG
    log=$work/$1
    shift
    "$@" >"$log" 2>&1 || fail "$* failed: $(tail -20 "$log")"
}

# import disksim in the venv, from a directory with no checkout: the
# installed copy, typed, of the header's version, and it runs.
check_import() { # WHAT
    (cd "$work/elsewhere" && "$env/python" - "$version") >"$work/import.log" 2>&1 <<'EOF' ||
import os, sys, sysconfig
import disksim
here = os.path.dirname(os.path.abspath(disksim.__file__))
assert os.path.samefile(os.path.dirname(here), sysconfig.get_paths()["platlib"]), here
for name in ("py.typed", "__init__.pyi"):
    assert os.path.isfile(os.path.join(here, name)), "no %s in %s" % (name, here)
assert disksim.__version__ == sys.argv[1], disksim.__version__
s = disksim.Sim(400, 5.0)
s.run(100)
assert s.positions.shape == (400, 2)
EOF
        fail "$1: import disksim from another directory: $(cat "$work/import.log")"
}

echo "-- pip install . (at the top)"
# shellcheck disable=SC2086
(cd "$src" && run install.log "$env/pip" install $offline .)
check_import "pip install ."

echo "-- the installed package is typed: stubtest, mypy --strict"
(cd "$work/elsewhere" && run stubtest.log "$env/python" -m mypy.stubtest disksim)
cat >"$work/elsewhere/uses.py" <<'EOF'
import numpy as np
from numpy.typing import NDArray

import disksim

with disksim.Sim(64, 20.0, integrator="event", boundary="periodic") as s:
    s.run(10)
    positions: NDArray[np.float64] = s.positions
    counts: NDArray[np.uint64] = s.pair_histogram(1.0, 10)
    contacts: disksim.Contacts = s.contacts()
    per_disk: float = contacts.per_disk
    growth: str = s.growth_state
frame: disksim.Frame = disksim.read_frame("frame.txt")
names: tuple[str, ...] = disksim.INTEGRATORS
EOF
(cd "$work/elsewhere" && run mypy.log "$env/python" -m mypy --strict --no-incremental \
    --cache-dir=/dev/null uses.py)
echo 'disksim.Sim(4, 1.0, integrator="evnt")' >>"$work/elsewhere/uses.py"
(cd "$work/elsewhere" && "$env/python" -m mypy --strict --no-incremental --cache-dir=/dev/null \
    uses.py >"$work/mypy.log" 2>&1) && fail "mypy passed integrator=\"evnt\""
grep -q 'Argument "integrator" to "Sim" has incompatible type "Literal\[.evnt.\]"' \
    "$work/mypy.log" || fail "mypy on integrator=\"evnt\": $(cat "$work/mypy.log")"

echo "-- pip install ./python (2.x's way)"
run uninstall.log "$env/pip" uninstall -y disksim
# shellcheck disable=SC2086
(cd "$src" && run install_python.log "$env/pip" install $offline ./python)
check_import "pip install ./python"

wheel_holds() { # WHEEL: the module, py.typed, the stubs and the licence
    "$python" - "$1" <<'EOF' || fail "$1 lacks what a wheel needs"
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
for want in ("disksim/__init__.py", "disksim/__init__.pyi", "disksim/py.typed"):
    assert want in names, want
assert any(n.startswith("disksim/_disksim.") and n.endswith(".so") for n in names), names
assert any(n.endswith(".dist-info/LICENSE") for n in names), names
EOF
}

echo "-- pip wheel ."
# shellcheck disable=SC2086
(cd "$src" && run wheel.log "$env/pip" wheel --no-deps $offline -w "$work/wheel" .)
wheel_holds "$work"/wheel/disksim-"$version"-*.whl

echo "-- the sdist, and a wheel from it alone"
(cd "$src" && run sdist.log "$python" -m build --sdist --no-isolation --outdir "$work/sdist" .)
sdist=$work/sdist/disksim-$version.tar.gz
[ -f "$sdist" ] || fail "no $sdist: $(ls "$work/sdist")"
tar -tzf "$sdist" | sed "s|^disksim-$version/||" | LC_ALL=C sort >"$work/sdist.list"
(cd "$src" && for f in LICENSE README.md setup.py pyproject.toml MANIFEST.in include/*.h \
    include/*/*.h src/*/*.c src/*/*.h python/src/*.c python/src/*.h python/disksim/__init__.py \
    python/disksim/__init__.pyi python/disksim/py.typed; do
    [ -f "$f" ] || continue # include/*/*.h before 3.0
    grep -qxF "$f" "$work/sdist.list" || echo "$f"
done) >"$work/missing"
[ ! -s "$work/missing" ] || fail "the sdist lacks $(tr '\n' ' ' <"$work/missing")"
! grep -q '^build/' "$work/sdist.list" || fail "the sdist holds build/: $(grep '^build/' "$work/sdist.list")"
# shellcheck disable=SC2086
(cd "$work/empty" && run sdist_wheel.log "$env/pip" wheel --no-deps $offline -w "$work/from_sdist" "$sdist")
from_sdist=$(ls "$work"/from_sdist/disksim-"$version"-*.whl)
wheel_holds "$from_sdist"
# shellcheck disable=SC2086
run install_wheel.log "$env/pip" install --no-deps --force-reinstall $offline "$from_sdist"
check_import "the wheel built from the sdist"

echo "-- the checkout is as it was"
snapshot >"$work/after"
cmp -s "$work/before" "$work/after" ||
    fail "the builds changed the checkout outside build/: $(diff "$work/before" "$work/after" | head -20)"
echo "python_packaging: 1 passed, 0 failed"
