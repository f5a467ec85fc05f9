"""Transient integration of a rotor in a rolling bearing (issue 4).

The time span is integrated in chunks with ``scipy.integrate.solve_ivp`` and
dense output.  From each chunk the response is sampled on a uniform grid (for
the time history and the spectrum) and at the Poincare instants
t_k = k / (N f_cage) (once per varying-compliance period, seed 000 section 5),
then the dense interpolant is dropped, so memory stays bounded on long runs.

A run that is interrupted (KeyboardInterrupt), meets a non-finite state or a
step-size collapse keeps every chunk already finished and is returned with
``complete=False`` and the reason; the caller still writes it.
Progress is reported through a callback (the CLI prints it on stderr) and
the module logger; nothing here prints.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass
from typing import Callable, Protocol

import numpy as np
from scipy.integrate import solve_ivp

from .spectrum import Spectrum, amplitude_spectrum, poincare_times

log = logging.getLogger(__name__)


class TransientSystem(Protocol):
    """What ``run_transient`` needs from a model (rigid_race or flexible_race)."""

    model_name: str

    @property
    def rollers(self) -> int: ...

    @property
    def cage_frequency_hz(self) -> float: ...

    @property
    def roller_pass_frequency_hz(self) -> float: ...

    @property
    def n_state(self) -> int: ...

    def initial_state(self) -> np.ndarray: ...

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray: ...

    def shaft_displacement(self, Y: np.ndarray) -> np.ndarray: ...

    def roller_forces(self, t: np.ndarray, Y: np.ndarray) -> np.ndarray: ...

    def race_deflection(self, t: np.ndarray, Y: np.ndarray) -> np.ndarray | None: ...


@dataclass(frozen=True)
class TransientSettings:
    """Integration settings.

    duration_s: simulated time.  settle_s: start of the steady part used for
    spectrum and Poincare map (default: 40% of the run).  sample_rate_hz:
    output grid (default 50 N f_cage, at least 2 kHz).  rtol / atol: relative
    tolerance and absolute tolerance; atol defaults to rtol times the system's
    ``state_scale()`` (typical magnitude of each state) if it has one.
    """

    duration_s: float
    settle_s: float | None = None
    sample_rate_hz: float | None = None
    method: str = "DOP853"
    rtol: float = 1e-7
    atol: float | np.ndarray | None = None
    max_step_s: float = np.inf
    chunks: int = 40
    initial_state: np.ndarray | None = None

    def __post_init__(self) -> None:
        if not self.duration_s > 0:
            raise ValueError("duration must be positive")
        if self.settle_s is not None and not 0 <= self.settle_s < self.duration_s:
            raise ValueError("settle time must lie in [0, duration)")


@dataclass(frozen=True)
class TransientResult:
    """Response of a transient run (SI units)."""

    model: str
    rollers: int
    cage_frequency_hz: float
    roller_pass_frequency_hz: float
    time_s: np.ndarray  # [t]
    displacement_m: np.ndarray  # [t, 2] shaft centre x, y
    roller_force_N: np.ndarray  # [t, N] contact load per rolling element (outer contact)
    race_deflection_m: np.ndarray | None  # [t, segments] radial deflection of outer race segments
    settle_s: float
    sample_rate_hz: float
    spectrum: Spectrum  # of displacement_m for t >= settle_s
    poincare_time_s: np.ndarray  # [k]
    poincare_xy_m: np.ndarray  # [k, 2]
    poincare_v_m_s: np.ndarray  # [k, 2]
    complete: bool
    reason: str  # "" when complete
    t_reached_s: float
    wall_time_s: float
    rhs_evaluations: int


def _default_rate(system: TransientSystem) -> float:
    return max(2000.0, 50.0 * system.roller_pass_frequency_hz)


def run_transient(system: TransientSystem, settings: TransientSettings,
                  progress: Callable[[float, float], None] | None = None) -> TransientResult:
    """Integrate ``system`` over settings.duration_s and sample its response.

    ``progress(fraction, t_s)`` is called after every chunk.
    """
    T = settings.duration_s
    settle = 0.4 * T if settings.settle_s is None else settings.settle_s
    fs = settings.sample_rate_hz or _default_rate(system)
    y0 = system.initial_state() if settings.initial_state is None else np.asarray(settings.initial_state, float)
    if settings.atol is None:
        scale = getattr(system, "state_scale", None)
        atol = settings.rtol * (scale() if callable(scale) else np.maximum(np.abs(y0), 1e-12))
    else:
        atol = settings.atol
    t_grid = np.arange(0.0, T + 0.5 / fs, 1.0 / fs)
    t_grid = t_grid[t_grid <= T * (1 + 1e-12)]
    frp = system.roller_pass_frequency_hz
    tp = poincare_times(settle, T, 1.0 / frp) if frp > 0 else np.zeros(0)
    edges = np.linspace(0.0, T, max(1, settings.chunks) + 1)

    ts: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    pts: list[np.ndarray] = []
    pys: list[np.ndarray] = []
    complete, reason = True, ""
    t_reached = 0.0
    nfev = 0
    wall0 = time.perf_counter()
    y = y0.copy()
    for i in range(len(edges) - 1):
        ta, tb = edges[i], edges[i + 1]
        try:
            sol = solve_ivp(system.rhs, (ta, tb), y, method=settings.method, rtol=settings.rtol, atol=atol,
                            dense_output=True, max_step=settings.max_step_s)
        except KeyboardInterrupt:
            complete, reason = False, f"interrupted by user at t = {t_reached:.6g} s"
            break
        except (FloatingPointError, ValueError, np.linalg.LinAlgError) as exc:
            complete, reason = False, f"integration failed at t = {t_reached:.6g} s: {exc}"
            break
        nfev += int(sol.nfev)
        if not np.all(np.isfinite(sol.y)):
            complete, reason = False, f"non-finite state in [{ta:.6g}, {tb:.6g}] s"
            break
        if sol.status != 0:
            # the part solved before the collapse is still valid
            t_end = float(sol.t[-1])
            sel = (t_grid >= ta) & (t_grid <= t_end)
            if sel.any():
                ts.append(t_grid[sel]); ys.append(sol.sol(t_grid[sel]).T)
            t_reached = t_end
            complete, reason = False, f"step-size collapse at t = {t_end:.6g} s: {sol.message}"
            break
        last = i == len(edges) - 2
        sel = (t_grid >= ta) & ((t_grid < tb) | last)
        if sel.any():
            ts.append(t_grid[sel]); ys.append(sol.sol(t_grid[sel]).T)
        psel = (tp >= ta) & ((tp < tb) | last)
        if psel.any():
            pts.append(tp[psel]); pys.append(sol.sol(tp[psel]).T)
        y = sol.y[:, -1].copy()
        t_reached = tb
        if progress is not None:
            progress(tb / T, tb)
        log.debug("transient %s: t = %.4g / %.4g s (%d rhs)", system.model_name, tb, T, nfev)

    t_out = np.concatenate(ts) if ts else np.zeros(0)
    Y = np.concatenate(ys) if ys else np.zeros((0, system.n_state))
    disp = system.shaft_displacement(Y) if len(Y) else np.zeros((0, 2))
    forces = system.roller_forces(t_out, Y) if len(Y) else np.zeros((0, system.rollers))
    race = system.race_deflection(t_out, Y) if len(Y) else None
    steady = t_out >= settle
    spec = amplitude_spectrum(disp[steady], fs) if steady.sum() >= 4 else Spectrum(np.zeros(0), np.zeros((0, 2)))
    pt = np.concatenate(pts) if pts else np.zeros(0)
    PY = np.concatenate(pys) if pys else np.zeros((0, system.n_state))
    pxy = system.shaft_displacement(PY) if len(PY) else np.zeros((0, 2))
    pv = _shaft_velocity(system, PY)
    if not complete:
        log.warning("transient %s incomplete: %s", system.model_name, reason)
    return TransientResult(
        model=system.model_name, rollers=system.rollers, cage_frequency_hz=system.cage_frequency_hz,
        roller_pass_frequency_hz=frp, time_s=t_out, displacement_m=disp, roller_force_N=forces,
        race_deflection_m=race, settle_s=settle, sample_rate_hz=fs, spectrum=spec, poincare_time_s=pt,
        poincare_xy_m=pxy, poincare_v_m_s=pv, complete=complete, reason=reason, t_reached_s=t_reached,
        wall_time_s=time.perf_counter() - wall0, rhs_evaluations=nfev)


def _shaft_velocity(system: TransientSystem, PY: np.ndarray) -> np.ndarray:
    fn = getattr(system, "shaft_velocity", None)
    if len(PY) == 0:
        return np.zeros((0, 2))
    if callable(fn):
        return fn(PY)
    return PY[:, 2:4]
