# SPDX-License-Identifier: MIT
"""disksim: hard disks (2D elastic billiards) from Python.

A thin face over libdisksim, the C library of this repository: N disks of
radius R (or a mixture of radii and masses) bouncing elastically in a box
with walls or periodic edges, advanced by a fixed time step or by exact
event-driven dynamics, at constant energy or in the canonical and isobaric
ensembles (a heat bath, a barostat), compressed by growing them, with the
library's observables (energy, momentum, wall and virial pressure, psi6)
and frames. Everything runs in the library; the arrays are numpy copies.

    import disksim
    s = disksim.Sim(400, 5.0)          # the command's `disks 400 5`
    s.run(100)                         # 100 steps of dt = 0.001, GIL released
    s.positions.shape                  # (400, 2), a fresh float64 copy
    s.kinetic_energy, s.momentum, s.pressure

Sim           one simulation (help(disksim.Sim) for its arguments)
Writer        a trajectory file written a frame at a time: GSD (HOOMD's, which
              OVITO, VMD, freud and gsd.hoomd read), extended XYZ or frames
read_frame    a frame file as arrays (Frame: positions, radii, velocities)
load          a Sim from an exact checkpoint written by Sim.save (pickle
              and copy.copy use the same checkpoint)
pair_histogram, rdf, local_psi6
              g(r) pair counts, g(r) itself (normalised by the ideal gas in
              the same box) and psi6 of any (n, 2) array of centres
memory_needed the bytes a Sim would allocate
Error         every failure the library reports; ArgumentError (also a
              ValueError), FormatError (ValueError), FileError (OSError),
              NoMemoryError (MemoryError)

INTEGRATORS, BOUNDARIES, PLACEMENTS, BROADPHASES, MASS_RULES, GROWTH_STATES,
THERMOSTATS and FORMATS are the names the arguments and properties take;
DEFAULT_SEED, CONTACT_TOLERANCE, MAX_AREA_FRACTION, MANY_DISKS, JAMMED_Z,
VELOCITY_MAX and SHEAR_MAX_STRAIN_PER_STEP the library's constants. Contacts is what Sim.contacts() returns. docs/python.md in the repository is the manual.
"""
from ._disksim import (
    BOUNDARIES,
    BROADPHASES,
    CONTACT_TOLERANCE,
    DEFAULT_SEED,
    FORMATS,
    GROWTH_STATES,
    INTEGRATORS,
    JAMMED_Z,
    MANY_DISKS,
    MASS_RULES,
    MAX_AREA_FRACTION,
    PLACEMENTS,
    SHEAR_MAX_STRAIN_PER_STEP,
    THERMOSTATS,
    VELOCITY_MAX,
    ArgumentError,
    Contacts,
    Error,
    FileError,
    FormatError,
    Frame,
    NoMemoryError,
    Sim,
    Writer,
    library_version,
    load,
    local_psi6,
    memory_needed,
    pair_histogram,
    rdf,
    read_frame,
)

__version__ = library_version

__all__ = [
    "Sim",
    "Writer",
    "read_frame",
    "load",
    "pair_histogram",
    "local_psi6",
    "rdf",
    "memory_needed",
    "Frame",
    "Contacts",
    "Error",
    "ArgumentError",
    "FormatError",
    "FileError",
    "NoMemoryError",
    "INTEGRATORS",
    "BOUNDARIES",
    "PLACEMENTS",
    "BROADPHASES",
    "MASS_RULES",
    "GROWTH_STATES",
    "THERMOSTATS",
    "FORMATS",
    "JAMMED_Z",
    "VELOCITY_MAX",
    "SHEAR_MAX_STRAIN_PER_STEP",
    "DEFAULT_SEED",
    "CONTACT_TOLERANCE",
    "MAX_AREA_FRACTION",
    "MANY_DISKS",
    "library_version",
]
