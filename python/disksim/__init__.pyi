# SPDX-License-Identifier: MIT
# The types of the package disksim (PEP 561; py.typed beside it says the
# package has them), for mypy, pyright and editors. The module is C
# (python/src/*.c): these are its method tables, getters and docstrings
# written as Python signatures; help() has the words. The names,
# signatures, defaults, base classes, fields and the Literal names here
# are checked against the built module by python/tests/test_stubs.py.
from collections.abc import Callable, Sequence
from typing import Any, Final, Literal, final

import numpy as np
from _typeshed import StrOrBytesPath, structseq
from numpy.typing import ArrayLike, NDArray
from typing_extensions import Self

__version__: Final[str]
library_version: Final[str]

# The names the arguments and properties take: the tuples below, as
# Literal types (test_stubs.py holds each equal to its tuple).
_Integrator = Literal["step", "event", "chain"]
_Boundary = Literal["walls", "periodic", "channel"]
_Placement = Literal["random", "lattice"]
_Broadphase = Literal["auto", "sap", "strips", "cells", "brute"]
_MassRule = Literal["equal", "area"]
_GrowthState = Literal["none", "growing", "reached_eta", "jammed"]
_Thermostat = Literal["none", "andersen", "isokinetic"]
_Format = Literal["frame", "xyz", "gsd"]

INTEGRATORS: Final[tuple[_Integrator, ...]]
BOUNDARIES: Final[tuple[_Boundary, ...]]
PLACEMENTS: Final[tuple[_Placement, ...]]
BROADPHASES: Final[tuple[_Broadphase, ...]]
MASS_RULES: Final[tuple[_MassRule, ...]]
GROWTH_STATES: Final[tuple[_GrowthState, ...]]
THERMOSTATS: Final[tuple[_Thermostat, ...]]
FORMATS: Final[tuple[_Format, ...]]

DEFAULT_SEED: Final[int]
CONTACT_TOLERANCE: Final[float]
MAX_AREA_FRACTION: Final[float]
MANY_DISKS: Final[int]
JAMMED_Z: Final[float]
VELOCITY_MAX: Final[float]
SHEAR_MAX_STRAIN_PER_STEP: Final[float]

# A mixture by kind: (count, radius), (count, radius, mass), and either
# with the kind's name last.
_Species = Sequence[
    tuple[int, float]
    | tuple[int, float, float]
    | tuple[int, float, str]
    | tuple[int, float, float, str]
]

class Error(Exception):
    status: str | None
    field: str | None
    value: float | None
    limit: float | None

class ArgumentError(Error, ValueError): ...

class FormatError(Error, ValueError):
    line: int
    path: StrOrBytesPath

class FileError(Error, OSError): ...
class NoMemoryError(Error, MemoryError): ...

# Struct sequences, as os.stat_result: named fields, a tuple, not subclassable.
@final
class Frame(
    structseq[Any],
    tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64] | None],
):
    __match_args__: Final = ("positions", "radii", "velocities")
    @property
    def positions(self) -> NDArray[np.float64]: ...
    @property
    def radii(self) -> NDArray[np.float64]: ...
    @property
    def velocities(self) -> NDArray[np.float64] | None: ...

@final
class Contacts(structseq[Any], tuple[int, int, float, float]):
    __match_args__: Final = ("pairs", "rattlers", "per_disk", "rattler_fraction")
    @property
    def pairs(self) -> int: ...
    @property
    def rattlers(self) -> int: ...
    @property
    def per_disk(self) -> float: ...
    @property
    def rattler_fraction(self) -> float: ...

