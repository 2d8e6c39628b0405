# SPDX-License-Identifier: MIT
"""Shared by the suite: the module under test and the disks command.

The module is whichever `import disksim` finds (PYTHONPATH=python after
`make python`, as `make test` runs it, or an installed copy); failing that,
the one built in place in python/. The command is $DISKSIM_DISKS (make test
sets it to the disks of its build) or the top directory's ./disks.
"""
import os
import sys

import pytest

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

try:
    import disksim  # noqa: F401
except ImportError:
    sys.path.insert(0, os.path.join(TOP, "python"))


@pytest.fixture(scope="session")
def disks_command():
    path = os.environ.get("DISKSIM_DISKS") or os.path.join(TOP, "disks")
    if not os.access(path, os.X_OK):
        pytest.skip("no disks command at %s (run make first)" % path)
    return path
