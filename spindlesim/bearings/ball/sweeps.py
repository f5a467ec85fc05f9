"""Sweeps over preload, a load component and speed, and the standalone run of a ``BallSection``.

Each point is a full set equilibrium (:meth:`BallBearing.solve`) at cage angle 0 with the section's
held DOFs; consecutive points start from the previous displacement (the result does not depend on
it).  With ``model: auto`` every ball of every point takes the race control Jones' criterion admits
at its state (:meth:`Solver.solve`).  The run then checks what the states say about themselves: a free inner ring
that tilts more than :data:`TILT_WARN_RAD` (with the state it would have with the tilt held) and
contact ellipses that run over a shoulder; each finding is logged and kept on the run for the file.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field

import numpy as np

from .bearing import BallBearing
from .equilibrium import FREE, Held
from .results import BallState, BallSweep, sweep_from_states

log = logging.getLogger(__name__)

LOAD_NAMES = ("fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm")
RPM = math.pi / 30.0
#: tilt of a free inner ring above which the run warns and reports the state with the tilt held [rad]
#: (about 3.4 minutes of arc: more than a mounted angular-contact ball bearing is meant to see)
TILT_WARN_RAD = 1e-3


#: most solves of one point under model auto (each ball settles in two or three)
MAX_AUTO_SOLVES = 8


@dataclass(frozen=True)
class Solver:
    """How the points of a run are solved: the bearing, the held DOFs, and auto (race control per ball)."""

    bearing: BallBearing
    held: Held = FREE
    auto: bool = False

    @classmethod
    def of(cls, bearing: BallBearing, held: Held = FREE, auto: bool = False) -> "Solver":
        return cls(bearing.with_model("outer_race_control") if auto else bearing, held, auto)

    @property
    def setting(self) -> str:
        return "auto" if self.auto else self.bearing.model

    def with_preload(self, value: float) -> "Solver":
        return Solver(self.bearing.with_preload(value), self.held, self.auto)

    def solve(self, load, speed: float, q0=None) -> BallState:
        """The state at (load, speed).  auto: every ball starts under outer-race control and then takes the race
        Jones' criterion admits at its state (keeping its race where both are admitted), solved again until no
        ball changes; a ball sent back to a race it has left shares the couple (full)."""
        load = np.asarray(load, float)
        st = self.bearing.solve(load, speed, 0.0, self.held, q0)
        if not self.auto or speed == 0.0:
            return st
        codes = st.race_used.copy()
        tried = {1: codes == 1, -1: codes == -1}
        locked = np.zeros(codes.shape, bool)
        for _ in range(MAX_AUTO_SOLVES):
            want = np.where(locked, 0, np.where(st.race_control == 0, codes, st.race_control)).astype(np.int8)
            back = (want != codes) & (want != 0) & np.where(want > 0, tried[1], tried[-1])
            want[back] = 0
            locked |= back
            if np.array_equal(want, codes):
                return st
            tried[1] |= want == 1
            tried[-1] |= want == -1
            codes = want
            st = self.bearing.with_race(codes).solve(load, speed, 0.0, self.held, st.displacement)
        log.warning("bearing %r at %.6g rpm: the race control of the balls did not settle in %d solves under model "
                    "auto; the last state is kept", self.bearing.name, speed / RPM, MAX_AUTO_SOLVES)
        return st

    def chain(self, points) -> list[BallState]:
        """States of (solver, load, speed) triples, each started from the previous displacement."""
        states, q = [], None
        for solver, load, speed in points:
            st = solver.solve(load, float(speed), q)
            q = st.displacement
            states.append(st)
        return states


def _as_solver(b) -> Solver:
    return b if isinstance(b, Solver) else Solver.of(b)


def preload_sweep(bearing, values_si, load, speed_rad_s: float = 0.0) -> BallSweep:
    """Preload values in SI (axial_m for a position preload, axial_N for a spring preload); ``bearing``:
    a :class:`BallBearing` or a :class:`Solver`."""
    s = _as_solver(bearing)
    values_si = np.asarray(values_si, float)
    kind = s.bearing.preload.kind
    if kind == "position":
        name, shown = "preload_axial_um", values_si * 1e6
    elif kind == "spring":
        name, shown = "preload_axial_N", values_si
    else:
        raise ValueError("the bearing has no preload to sweep")
    states = s.chain((s.with_preload(v), load, speed_rad_s) for v in values_si)
    return sweep_from_states(name, shown, states, f"{_load_label(load, s.held)}, {speed_rad_s / RPM:.6g} rpm")


def load_sweep(bearing, component: int, values, load, speed_rad_s: float = 0.0) -> BallSweep:
    """One load component (0..4: Fx, Fy, Fz [N], Mx, My [N m]) over ``values``, the others from ``load``."""
    s = _as_solver(bearing)
    base = np.asarray(load, float)

    def point(v):
        L = base.copy()
        L[component] = v
        return s, L, speed_rad_s

    states = s.chain(point(float(v)) for v in values)
    return sweep_from_states(LOAD_NAMES[component], values, states,
                             f"{s.bearing.preload.label()}, {speed_rad_s / RPM:.6g} rpm")


def speed_sweep(bearing, speeds_rad_s, load) -> BallSweep:
    """Shaft speeds [rad/s]; the sweep's values are in rpm."""
    s = _as_solver(bearing)
    speeds = np.asarray(speeds_rad_s, float)
    states = s.chain((s, load, w) for w in speeds)
    return sweep_from_states("speed_rpm", speeds / RPM, states,
                             f"{s.bearing.preload.label()}, {_load_label(load, s.held)}")


