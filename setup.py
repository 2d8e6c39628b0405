# SPDX-License-Identifier: MIT
"""The one build definition of the Python module disksim (pyproject.toml
beside it has the project's metadata): the extension disksim._disksim from
python/src/*.c and the library's own sources src/*/*.c, so neither a PIC
static library nor an installed libdisksim is needed. Every route builds
through it: `pip install .`, `pip wheel .`, the sdist and the wheel made
from it, `make python` (setup.py build_ext --inplace), and
`pip install ./python`, whose python/setup.py runs this one.

Every path is relative to this directory, none with "..": setuptools
copies an extension's sources into the sdist at their relative path, and
a "../src/x.c" lands outside the sdist (python/setup.py of disksim 2.x
copied the library's 39 sources into python/src/ that way and shipped
none of them). What the sdist holds beyond the sources is MANIFEST.in.

Honours CC and CFLAGS from the environment (as setuptools does), which is
how `make python` passes the Makefile's.
"""
import glob
import os
import re
import sys

from setuptools import Extension, setup
from setuptools.command.sdist import sdist

HERE = os.path.dirname(os.path.abspath(__file__))

if not os.path.exists(os.path.join(HERE, "include", "disk_sim.h")):
    sys.exit("disksim: %s is missing: build the module from a checkout of the disksim "
             "repository or from its sdist (pip install --no-build-isolation .)"
             % os.path.join(HERE, "include", "disk_sim.h"))

try:
    import numpy
except ImportError:
    sys.exit("disksim: numpy is needed to build the module (Debian: python3-numpy)")


def relative(*patterns):
    """The files matching the patterns, relative to this directory, sorted."""
    return sorted(os.path.relpath(p, HERE) for pattern in patterns
                  for p in glob.glob(os.path.join(HERE, pattern)))


# The public headers: disk_sim.h and those it includes (include/disksim/
# from 3.0 on), globbed so that a new one is a dependency without an edit.
public_headers = relative("include/*.h", "include/*/*.h")


def version():
    """DS_VERSION_STRING, from whichever public header defines it: the one
    place the version is written."""
    for header in public_headers:
        with open(os.path.join(HERE, header)) as f:
            found = re.search(r'#define DS_VERSION_STRING "([^"]+)"', f.read())
        if found:
            return found.group(1)
    sys.exit("disksim: no public header under %s defines DS_VERSION_STRING"
             % os.path.join(HERE, "include"))


# setuptools' own build/ would share the top's build/ with make's objects:
# it gets build/python/, beside make python's temporaries. The egg-info
# that pip's wheel build writes goes there too, not into the source tree
# (egg_info wants the directory to exist).
BUILD_BASE = os.path.join("build", "python")
os.makedirs(BUILD_BASE, exist_ok=True)

extension = Extension(
    "disksim._disksim",
    sources=relative("python/src/*.c") + relative("src/*/*.c"),
    depends=public_headers + relative("src/*/*.h", "python/src/*.h"),
    include_dirs=["include", "src", numpy.get_include()],
    # C99 like the library; only PyInit__disksim is exported (PyMODINIT_FUNC
    # marks it visible), so the library's ds_* stay inside the module.
    extra_compile_args=["-std=c99", "-Wall", "-Wextra", "-fvisibility=hidden"],
    libraries=["m"],
)



class sdist_without_build(sdist):
    """The sdist, less the egg-info's SOURCES.txt that setuptools adds
    from wherever egg_base is (here build/python/): the sdist has its
    PKG-INFO at the top, and nothing under build/."""

    def make_release_tree(self, base_dir, files):
        inside = BUILD_BASE + os.sep
        super().make_release_tree(base_dir, [f for f in files if not f.startswith(inside)])


setup(
    version=version(),
    packages=["disksim"],
    package_dir={"disksim": "python/disksim"},
    # PEP 561: the module's types, for mypy, pyright and editors.
    package_data={"disksim": ["py.typed", "*.pyi"]},
    ext_modules=[extension],
    cmdclass={"sdist": sdist_without_build},
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
)
