# SPDX-License-Identifier: MIT
"""Prints the Debian packages this Python lacks for building the module
(`build`) or also for running its tests (`test`), space-separated; prints
nothing when all are there. The Makefile's python targets use it to say in
one line what is missing, as the renderer's note does.

    python3 python/check_deps.py build|test
"""
import importlib.util
import os
import sys
import sysconfig

need = [
    ("python3-dev", lambda: os.path.exists(os.path.join(sysconfig.get_paths()["include"],
                                                        "Python.h"))),
    ("python3-numpy", lambda: importlib.util.find_spec("numpy")),
    ("python3-setuptools", lambda: importlib.util.find_spec("setuptools")),
]
if sys.argv[1:] == ["test"]:
    need.append(("python3-pytest", lambda: importlib.util.find_spec("pytest")))
print(" ".join(package for package, found in need if not found()))
