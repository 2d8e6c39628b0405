# SPDX-License-Identifier: MIT
"""`pip install ./python`, as disksim 2.x documented it: the build is the
top directory's, setup.py there (the one build definition, which
`pip install .` uses), run from there. pip builds a local directory in
place, so the checkout around this directory is there to run it in.
"""
import os
import runpy
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if not os.path.exists(os.path.join(TOP, "setup.py")):
    sys.exit("disksim: %s is missing: build the module from a checkout of the disksim "
             "repository (pip install --no-build-isolation .)" % os.path.join(TOP, "setup.py"))
os.chdir(TOP)
runpy.run_path(os.path.join(TOP, "setup.py"), run_name="__main__")
