"""The one transient engine: any rotor (Timoshenko shaft or rigid journal) with any mix of bearings.

1. Bearings frozen at the deck's operating point (``at_operating_point``: a fluid film's
   thermal-equilibrium viscosity), static equilibrium by Newton on the full nonlinear reactions
   at the start speed (``analysis.operating``): the run starts there, at rest, plus an optional
   released static force (perturbation).
2. Time integration of ``system.RotorSystem`` by the chosen method; like scipy's solve_ivp the
   driver never asks which method it has: every method is ``integrate(system, x0, v0, plan,
   targets, progress, **options) -> Trajectory`` (``METHODS``):
   newmark (implicit, any bearing), rk4 (explicit, compiled bearing forces), or one of scipy's
   adaptive methods (a cross-check).
3. Exact stepping at constant speed: the step divides the primary period (a rolling bearing's
   roller pass, otherwise the revolution) into whole steps, so its Poincare points are grid
   points; the other Poincare sets (revolution, cage, each rolling bearing's roller pass) are
   interpolated between steps.  A run-up samples them at the shaft angles where they fall.
4. Outputs: the record node's (x, y), every rotor DOF, each bearing's ``outputs()`` (its force
   and what it adds), the spectrum of the steady part, the Poincare sets with their periodicity,
   and whether the steady part has settled (``steadiness``).  A run that stops early (interrupt,
   Newton failure, non-finite state) returns what it computed with ``complete=False`` and the
   reason.
"""

from __future__ import annotations

import dataclasses
import functools
import logging
import math
import time
from dataclasses import dataclass

import numpy as np

from ...model.rotor import Rotor
from ..operating import operating_state, system_matrices
from . import explicit, ivp, newmark
from .fixed_step import plan_steps, stability_step_s
from .result import Plan, PoincareSet, TransientResult
from .spectrum import Spectrum, amplitude_spectrum
from .steadiness import LinearModes, assess_settling, linear_modes, orbit_scale, poincare_periodicity
from .system import Excitation, SpeedProfile, assemble_system

log = logging.getLogger(__name__)
RPM = np.pi / 30.0
METHODS = {"newmark": newmark.integrate, "rk4": explicit.integrate,
           **{m: functools.partial(ivp.integrate, method=m) for m in ("RK45", "DOP853", "Radau", "BDF", "LSODA")}}
#: default largest step of each method [s]
NEWMARK_STEP = 5e-5
RK4_STEP = 1e-6
#: most time steps of one run (the deck checks the same bound, deck/limits.MAX_TRANSIENT_STEPS, for the
#: default step; the step a stability limit picks is only known here)
MAX_STEPS = 10_000_000


@dataclass(frozen=True)
class Perturbation:
    """A static force on one rotor DOF held until t = 0 and released."""

    index: int
    force_N: float


@dataclass(frozen=True)
class TransientSettings:
    duration_s: float
    method: str = "newmark"
    step_s: float | None = None  # largest step (newmark 5e-5 s; rk4 min(rk4_step_bound_s, RK4 stability limit))
    rk4_step_bound_s: float = RK4_STEP  # the accuracy bound of rk4's default step
    sample_rate_hz: float | None = None  # newmark: every step; rk4: max(2 kHz, 50 x primary frequency)
    settle_s: float | None = None  # start of the steady part (spectrum, Poincare); default 30 % of the run
    speed_rpm: tuple[float, float] | None = None  # (start, stop) ramp; None: the rotor's speed, constant
    record_node: int | None = None  # 0-based; default the first bearing's node
    excitation: Excitation = Excitation()
    perturbation: Perturbation | None = None
    initial_velocity: tuple[tuple[int, float], ...] = ()  # (DOF index, m/s) given at t = 0: an impact
    rtol: float = 1e-8  # scipy methods
    chunks: int = 40
    tol: float = 1e-10  # Newton (newmark)

    def __post_init__(self) -> None:
        if not self.duration_s > 0:
            raise ValueError("duration must be positive")
        if self.method not in METHODS:
            raise ValueError(f"unknown method {self.method!r}; known: {', '.join(METHODS)}")
        if self.settle_s is not None and not 0 <= self.settle_s < self.duration_s:
            raise ValueError("settle time must lie in [0, duration)")
        if self.step_s is not None and not self.step_s > 0:
            raise ValueError("step must be positive")
        if not self.rk4_step_bound_s > 0:
            raise ValueError("the bound of the RK4 step must be positive")


