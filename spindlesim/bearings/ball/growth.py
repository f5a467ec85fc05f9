"""The ball bearing (set) at temperature: a new frozen geometry and preload from the growth of its parts.

The growth itself (free thermal growth of rings and balls, fits, centrifugal growth of the inner ring,
the exact change of the groove-centre vector of every row) is computed by
:func:`spindlesim.thermal.growth_bearings.ball_bearing_growth`; this module turns its result into the
model's inputs (docs/theory.md, "Spindle thermal model: heat generation and growth").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...thermal.growth import BEARING_STEEL, ThermoElastic
from ...thermal.growth_bearings import BallGrowth, BearingTemperatures, Mounting, ball_bearing_growth, ring_growth
from .bearing import Preload
from .geometry import BallGeometry, ball_geometry


def _direction(g: BallGeometry) -> int:
    """The ``direction`` argument that rebuilds the rows of ``g`` (the tandem pair's thrust of 3 rows)."""
    if g.arrangement in ("single", "DT"):
        return int(g.row_sign[0])
    if g.rows % 2 == 0:
        return 1
    return 1 if int(np.sum(g.row_sign)) > 0 else -1


def geometry_from_growth(g: BallGeometry, growth: BallGrowth) -> BallGeometry:
    """A new frozen geometry with the grown ball, grooves, pitch circle, row spacing and clearance."""
    try:
        return ball_geometry(
            balls=g.balls, ball_diameter_m=growth.ball_diameter_m, pitch_diameter_m=growth.pitch_diameter_m,
            contact_angle_deg=math.degrees(g.contact_angle_rad), inner_conformity=growth.inner_conformity,
            outer_conformity=growth.outer_conformity, clearance_m=growth.clearance_m, ring=g.ring, ball=g.ball,
            arrangement=g.arrangement, rows=g.rows, row_spacing_m=growth.row_spacing_m, direction=_direction(g))
    except ValueError as exc:
        raise ValueError(f"the bearing at temperature has no valid geometry (operating clearance "
                         f"{growth.clearance_m * 1e6:.4g} um): {exc}") from exc


def at_temperature(geometry: BallGeometry, preload: Preload, temps: BearingTemperatures,
                   ring: ThermoElastic = BEARING_STEEL, ball: ThermoElastic | None = None,
                   mounting: Mounting | None = None,
                   speed_rad_s: float = 0.0) -> tuple[BallGeometry, Preload, BallGrowth]:
    """(geometry, preload, growth) of the bearing (set) at the prescribed temperatures (fits, speed)."""
    growth = ball_bearing_growth(geometry, preload, temps, ring, ball, mounting, speed_rad_s)
    return geometry_from_growth(geometry, growth), growth.preload, growth


@dataclass(frozen=True)
class SpeedGrowth:
    """Radial growth of the inner groove centre at a speed beyond that at rest [m] (the inner ring's own
    centrifugal growth and the loosening of its fit on the spinning shaft), for the bearing made as
    ``geometry`` at ``temps`` on ``mounting``.  A :class:`~.bearing.BallBearing` adds it to A_r at every
    speed; the contact (Hertz) constants stay those of the geometry at rest."""

    geometry: BallGeometry
    temps: BearingTemperatures
    ring: ThermoElastic
    mounting: Mounting

    def _rings(self, speed_rad_s: float):
        g = self.geometry
        d_ie = 2.0 * (g.inner_centre_radius_m - g.inner_conformity * g.ball_diameter_m)
        d_oe = 2.0 * (g.inner_centre_radius_m - g.reference_radial_m + g.outer_conformity * g.ball_diameter_m)
        return ring_growth(d_ie, d_oe, g.ball_diameter_m, self.temps, self.ring, self.ring, self.mounting, speed_rad_s)

    def _inner_change(self, speed_rad_s: float) -> float:
        return self._rings(speed_rad_s).inner_raceway_change_m

    def fit(self, speed_rad_s: float):
        """The inner ring's fit on the shaft at the speed (:class:`~spindlesim.thermal.growth.FitState`)."""
        return self._rings(speed_rad_s).inner_fit

    def __call__(self, speed_rad_s: float) -> float:
        if speed_rad_s == 0.0:
            return 0.0
        return 0.5 * (self._inner_change(speed_rad_s) - self._inner_change(0.0))