def _load_label(load, held: Held = FREE) -> str:
    L = np.asarray(load, float)
    parts = [f"{n.split('_')[0].capitalize()} {v:.6g} {n.split('_')[1].replace('Nm', 'N m')}"
             for n, v in zip(LOAD_NAMES, L) if v != 0.0]
    text = "no external load" if not parts else ", ".join(parts)
    return text if not held.any else f"{text} ({held.label()})"


@dataclass(frozen=True)
class TiltCheck:
    """A free inner ring that tilts more than TILT_WARN_RAD, and its state with the tilt held at 0."""

    tilt_rad: float
    held_state: BallState
    message: str


@dataclass(frozen=True)
class BallRun:
    """What ``spindlesim bearing`` computes for a ``type: ball`` section."""

    bearing: BallBearing
    load: np.ndarray                 # (5,) the section's load (without holding loads)
    speed_rad_s: float
    state: BallState                 # at the section's load and speed
    sweeps: dict[str, BallSweep] = field(default_factory=dict)  # "preload", "load", "speed"
    held: Held = FREE
    model_setting: str = "outer_race_control"   # the deck's model (auto included)
    tilt_check: TiltCheck | None = None
    truncation: tuple[str, ...] = ()  # one message per state or sweep with truncated contacts

    def title(self) -> str:
        return operating_label(self.bearing, self.load, self.speed_rad_s, self.held)


def operating_label(bearing: BallBearing, load, speed_rad_s: float, held: Held = FREE) -> str:
    g = bearing.geometry
    kind = g.arrangement if g.arrangement != "single" else "single row"
    return (f"{bearing.name}: {kind}, {g.balls} x {g.ball_diameter_m * 1e3:.4g} mm balls, "
            f"{math.degrees(g.contact_angle_rad):.3g} deg; {bearing.preload.label()}; {_load_label(load, held)}; "
            f"{speed_rad_s / RPM:.6g} rpm")


def tilt_check(solver: Solver, state: BallState, load: np.ndarray, speed: float) -> TiltCheck | None:
    """The state with the tilt held at 0 when the free inner ring tilts more than TILT_WARN_RAD under a load
    without moments (with moments in the load the tilt is what they ask for)."""
    if solver.held.mask[3] or solver.held.mask[4] or load[3] != 0.0 or load[4] != 0.0:
        return None
    tilt = math.hypot(state.displacement[3], state.displacement[4])
    if not tilt > TILT_WARN_RAD:
        return None
    mask = tuple(solver.held.mask[:3]) + (True, True)
    values = tuple(solver.held.values[:3]) + (0.0, 0.0)
    held = Solver(solver.bearing, Held(mask, values), solver.auto)
    st = held.solve(load, speed, state.displacement)
    name = solver.bearing.name
    d, h = state.displacement, st.displacement
    msg = (f"bearing {name!r}: the free inner ring tilts {tilt * 1e3:.3g} mrad under {_load_label(load)} at "
           f"{speed / RPM:.6g} rpm (radial deflection {math.hypot(d[0], d[1]) * 1e6:.4g} um); on a shaft that holds "
           f"the tilt (held: {{theta_x_mrad: 0, theta_y_mrad: 0}}) it deflects {math.hypot(h[0], h[1]) * 1e6:.4g} um "
           f"radially and {h[2] * 1e6:.4g} um axially, and the shaft carries a moment of "
           f"{math.hypot(st.holding_load[3], st.holding_load[4]):.4g} N m")
    return TiltCheck(tilt, st, msg)