def _ratios(bearings, speed: float) -> dict[str, float]:
    """Characteristic frequencies as multiples of the shaft speed: "revolution" plus each bearing's."""
    out = {"revolution": 1.0}
    if speed > 0:
        for b in bearings:
            for k, f in b.frequencies_hz(speed).items():
                if f > 0:
                    out[f"{b.name}.{k}"] = 2 * math.pi * f / speed
    return out


def _primary(ratios: dict[str, float]) -> str:
    """The period stepped exactly: the first roller pass, else the revolution."""
    return next((k for k in ratios if k.endswith(".roller_pass")), "revolution")


@dataclass(frozen=True)
class Prepared:
    """Everything a run needs before the time integration (``prepare``)."""

    system: object  # RotorSystem
    operating: object  # OperatingState at the deck speed (bearings frozen there)
    start: object  # OperatingState at the start speed
    x0: np.ndarray
    v0: np.ndarray
    plan: Plan
    ratios: dict
    primary: str
    targets: np.ndarray
    owner: np.ndarray
    settle_s: float


def prepare(rotor: Rotor, settings: TransientSettings) -> Prepared:
    """Static state, initial conditions, system, time grid and Poincare instants of a run."""
    T = settings.duration_s
    deck_speed = rotor.speed_rpm
    start_rpm, stop_rpm = settings.speed_rpm or (deck_speed, deck_speed)
    op = operating_state(rotor, deck_speed, transient=True)  # bearings frozen at the deck's operating point
    if start_rpm == deck_speed:
        st = op
    else:
        st = operating_state(dataclasses.replace(rotor, bearings=op.bearings), start_rpm, shaft=op.shaft, freeze=False)
    profile = SpeedProfile(start_rpm * RPM, stop_rpm * RPM, T)
    system = assemble_system(rotor, op.bearings, op.shaft, st.Q, settings.excitation, profile)
    n = rotor.dofs.size
    x0 = np.concatenate([st.q] + list(st.internal))
    v0 = np.zeros_like(x0)
    if settings.perturbation is not None:
        e = np.zeros(n)
        e[settings.perturbation.index] = settings.perturbation.force_N
        x0[:n] += np.linalg.solve(system_matrices(rotor, state=st).K, e)
    for index, value in settings.initial_velocity:
        v0[index] += value
    ratios = _ratios(op.bearings, deck_speed * RPM)
    primary = _primary(ratios)
    f_primary = ratios[primary] * profile.start_rad_s / (2 * math.pi) if profile.constant else 0.0
    plan = _plan(settings, system, x0, v0, f_primary)
    settle = 0.3 * T if settings.settle_s is None else settings.settle_s
    targets, owner = _poincare_targets(ratios, profile, settle, plan.n_steps * plan.step_s)
    return Prepared(system, op, st, x0, v0, plan, ratios, primary, targets, owner, settle)


def integrate(p: Prepared, settings: TransientSettings, progress=None):
    """The time integration of a prepared run by the method the settings name (a ``Trajectory``)."""
    log.info("transient: %s, h = %.4g s, %d steps, %d samples", settings.method, p.plan.step_s, p.plan.n_steps,
             p.plan.n_samples)
    return METHODS[settings.method](p.system, p.x0, p.v0, p.plan, p.targets, progress=progress, rtol=settings.rtol,
                                    chunks=settings.chunks, tol=settings.tol)


