"""Geometry of a ball bearing (single row or matched set) in SI: rows, grooves, Hertz constants.

Meridional plane of one ball (Jones 1960; Harris and Kotzalas 2007, *Advanced Concepts of
Bearing Technology*, ch. 3, "inner and outer raceway groove curvature centre loci").  In the
plane through the bearing axis and the ball centre, coordinates (a, r): a axial, positive in
the row's contact direction s (s = +1 when the row carries the shaft's +z thrust), r radial,
positive outwards.  The outer groove has its curvature centre O_o (radius r_o = f_o D), the
inner groove O_i (r_i = f_i D).  A ball touching both grooves lies on the line O_o -> O_i,
whose length is then A0 = r_o + r_i - D = B D, B = f_i + f_o - 1, and whose direction is the
contact angle: O_i - O_o = A0 (sin alpha, cos alpha).

Reference state (outer ring fixed, inner ring concentric, no load): O_i - O_o =
(A0 sin alpha0, A0 cos alpha0 - P_d / 2), where alpha0 = ``contact_angle_rad`` is the free
contact angle the bearing is made with (0 for a deep-groove bearing) and P_d =
``clearance_m`` the operating radial (diametral) clearance, i.e. the total radial play of the
inner ring (negative = interference from fits and temperature).  With P_d = 0 every ball just
touches both grooves at alpha0; a deep-groove bearing (alpha0 = 0) with P_d > 0 takes the
classical free contact angle cos alpha_f = 1 - P_d / (2 A0) once its axial play is taken up
(Harris and Kotzalas 2007, *Essential Concepts*, eq. 2.11).  In general alpha_f = arccos of
(A0 cos alpha0 - P_d / 2) / A0, the "mounted free contact angle" used below for the Hertz
curvatures and the kinematic (catalogue) frequencies.

Rows of a set.  Rows sit at z_k = (k - (n - 1) / 2) * spacing about the node (k = 0 at the
smallest z).  DB (back-to-back, "O"): the contact lines of the two groups diverge outwards,
so the rows at z < 0 carry +z thrust (s = +1) and those at z > 0 carry -z thrust; DF
(face-to-face, "X") is the mirror; DT (tandem) has every row in one direction.  With three rows
(e.g. DB: tandem pair against one row) the pair carries the thrust direction ``direction``.

Hertz constants.  Ball against raceway (Harris and Kotzalas, *Essential Concepts*, ch. 2 and
6): curvature sums in the rolling plane (2/D)/(1 -/+ gamma) (inner -, outer +) and across the
groove (2 - 1/f)/D, gamma = D cos alpha / d_m.  They are evaluated once at alpha_f (the
contact angle changes K by less than 0.2 % between 8 and 27 deg for the default bearing; the
bench script prints it) with the exact elliptic integrals of :func:`spindlesim.contact.hertz.point_contact`,
giving Q = K delta^1.5 and the semi-axes and peak pressure at 1 N, which scale as Q^(1/3).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...contact.hertz import combined_modulus, point_contact, series_stiffness
from ..rolling import pitch_ratio

ARRANGEMENTS = ("single", "DB", "DF", "DT")


@dataclass(frozen=True)
class Material:
    """Elastic and mass properties of one body (SI)."""

    E_Pa: float
    poisson: float
    density_kg_m3: float


@dataclass(frozen=True)
class HertzUnit:
    """Hertz solution of one ball/raceway contact at a load of 1 N: a = a1 Q^(1/3), b = b1 Q^(1/3),
    p0 = p1 Q^(1/3), delta = (Q / K)^(2/3)."""

    K: float   # [N/m^1.5]
    a1: float  # [m N^-1/3] semi-axis across the rolling direction (the long one)
    b1: float  # [m N^-1/3] semi-axis along the rolling direction
    p1: float  # [Pa N^-1/3]


@dataclass(frozen=True)
class BallGeometry:
    """Bearing (set) geometry in SI plus everything the kernels need, computed once."""

    balls: int                      # Z, per row
    ball_diameter_m: float          # D
    pitch_diameter_m: float         # d_m
    contact_angle_rad: float        # alpha0, free contact angle as made
    inner_conformity: float         # f_i = r_i / D
    outer_conformity: float         # f_o = r_o / D
    clearance_m: float              # P_d, operating radial (diametral) clearance
    ring: Material
    ball: Material
    arrangement: str                # single | DB | DF | DT
    row_z_m: np.ndarray             # (n,) axial position of each ball row from the node
    row_sign: np.ndarray            # (n,) +1 / -1: thrust direction each row carries
    # derived
    E_star_Pa: float                # 1/E* = (1 - nu_b^2)/E_b + (1 - nu_r^2)/E_r
    groove_distance_m: float        # A0 = (f_i + f_o - 1) D
    reference_axial_m: float        # A0 sin alpha0
    reference_radial_m: float       # A0 cos alpha0 - P_d / 2
    mounted_angle_rad: float        # alpha_f
    inner_centre_radius_m: float    # radius of the inner groove curvature-centre locus
    inner_centre_offset_m: float    # axial offset of that locus from the ball row (times s)
    ball_mass_kg: float
    ball_inertia_kg_m2: float       # J = m D^2 / 10
    inner: HertzUnit
    outer: HertzUnit
    K_series: float                 # both contacts in series (rest, both loads equal)

    @property
    def rows(self) -> int:
        return int(self.row_z_m.size)

    @property
    def gamma(self) -> float:
        """D cos(alpha_f) / d_m."""
        return pitch_ratio(self.ball_diameter_m, self.mounted_angle_rad, self.pitch_diameter_m)

    @property
    def inner_groove_radius_m(self) -> float:
        return self.inner_conformity * self.ball_diameter_m

    @property
    def outer_groove_radius_m(self) -> float:
        return self.outer_conformity * self.ball_diameter_m

    def cage_ratio(self) -> float:
        """Cage speed / shaft speed, outer ring fixed, pure rolling at alpha_f: (1 - gamma) / 2."""
        return 0.5 * (1.0 - self.gamma)

    def kinematic_frequencies_hz(self, speed_rad_s: float) -> dict[str, float]:
        """Catalogue (kinematic) frequencies at alpha_f, outer ring fixed (Harris and Kotzalas,
        *Essential Concepts*, ch. 8): cage f_c = f (1 - gamma)/2, ball pass outer Z f_c, ball pass
        inner Z (f - f_c), ball spin (d_m / 2D) f (1 - gamma^2)."""
        f = abs(speed_rad_s) / (2.0 * math.pi)
        g = self.gamma
        fc = 0.5 * f * (1.0 - g)
        return {
            "shaft": f,
            "cage": fc,
            "ball_pass_outer": self.balls * fc,
            "ball_pass_inner": self.balls * (f - fc),
            "ball_spin": 0.5 * self.pitch_diameter_m / self.ball_diameter_m * f * (1.0 - g * g),
        }


def row_layout(arrangement: str, rows: int, spacing_m: float, direction: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """(z_k, s_k) of the rows of an arrangement; see the module docstring."""
    if arrangement not in ARRANGEMENTS:
        raise ValueError(f"arrangement must be one of {ARRANGEMENTS}, not {arrangement!r}")
    if direction not in (1, -1):
        raise ValueError("direction must be +1 or -1")
    if arrangement == "single":
        if rows != 1:
            raise ValueError("a single bearing has one row")
        return np.zeros(1), np.array([direction], dtype=np.int64)
    if not 2 <= rows <= 4:
        raise ValueError("a set has 2 to 4 rows")
    z = (np.arange(rows) - 0.5 * (rows - 1)) * spacing_m
    if arrangement == "DT":
        return z, np.full(rows, direction, dtype=np.int64)
    n_plus = rows // 2 if rows % 2 == 0 else (rows // 2 + 1 if direction > 0 else rows // 2)
    if arrangement == "DB":  # +z-thrust rows on the z < 0 side
        s = np.array([1 if k < n_plus else -1 for k in range(rows)], dtype=np.int64)
    else:  # DF: -z-thrust rows on the z < 0 side
        s = np.array([-1 if k < rows - n_plus else 1 for k in range(rows)], dtype=np.int64)
    return z, s


def _hertz_unit(curv_roll: float, curv_cross: float, e_star: float) -> HertzUnit:
    a, b, delta, p0 = point_contact(1.0, curv_roll, curv_cross, e_star)
    return HertzUnit(K=float(delta ** -1.5), a1=float(a), b1=float(b), p1=float(p0))


def ball_geometry(*, balls: int, ball_diameter_m: float, pitch_diameter_m: float, contact_angle_deg: float,
                  inner_conformity: float, outer_conformity: float, clearance_m: float = 0.0,
                  ring: Material = Material(208e9, 0.3, 7850.0), ball: Material | None = None,
                  arrangement: str = "single", rows: int = 1, row_spacing_m: float = 0.0,
                  direction: int = 1) -> BallGeometry:
    """Build the geometry from catalogue-style data (SI except the angle); checks consistency."""
    D, dm = float(ball_diameter_m), float(pitch_diameter_m)
    Z = int(balls)
    ball = ring if ball is None else ball
    if Z < 3:
        raise ValueError("need at least 3 balls per row")
    if not 0.0 < D < 0.5 * dm:
        raise ValueError("ball diameter must be positive and below half the pitch diameter")
    if 2.0 * (0.5 * dm) * math.sin(math.pi / Z) <= D:
        raise ValueError(f"{Z} balls of {D * 1e3:g} mm do not fit on a {dm * 1e3:g} mm pitch circle")
    if not (inner_conformity > 0.5 and outer_conformity > 0.5):
        raise ValueError("groove conformities f = r / D must exceed 0.5")
    if not 0.0 <= contact_angle_deg < 60.0:
        raise ValueError("contact angle must be in [0, 60) deg")
    alpha0 = math.radians(contact_angle_deg)
    A0 = (inner_conformity + outer_conformity - 1.0) * D
    a_ax = A0 * math.sin(alpha0)
    a_rad = A0 * math.cos(alpha0) - 0.5 * clearance_m
    if a_rad <= 0.5 * A0:
        raise ValueError("radial clearance too large for the grooves (free contact angle above 60 deg)")
    if clearance_m == 0.0:
        alpha_f = alpha0
    elif a_rad < A0:  # play: the contact angle once the axial play is taken up
        alpha_f = math.acos(a_rad / A0)
    else:  # interference: the angle of the groove-centre line in the reference state
        alpha_f = math.atan2(a_ax, a_rad)
    z, s = row_layout(arrangement, rows, row_spacing_m, direction)
    e_star = combined_modulus(ball.E_Pa, ball.poisson, ring.E_Pa, ring.poisson)
    g = pitch_ratio(D, alpha_f, dm)
    inner = _hertz_unit((2.0 / D) / (1.0 - g), (2.0 - 1.0 / inner_conformity) / D, e_star)
    outer = _hertz_unit((2.0 / D) / (1.0 + g), (2.0 - 1.0 / outer_conformity) / D, e_star)
    mass = ball.density_kg_m3 * math.pi * D ** 3 / 6.0
    ri = inner_conformity * D
    return BallGeometry(
        balls=Z, ball_diameter_m=D, pitch_diameter_m=dm, contact_angle_rad=alpha0,
        inner_conformity=float(inner_conformity), outer_conformity=float(outer_conformity),
        clearance_m=float(clearance_m), ring=ring, ball=ball, arrangement=arrangement,
        row_z_m=z, row_sign=s, E_star_Pa=e_star, groove_distance_m=A0, reference_axial_m=a_ax,
        reference_radial_m=a_rad, mounted_angle_rad=alpha_f,
        inner_centre_radius_m=0.5 * dm + (ri - 0.5 * D) * math.cos(alpha_f),
        inner_centre_offset_m=(ri - 0.5 * D) * math.sin(alpha_f),
        ball_mass_kg=mass, ball_inertia_kg_m2=mass * D * D / 10.0, inner=inner, outer=outer,
        K_series=series_stiffness(inner.K, outer.K, 1.5),
    )
