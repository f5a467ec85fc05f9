"""The minimum stable depth of cut through a warm-up.

At each instant of a warm-up the bearings sit at that instant's temperatures and preload, so the tool-point
FRF, and with it the lobe diagram, drifts as the spindle warms.  Each instant's tool-point model (the full
state space of the rotor on its bearings at that state, ``tool_point.state_space``) gives the zero-order
(Altintas-Budak) lobes over the ``chatter:`` section's speeds, and their minimum is the depth that instant
allows at any of those speeds.  The bearings are held at the instant's own state for every speed of the
diagram (the spindle's temperatures change in minutes, a speed is changed in seconds).

Zero order is the trend's method, chosen for its cost (about 0.3 s an instant on the milling spindle against
several seconds a speed for the semi-discretization); it can over-promise a lobe's depth at low radial
immersion, but the minimum of the envelope is close to the semi-discretization's where one tooth or more is
in the cut (milling spindle: 0.744 mm against 0.741 mm, docs/validation.md).  The figure and thermal.h5 say
so; `spindlesim chatter` on the same deck gives the full diagram at the steady state.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..chatter import zero_order_lobes
from .points import OperatingPoints
from .tool_point import point_dofs, state_space

__all__ = ["MinimumDepth", "minimum_depth_through"]

METHOD = "zero order (Altintas-Budak), the FRF of each instant at every speed"


@dataclass(frozen=True)
class MinimumDepth:
    """Per instant: the smallest limit depth [m] over the speeds, the speed [rpm] and chatter frequency [Hz]
    where it falls (NaN at an instant whose lobes failed; ``failures`` says which and why)."""

    depth_m: np.ndarray
    speed_rpm: np.ndarray
    chatter_frequency_hz: np.ndarray
    method: str = METHOD
    failures: tuple[str, ...] = ()


def minimum_depth_through(points: OperatingPoints, states, process, speeds_rpm,
                          node: int | None = None) -> MinimumDepth:
    """The module note's minimum depth at each of ``states`` (``spindle_thermal.ThermalState`` instants);
    instants that share one operating state (the two sides of a speed step) are solved once.  An instant whose
    lobes fail (a linear-algebra or arithmetic failure) is NaN and named in ``failures``; the others are kept."""
    speeds = np.asarray(speeds_rpm, float)
    _, tip = point_dofs(points.rotor, node)
    done: dict[int, tuple[float, float, float]] = {}
    rows, failures = [], []
    for ts in states:
        key = id(ts.operating)
        if key not in done:
            sysm = points.system(ts.operating)
            try:
                diagram = zero_order_lobes(process, state_space(sysm, np.eye(sysm.size)[:, tip]), speeds)
            except (np.linalg.LinAlgError, ArithmeticError, ValueError) as exc:
                when = "" if ts.time_s is None else f" at {ts.time_s / 60.0:.1f} min"
                failures.append(f"lobes{when} ({ts.speed_rpm:g} rpm) failed: {exc}")
                done[key] = (np.nan, np.nan, np.nan)
                rows.append(done[key])
                continue
            lim = diagram.limit_depth_m
            if np.isfinite(lim).any():
                i = int(np.nanargmin(lim))
                done[key] = (float(lim[i]), float(speeds[i]), float(diagram.chatter_frequency_hz[i]))
            else:
                done[key] = (np.nan, np.nan, np.nan)
        rows.append(done[key])
    a = np.array(rows, float).reshape(len(rows), 3)
    return MinimumDepth(a[:, 0], a[:, 1], a[:, 2], failures=tuple(failures))
