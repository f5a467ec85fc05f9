"""The ball bearing (set) at temperature: the growth of its parts and the new frozen geometry and preload.

The ball model (:mod:`spindlesim.bearings.ball`) places the inner groove
curvature centre O_i of row k relative to the outer one O_o at (A_a, A_r) = (A0 sin a0 + c_k,
A0 cos a0 - P_d / 2) with A0 = r_i + r_o - D (docs/theory.md, "Ball bearings").  Growth changes every
term of it, exactly:

- radial: R_Oi' - R_Oo' with R_Oi' = R_Oi (1 + e_i) + (d_ie' - d_ie (1 + e_i)) / 2 (the groove centre moves
  radially with the raceway: free thermal strain e_i = alpha_ring (T_i - T_ref), plus the fit pressure and
  the centrifugal growth of the rotating ring), likewise R_Oo' with the outer ring (e_o, fit contraction);
- groove radii r' = r (1 + e) with their ring, ball D' = D (1 + e_b) with its own material, so
  A0' = r_i' + r_o' - D';
- axial: the ring stacks of the set grow about the set's centre plane (z = 0); a groove centre at z moves
  to z (1 + e), so A_a of row k changes by s_k (z_Oi e_i - z_Oo e_o).  (Any other reference plane differs
  by a uniform shift of the inner stack against the outer one, which the set's own axial equilibrium
  takes; across the spindle it is :func:`spindlesim.thermal.growth.shaft_housing_axial_growth`.)

With the free contact angle a0 kept (it is what the rings were made to; a uniform growth of every part
then scales P_d and c_k and nothing else), the model's inputs at temperature are

    P_d' = 2 (A0' cos a0 - A_r'),        c_k' = A_a,k' - A0' sin a0,

the catalogue-style inputs of a new frozen ``BallGeometry`` (D', d_m', f_i' = r_i'/D', f_o' = r_o'/D', P_d';
built by :func:`at_temperature`) and a ``Preload`` with the change of c_k
as ``row_offsets_m``.  A radial change dA_r moves a position-preloaded row as an axial change
dA_a = dA_r A_r / A_a = dA_r / tan(a) does (same |A|, :func:`axial_equivalent_of_radial`).

The rings' and balls' own growth (free thermal strain, fits, the inner ring's centrifugal growth) is the
shared :func:`spindlesim.thermal.growth_bearings.ring_growth`; docs/theory.md, "Spindle thermal model: heat
generation and growth".
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ...thermal.growth import BEARING_STEEL, ThermoElastic
from ...thermal.growth_bearings import BearingTemperatures, Mounting, RingGrowth, ring_growth
from .bearing import Preload
from .geometry import BallGeometry, ball_geometry



@dataclass(frozen=True)
class BallGrowth:
    """A ball bearing (set) at temperature (and speed): the inputs of the ball model and what changed.

    :func:`spindlesim.bearings.ball.growth.at_temperature` builds the frozen geometry and preload from it."""

    ball_diameter_m: float             # D'
    pitch_diameter_m: float            # d_m'
    inner_conformity: float            # r_i' / D'
    outer_conformity: float            # r_o' / D'
    clearance_m: float                 # operating diametral clearance P_d' (< 0: interference)
    row_spacing_m: float               # distance between adjacent ball rows (0: single row)
    preload: object                    # Preload at temperature (position: thermal row offsets)
    clearance_change_m: float          # P_d' - P_d
    row_offset_change_m: np.ndarray    # (rows,) change of each row's axial offset c_k (> 0: more preload)
    groove_distance_change_m: float    # A0' - A0
    radial_change_m: float             # A_r' - A_r (> 0: more preload)
    rings: RingGrowth
    speed_rad_s: float

    @property
    def preload_offset_change_m(self) -> float:
        """Change of the total axial preload offset of an opposed pair (twice the mean row change)."""
        return 2.0 * float(np.mean(self.row_offset_change_m))


def _ball_reference(g, preload):
    """Groove-centre radii and axial positions of every row of the model's reference state."""
    D = g.ball_diameter_m
    R_oi = g.inner_centre_radius_m
    R_oo = R_oi - g.reference_radial_m
    s = g.row_sign.astype(float)
    z_oi = g.row_z_m + s * g.inner_centre_offset_m
    c = preload.row_offsets(g.rows)
    z_oo = z_oi - s * (g.reference_axial_m + c)
    r_i, r_o = g.inner_conformity * D, g.outer_conformity * D
    return R_oi, R_oo, z_oi, z_oo, r_i, r_o, c