class Sim:
    def __init__(
        self,
        n: int,
        radius: float,
        *,
        seed: int = 20260101,
        integrator: _Integrator = "step",
        boundary: _Boundary = "walls",
        placement: _Placement = "random",
        box: float = 1000.0,
        box_y: float | None = None,
        dt: float = 0.001,
        speed: float = 100.0,
        broadphase: _Broadphase = "auto",
        species: _Species | None = None,
        radii: ArrayLike | None = None,
        masses: ArrayLike | None = None,
        mass: _MassRule = "equal",
    ) -> None: ...

    # running
    def step(self) -> None: ...
    def run(
        self,
        steps: int | None = None,
        *,
        until: float | None = None,
        callback: Callable[[Self], object] | None = None,
        every: int = 1,
    ) -> None: ...
    def reset_observables(self) -> None: ...
    def set_state(self, positions: ArrayLike, velocities: ArrayLike | None = None) -> None: ...
    def set_growth(self, rate: float, until_eta: float = 0.0, until_z: float = 0.0) -> None: ...
    def set_thermostat(
        self, kind: _Thermostat, kt: float = 0.0, collision_rate: float = 0.0
    ) -> None: ...
    def set_barostat(
        self, pressure: float, every: int = 0, max_step: float = 0.0, aspect: bool = False
    ) -> None: ...
    def scale_velocities(self, factor: float) -> None: ...
    def set_restitution(self, restitution: float, wall_restitution: float | None = None) -> None: ...
    def set_contact_time(self, contact_time: float) -> None: ...
    def set_gravity(self, gx: float, gy: float) -> None: ...
    def set_drive(self, strength: float) -> None: ...
    def set_shear(self, rate: float) -> None: ...

    # analysis and output
    def contacts(self, gap: float = 0.0001) -> Contacts: ...
    def pair_histogram(self, dr: float, bins: int) -> NDArray[np.uint64]: ...
    def local_psi6(self, cutoff: float | None = None) -> NDArray[np.complex128]: ...
    def velocity_profile(
        self, bins: int
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]: ...
    def rdf(self, r_max: float, bins: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...
    def write_frame(self, path: StrOrBytesPath, velocities: bool = False) -> None: ...
    def save(self, path: StrOrBytesPath) -> None: ...
    # An ase.Atoms; Any, so that the types need no ASE (an optional dependency).
    def to_ase(self) -> Any: ...
    # freud's and HOOMD-blue's Box.from_box dict (Lx, Ly, Lz, xy, xz, yz,
    # dimensions) and their (n, 3) points.
    def freud_box(self) -> dict[str, float]: ...
    def freud_points(self) -> NDArray[np.float64]: ...

    # life
    def close(self) -> None: ...
    def __enter__(self) -> Self: ...
    def __exit__(self, *exc_info: object) -> Literal[False]: ...
    def __reduce__(self) -> tuple[Any, ...]: ...
    def __len__(self) -> int: ...
    def __bool__(self) -> Literal[True]: ...

    # the system
    @property
    def n(self) -> int: ...
    @property
    def radius(self) -> float: ...
    @property
    def radii(self) -> NDArray[np.float64]: ...
    @property
    def kinds(self) -> NDArray[np.uint32]: ...
    @property
    def kind_names(self) -> tuple[str, ...]: ...
    @property
    def masses(self) -> NDArray[np.float64]: ...
    @property
    def radius_max(self) -> float: ...
    @property
    def area_fraction(self) -> float: ...
    @property
    def box(self) -> float: ...
    @property
    def box_y(self) -> float: ...
    @property
    def dt(self) -> float: ...
    @property
    def integrator(self) -> _Integrator: ...
    @property
    def boundary(self) -> _Boundary: ...
    @property
    def placement(self) -> _Placement | None: ...
    @property
    def broadphase(self) -> _Broadphase: ...
    @property
    def params(self) -> dict[str, Any]: ...

    # the state
    @property
    def time(self) -> float: ...
    @property
    def steps(self) -> int: ...
    @property
    def positions(self) -> NDArray[np.float64]: ...
    @property
    def velocities(self) -> NDArray[np.float64]: ...
    @property
    def unwrapped(self) -> NDArray[np.float64]: ...
    @property
    def images(self) -> NDArray[np.int32]: ...

    # observables
    @property
    def kinetic_energy(self) -> float: ...
    @property
    def momentum(self) -> tuple[float, float]: ...
    @property
    def pressure(self) -> float: ...
    @property
    def virial_pressure(self) -> float: ...
    @property
    def temperature(self) -> float: ...
    @property
    def compressibility_factor(self) -> float: ...
    @property
    def psi6(self) -> float: ...
    @property
    def collision_count(self) -> int: ...
    @property
    def wall_count(self) -> int: ...
    @property
    def wall_impulse(self) -> float: ...
    @property
    def pairs_tested(self) -> int: ...
    @property
    def collision_seconds(self) -> float: ...
    @property
    def growth_state(self) -> _GrowthState: ...
    @property
    def growth_z(self) -> float: ...
    @property
    def restitution(self) -> float: ...
    @property
    def wall_restitution(self) -> float: ...
    @property
    def contact_time(self) -> float: ...
    @property
    def gravity(self) -> tuple[float, float]: ...
    @property
    def drive(self) -> float: ...
    @property
    def energy_lost(self) -> float: ...
    @property
    def energy_input(self) -> float: ...
    @property
    def power_lost(self) -> float: ...
    @property
    def power_input(self) -> float: ...
    @property
    def potential_energy(self) -> float: ...
    @property
    def thermostat(self) -> _Thermostat: ...
    @property
    def thermostat_kt(self) -> float: ...
    @property
    def barostat_pressure(self) -> float: ...
    @property
    def barostat_acceptance(self) -> float: ...
    @property
    def stress_integral(self) -> tuple[float, float, float]: ...
    @property
    def shear_rate(self) -> float: ...
    @property
    def shear_shift(self) -> float: ...
    @property
    def shear_offset(self) -> float: ...

    # whether it can be used
    @property
    def closed(self) -> bool: ...
    @property
    def running(self) -> bool: ...

@final
class Writer:
    def __init__(
        self,
        path: StrOrBytesPath,
        format: _Format = "gsd",
        *,
        velocities: bool = False,
        append: bool = False,
    ) -> None: ...
    def write(self, sim: Sim) -> None: ...
    def close(self) -> None: ...
    def __enter__(self) -> Self: ...
    def __exit__(self, *exc_info: object) -> Literal[False]: ...
    @property
    def path(self) -> StrOrBytesPath: ...
    @property
    def format(self) -> _Format: ...
    @property
    def frames(self) -> int: ...
    @property
    def closed(self) -> bool: ...

def read_frame(path: StrOrBytesPath) -> Frame: ...
def load(path: StrOrBytesPath) -> Sim: ...
def pair_histogram(
    positions: ArrayLike,
    dr: float,
    bins: int,
    *,
    box: float = 1000.0,
    box_y: float | None = None,
    boundary: _Boundary = "walls",
) -> NDArray[np.uint64]: ...
def rdf(
    positions: ArrayLike,
    r_max: float,
    bins: int,
    *,
    box: float = 1000.0,
    box_y: float | None = None,
    boundary: _Boundary = "walls",
    radius: float = 0.0,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...
def local_psi6(
    positions: ArrayLike,
    cutoff: float,
    *,
    box: float = 1000.0,
    box_y: float | None = None,
    boundary: _Boundary = "walls",
) -> NDArray[np.complex128]: ...

# Sim's arguments (the module takes them as **arguments and hands them to
# the same parser as Sim's).
def memory_needed(
    n: int,
    radius: float,
    *,
    seed: int = 20260101,
    integrator: _Integrator = "step",
    boundary: _Boundary = "walls",
    placement: _Placement = "random",
    box: float = 1000.0,
    box_y: float | None = None,
    dt: float = 0.001,
    speed: float = 100.0,
    broadphase: _Broadphase = "auto",
    species: _Species | None = None,
    radii: ArrayLike | None = None,
    masses: ArrayLike | None = None,
    mass: _MassRule = "equal",
) -> int: ...

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
    "DEFAULT_SEED",
    "CONTACT_TOLERANCE",
    "MAX_AREA_FRACTION",
    "MANY_DISKS",
    "VELOCITY_MAX",
    "SHEAR_MAX_STRAIN_PER_STEP",
    "library_version",
]
