"""What ``spindlesim bearing`` computes for a ``type: ball`` section, as one frozen result (:class:`BallStudy`):
the run at the section's load and speed with its sweeps and checks (:class:`~.sweeps.BallRun`), and what the
deck's temperatures, fits and speed make of the bearing (:class:`AtTemperature`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from .sweeps import BallRun


@dataclass(frozen=True)
class AtTemperature:
    """What the deck's temperatures, fits and speed made of the bearing: its growth
    at rest (clearance, groove offsets, fits), the radial growth of the inner ring from speed, each row's
    groove-centre offset, each row's thrust without external load (None: a spring preload, which sets it
    whatever the growth), the fits at speed, and the deck's temperatures [degC] by part."""

    growth: Any
    speed_growth_m: float
    row_offsets_m: np.ndarray
    preload_N: np.ndarray | None
    inner_fit: Any
    outer_fit: Any
    temperatures_C: dict[str, float]

    @property
    def operating_clearance_m(self) -> float:
        """Diametral clearance at the deck's temperatures, fits and speed (< 0: interference)."""
        return float(np.array(self.growth.clearance_m - 2.0 * self.speed_growth_m))

    @property
    def clearance_change_m(self) -> float:
        """The operating clearance minus the clearance as made (the deck's value)."""
        return float(np.array(self.growth.clearance_change_m - 2.0 * self.speed_growth_m))

    def fits(self) -> list[tuple[str, Any]]:
        """("inner" / "outer", fit) of the fits the deck gives."""
        return [(side, fit) for side, fit in (("inner", self.inner_fit), ("outer", self.outer_fit)) if fit is not None]


@dataclass(frozen=True)
class BallStudy:
    """The ball bearing's run (``run``: state, sweeps, checks) and the bearing at the deck's temperatures
    (``at``; None: the deck gives none)."""

    run: BallRun
    at: AtTemperature | None = None


def at_temperature(b, speed: float, temperatures) -> AtTemperature | None:
    """The bearing ``b`` at the deck's temperatures and fits at ``speed`` [rad/s] (None: the deck gives none)."""
    gr = b.growth
    if gr is None:
        return None
    inner_fit = gr.rings.inner_fit
    if inner_fit is not None and b.speed_growth is not None:
        inner_fit = b.speed_growth.fit(speed)
    preload = None
    if b.preload.kind != "spring":  # a spring sets the preload force whatever the growth
        preload = np.asarray(b.solve(np.zeros(5), speed).row_axial_load_N, float)
    temps = {} if temperatures is None else {k: float(v) for k, v in temperatures.model_dump().items() if v is not None}
    return AtTemperature(gr, 0.0 if b.speed_growth is None else float(b.speed_growth(speed)),
                         b.preload.row_offsets(b.geometry.rows), preload, inner_fit, gr.rings.outer_fit, temps)


def ball_study(section) -> BallStudy:
    """Solve a validated ``BallSection`` (:func:`~.sweeps.run`) and evaluate it at the section's temperatures."""
    from .sweeps import run

    res = run(section)
    return BallStudy(res, at_temperature(res.bearing, res.speed_rad_s, section.temperatures_C))
