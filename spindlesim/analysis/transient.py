"""Transient integration of a rotor in a rolling bearing (issue 4).

Two integrators:

- ``method="RK4"`` (default): classical fixed-step RK4 with exact stepping
  (``fixed_step``): the output grid and the Poincare instants
  t_k = k / (N f_cage) (once per varying-compliance period, seed 000 sec. 5)
  fall on steps.  A system's compiled loop (``compiled_stepper()``) is used
  when it has one.  The step is settings.step_s, else the system's
  ``default_step_s()``, else 1 us.
- any ``scipy.integrate.solve_ivp`` method (DOP853, RK45, Radau, ...) with
  dense output on the system's numpy ``rhs``: adaptive, and an independent
  check of the compiled kernels.

Both integrate in chunks and keep only the sampled response, so memory stays
bounded on long runs.  A run that is interrupted (KeyboardInterrupt, between
chunks), meets a non-finite state or a step-size collapse keeps every chunk
already finished and is returned with ``complete=False`` and the reason; the
caller still writes it.  Progress is reported through a callback (the CLI
prints it on stderr) and the module logger; nothing here prints.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass
from typing import Callable, Protocol

import numpy as np
from scipy.integrate import solve_ivp

from .fixed_step import Stepper, plan_steps, python_rk4
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
    output grid (default 50 N f_cage, at least 2 kHz; with RK4 rounded to a
    whole number of samples per roller pass).  method: "RK4" (fixed step
    step_s, an upper bound) or a solve_ivp method.  rtol / atol (solve_ivp
    only): relative and absolute tolerance; atol defaults to rtol times the
    system's ``state_scale()`` (typical magnitude of each state) if it has one.
    """

    duration_s: float
    settle_s: float | None = None
    sample_rate_hz: float | None = None
    method: str = "RK4"
    step_s: float | None = None
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
        if self.step_s is not None and not self.step_s > 0:
            raise ValueError("step must be positive")


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
    method: str = ""
    step_s: float = float("nan")  # fixed step (RK4); NaN for adaptive methods


def _default_rate(system: TransientSystem) -> float:
    return max(2000.0, 50.0 * system.roller_pass_frequency_hz)


def run_transient(system: TransientSystem, settings: TransientSettings,
                  progress: Callable[[float, float], None] | None = None) -> TransientResult:
    """Integrate ``system`` over settings.duration_s and sample its response.

    ``progress(fraction, t_s)`` is called after every chunk.
    """
    if settings.method.upper() == "RK4":
        return _run_fixed_step(system, settings, progress)
    return _run_solve_ivp(system, settings, progress)


def _initial_state(system: TransientSystem, settings: TransientSettings) -> np.ndarray:
    if settings.initial_state is not None:
        return np.array(settings.initial_state, dtype=float)
    return np.array(system.initial_state(), dtype=float)


def _stepper(system: TransientSystem) -> Stepper:
    compiled = getattr(system, "compiled_stepper", None)
    return compiled() if callable(compiled) else python_rk4(system.rhs)