def _worst_contact(rec, i, shoulders_deg) -> tuple[int, str] | None:
    """(count, text) of the truncated contacts of a state (i None) or of point i of a sweep, or None."""
    parts = []
    for race, sh in zip(("inner", "outer"), shoulders_deg):
        cut = getattr(rec, f"truncated_{race}")
        edge = getattr(rec, f"edge_angle_{race}_deg")
        alpha = getattr(rec, f"contact_angle_{race}_deg")
        if i is not None:
            cut, edge, alpha = cut[i], edge[i], alpha[i]
        if np.any(cut):
            over = np.where(cut, edge - sh, -np.inf)
            k, j = np.unravel_index(int(np.argmax(over)), over.shape)
            parts.append((over[k, j], int(np.sum(cut)), race, k, j, edge[k, j], sh, alpha[k, j]))
    if not parts:
        return None
    _, _, race, k, j, edge, sh, alpha = max(parts)
    return sum(p[1] for p in parts), (
        f"the {race} contact of ball {j + 1} of row {k + 1} (contact angle {alpha:.3g} deg) reaches {edge:.3g} deg "
        f"with its ellipse, over the shoulder at {sh:.3g} deg")


def truncation_message(name: str, state: BallState, where: str) -> str | None:
    """The truncated contacts of a state (count and the worst), or None."""
    found = _worst_contact(state, None, (state.shoulder_angle_inner_deg, state.shoulder_angle_outer_deg))
    if found is None:
        return None
    return (f"bearing {name!r}, {where}: contact ellipse truncated at the land: {found[0]} contact(s) run over the "
            f"shoulder, the worst {found[1]} (edge stress: the pressure there exceeds Hertz's)")


def sweep_truncation_message(bearing: BallBearing, key: str, sw: BallSweep) -> str | None:
    """The first point of a sweep with truncated contacts, and how many points have them, or None."""
    n = sw.values.size
    hits = [i for i in range(n) if np.any(sw.truncated_inner[i]) or np.any(sw.truncated_outer[i])]
    if not hits:
        return None
    sh = tuple(math.degrees(a) for a in (bearing.shoulders.inner_angle_rad, bearing.shoulders.outer_angle_rad))
    count, worst = _worst_contact(sw, hits[0], sh)
    unit = {"speed_rpm": "rpm", "preload_axial_um": "um", "preload_axial_N": "N", "mx_Nm": "N m",
            "my_Nm": "N m"}.get(sw.name, "N")
    return (f"bearing {bearing.name!r}, {key} sweep: contact ellipse truncated at the land at {len(hits)} of {n} "
            f"points, from {sw.name.rsplit('_', 1)[0]} {sw.values[hits[0]]:.6g} {unit} ({count} contact(s) there, "
            f"the worst {worst})")


def run(section) -> BallRun:
    """Solve a validated :class:`~.section.BallSection`: the state at its load and speed, and its sweeps."""
    from .section import build, preload_unit_to_si

    b = build(section)
    held = section.held.held()
    solver = Solver.of(b, held, section.model == "auto")
    load = np.array(section.load.vector(), float)
    speed = section.speed_rpm * RPM
    sweeps: dict[str, BallSweep] = {}
    sw = section.sweeps
    if sw.preload is not None:
        vals = np.linspace(sw.preload.start, sw.preload.stop, sw.preload.count)
        sweeps["preload"] = preload_sweep(solver, [preload_unit_to_si(section, v) for v in vals], load, speed)
    if sw.load is not None:
        vals = np.linspace(sw.load.start, sw.load.stop, sw.load.count)
        sweeps["load"] = load_sweep(solver, LOAD_NAMES.index(sw.load.component), vals, load, speed)
    if sw.speed_rpm is not None:
        vals = np.linspace(sw.speed_rpm.start, sw.speed_rpm.stop, sw.speed_rpm.count)
        sweeps["speed"] = speed_sweep(solver, vals * RPM, load)
    state = solver.solve(load, speed)
    tc = tilt_check(solver, state, load, speed)
    if tc is not None:
        log.warning("%s", tc.message)
    found = [truncation_message(b.name, state, f"{_load_label(load, held)}, {speed / RPM:.6g} rpm")]
    found += [sweep_truncation_message(b, key, sweeps[key]) for key in sweeps]
    truncation = tuple(m for m in found if m)
    for m in truncation:
        log.warning("%s", m)
    return BallRun(bearing=b, load=load, speed_rad_s=speed, state=state, sweeps=sweeps, held=held,
                   model_setting=solver.setting, tilt_check=tc, truncation=truncation)
