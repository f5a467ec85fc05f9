"""The stable depth of cut through a warm-up, at the speed the spindle runs.

At each instant of a warm-up the bearings sit at that instant's temperatures and preload, so the tool-point
FRF, and with it the lobe diagram, drifts as the spindle warms: a pocket found cold may lie on a lobe's
flank an hour later.  At each instant the limit depth at the instant's own speed is solved with the
``chatter:`` section's method and options (the semi-discretization for milling with a fluctuating
directional matrix), on the tool-point model of that instant (the full state space of the rotor on its
bearings at that state, ``tool_point.state_space``): the method and the number of ``spindlesim chatter``, whose
diagram at a speed holds the bearings at that speed's thermal equilibrium; at the end of a step long enough to
settle, the two agree (tests/validation/test_warm_up_chatter.py).  One speed an instant, not the whole diagram:
about 0.3 s an instant on the milling spindle instead of several seconds, the instants shared among the
cores (:func:`~.aside.map_aside`).  An instant at rest (speed 0) cuts
nothing: NaN.  The minimum over every speed stays the steady-state diagram's (``spindlesim chatter``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from ..chatter import stability_lobes
from .aside import map_aside
from .points import OperatingPoints
from .tool_point import point_dofs, state_space

__all__ = ["StableDepth", "method_text", "stable_depth_through"]


@dataclass(frozen=True)
class StableDepth:
    """Per instant: the limit depth of cut [m] at the instant's speed [rpm] and the chatter frequency [Hz] there;
    NaN at rest, where the speed is stable up to the depth cap (``capped``, the cap in ``depth_cap_m``) and at an
    instant whose lobes failed (``failures`` says which and why).  ``method``: how it was solved."""

    depth_m: np.ndarray
    speed_rpm: np.ndarray
    chatter_frequency_hz: np.ndarray
    capped: np.ndarray
    depth_cap_m: np.ndarray
    method: str
    failures: tuple[str, ...] = field(default=())


_NAMES = {"semi_discretization": "semi-discretization", "zero_order": "zero order", "oriented_frf": "oriented FRF"}


def method_text(process, method: str) -> str:
    """How the depths were solved, for the file and the figure."""
    name = process.method_for(method)
    return (f"{_NAMES.get(name, name)} (the chatter section's method) at the instant's own speed, with the "
            "tool-point FRF of that instant")


def stable_depth_through(points: OperatingPoints, states, process, method: str = "auto",
                         options: Mapping | None = None, node: int | None = None) -> StableDepth:
    """The module note's depth at each of ``states`` (``spindle_thermal.ThermalState`` instants) with ``method`` and
    its ``options`` (the chatter section's); instants that share one operating state (the two sides of a speed
    step) are solved once.  An instant whose lobes fail (a linear-algebra or arithmetic failure) is NaN and named
    in ``failures``; the others are kept."""
    opts = dict(options or {}) | {"stability_map": False}
    _, tip = point_dofs(points.rotor, node)
    unique: dict[int, object] = {}  # the instants to solve, one per operating state in motion
    for ts in states:
        if float(ts.speed_rpm) > 0.0:
            unique.setdefault(id(ts.operating), ts)

    def solve(ts) -> tuple[tuple[float, float, bool, float], str]:
        rpm = float(ts.speed_rpm)
        sysm = points.system(ts.operating)
        try:
            dg = stability_lobes(process, state_space(sysm, np.eye(sysm.size)[:, tip]), [rpm], method, **opts)
        except (np.linalg.LinAlgError, ArithmeticError, ValueError) as exc:
            when = "" if ts.time_s is None else f" at {ts.time_s / 60.0:.1f} min"
            return (np.nan, np.nan, False, np.nan), f"lobes{when} ({rpm:g} rpm) failed: {exc}"
        capped = bool(len(dg.capped) and dg.capped[0])
        return (float(dg.limit_depth_m[0]), float(dg.chatter_frequency_hz[0]), capped, float(dg.depth_cap_m)), ""

    # the instants are independent: shared with a forked child per further core (the same numbers as in turn)
    got = dict(zip(unique, map_aside(solve, unique.values())))
    failures = [why for _, why in got.values() if why]
    rows = [(float(ts.speed_rpm),) + (got[id(ts.operating)][0] if id(ts.operating) in got
                                      else (np.nan, np.nan, False, np.nan)) for ts in states]
    speed = np.array([r[0] for r in rows], float)
    return StableDepth(np.array([r[1] for r in rows], float), speed, np.array([r[2] for r in rows], float),
                       np.array([r[3] for r in rows], bool), np.array([r[4] for r in rows], float),
                       method_text(process, method), tuple(failures))