def _run_fixed_step(system: TransientSystem, settings: TransientSettings,
                    progress: Callable[[float, float], None] | None) -> TransientResult:
    T = settings.duration_s
    settle = 0.4 * T if settings.settle_s is None else settings.settle_s
    frp = system.roller_pass_frequency_hz
    y = _initial_state(system, settings)
    h_max = settings.step_s
    if h_max is None:
        default = getattr(system, "default_step_s", None)
        h_max = default(y) if callable(default) else 1e-6
    plan = plan_steps(T, h_max, settings.sample_rate_hz or _default_rate(system), frp)
    stepper = _stepper(system)
    fs, h, s = plan.sample_rate_hz, plan.step_s, plan.steps_per_sample
    samples = np.empty((plan.n_samples + 1, y.size))
    samples[0] = y
    bounds = np.linspace(0, plan.n_samples, max(1, min(settings.chunks, plan.n_samples)) + 1).round().astype(int)
    complete, reason = True, ""
    done = 0  # samples after t = 0 computed
    wall0 = time.perf_counter()
    log.debug("transient %s: RK4, h = %.4g s, %d steps per sample, fs = %.6g Hz", system.model_name, h, s, fs)
    for a, b in zip(bounds[:-1], bounds[1:]):
        if b <= a:
            continue
        try:
            rows, status = stepper(y, a * s * h, h, (b - a) * s, s, samples[a + 1:b + 1])
        except KeyboardInterrupt:
            complete, reason = False, f"interrupted by user at t = {done / fs:.6g} s"
            break
        except (FloatingPointError, ValueError, ZeroDivisionError) as exc:
            complete, reason = False, f"integration failed at t = {done / fs:.6g} s: {exc}"
            break
        if status != 0:
            good = rows - 1
            done = a + good
            complete, reason = False, (f"non-finite state between t = {done / fs:.6g} and {(done + 1) / fs:.6g} s "
                                       f"(RK4, h = {h:.4g} s; a smaller integrator.step_us may help)")
            break
        done = b
        if progress is not None:
            progress(b / plan.n_samples, b / fs)
        log.debug("transient %s: t = %.4g / %.4g s", system.model_name, b / fs, T)
    n = done + 1
    t_out = np.arange(n) / fs
    Y = samples[:n]
    if frp > 0:
        M = plan.samples_per_pass
        first = int(np.ceil(settle * fs / M - 1e-9)) * M
        idx = np.arange(first, n, M)
    else:
        idx = np.zeros(0, dtype=int)
    return _result(system, settings, settle, fs, t_out, Y, t_out[idx], Y[idx], complete, reason,
                   t_reached=done / fs, wall=time.perf_counter() - wall0, nfev=4 * done * s, method="RK4", step=h)


def _run_solve_ivp(system: TransientSystem, settings: TransientSettings,
                   progress: Callable[[float, float], None] | None) -> TransientResult:
    T = settings.duration_s
    settle = 0.4 * T if settings.settle_s is None else settings.settle_s
    fs = settings.sample_rate_hz or _default_rate(system)
    y0 = _initial_state(system, settings)
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
    pt = np.concatenate(pts) if pts else np.zeros(0)
    PY = np.concatenate(pys) if pys else np.zeros((0, system.n_state))
    return _result(system, settings, settle, fs, t_out, Y, pt, PY, complete, reason, t_reached,
                   time.perf_counter() - wall0, nfev, settings.method, float("nan"))


def _result(system: TransientSystem, settings: TransientSettings, settle: float, fs: float, t_out: np.ndarray,
            Y: np.ndarray, pt: np.ndarray, PY: np.ndarray, complete: bool, reason: str, t_reached: float,
            wall: float, nfev: int, method: str, step: float) -> TransientResult:
    """Derived outputs (forces, race, spectrum of the steady part, Poincare map) of sampled states."""
    disp = system.shaft_displacement(Y) if len(Y) else np.zeros((0, 2))
    forces = system.roller_forces(t_out, Y) if len(Y) else np.zeros((0, system.rollers))
    race = system.race_deflection(t_out, Y) if len(Y) else None
    steady = t_out >= settle - 1e-12
    spec = amplitude_spectrum(disp[steady], fs) if steady.sum() >= 4 else Spectrum(np.zeros(0), np.zeros((0, 2)))
    pxy = system.shaft_displacement(PY) if len(PY) else np.zeros((0, 2))
    pv = _shaft_velocity(system, PY)
    if not complete:
        log.warning("transient %s incomplete: %s", system.model_name, reason)
    return TransientResult(
        model=system.model_name, rollers=system.rollers, cage_frequency_hz=system.cage_frequency_hz,
        roller_pass_frequency_hz=system.roller_pass_frequency_hz, time_s=t_out, displacement_m=disp,
        roller_force_N=forces, race_deflection_m=race, settle_s=settle, sample_rate_hz=fs, spectrum=spec,
        poincare_time_s=pt, poincare_xy_m=pxy, poincare_v_m_s=pv, complete=complete, reason=reason,
        t_reached_s=t_reached, wall_time_s=wall, rhs_evaluations=nfev, method=method, step_s=step)


def _shaft_velocity(system: TransientSystem, PY: np.ndarray) -> np.ndarray:
    fn = getattr(system, "shaft_velocity", None)
    if len(PY) == 0:
        return np.zeros((0, 2))
    if callable(fn):
        return fn(PY)
    return PY[:, 2:4]