def ball_bearing_growth(geometry, preload, temps: BearingTemperatures, ring: ThermoElastic = BEARING_STEEL,
                        ball: ThermoElastic | None = None, mounting: Mounting | None = None,
                        speed_rad_s: float = 0.0) -> BallGrowth:
    """The ball bearing (set) ``geometry`` (a BallGeometry) with ``preload`` (a Preload) at the temperatures
    ``temps`` (and fits, inner-ring speed): see the module docstring.  ``ring`` and ``ball`` carry the
    expansion coefficients (``ball`` defaults to ``ring``)."""
    g = geometry
    ball = ring if ball is None else ball
    R_oi, R_oo, z_oi, z_oo, r_i, r_o, c = _ball_reference(g, preload)
    d_ie, d_oe = 2.0 * (R_oi - r_i), 2.0 * (R_oo + r_o)
    rg = ring_growth(d_ie, d_oe, g.ball_diameter_m, temps, ring, ball, mounting, speed_rad_s)
    e_i, e_o, e_b = rg.inner_strain, rg.outer_strain, rg.element_strain
    R_oi2 = R_oi + 0.5 * rg.inner_raceway_change_m + r_i * e_i  # groove centre follows the raceway; r grows too
    R_oo2 = R_oo + 0.5 * rg.outer_raceway_change_m - r_o * e_o
    r_i2, r_o2, D2 = r_i * (1.0 + e_i), r_o * (1.0 + e_o), g.ball_diameter_m * (1.0 + e_b)
    A0, A02 = g.groove_distance_m, r_i2 + r_o2 - D2
    a0 = g.contact_angle_rad
    A_r, A_r2 = g.reference_radial_m, R_oi2 - R_oo2
    P_d2 = 2.0 * (A02 * math.cos(a0) - A_r2)
    s = g.row_sign.astype(float)
    A_a = g.reference_axial_m + c
    A_a2 = A_a + s * (z_oi * e_i - z_oo * e_o)
    dc = (A_a2 - A02 * math.sin(a0)) - c
    # pitch circle: the ball centre midway between the points where it would touch either groove at the
    # mounted free contact angle (exact for a clearance, where it touches both; the model's own convention)
    af2 = math.acos(A_r2 / A02) if 0.0 < P_d2 and A_r2 < A02 else math.atan2(A02 * math.sin(a0), A_r2)
    ca = math.cos(af2)
    dm2 = (R_oo2 + (r_o2 - 0.5 * D2) * ca) + (R_oi2 - (r_i2 - 0.5 * D2) * ca)
    spacing = 0.0 if g.rows == 1 else float(g.row_z_m[1] - g.row_z_m[0]) * (1.0 + 0.5 * (e_i + e_o))
    opposed = bool(np.any(g.row_sign > 0) and np.any(g.row_sign < 0))
    if preload.kind == "position" or (preload.kind == "none" and opposed):
        base = np.zeros(g.rows) if preload.row_offsets_m is None else np.asarray(preload.row_offsets_m, float)
        pre2 = replace(preload, kind="position", row_offsets_m=tuple(float(v) for v in base + dc))
    else:
        pre2 = preload
    return BallGrowth(ball_diameter_m=D2, pitch_diameter_m=dm2, inner_conformity=r_i2 / D2,
                      outer_conformity=r_o2 / D2, clearance_m=P_d2, row_spacing_m=spacing, preload=pre2,
                      clearance_change_m=P_d2 - g.clearance_m, row_offset_change_m=dc,
                      groove_distance_change_m=A02 - A0, radial_change_m=A_r2 - A_r, rings=rg,
                      speed_rad_s=float(speed_rad_s))


def axial_equivalent_of_radial(radial_change_m: float, axial_m: float, radial_m: float) -> float:
    """Axial change of the groove-centre distance with the same effect on the contact approach as the
    radial change ``radial_change_m`` (|A| kept): exact, sqrt(A_a^2 + A_r'^2 - A_r^2) - A_a; to first order
    dA_r A_r / A_a = dA_r / tan(alpha)."""
    r2 = radial_m + radial_change_m
    return math.sqrt(axial_m * axial_m + r2 * r2 - radial_m * radial_m) - axial_m


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
