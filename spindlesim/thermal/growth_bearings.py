"""What growth does to the bearings: operating clearance and preload offset at temperature (SI).

Ball bearings (set).  The ball model (:mod:`spindlesim.bearings.ball`) places the inner groove
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
  takes; across the spindle it is :func:`~.growth.shaft_housing_axial_growth`.)

With the free contact angle a0 kept (it is what the rings were made to; a uniform growth of every part
then scales P_d and c_k and nothing else), the model's inputs at temperature are

    P_d' = 2 (A0' cos a0 - A_r'),        c_k' = A_a,k' - A0' sin a0,

the catalogue-style inputs of a new frozen ``BallGeometry`` (D', d_m', f_i' = r_i'/D', f_o' = r_o'/D', P_d';
built by :func:`spindlesim.bearings.ball.growth.at_temperature`) and a ``Preload`` with the change of c_k
as ``row_offsets_m``.  A radial change dA_r moves a position-preloaded row as an axial change
dA_a = dA_r A_r / A_a = dA_r / tan(a) does (same |A|, :func:`axial_equivalent_of_radial`).

DTRB: the same misfit argument along the raceway normals (:func:`dtrb_preload_change`), converted to the
change of delta0 (axial cone displacement).  Cylindrical roller bearing: P_d' = d_o' - d_i' - 2 D_w'.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .growth import (BEARING_STEEL, CAST_IRON, STEEL_SHAFT, FitState, ThermoElastic, check_temperature,
                     inner_raceway_growth, inner_ring_fit, outer_raceway_growth, outer_ring_fit, thermal_strain)


@dataclass(frozen=True)
class BearingTemperatures:
    """Prescribed (or computed) uniform temperatures of the parts [C]; shaft and housing default to the
    inner and outer ring."""

    inner_ring_C: float
    outer_ring_C: float
    rolling_elements_C: float
    reference_C: float = 20.0
    shaft_C: float | None = None
    housing_C: float | None = None

    def __post_init__(self) -> None:
        for name in ("inner_ring_C", "outer_ring_C", "rolling_elements_C", "reference_C", "shaft_C", "housing_C"):
            v = getattr(self, name)
            if v is not None:
                check_temperature(v, name)

    @property
    def shaft(self) -> float:
        return self.inner_ring_C if self.shaft_C is None else self.shaft_C

    @property
    def housing(self) -> float:
        return self.outer_ring_C if self.housing_C is None else self.housing_C

    @classmethod
    def uniform(cls, temperature_C: float, reference_C: float = 20.0) -> "BearingTemperatures":
        return cls(temperature_C, temperature_C, temperature_C, reference_C)


@dataclass(frozen=True)
class Mounting:
    """Fits of a bearing: diametral interferences (> 0) or clearances (< 0) at the reference temperature,
    the seat diameters and the shaft and housing bodies (SI)."""

    bore_m: float                                # bearing bore d = shaft seat
    outer_diameter_m: float                      # bearing outside diameter = housing seat
    shaft_interference_m: float = 0.0
    housing_interference_m: float = 0.0
    shaft_bore_m: float = 0.0                    # 0: solid shaft
    housing_outer_diameter_m: float = math.inf   # inf: a housing wall much thicker than the ring
    shaft: ThermoElastic = STEEL_SHAFT
    housing: ThermoElastic = CAST_IRON


@dataclass(frozen=True)
class RingGrowth:
    """Diametral changes of the raceways and the rolling element, and the fits, at one operating point."""

    inner_raceway_diameter_m: float    # groove bottom (ball) or raceway (roller) at the reference state
    outer_raceway_diameter_m: float
    inner_raceway_change_m: float      # diametral, thermal + fit + centrifugal
    outer_raceway_change_m: float
    element_change_m: float            # ball or roller diameter change
    inner_strain: float                # free thermal strains
    outer_strain: float
    element_strain: float
    inner_fit: FitState | None
    outer_fit: FitState | None

    @property
    def fit_lost(self) -> bool:
        return any(f is not None and f.lost for f in (self.inner_fit, self.outer_fit))


def ring_growth(inner_raceway_diameter_m: float, outer_raceway_diameter_m: float, element_diameter_m: float,
                temps: BearingTemperatures, ring: ThermoElastic, element: ThermoElastic,
                mounting: Mounting | None = None, speed_rad_s: float = 0.0,
                outer_ring: ThermoElastic | None = None) -> RingGrowth:
    """Raceway and rolling-element diameter changes of a bearing with a rotating inner ring.

    Without ``mounting`` the rings are free (no fit) and the inner ring's centrifugal growth is not
    computed (its bore is unknown)."""
    ref = temps.reference_C
    outer_ring = ring if outer_ring is None else outer_ring
    e_i = thermal_strain(ring.expansion_1_K, temps.inner_ring_C, ref)
    e_o = thermal_strain(outer_ring.expansion_1_K, temps.outer_ring_C, ref)
    e_b = thermal_strain(element.expansion_1_K, temps.rolling_elements_C, ref)
    fi = fo = None
    if mounting is not None:
        m = mounting
        fi = inner_ring_fit(m.shaft_interference_m, m.bore_m, inner_raceway_diameter_m, ring, m.shaft_bore_m, m.shaft,
                            ring_strain=e_i, shaft_strain=thermal_strain(m.shaft.expansion_1_K, temps.shaft, ref),
                            speed_rad_s=speed_rad_s)
        fo = outer_ring_fit(m.housing_interference_m, m.outer_diameter_m, outer_raceway_diameter_m, outer_ring,
                            m.housing_outer_diameter_m, m.housing, ring_strain=e_o,
                            housing_strain=thermal_strain(m.housing.expansion_1_K, temps.housing, ref))
        d_in = inner_raceway_growth(inner_raceway_diameter_m, m.bore_m, ring, e_i, fi, speed_rad_s)
    else:
        d_in = inner_raceway_diameter_m * e_i
    d_out = outer_raceway_growth(outer_raceway_diameter_m, e_o, fo)
    return RingGrowth(inner_raceway_diameter_m, outer_raceway_diameter_m, d_in, d_out, element_diameter_m * e_b,
                      e_i, e_o, e_b, fi, fo)


# ---- ball bearings ------------------------------------------------------------------------------------
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


# ---- tapered roller bearings (DTRB) ------------------------------------------------------------------------
@dataclass(frozen=True)
class DtrbGrowth:
    """Change of the DTRB's axial preload delta0 (per row, cone towards the centre) from growth."""

    preload_change_m: float
    cone_misfit_m: float        # approach change at the cone's mid-roller contact, roller carried with the rings
    cup_misfit_m: float
    rings: RingGrowth


