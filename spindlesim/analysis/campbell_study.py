"""What ``spindlesim campbell`` computes, as one frozen result: the diagram with the bearings at every speed's
state, and its comparisons: the bearings frozen at one speed's state (their speed effects), and, for a spindle
solved at its thermal equilibrium, the cold spindle with the bearings' radial stiffness at both.

A Ctrl-C in a comparison keeps the diagram (marked interrupted); a failure at a speed ends the diagram there (the
speeds before it kept, ``incomplete_reason``), as :func:`~.campbell.solve_campbell` does.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np

from .campbell import solve_campbell
from .points import OperatingPoints
from .results import CampbellResult


@dataclass(frozen=True)
class CampbellStudy:
    """The diagram (``hot``: at the operating points, the thermal equilibrium where the points have one), the
    frozen comparison (``frozen``, its speed ``frozen_rpm``), the cold spindle and the bearings' radial stiffness
    at both (``cold``, ``stiffness``: speed_rpm, bearing names, "thermal" and "cold" [speed, bearing] N/m),
    what the thermal comparison is ("at thermal equilibrium" or an instant of a warm-up), and the spindle's
    operating speed (``operating_rpm``; None without a positive one), which the diagram is read against."""

    hot: CampbellResult
    frozen: CampbellResult | None = None
    frozen_rpm: float | None = None
    cold: CampbellResult | None = None
    stiffness: dict | None = None
    thermal_label: str = ""
    operating_rpm: float | None = None

    @property
    def incomplete_reason(self) -> str:
        return self.hot.incomplete_reason

    @property
    def interrupted(self) -> bool:
        return self.hot.interrupted

    # ---- named results --------------------------------------------------------------------------------
    @property
    def critical_speeds_rpm(self) -> np.ndarray:
        return self.hot.critical_speeds_rpm

    @property
    def first_natural_frequency_hz(self) -> float:
        """The lowest tracked frequency at the diagram's first speed."""
        f = self.hot.frequency_hz
        return float(np.nanmin(f[0])) if f.size and np.isfinite(f[0]).any() else float("nan")


def bearing_stiffness(hot: OperatingPoints, cold: OperatingPoints, speeds) -> dict:
    """Each bearing's radial stiffness K_xx [N/m] at every speed, at its thermal equilibrium ("thermal") and
    as assembled ("cold"), from the operating points' states (solved already by the two diagrams)."""
    names = [b.name for b in hot.rotor.bearings]

    def table(points):
        return np.array([[kb[0, 0] for kb, _ in points.state(s).coefficients] for s in speeds])

    return {"speed_rpm": np.asarray(speeds, float), "bearing": names, "thermal": table(hot), "cold": table(cold)}


def campbell_study(points: OperatingPoints, speeds_rpm: Sequence[float], n_modes: int = 8,
                   frozen_rpm: float | None = None, orders=(1.0,), operating: tuple[float, float] | None = None,
                   exact: bool = False, progress: Callable[[int, int], None] | None = None,
                   operating_rpm: float | None = None) -> CampbellStudy:
    """The module note's diagram and comparisons; ``orders`` the excitation orders checked for crossings,
    ``operating`` the (minimum operating, maximum continuous) speed of API 684's margins, ``operating_rpm`` the
    spindle's operating speed (kept in the study; not positive: none)."""
    opts = dict(n_modes=n_modes, orders=orders, operating=operating, exact=exact)
    res = solve_campbell(points, np.asarray(speeds_rpm, float), progress=progress, **opts)
    frozen = cold = stiffness = None
    label = ""
    try:  # the comparisons: a Ctrl-C in them keeps the diagram solved, marked interrupted
        if frozen_rpm is not None and not res.interrupted:  # the same assembly, states and basis
            frozen = solve_campbell(points, res.speed_rpm, frozen_rpm=frozen_rpm, **opts)
        if points.thermal is not None and len(res.speed_rpm) and not res.interrupted:
            # the bearings as assembled at the same speeds: what the temperatures change
            cold_points = OperatingPoints(points.rotor, shaft=points.shaft)
            cold = solve_campbell(cold_points, res.speed_rpm, **opts)
            if cold.interrupted:
                raise KeyboardInterrupt
            stiffness = bearing_stiffness(points, cold_points, res.speed_rpm)
            m = points.thermal.model
            label = (f"at the temperatures of the warm-up at {m.analyses_at_s / 60.0:g} min"
                     if m.analyses == "warm_up" else "at thermal equilibrium")
    except KeyboardInterrupt:
        frozen = frozen if frozen is not None and not frozen.interrupted else None
        cold = stiffness = None
        res = dataclasses.replace(res, interrupted=True, incomplete_reason=(
            "interrupted by the user in the comparison diagrams (frozen bearings, cold spindle): the diagram "
            "itself is complete, the comparisons not written"))
    op = float(operating_rpm) if operating_rpm is not None and operating_rpm > 0 else None
    return CampbellStudy(res, frozen, frozen_rpm, cold, stiffness, label, op)
