"""What a transient method returns (``Trajectory``), what the engine returns (``TransientResult``) and what the
``transient`` analysis hands back (``TransientStudy``: the engine's result with the linear modes at the static state
and the thermal state it ran at)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .spectrum import Spectrum
from .steadiness import Periodicity, Settling


@dataclass(frozen=True)
class Plan:
    """Time grid of a run: step h, samples every ``steps_per_sample`` steps, ``n_samples`` samples after
    t = 0 (sample 0 is the initial state)."""

    step_s: float
    steps_per_sample: int
    n_samples: int

    @property
    def sample_rate_hz(self) -> float:
        return 1.0 / (self.step_s * self.steps_per_sample)

    @property
    def n_steps(self) -> int:
        return self.n_samples * self.steps_per_sample


@dataclass(frozen=True)
class Trajectory:
    """Sampled states of a run from one method (x and v on every DOF of the system)."""

    time_s: np.ndarray  # [k]
    x: np.ndarray  # [k, N]
    v: np.ndarray  # [k, N]
    poincare_time_s: np.ndarray  # [p] the requested instants reached
    poincare_x: np.ndarray  # [p, N]
    poincare_v: np.ndarray  # [p, N]
    complete: bool
    reason: str
    iterations: np.ndarray = field(default_factory=lambda: np.zeros(0, int))  # Newton iterations per sample


@dataclass(frozen=True)
class PoincareSet:
    """The response sampled once per period of one excitation (revolution, roller pass, ...)."""

    name: str
    frequency_hz: float  # at the start speed
    time_s: np.ndarray
    xy_m: np.ndarray  # [k, 2] at the record node
    v_m_s: np.ndarray  # [k, 2]
    periodicity: Periodicity | None = None  # what the points say (steadiness.poincare_periodicity)


@dataclass(frozen=True)
class TransientResult:
    """One layout for every rotor transient (docs/output-format.md, transient.h5)."""

    method: str
    step_s: float
    sample_rate_hz: float
    time_s: np.ndarray  # [t]
    speed_rpm: np.ndarray  # [t]
    dof_names: tuple[str, ...]  # per node of the rotor
    record_node: int  # 0-based
    displacement_m: np.ndarray  # [t, 2] x, y at the record node
    velocity_m_s: np.ndarray  # [t, 2]
    rotor_displacement: np.ndarray  # [t, n] every rotor DOF (m, rad)
    static_displacement: np.ndarray  # [n] the static equilibrium the run starts from (perturbation excluded)
    bearing_names: tuple[str, ...]
    bearing_dofs: tuple[tuple[str, ...], ...]
    bearing_force_N: tuple[np.ndarray, ...]  # per bearing [t, len(dofs)]: force (moment) on the shaft
    bearing_outputs: tuple[dict, ...]  # per bearing: name -> ([t, ...] array, units)
    frequencies_hz: dict  # characteristic frequencies at the start speed, "<bearing>.<name>" -> Hz
    settle_s: float
    spectrum: Spectrum  # of displacement_m for t >= settle_s
    poincare: tuple[PoincareSet, ...]
    complete: bool
    reason: str
    newton_iterations: np.ndarray
    wall_time_s: float
    settling: Settling | None = None  # has the steady part settled, what its spectrum resolves

    def poincare_set(self, name: str) -> PoincareSet:
        for p in self.poincare:
            if p.name == name:
                return p
        raise KeyError(name)


@dataclass(frozen=True)
class TransientStudy:
    """The ``transient`` analysis's result: the run in time, the linear natural frequencies at the static state it
    starts from (None when they could not be computed) and, on a spindle at its thermal equilibrium, that
    equilibrium's speed (None otherwise)."""

    result: TransientResult
    linearized_hz: np.ndarray | None = None
    thermal_equilibrium_rpm: float | None = None
