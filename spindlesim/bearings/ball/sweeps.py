"""Sweeps over preload, a load component and speed, and the standalone run of a ``BallSection``.

Each point is a full set equilibrium (:meth:`BallBearing.state`) at cage angle 0; consecutive
points start from the previous displacement (the result does not depend on it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .bearing import BallBearing
from .results import BallState, BallSweep, sweep_from_states

LOAD_NAMES = ("fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm")
RPM = math.pi / 30.0


def _solve_chain(runs) -> list[BallState]:
    """States of (bearing, load, speed) triples, each Newton started from the previous displacement."""
    states, q = [], None
    for b, load, speed in runs:
        q, ev, its = b._equilibrium(np.asarray(load, float), float(speed), 0.0, q)
        states.append(b._state(q, ev, float(speed), 0.0, its, load))
    return states


def preload_sweep(bearing: BallBearing, values_si, load, speed_rad_s: float = 0.0) -> BallSweep:
    """Preload values in SI (axial_m for a position preload, axial_N for a spring preload)."""
    values_si = np.asarray(values_si, float)
    if bearing.preload.kind == "position":
        name, shown = "preload_axial_um", values_si * 1e6
    elif bearing.preload.kind == "spring":
        name, shown = "preload_axial_N", values_si
    else:
        raise ValueError("the bearing has no preload to sweep")
    states = _solve_chain((bearing.with_preload(v), load, speed_rad_s) for v in values_si)
    return sweep_from_states(name, shown, states, f"{_load_label(load)}, {speed_rad_s / RPM:.6g} rpm")


def load_sweep(bearing: BallBearing, component: int, values, load, speed_rad_s: float = 0.0) -> BallSweep:
    """One load component (0..4: Fx, Fy, Fz [N], Mx, My [N m]) over ``values``, the others from ``load``."""
    base = np.asarray(load, float)

    def run(v):
        L = base.copy()
        L[component] = v
        return bearing, L, speed_rad_s

    states = _solve_chain(run(float(v)) for v in values)
    return sweep_from_states(LOAD_NAMES[component], values, states,
                             f"{bearing.preload.label()}, {speed_rad_s / RPM:.6g} rpm")


def speed_sweep(bearing: BallBearing, speeds_rad_s, load) -> BallSweep:
    """Shaft speeds [rad/s]; the sweep's values are in rpm."""
    speeds = np.asarray(speeds_rad_s, float)
    states = _solve_chain((bearing, load, w) for w in speeds)
    return sweep_from_states("speed_rpm", speeds / RPM, states, f"{bearing.preload.label()}, {_load_label(load)}")


def _load_label(load) -> str:
    L = np.asarray(load, float)
    parts = [f"{n.split('_')[0].capitalize()} {v:.4g} {n.split('_')[1].replace('Nm', 'N m')}"
             for n, v in zip(LOAD_NAMES, L) if v != 0.0]
    return "no external load" if not parts else ", ".join(parts)


@dataclass(frozen=True)
class BallRun:
    """What ``spindlesim bearing`` computes for a ``type: ball`` section."""

    bearing: BallBearing
    load: np.ndarray                 # (5,)
    speed_rad_s: float
    state: BallState                 # at the section's load and speed
    sweeps: dict[str, BallSweep] = field(default_factory=dict)  # "preload", "load", "speed"

    def title(self) -> str:
        return operating_label(self.bearing, self.load, self.speed_rad_s)


def operating_label(bearing: BallBearing, load, speed_rad_s: float) -> str:
    g = bearing.geometry
    kind = g.arrangement if g.arrangement != "single" else "single row"
    return (f"{bearing.name}: {kind}, {g.balls} x {g.ball_diameter_m * 1e3:.4g} mm balls, "
            f"{math.degrees(g.contact_angle_rad):.3g} deg; {bearing.preload.label()}; {_load_label(load)}; "
            f"{speed_rad_s / RPM:.6g} rpm")


def run(section) -> BallRun:
    """Solve a validated :class:`~.section.BallSection`: the state at its load and speed, and its sweeps."""
    from .section import build, preload_unit_to_si

    b = build(section)
    load = np.array(section.load.vector(), float)
    speed = section.speed_rpm * RPM
    sweeps: dict[str, BallSweep] = {}
    sw = section.sweeps
    if sw.preload is not None:
        vals = np.linspace(sw.preload.start, sw.preload.stop, sw.preload.count)
        sweeps["preload"] = preload_sweep(b, [preload_unit_to_si(section, v) for v in vals], load, speed)
    if sw.load is not None:
        vals = np.linspace(sw.load.start, sw.load.stop, sw.load.count)
        sweeps["load"] = load_sweep(b, LOAD_NAMES.index(sw.load.component), vals, load, speed)
    if sw.speed_rpm is not None:
        vals = np.linspace(sw.speed_rpm.start, sw.speed_rpm.stop, sw.speed_rpm.count)
        sweeps["speed"] = speed_sweep(b, vals * RPM, load)
    return BallRun(bearing=b, load=load, speed_rad_s=speed, state=b.state(load, speed), sweeps=sweeps)
