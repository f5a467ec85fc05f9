"""The bearing contract: what every bearing is and answers, written once (DESIGN.md section 3).

Every analysis (static equilibrium, modal, Campbell, FRF, unbalance, chatter, transient) talks to
its bearings through this contract and nothing else: no analysis asks which kind of bearing it
holds or probes its attributes.  A bearing family implements it in its own folder
(``bearings/<family>/``); :class:`BearingBase` gives the defaults of the optional parts.

Frame and signs
---------------
x horizontal, y vertical (gravity along -y), z along the shaft; the shaft spins about +z, so a
positive speed turns x towards y.  Node DOFs are named from ("x", "y", "z", "theta_x",
"theta_y"); theta_x and theta_y are rotations about +x and +y.  Forces and moments are those
the bearing exerts ON THE SHAFT; a stiffness is minus the derivative of that force.

Attributes
----------
name : str
    The deck's name of the bearing (unique in a rotor).
node : int
    0-based shaft node the bearing acts on.
dof_names : tuple[str, ...]
    The node DOFs it acts on, in the order of q, f and the matrices: ("x", "y") for a radial
    bearing, ("x", "y", "z", "theta_x", "theta_y") for one that also carries axial load and
    tilt (DTRB, ball bearing sets).
internal_mass : np.ndarray
    Mass (or inertia) of each of the bearing's own dynamic DOFs, e.g. the rollers and
    outer-race segments of a flexible-race roller bearing; empty for most bearings.  They
    follow the node DOFs in q, v, f and the tangents; the transient engine integrates them
    with the rotor, every other analysis condenses them out (through ``linearized``).
iterative : bool
    Whether its state at an operating point is found by iteration (a contact equilibrium, a film's
    thermal equilibrium): a sweep over many speeds then shares its static states among the cores
    (``analysis.points``).  False for a bearing whose reaction is linear; the default is True.
speed_independent : bool
    Whether its reaction, and so its operating point and coefficients, are the same at every speed (a
    linear bearing without a speed table): a rotor whose bearings all are, and whose shaft has no
    speed-dependent stiffness, has one static state at every speed (``analysis.points`` solves it once).
    The default is False.

Methods
-------
force_and_tangent(q, v, t, speed, angle=None) -> (f, K_t, C_t)
    The nonlinear reaction.  q, v: displacement [m, rad] and velocity of the node DOFs
    (``dof_names`` order, measured from the bearing's centre) followed by the internal DOFs;
    t: time [s]; speed: shaft speed [rad/s]; angle: shaft rotation angle [rad] at t (default
    speed * t; a speed ramp passes the integral).  f: force on the shaft (and on the internal
    DOFs); K_t = -df/dq and C_t = -df/dv, square of the size of q.  Used by the one static
    equilibrium solver and by the transient engine.
force(q, v, t, speed, angle=None) -> f
    The force alone (the first output of ``force_and_tangent``); the default evaluates that, a
    family whose tangent costs more (differences) gives the force directly.
linearized(speed, static_load, start=None) -> (K, C)
    Stiffness [N/m, N/rad, N m/rad] and damping coefficients on ``dof_names`` at the operating
    point: ``static_load`` is what the shaft puts on the bearing at static equilibrium
    (= -f there), on ``dof_names``.  Used by static, modal, Campbell, FRF, unbalance, chatter.
    For a bearing whose reaction does not vary in time this equals the tangent of
    ``force_and_tangent`` at the displacement that carries ``static_load``; a rolling bearing
    returns that tangent averaged over one rolling-element pitch, and as C the damping of its model
    (``bearings.damping``: C = beta K for ball sets, DTRBs and rigid races, whose ``force_and_tangent``
    carries -beta K_t v; a flexible race's own contact damping, condensed).  ``start``: a displacement near
    the one that carries ``static_load`` (node DOFs, then internal; the rotor's state there, or a
    neighbouring speed's), where a family that iterates may start (the ball set does); a start
    only, the answer is the same to the family's tolerance.
static_displacement(speed, static_load, start=None) -> q
    The displacement (node DOFs followed by internal DOFs) at which the bearing alone carries
    ``static_load``: the start of the rotor's static equilibrium, exact for a statically
    determinate rotor.  The default solves the linearised bearing.  ``start``: as in ``linearized``.
at_operating_point(speed, static_load, transient=False) -> bearing
    The same bearing with everything the operating point sets held fixed (a fluid film: the
    viscosity of its thermal equilibrium), for a nonlinear analysis about that point: the static
    equilibrium, or with ``transient=True`` a time integration, which evaluates the reaction some
    1e5 times along a trajectory and may get a reduced model where it is exact enough (a fluid
    film's tabulated force, ``fluidfilm.film_table``).  Bearings with no such quantity return
    themselves.
frequencies_hz(speed) -> dict[str, float]
    Characteristic excitation frequencies, e.g. {"cage": .., "roller_pass": ..}: the transient
    samples a Poincare map once per period of each and marks them on its spectrum.
compiled() -> CompiledForce
    Parameters of the bearing's compiled force (``bearings.compiled``), for the transient
    engine's explicit integrator.  Raises NotImplementedError for bearings without one.
at_temperatures(temperatures) -> bearing
    The bearing with its parts at ``temperatures`` (a
    :class:`~spindlesim.thermal.growth_bearings.BearingTemperatures`: inner ring, rolling elements,
    outer ring, the shaft and housing seats and the reference of the cold assembly): grown rings and
    rolling elements, fits, the operating clearance or preload that follows.  The thermal model of the
    spindle calls it at every step; a bearing without a growth model returns itself.
heat(speed, static_load, lubrication, lubricant_C, displacement=None) -> HeatReport or None
    The heat the bearing generates at the operating point (``static_load`` as in ``linearized``; with
    ``displacement``, the node DOFs' static displacement there, no equilibrium need be solved again), split
    where it goes (inner ring, rolling elements, outer ring) with the contact loads the thermal network's
    conductances need; ``lubrication`` a :class:`Lubrication`, ``lubricant_C`` the oil's temperature.
    None: the family has no heat model in the spindle's network (a fluid film keeps its own heat balance).
outputs(q, v, t, speed, angle=None) -> dict[str, tuple[np.ndarray, str]]
    What a transient records for this bearing at a sampled state, name -> (value, units): always
    "force" (the reaction on the node DOFs, as in ``force_and_tangent``), and what the family
    adds, e.g. {"roller_load_N": (Q_j, "N")}.  The default evaluates ``force_and_tangent``.

The speed is always passed in, never stored on the bearing, so one bearing object serves every
speed of a Campbell diagram and every instant of a run-up.

The spindle's thermal network
-----------------------------
Besides ``at_temperatures`` and ``heat`` above, what the network asks of a family is answered by its row of
``BEARING_TYPES`` (``bearings/types.py``: ``thermal_set(entry, z_m)``, the family's set at a position, and
``thermal_refusal``) and by the set it builds: a :class:`spindlesim.thermal.layout.BearingSet` carrying the
family's contact paths (:class:`spindlesim.thermal.layout.ContactPaths`, ``bearings/conductance.py``): its
rolling elements and their conductances at a state (speed, contact loads, films, cavity temperature).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Protocol, runtime_checkable

import numpy as np

RADIAL = ("x", "y")
FIVE = ("x", "y", "z", "theta_x", "theta_y")


class SpeedRequiredError(ValueError):
    """A bearing that carries load only while the shaft turns (a fluid film) was asked to at rest: an input
    to correct (the speed of the deck or the command line), not a solver failure."""


@runtime_checkable
class Bearing(Protocol):
    """The contract of the module docstring (static type checking and documentation)."""

    name: str
    node: int
    dof_names: tuple[str, ...]
    internal_mass: np.ndarray
    iterative: bool
    speed_independent: bool

    def force_and_tangent(self, q: np.ndarray, v: np.ndarray, t: float, speed: float,
                          angle: float | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]: ...

    def linearized(self, speed: float, static_load: np.ndarray | None = None,
                   start: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]: ...

    def static_displacement(self, speed: float, static_load: np.ndarray | None = None,
                            start: np.ndarray | None = None) -> np.ndarray: ...

    def force(self, q: np.ndarray, v: np.ndarray, t: float, speed: float, angle: float | None = None) -> np.ndarray: ...

    def at_operating_point(self, speed: float, static_load: np.ndarray | None = None,
                           transient: bool = False) -> "Bearing": ...

    def frequencies_hz(self, speed: float) -> dict[str, float]: ...

    def compiled(self) -> "CompiledForce": ...

    def outputs(self, q: np.ndarray, v: np.ndarray, t: float, speed: float,
                angle: float | None = None) -> dict[str, tuple[np.ndarray, str]]: ...


@dataclass(frozen=True)
class Lubrication:
    """How a rolling bearing is lubricated, for its heat: the oil (``thermal.friction.Lubricant``), the method
    (grease, oil_mist, oil_air, oil_bath, oil_jet) and the oil's volume share in the cavity."""

    lubricant: object
    method: str = "oil_air"
    oil_volume_fraction: float = 0.01


