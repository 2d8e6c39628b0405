# SPDX-License-Identifier: MIT
"""Builds the extension disksim._disksim from python/src/*.c and the
library's own sources (../src/*/*.c), so neither a PIC static library nor
an installed libdisksim is needed. The version is DS_VERSION_STRING of
include/disksim/base.h, the one place it is written.

Honours CC and CFLAGS from the environment (as setuptools does), which is
how `make python` passes the Makefile's.
"""
import glob
import os
import re
import sys

from setuptools import Extension, setup

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
HEADER = os.path.join(TOP, "include", "disksim", "base.h")

if not os.path.exists(HEADER):
    sys.exit("disksim: %s is missing: build the module from a checkout of the "
             "disksim repository (pip install --no-build-isolation ./python)" % HEADER)

try:
    import numpy
except ImportError:
    sys.exit("disksim: numpy is needed to build the module (Debian: python3-numpy)")


def version():
    with open(HEADER) as f:
        return re.search(r'#define DS_VERSION_STRING "([^"]+)"', f.read()).group(1)


# Paths relative to this directory, as setuptools requires. The library's
# sources are ../src/*/*.c, so their objects land one level above the build
# directory setuptools is given (make python gives it $(BUILD)/python/temp:
# the objects go to $(BUILD)/python/src/).
def relative(pattern):
    return sorted(os.path.relpath(p, HERE) for p in glob.glob(os.path.join(HERE, pattern)))


lib_sources = relative("../src/*/*.c")
module_sources = relative("src/*.c")
headers = (relative("../include/disk_sim.h") + relative("../include/disksim/*.h") +
           relative("../src/*/*.h") + relative("src/*.h"))

extension = Extension(
    "disksim._disksim",
    sources=module_sources + lib_sources,
    depends=headers,
    include_dirs=[os.path.join(TOP, "include"), os.path.join(TOP, "src"),
                  numpy.get_include()],
    # C99 like the library; only PyInit__disksim is exported (PyMODINIT_FUNC
    # marks it visible), so the library's ds_* stay inside the module.
    extra_compile_args=["-std=c99", "-Wall", "-Wextra", "-fvisibility=hidden"],
    libraries=["m"],
)

setup(version=version(), packages=["disksim"], ext_modules=[extension])
