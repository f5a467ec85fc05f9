"""Bearing friction heat, global (Palmgren) model, and the lubricant's viscosity (SI in and out).

Palmgren (1959), as tabulated by Harris and Kotzalas (2007, *Essential Concepts*, friction-torque
chapter; the same coefficients as in Palmgren's *Ball and Roller Bearing Engineering*):

    M = M_l + M_v
    M_l = f1 P1 d_m
    M_v = 1e-7 f0 (nu n)^(2/3) d_m^3      for nu n >= 2000,    160e-7 f0 d_m^3 below
          (N mm, with nu in mm^2/s (cSt), n in rpm, d_m in mm; the functions here take and return SI)

- f1 for ball bearings f1 = z (P0/C0)^y: deep groove z = 0.0004-0.0006 (0.0005 taken), y = 0.55;
  angular contact z = 0.001, y = 0.33 (tabulated for 30-40 deg; applied to spindle bearings of
  15-25 deg as the spindle literature does, e.g. Bossmanns and Tu 1999).  P0 is the static equivalent
  load of ISO 76 (X0, Y0 below), C0 the static load rating.  Roller bearings: f1 = 0.0003 (cylindrical
  with cage, 0.0002-0.0004), 0.0004 (tapered).
- P1: angular contact ball max(0.9 Fa cot(alpha) - 0.1 Fr, Fr); deep groove max(3 Fa - 0.1 Fr, Fr);
  cylindrical roller Fr; tapered roller max(2 Y Fa, Fr) (single row; Y its axial load factor).
- f0 by lubrication (Harris and Kotzalas, after Palmgren; ranges taken at their middle):

  | family | grease | oil mist / oil-air | oil bath | oil jet |
  |---|---|---|---|---|
  | deep groove ball | 1.35 (0.7-2) | 1 | 2 | 4 |
  | angular contact ball | 2 | 1.7 | 3.3 | 6.6 |
  | cylindrical roller, cage | 0.8 (0.6-1) | 2.15 (1.5-2.8) | 3.1 (2.2-4) | 3.1 (2.2-4) |
  | tapered roller | 6 | 3 | 6 | 9 (8-10) |

- ISO 76 static equivalent load of radial ball bearings: P0 = max(X0 Fr + Y0 Fa, Fr); deep groove
  X0 0.6, Y0 0.5; single-row angular contact X0 0.5, Y0 0.46 / 0.42 / 0.38 / 0.33 / 0.29 / 0.26 / 0.22 at
  15 / 20 / 25 / 30 / 35 / 40 / 45 deg (interpolated between).

Where the heat goes (roller bearings in the spindle's network, :func:`palmgren_parts_W`; our choice, the
global model says nothing of it): the load moment is friction in the raceway contacts, taken half at the
inner and half at the outer contacts and, as in the ball model, half of each contact's heat to the ring and
half to the rolling elements (1/4, 1/2, 1/4); the viscous moment is the lubricant's drag and churning,
heat in the oil around the rolling elements (to the rolling elements' node, as the ball model's drag).

Viscosity: the Walther (ASTM D341) relation and ISO VG data of :mod:`spindlesim.bearings.fluidfilm.viscosity`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .oil import WaltherViscosity

RPM = math.pi / 30.0

LUBRICATION = ("grease", "oil_mist", "oil_air", "oil_bath", "oil_jet")
FAMILIES = ("deep_groove_ball", "angular_contact_ball", "cylindrical_roller", "tapered_roller")

#: Palmgren's f0 (Harris and Kotzalas), oil-air taken as oil mist
F0_TABLE: dict[str, dict[str, float]] = {
    "deep_groove_ball": {"grease": 1.35, "oil_mist": 1.0, "oil_air": 1.0, "oil_bath": 2.0, "oil_jet": 4.0},
    "angular_contact_ball": {"grease": 2.0, "oil_mist": 1.7, "oil_air": 1.7, "oil_bath": 3.3, "oil_jet": 6.6},
    "cylindrical_roller": {"grease": 0.8, "oil_mist": 2.15, "oil_air": 2.15, "oil_bath": 3.1, "oil_jet": 3.1},
    "tapered_roller": {"grease": 6.0, "oil_mist": 3.0, "oil_air": 3.0, "oil_bath": 6.0, "oil_jet": 9.0},
}
#: (z, y) of f1 = z (P0/C0)^y for ball bearings
F1_BALL = {"deep_groove_ball": (0.0005, 0.55), "angular_contact_ball": (0.001, 0.33)}
#: f1 of roller bearings (no load-ratio term)
F1_ROLLER = {"cylindrical_roller": 0.0003, "tapered_roller": 0.0004}
#: ISO 76 Y0 of single-row angular-contact ball bearings (X0 = 0.5)
ISO76_ANGLES_DEG = np.array([15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
ISO76_Y0 = np.array([0.46, 0.42, 0.38, 0.33, 0.29, 0.26, 0.22])


# ---- lubricant -------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Lubricant:
    """An oil (or a grease's base oil): Walther viscosity-temperature law, density, pressure-viscosity
    coefficient (EHL), and the name it was made from."""

    viscosity: WaltherViscosity
    pressure_viscosity_1_Pa: float = 2.0e-8   # mineral oils 1.5-2.5e-8 1/Pa; esters about 1.0-1.5e-8
    name: str = "oil"
    synthetic: bool = False

    @classmethod
    def from_grade(cls, grade: str, density_kg_m3: float = 860.0, **kw) -> "Lubricant":
        """ISO VG grade (``"ISO VG 32"``, ``"VG 3"``): the Walther data of fluidfilm.viscosity."""
        return cls(WaltherViscosity.from_grade(grade, density_kg_m3), name=grade.strip(), **kw)

    @classmethod
    def from_two_points(cls, nu1_cst: float, t1_C: float, nu2_cst: float, t2_C: float,
                        density_kg_m3: float = 860.0, **kw) -> "Lubricant":
        return cls(WaltherViscosity.from_two_points(nu1_cst, t1_C, nu2_cst, t2_C, density_kg_m3), **kw)

    @property
    def density_kg_m3(self) -> float:
        return self.viscosity.density_kg_m3

    def kinematic_m2_s(self, temperature_C: float) -> float:
        return self.viscosity.kinematic_cst(temperature_C) * 1e-6

    def dynamic_Pa_s(self, temperature_C: float) -> float:
        return self.viscosity(temperature_C)


def kinematic_viscosity_m2_s(grade: str, temperature_C: float) -> float:
    """Kinematic viscosity [m^2/s] of an ISO VG grade at a temperature (Walther, fluidfilm.viscosity)."""
    return WaltherViscosity.from_grade(grade, 860.0).kinematic_cst(temperature_C) * 1e-6


# ---- Palmgren ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PalmgrenMoment:
    """Friction moment [N m] and heat [W] of one bearing (row)."""

    load_Nm: float
    viscous_Nm: float
    speed_rad_s: float
    f0: float
    f1: float
    P1_N: float

    @property
    def total_Nm(self) -> float:
        return self.load_Nm + self.viscous_Nm

    @property
    def power_W(self) -> float:
        return self.total_Nm * abs(self.speed_rad_s)


def f0_coefficient(family: str, lubrication: str) -> float:
    """Palmgren's f0 for a bearing family and lubrication method (table in the module docstring)."""
    if family not in F0_TABLE:
        raise ValueError(f"bearing family must be one of {FAMILIES}, not {family!r}")
    if lubrication not in LUBRICATION:
        raise ValueError(f"lubrication must be one of {LUBRICATION}, not {lubrication!r}")
    return F0_TABLE[family][lubrication]


def viscous_moment_Nm(f0: float, pitch_diameter_m: float, speed_rad_s: float, viscosity_m2_s: float) -> float:
    """Palmgren's load-independent moment M_v [N m]."""
    n_rpm = abs(speed_rad_s) / RPM
    nu_cst = viscosity_m2_s * 1e6
    dm_mm = pitch_diameter_m * 1e3
    if nu_cst * n_rpm >= 2000.0:
        m_Nmm = 1e-7 * f0 * (nu_cst * n_rpm) ** (2.0 / 3.0) * dm_mm ** 3
    else:
        m_Nmm = 160e-7 * f0 * dm_mm ** 3
    return m_Nmm * 1e-3 if speed_rad_s != 0.0 else 0.0


def static_equivalent_load_N(radial_N: float, axial_N: float, contact_angle_rad: float) -> float:
    """ISO 76 P0 of a single-row radial ball bearing (deep groove at 0 deg)."""
    Fr, Fa = abs(radial_N), abs(axial_N)
    deg = math.degrees(contact_angle_rad)
    if deg < 1e-9:
        x0, y0 = 0.6, 0.5
    else:
        if not 15.0 - 1e-9 <= deg <= 45.0 + 1e-9:
            raise ValueError(f"ISO 76 X0, Y0 are tabulated for 15-45 deg, not {deg:.3g} deg")
        x0, y0 = 0.5, float(np.interp(deg, ISO76_ANGLES_DEG, ISO76_Y0))
    return max(x0 * Fr + y0 * Fa, Fr)


def ball_palmgren(*, pitch_diameter_m: float, contact_angle_rad: float, radial_N: float, axial_N: float,
                  static_rating_N: float, speed_rad_s: float, viscosity_m2_s: float, lubrication: str,
                  f0: float | None = None, z_y: tuple[float, float] | None = None) -> PalmgrenMoment:
    """Palmgren's moment of ONE ball bearing (one row of a set) under Fr, Fa (its own share, preload
    included) with static rating C0.  ``f0`` and ``z_y`` override the tables."""
    if static_rating_N <= 0.0:
        raise ValueError("the static load rating C0 must be positive")
    deep = contact_angle_rad < 1e-9
    family = "deep_groove_ball" if deep else "angular_contact_ball"
    f0 = f0_coefficient(family, lubrication) if f0 is None else float(f0)
    z, y = F1_BALL[family] if z_y is None else z_y
    Fr, Fa = abs(radial_N), abs(axial_N)
    P0 = static_equivalent_load_N(Fr, Fa, contact_angle_rad)
    f1 = z * (P0 / static_rating_N) ** y
    if deep:
        P1 = max(3.0 * Fa - 0.1 * Fr, Fr)
    else:
        P1 = max(0.9 * Fa / math.tan(contact_angle_rad) - 0.1 * Fr, Fr)
    return PalmgrenMoment(load_Nm=f1 * P1 * pitch_diameter_m,
                          viscous_Nm=viscous_moment_Nm(f0, pitch_diameter_m, speed_rad_s, viscosity_m2_s),
                          speed_rad_s=float(speed_rad_s), f0=f0, f1=f1, P1_N=P1)


def roller_palmgren(*, family: str, pitch_diameter_m: float, radial_N: float, speed_rad_s: float,
                    viscosity_m2_s: float, lubrication: str, axial_N: float = 0.0, axial_factor_Y: float = 0.0,
                    f0: float | None = None, f1: float | None = None) -> PalmgrenMoment:
    """Palmgren's moment of a cylindrical (``cylindrical_roller``, radial load only; the flange friction of
    an axially loaded cylindrical roller bearing is not included) or single-row tapered roller bearing
    (``tapered_roller``, P1 = max(2 Y Fa, Fr) with the catalogue axial factor Y)."""
    if family not in F1_ROLLER:
        raise ValueError(f"roller family must be one of {tuple(F1_ROLLER)}, not {family!r}")
    f0 = f0_coefficient(family, lubrication) if f0 is None else float(f0)
    f1 = F1_ROLLER[family] if f1 is None else float(f1)
    Fr = abs(radial_N)
    P1 = Fr if family == "cylindrical_roller" else max(2.0 * axial_factor_Y * abs(axial_N), Fr)
    return PalmgrenMoment(load_Nm=f1 * P1 * pitch_diameter_m,
                          viscous_Nm=viscous_moment_Nm(f0, pitch_diameter_m, speed_rad_s, viscosity_m2_s),
                          speed_rad_s=float(speed_rad_s), f0=f0, f1=f1, P1_N=P1)


def palmgren_parts_W(moments) -> tuple[float, float, float]:
    """(inner ring, rolling elements, outer ring) heat [W] of Palmgren moments (one per row), module note."""
    load = sum(m.load_Nm * abs(m.speed_rad_s) for m in moments)
    viscous = sum(m.viscous_Nm * abs(m.speed_rad_s) for m in moments)
    return 0.25 * load, 0.5 * load + viscous, 0.25 * load


def row_loads_N(state) -> tuple[np.ndarray, np.ndarray]:
    """(Fr, Fa) each row of a ball set carries in a :class:`~spindlesim.bearings.ball.results.BallState`:
    the radial resultant of its inner contact loads and its thrust (preload included)."""
    a = np.radians(state.contact_angle_inner_deg)
    q = np.maximum(state.element_load_inner_N, 0.0) * np.cos(a)
    fx = np.sum(q * np.cos(state.psi_rad), axis=1)
    fy = np.sum(q * np.sin(state.psi_rad), axis=1)
    return np.hypot(fx, fy), np.abs(state.row_axial_load_N)


def ball_set_palmgren(state, geometry, *, static_rating_N: float, viscosity_m2_s: float, lubrication: str,
                      f0: float | None = None) -> list[PalmgrenMoment]:
    """Palmgren per row of a ball set at its quasi-static state (each row a bearing of rating C0)."""
    Fr, Fa = row_loads_N(state)
    return [ball_palmgren(pitch_diameter_m=geometry.pitch_diameter_m, contact_angle_rad=geometry.contact_angle_rad,
                          radial_N=float(fr), axial_N=float(fa), static_rating_N=static_rating_N,
                          speed_rad_s=state.speed_rad_s, viscosity_m2_s=viscosity_m2_s, lubrication=lubrication,
                          f0=f0) for fr, fa in zip(Fr, Fa)]