@dataclass(frozen=True)
class HeatReport:
    """Heat of a bearing at its operating point [W], split where it goes, and its contacts for the network:
    the loads per rolling element [N] at the inner and outer race (arrays) and the lubricant films [m]."""

    inner_W: float
    elements_W: float
    outer_W: float
    inner_contact_N: np.ndarray
    outer_contact_N: np.ndarray
    film_inner_m: float = 0.0
    film_outer_m: float = 0.0
    row_thrust_N: np.ndarray | None = None  # axial load each row carries (its preload at rest), where it has rows
    contact_angle_inner_deg: np.ndarray | None = None  # per row, mean over the rolling elements
    contact_angle_outer_deg: np.ndarray | None = None
    detail: object = None  # the family's own breakdown (spin, rolling, drag ...)

    @property
    def total_W(self) -> float:
        return self.inner_W + self.elements_W + self.outer_W


@dataclass(frozen=True)
class CompiledForce:
    """A bearing's compiled force: ``kind`` selects the kernel in ``bearings.compiled``; the
    kernel reads its parameters from ``floats`` and ``ints``."""

    kind: int
    floats: np.ndarray
    ints: np.ndarray


class BearingBase:
    """Defaults of the optional parts of the contract; a family overrides what applies to it."""

    internal_mass: np.ndarray = np.zeros(0)
    iterative: bool = True
    speed_independent: bool = False

    def static_displacement(self, speed: float, static_load: np.ndarray | None = None,
                            start: np.ndarray | None = None) -> np.ndarray:
        n = len(self.dof_names)
        q = np.zeros(n + self.internal_mass.size)
        if static_load is not None and np.any(static_load):
            K, _ = self.linearized(speed, static_load)
            q[:n] = np.linalg.lstsq(K, np.asarray(static_load, float)[:n], rcond=None)[0]
        return q

    def force(self, q, v, t, speed, angle=None) -> np.ndarray:
        return self.force_and_tangent(q, v, t, speed, angle)[0]

    def at_operating_point(self, speed: float, static_load: np.ndarray | None = None, transient: bool = False):
        return self

    def frequencies_hz(self, speed: float) -> dict[str, float]:
        return {}

    def at_temperatures(self, temperatures):
        return self

    def heat(self, speed: float, static_load: np.ndarray | None, lubrication: Lubrication,
             lubricant_C: float, displacement: np.ndarray | None = None) -> HeatReport | None:
        return None

    def rating_life_Mrev(self, speed: float, static_load: np.ndarray) -> float | None:
        """The basic rating life under ``static_load`` (what the shaft puts on the bearing) at ``speed`` [rad/s],
        in 10^6 revolutions; None where the family has no rating (linear coefficients, fluid films ...)."""
        return None

    def compiled(self) -> CompiledForce:
        raise NotImplementedError(
            f"bearing {getattr(self, 'name', '?')!r} has no compiled force; integrate with method newmark")

    def outputs(self, q, v, t, speed, angle=None) -> dict[str, tuple[np.ndarray, str]]:
        f = self.force_and_tangent(q, v, t, speed, angle)[0]
        return {"force": (f[: len(self.dof_names)], force_units(self.dof_names))}