def simulate(rotor: Rotor, settings: TransientSettings, progress=None) -> TransientResult:
    """Run the transient of ``rotor`` (module note)."""
    wall0 = time.perf_counter()
    p = prepare(rotor, settings)
    traj = integrate(p, settings, progress)
    return _result(rotor, settings, p, traj, start_modes(p), time.perf_counter() - wall0)


def record_node(rotor: Rotor, settings: TransientSettings) -> int:
    """The node (0-based) whose x, y are recorded: the settings' record node, else the first bearing's."""
    if settings.record_node is not None:
        return settings.record_node
    return rotor.bearings[0].node if rotor.bearings else 0


def start_modes(p: Prepared) -> LinearModes | None:
    """Modes of the system linearised at the static state the run starts from (the perturbation and
    the initial velocities excluded), at the start speed; None when they cannot be computed."""
    system = p.system
    x = np.concatenate([p.start.q] + list(p.start.internal))
    try:
        _, Kt, Ct, _ = system.bearing_forces(x, np.zeros_like(x), 0.0)
        W = system.profile.start_rad_s
        return linear_modes(system.M, system.stiffness(W) + Kt, system.damping(W) + Ct)
    except (np.linalg.LinAlgError, ValueError, ArithmeticError) as exc:
        log.warning("no linear modes at the start state (settling judged without them): %s", exc)
        return None


def stability_step(system, x0: np.ndarray, v0: np.ndarray) -> float:
    """RK4's stability limit 2 / rho of the system linearised at (x0, v0) (``fixed_step.stability_step_s``)."""
    W = system.profile.start_rad_s
    _, Kt, Ct, _ = system.bearing_forces(x0, v0, 0.0)
    return stability_step_s(system.M, system.stiffness(W) + Kt, system.damping(W) + Ct)


def _plan(settings: TransientSettings, system, x0, v0, f_primary: float) -> Plan:
    h = settings.step_s
    if h is None and settings.method == "rk4":
        h = min(settings.rk4_step_bound_s, stability_step(system, x0, v0))
    elif h is None:
        h = NEWMARK_STEP
    if settings.sample_rate_hz is not None:
        fs = settings.sample_rate_hz
    elif settings.method == "newmark":
        fs = 1.0 / h
    else:
        fs = max(2000.0, 50.0 * f_primary)
    steps = settings.duration_s / h
    if steps > MAX_STEPS:
        raise RuntimeError(f"the run would take {steps:.3g} time steps of {h:.3g} s (the step the stiffest "
                           f"contact allows) for {settings.duration_s:g} s; the limit is {MAX_STEPS:g}: check "
                           "the masses, stiffnesses and damping of the deck (an extreme value makes the step tiny)")
    plan, _ = plan_steps(settings.duration_s, h, fs, f_primary)
    return plan


def _poincare_targets(ratios: dict[str, float], profile: SpeedProfile, settle: float, t_end: float):
    """Sorted instants in [settle, t_end] where r phi(t) = 2 pi k, for each ratio r; and their owner."""
    times, owner = [], []
    if profile.start_rad_s <= 0 and profile.stop_rad_s <= 0:
        return np.zeros(0), np.zeros(0, int)
    phi0, phi1 = profile.angle(settle), profile.angle(t_end)
    for j, r in enumerate(ratios.values()):
        k = np.arange(math.ceil(r * phi0 / (2 * math.pi) - 1e-9), math.floor(r * phi1 / (2 * math.pi) + 1e-9) + 1)
        if k.size > 200_000:
            k = k[-200_000:]
        t = profile.time_at_angle(2 * math.pi * k / r)
        t = t[(t >= settle - 1e-12) & (t <= t_end * (1 + 1e-12))]
        times.append(t)
        owner.append(np.full(t.size, j))
    t = np.concatenate(times) if times else np.zeros(0)
    o = np.concatenate(owner) if owner else np.zeros(0, int)
    order = np.argsort(t, kind="stable")
    return t[order], o[order]


