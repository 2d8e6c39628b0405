# SPDX-License-Identifier: MIT
# A packing compressed fast, stopped when Z passes 10^6, then run on at
# fixed radii: its contacts (gap 1e-4) at the stop and 0.1, 0.2, 0.3 time
# units later (docs/physics.md). Run from the top of the checkout after
# make python:  PYTHONPATH=python /usr/bin/python3 tools/analysis/unjam.py
import math, disksim
n = 1024; r = math.sqrt(0.5e6 / (math.pi * n * 1.48))
s = disksim.Sim(n, r, species=[(n // 2, r), (n // 2, 1.4 * r)], integrator="event",
                boundary="periodic", seed=1)
s.set_growth(0.1)
while s.growth_state == "growing":
    s.step()
print(f"jammed at t = {s.time:.4f}, area fraction {s.area_fraction:.6f}: {s.contacts(1e-4)}")
for steps in (100, 100, 100):
    s.run(steps)
    print(f"t = {s.time:.4f}: {s.contacts(1e-4)}")