def force_units(dof_names: tuple[str, ...]) -> str:
    """Units of a force vector on ``dof_names``: N for translations, N m for rotations."""
    return ", ".join("N m" if d.startswith("theta") else "N" for d in dof_names)


def shaft_angle(speed: float, t: float, angle: float | None) -> float:
    """The shaft angle the contract passes: ``angle`` when given, else speed * t."""
    return speed * t if angle is None else angle


def tangent_by_differences(force: Callable[[np.ndarray, np.ndarray], np.ndarray], q: np.ndarray,
                           v: np.ndarray, dq: float | np.ndarray, dv: float | np.ndarray | None = None
                           ) -> tuple[np.ndarray, np.ndarray]:
    """(K_t, C_t) = (-df/dq, -df/dv) by central differences of ``force(q, v)``.

    For models that give only a force (the contract allows it); ``dq`` and ``dv`` are the
    steps (scalars or one per DOF); ``dv=None`` skips the velocity (C_t = 0).
    """
    q = np.asarray(q, float)
    v = np.asarray(v, float)
    n = q.size
    hq = np.broadcast_to(np.asarray(dq, float), (n,))
    K = np.empty((n, n))
    for k in range(n):
        e = np.zeros(n)
        e[k] = hq[k]
        K[:, k] = -(force(q + e, v) - force(q - e, v)) / (2.0 * hq[k])
    C = np.zeros((n, n))
    if dv is not None:
        hv = np.broadcast_to(np.asarray(dv, float), (n,))
        for k in range(n):
            e = np.zeros(n)
            e[k] = hv[k]
            C[:, k] = -(force(q, v + e) - force(q, v - e)) / (2.0 * hv[k])
    return K, C