def _result(rotor, settings, p: Prepared, traj, modes: LinearModes | None, wall: float) -> TransientResult:
    system, st, plan, ratios, primary, targets, owner, settle = (p.system, p.start, p.plan, p.ratios, p.primary,
                                                                 p.targets, p.owner, p.settle_s)
    dofs = rotor.dofs
    n = dofs.size
    node = record_node(rotor, settings)
    ix, iy = dofs.index(node, "x"), dofs.index(node, "y")
    X, V, t = traj.x, traj.v, traj.time_s
    disp = np.column_stack([X[:, ix], X[:, iy]]) if len(t) else np.zeros((0, 2))
    vel = np.column_stack([V[:, ix], V[:, iy]]) if len(t) else np.zeros((0, 2))
    speeds = np.array([system.profile.speed(ti) for ti in t]) / RPM
    outputs = []
    for b, gi in zip(system.bearings, system.index):
        rec: dict[str, list] = {}
        units: dict[str, str] = {}
        for k in range(len(t)):
            for name, (val, unit) in b.outputs(X[k, gi], V[k, gi], t[k], system.profile.speed(t[k]),
                                               system.profile.angle(t[k])).items():
                rec.setdefault(name, []).append(np.asarray(val, float))
                units[name] = unit
        outputs.append({name: (np.array(vals), units[name]) for name, vals in rec.items()})
    forces = tuple(o.get("force", (np.zeros((len(t), len(b.dof_names))), ""))[0].reshape(len(t), -1)
                   for o, b in zip(outputs, system.bearings))
    steady = t >= settle - 1e-12
    spec = amplitude_spectrum(disp[steady], plan.sample_rate_hz) if steady.sum() >= 4 else \
        Spectrum(np.zeros(0), np.zeros((0, 2)))
    extent, noise = orbit_scale(disp[steady])
    sets = []
    reached = traj.poincare_time_s
    names = list(ratios)
    for j, name in enumerate(names):
        sel = np.isin(targets[owner == j], reached)
        tj = targets[owner == j][sel]
        rows = np.searchsorted(reached, tj)
        rows = np.minimum(rows, max(len(reached) - 1, 0))
        PX = traj.poincare_x[rows] if len(reached) else np.zeros((0, traj.x.shape[1]))
        PV = traj.poincare_v[rows] if len(reached) else np.zeros((0, traj.x.shape[1]))
        xy = np.column_stack([PX[:, ix], PX[:, iy]]) if len(tj) else np.zeros((0, 2))
        sets.append(PoincareSet(name, ratios[name] * system.profile.start_rad_s / (2 * math.pi), tj, xy,
                                np.column_stack([PV[:, ix], PV[:, iy]]) if len(tj) else np.zeros((0, 2)),
                                poincare_periodicity(xy, extent, noise)))
    sets.sort(key=lambda q: q.name != primary)  # the primary period first
    freqs = {k: r * system.profile.start_rad_s / (2 * math.pi) for k, r in ratios.items()}
    constant = system.profile.constant
    settling = assess_settling(t[steady], disp[steady], plan.sample_rate_hz, spec, settle_s=settle,
                               end_s=float(t[-1]) if len(t) else 0.0, constant_speed=constant,
                               periodic=sets[0].periodicity.periodic if sets and sets[0].time_s.size else None,
                               modes=modes, named_hz=freqs if constant else {})
    log.info("transient: %s", settling.note)
    return TransientResult(
        method=settings.method, step_s=plan.step_s, sample_rate_hz=plan.sample_rate_hz, time_s=t, speed_rpm=speeds,
        dof_names=dofs.names, record_node=node, displacement_m=disp, velocity_m_s=vel, rotor_displacement=X[:, :n],
        static_displacement=st.q, bearing_names=tuple(b.name for b in system.bearings),
        bearing_dofs=tuple(tuple(b.dof_names) for b in system.bearings), bearing_force_N=forces,
        bearing_outputs=tuple(outputs), frequencies_hz=freqs, settle_s=settle, spectrum=spec, poincare=tuple(sets),
        complete=traj.complete, reason=traj.reason, newton_iterations=traj.iterations, wall_time_s=wall,
        settling=settling)
