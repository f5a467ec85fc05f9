"""Rating life of a ball bearing (set): ISO 281 basic rating life and ISO/TS 16281 reference rating life.

ISO 281:2007, radial ball bearings (alpha < 45 deg):

- Basic dynamic radial load rating of ONE row (i = 1), N and mm:
  C_r = b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.8 for D_w <= 25.4 mm, and
  C_r = 3.647 b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.4 above; b_m = 1.3 (Table 2, radial ball
  bearings other than filling-slot types), f_c from Table 1 against D_w cos(alpha) / D_pw
  (column "single-row radial contact groove ball bearings and single- and double-row angular
  contact groove ball bearings", linear interpolation).  The standard's groove radii limits
  (r_i <= 0.52 D_w, r_e <= 0.53 D_w) are not enforced; a deck may override C with the catalogue
  value (``dynamic_load_rating_N``, one bearing).
- A set of i similar rows working as a unit: C = i^0.7 C_row; back-to-back and face-to-face sets
  are rated as double-row bearings, tandem sets as single-row bearings (ISO 281 sections 5.1.3,
  6.1.2).
- Equivalent load P = X F_r + Y F_a (Table 3); for nominal contact angles up to 15 deg the
  factors depend on the relative axial load f_0 F_a / C_0r, and since C_0r = f_0 i Z D_w^2
  cos(alpha) (ISO 76) the argument is F_a / (i Z D_w^2 cos alpha) [N/mm^2] (deep groove,
  "f_0 F_a / C_0r") or F_a / (Z D_w^2 cos alpha) (angular contact, "i f_0 F_a / C_0r"); f_0
  cancels.  Implemented: alpha = 0 (deep groove), 15 deg, and 20-45 deg (interpolated between
  the tabulated angles).  Other angles (5-10 deg tables, 15-20 deg) give no ISO 281 life (None).
- L_10 = (C / P)^3 [10^6 revolutions]; life modification for reliability a_1 =
  0.95 (ln(100/R) / ln(100/90))^(2/3) + 0.05 (reproduces ISO 281:2007 Table 12: 0.64 at 95 %,
  0.25 at 99 %).  ISO 281 ignores moments, preload and speed effects: that is what the
  reference rating life is for.

ISO/TS 16281:2008 (basic reference rating life from the load distribution), radial ball bearings:

- Load ratings of the contacts of one row, from C of that row:
  Q_ci = C / (0.407 Z cos alpha) [1 + (1.044 ((1 - g)/(1 + g))^1.72 (r_i (2 r_e - D_w) /
  (r_e (2 r_i - D_w)))^0.41)^(10/3)]^0.3, and Q_ce with 0.389 and the exponent -10/3 inside,
  g = D_w cos(alpha) / D_pw.
- Dynamic equivalent rolling element loads of row k: the inner ring rotates relative to the
  load, Q_eik = (sum_j Q_ijk^3 / Z)^(1/3); the outer ring is stationary,
  Q_eek = (sum_j Q_ojk^(10/3) / Z)^(3/10) (inner and outer contact loads differ at speed).
- L_10r = [sum_k ((Q_cik / Q_eik)^(-10/3) + (Q_cek / Q_eek)^(-10/3))]^(-9/10).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from ..rolling import pitch_ratio
from .geometry import BallGeometry

log = logging.getLogger(__name__)

#: ISO 281:2007 Table 2, radial ball bearings (not filling slot)
B_M = 1.3
#: ISO 281:2007 Table 1, D_w cos(alpha) / D_pw = 0.01, 0.02, ..., 0.40
FC_X = np.round(np.arange(1, 41) * 0.01, 2)
FC = np.array([29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
               56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,
               59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,
               55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4])

# ISO 281:2007 Table 3
DG_ARG = np.array([0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89])
DG_E = np.array([0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44])
DG_Y = np.array([2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00])
DG_X = 0.56
AC15_ARG = np.array([0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57, 5.35, 7.14])
AC15_E = np.array([0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56])
AC15_Y_SINGLE = np.array([1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00])
AC15_Y1_DOUBLE = np.array([1.65, 1.57, 1.46, 1.38, 1.34, 1.26, 1.14, 1.12, 1.12])
AC15_Y2_DOUBLE = np.array([2.39, 2.28, 2.11, 2.00, 1.93, 1.82, 1.66, 1.63, 1.63])
AC15_X_SINGLE, AC15_X2_DOUBLE = 0.44, 0.72
#: alpha [deg]: (e, X single, Y single, Y1 double, X2 double, Y2 double)
AC_FIXED = {
    20.0: (0.57, 0.43, 1.00, 1.09, 0.70, 1.63),
    25.0: (0.68, 0.41, 0.87, 0.92, 0.67, 1.41),
    30.0: (0.80, 0.39, 0.76, 0.78, 0.63, 1.24),
    35.0: (0.95, 0.37, 0.66, 0.66, 0.60, 1.07),
    40.0: (1.14, 0.35, 0.57, 0.55, 0.57, 0.93),
    45.0: (1.34, 0.33, 0.50, 0.47, 0.54, 0.81),
}


@dataclass(frozen=True)
class RatingInputs:
    """Deck choices for the lives: catalogue C of ONE bearing (None: ISO 281 formula) and the
    reliability of L_n."""

    dynamic_load_rating_N: float | None = None
    reliability_percent: float = 90.0


@dataclass(frozen=True)
class Lives:
    """Lives at one operating point [10^6 revolutions]; None where the method does not apply."""

    C_row_N: float                 # rating of one row (nan: geometry outside ISO 281 Table 1)
    C_set_N: float                 # i^0.7 C_row
    equivalent_load_N: float       # ISO 281 P of the set (nan if no factors)
    L10_iso281_Mrev: float | None
    L10r_iso16281_Mrev: float | None
    a1: float                      # reliability factor
    Q_ci_N: float                  # ISO/TS 16281 contact ratings of one row
    Q_ce_N: float
    Q_ei_N: np.ndarray             # (rows,) equivalent inner contact loads
    Q_ee_N: np.ndarray             # (rows,) equivalent outer contact loads

    @property
    def Ln_iso281_Mrev(self) -> float | None:
        return None if self.L10_iso281_Mrev is None else self.a1 * self.L10_iso281_Mrev

    @property
    def Lnr_iso16281_Mrev(self) -> float | None:
        return None if self.L10r_iso16281_Mrev is None else self.a1 * self.L10r_iso16281_Mrev


def fc_factor(x: float) -> float:
    """f_c of ISO 281 Table 1 at x = D_w cos(alpha) / D_pw (linear interpolation)."""
    if not FC_X[0] <= x <= FC_X[-1]:
        raise ValueError(f"D_w cos(alpha)/D_pw = {x:.4f} outside ISO 281 Table 1 (0.01-0.40)")
    return float(np.interp(x, FC_X, FC))


def row_load_rating_N(g: BallGeometry) -> float:
    """ISO 281 basic dynamic radial load rating of one row (i = 1) from the geometry [N]."""
    a = g.contact_angle_rad
    Dw = g.ball_diameter_m * 1e3
    fc = fc_factor(Dw * math.cos(a) / (g.pitch_diameter_m * 1e3))
    base = B_M * fc * math.cos(a) ** 0.7 * g.balls ** (2.0 / 3.0)
    return base * Dw ** 1.8 if Dw <= 25.4 else 3.647 * base * Dw ** 1.4


def reliability_factor(reliability_percent: float) -> float:
    """a_1 = 0.95 (ln(100/R) / ln(100/90))^(2/3) + 0.05, 90 <= R <= 99.95 (ISO 281:2007 Table 12)."""
    R = float(reliability_percent)
    if not 90.0 <= R <= 99.95:
        raise ValueError("reliability must be within 90 % and 99.95 %")
    return 0.95 * (math.log(100.0 / R) / math.log(100.0 / 90.0)) ** (2.0 / 3.0) + 0.05


def _factors(alpha_deg: float, double: bool, arg: float):
    """(e, X_low, Y_low, X_high, Y_high) of ISO 281 Table 3, or None (angle not implemented)."""
    if abs(alpha_deg) < 1e-9:
        e, y = np.interp(arg, DG_ARG, DG_E), np.interp(arg, DG_ARG, DG_Y)
        return float(e), 1.0, 0.0, DG_X, float(y)
    if abs(alpha_deg - 15.0) < 1e-9:
        e = float(np.interp(arg, AC15_ARG, AC15_E))
        if double:
            return (e, 1.0, float(np.interp(arg, AC15_ARG, AC15_Y1_DOUBLE)), AC15_X2_DOUBLE,
                    float(np.interp(arg, AC15_ARG, AC15_Y2_DOUBLE)))
        return e, 1.0, 0.0, AC15_X_SINGLE, float(np.interp(arg, AC15_ARG, AC15_Y_SINGLE))
    if 20.0 - 1e-9 <= alpha_deg <= 45.0 + 1e-9:
        angles = np.array(sorted(AC_FIXED))
        table = np.array([AC_FIXED[a] for a in angles])
        e, xs, ys, y1, x2, y2 = (float(np.interp(alpha_deg, angles, table[:, c])) for c in range(6))
        return (e, 1.0, y1, x2, y2) if double else (e, 1.0, 0.0, xs, ys)
    return None


def equivalent_load_N(g: BallGeometry, Fr: float, Fa: float) -> float | None:
    """ISO 281 P of the set for radial load Fr and axial load Fa [N] (None: angle not tabulated)."""
    rows = g.rows
    double = g.arrangement in ("DB", "DF")
    Dw = g.ball_diameter_m * 1e3
    ca = math.cos(g.contact_angle_rad)
    deg = math.degrees(g.contact_angle_rad)
    Fr, Fa = abs(Fr), abs(Fa)
    if deg < 1e-9:
        arg = Fa / (rows * g.balls * Dw * Dw * ca)
    else:
        arg = Fa / (g.balls * Dw * Dw * ca)
    fac = _factors(deg, double, arg)
    if fac is None:
        return None
    e, x_lo, y_lo, x_hi, y_hi = fac
    if Fa <= e * Fr:
        return x_lo * Fr + y_lo * Fa
    return x_hi * Fr + y_hi * Fa


def contact_ratings_N(g: BallGeometry, C_row: float) -> tuple[float, float]:
    """(Q_ci, Q_ce) of ISO/TS 16281 for one row of rating C_row."""
    gam = pitch_ratio(g.ball_diameter_m, g.contact_angle_rad, g.pitch_diameter_m)
    fi, fo = g.inner_conformity, g.outer_conformity
    ratio = 1.044 * ((1.0 - gam) / (1.0 + gam)) ** 1.72 * (fi * (2.0 * fo - 1.0) / (fo * (2.0 * fi - 1.0))) ** 0.41
    base = C_row / (g.balls * math.cos(g.contact_angle_rad))
    q_ci = base / 0.407 * (1.0 + ratio ** (10.0 / 3.0)) ** 0.3
    q_ce = base / 0.389 * (1.0 + ratio ** (-10.0 / 3.0)) ** 0.3
    return q_ci, q_ce


def lives(g: BallGeometry, inputs: RatingInputs, Q_inner: np.ndarray, Q_outer: np.ndarray,
          Fr: float, Fa: float) -> Lives:
    """Both lives at one operating point: Q_inner, Q_outer (rows, Z) contact loads [N]; Fr, Fa the
    radial and axial load on the set [N] (ISO 281)."""
    a1 = reliability_factor(inputs.reliability_percent)
    Z = g.balls
    Qi = np.maximum(np.asarray(Q_inner, float), 0.0)
    Qo = np.maximum(np.asarray(Q_outer, float), 0.0)
    Qei = (np.sum(Qi ** 3, axis=-1) / Z) ** (1.0 / 3.0)
    Qee = (np.sum(Qo ** (10.0 / 3.0), axis=-1) / Z) ** 0.3
    try:
        C_row = inputs.dynamic_load_rating_N or row_load_rating_N(g)
    except ValueError as exc:
        log.info("no ISO 281 load rating: %s", exc)
        nan = float("nan")
        return Lives(C_row_N=nan, C_set_N=nan, equivalent_load_N=nan, L10_iso281_Mrev=None, L10r_iso16281_Mrev=None,
                     a1=a1, Q_ci_N=nan, Q_ce_N=nan, Q_ei_N=Qei, Q_ee_N=Qee)
    C_set = g.rows ** 0.7 * C_row
    P = equivalent_load_N(g, Fr, Fa)
    if P is None:
        log.info("ISO 281 X, Y factors not tabulated here for %.3g deg: no ISO 281 life",
                 math.degrees(g.contact_angle_rad))
        L10 = None
    else:
        L10 = math.inf if P <= 0.0 else (C_set / P) ** 3
    q_ci, q_ce = contact_ratings_N(g, C_row)
    damage = np.sum((Qei / q_ci) ** (10.0 / 3.0) + (Qee / q_ce) ** (10.0 / 3.0))
    L10r = math.inf if damage <= 0.0 else float(damage ** (-0.9))
    return Lives(C_row_N=float(C_row), C_set_N=float(C_set), equivalent_load_N=float("nan") if P is None else float(P),
                 L10_iso281_Mrev=L10, L10r_iso16281_Mrev=L10r, a1=a1, Q_ci_N=q_ci, Q_ce_N=q_ce,
                 Q_ei_N=Qei, Q_ee_N=Qee)