def dtrb_preload_change(geometry, temps: BearingTemperatures, ring: ThermoElastic = BEARING_STEEL,
                        roller: ThermoElastic | None = None, mounting: Mounting | None = None,
                        speed_rad_s: float = 0.0) -> DtrbGrowth:
    """Thermal (and fit) change of delta0 of a back-to-back DTRB (:mod:`spindlesim.bearings.dtrb`).

    Mid-roller contacts P_c (cone) and P_u (cup), normals N_c, N_u (force on the roller), in a row's
    meridional plane about the bearing centre; every part grows about the centre (the cones abut there),
    the roller about its mass centre G and is carried with the mean ring strain e_m.  The approach gained
    at a contact is (u_race - u_roller) . N with u_roller = e_r (P - G) + e_m G; a cone moved axially by
    delta0 gains sin(beta) delta0 at the cone, so delta0 changes by (m_cone + m_cup) / sin(beta).  Fits
    and the cone's centrifugal growth enter as radial raceway changes.  A uniform growth gives zero."""
    g = geometry
    roller = ring if roller is None else roller
    S = g.n_slices
    mid = S // 2
    P_c, P_u = g.point_m[mid], g.point_m[S + mid]
    N_c, N_u = g.normal[mid], g.normal[S + mid]
    G = np.array([g.mass_centre_radius_m, -g.large_end_offset_m + g.mass_centre_from_large_end_m *
                  math.cos(g.roller_axis_angle_rad)])
    d_c, d_u = 2.0 * P_c[0], 2.0 * P_u[0]
    rg = ring_growth(d_c, d_u, 2.0 * g.large_end_radius_m, temps, ring, roller, mounting, speed_rad_s)
    e_i, e_o, e_r = rg.inner_strain, rg.outer_strain, rg.element_strain
    e_m = 0.5 * (e_i + e_o)
    u_c = e_i * P_c + np.array([0.5 * rg.inner_raceway_change_m - e_i * P_c[0], 0.0])
    u_u = e_o * P_u + np.array([0.5 * rg.outer_raceway_change_m - e_o * P_u[0], 0.0])
    m_c = float((u_c - (e_r * (P_c - G) + e_m * G)) @ N_c)
    m_u = float((u_u - (e_r * (P_u - G) + e_m * G)) @ N_u)
    return DtrbGrowth((m_c + m_u) / math.sin(g.cone_angle_rad), m_c, m_u, rg)


# ---- cylindrical roller bearings ------------------------------------------------------------------------
@dataclass(frozen=True)
class RollerClearance:
    """Operating clearance of a cylindrical roller bearing."""

    diametral_clearance_m: float      # d_o' - d_i' - 2 D_w' (< 0: interference)
    change_m: float
    rings: RingGrowth

    @property
    def radial_clearance_m(self) -> float:
        """Half the diametral clearance: the ``radial_clearance`` of spindlesim's roller model."""
        return 0.5 * self.diametral_clearance_m


def roller_operating_clearance(inner_raceway_diameter_m: float, outer_raceway_diameter_m: float,
                               roller_diameter_m: float, temps: BearingTemperatures,
                               ring: ThermoElastic = BEARING_STEEL, roller: ThermoElastic | None = None,
                               mounting: Mounting | None = None, speed_rad_s: float = 0.0) -> RollerClearance:
    """P_d' = d_o' - d_i' - 2 D_w' at temperature, with fits and the inner ring's centrifugal growth."""
    roller = ring if roller is None else roller
    rg = ring_growth(inner_raceway_diameter_m, outer_raceway_diameter_m, roller_diameter_m, temps, ring, roller,
                     mounting, speed_rad_s)
    P0 = outer_raceway_diameter_m - inner_raceway_diameter_m - 2.0 * roller_diameter_m
    ch = rg.outer_raceway_change_m - rg.inner_raceway_change_m - 2.0 * rg.element_change_m
    return RollerClearance(P0 + ch, ch, rg)