class AxiallyShifted(BearingBase):
    """A bearing whose housing seat has moved along z by ``offset_m`` relative to its shaft seat (the
    shaft and the housing growing by different amounts between the bearing sets): the bearing sees the
    rotor's displacement plus that offset.  Everything else is the bearing's own."""

    def __init__(self, bearing, offset_m: float):
        if "z" not in bearing.dof_names:
            raise ValueError(f"bearing {bearing.name!r} has no axial DOF to shift")
        self.inner = bearing
        self.offset_m = float(offset_m)
        self._shift = np.zeros(len(bearing.dof_names) + bearing.internal_mass.size)
        self._shift[bearing.dof_names.index("z")] = self.offset_m

    def __getattr__(self, name):  # name, node, dof_names, internal_mass and the family's own attributes
        if name == "inner" or name.startswith("__"):  # not set yet (a copy or an unpickling in progress)
            raise AttributeError(name)
        return getattr(self.inner, name)

    @property
    def iterative(self) -> bool:
        return self.inner.iterative

    @property
    def speed_independent(self) -> bool:
        return self.inner.speed_independent

    def force_and_tangent(self, q, v, t, speed, angle=None):
        return self.inner.force_and_tangent(np.asarray(q, float) + self._shift, v, t, speed, angle)

    def force(self, q, v, t, speed, angle=None):
        return self.inner.force(np.asarray(q, float) + self._shift, v, t, speed, angle)

    def linearized(self, speed, static_load=None, start=None):
        return self.inner.linearized(speed, static_load, start=self._shifted(start))

    def static_displacement(self, speed, static_load=None, start=None):
        return self.inner.static_displacement(speed, static_load, start=self._shifted(start)) - self._shift

    def _shifted(self, start):
        return None if start is None else np.asarray(start, float) + self._shift[:len(start)]

    def at_operating_point(self, speed, static_load=None, transient=False):
        inner = self.inner.at_operating_point(speed, static_load, transient)
        return self if inner is self.inner else AxiallyShifted(inner, self.offset_m)

    def at_temperatures(self, temperatures):
        return AxiallyShifted(self.inner.at_temperatures(temperatures), self.offset_m)

    def heat(self, speed, static_load, lubrication, lubricant_C, displacement=None):
        q = None if displacement is None else np.asarray(displacement, float) + self._shift[:len(displacement)]
        return self.inner.heat(speed, static_load, lubrication, lubricant_C, q)

    def frequencies_hz(self, speed):
        return self.inner.frequencies_hz(speed)

    def outputs(self, q, v, t, speed, angle=None):
        return self.inner.outputs(np.asarray(q, float) + self._shift, v, t, speed, angle)
