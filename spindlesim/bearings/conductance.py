"""Internal conductances of a rolling bearing in the spindle's thermal network: inner ring -- rolling elements --
outer ring, and rolling elements -- bearing cavity (oil-air), SI.  The families' contact paths
(:class:`BallContactPaths`, :class:`RollerContactPaths`) answer the network's question (the protocol
:class:`spindlesim.thermal.layout.ContactPaths`): each bearing set carries its family's.

Model (the two paths of the spindle-bearing networks of Stein and Tu 1994 and Bossmanns and Tu
1999, contact conduction and convection to the lubricant; the formulas below are taken from their
primary sources, the assembly is ours):

1. Conduction through each Hertz contact ellipse (semi-axes a >= b).  The constriction resistance
   of an isothermal elliptical contact on a half-space is R = K(e) / (2 pi k a) with K the complete
   elliptic integral of the first kind, e^2 = 1 - (b/a)^2 (Holm, Electric Contacts, 1967; for a
   circle R = 1/(4 k a)); ball and race are in series, R_c = K(e)/(2 pi a) (1/k_ball + 1/k_race).
   An EHL film of thickness h in the contact adds R_f = h / (k_lub pi a b) in series.  The
   ring-to-balls conductance is the sum over all loaded contacts of 1 / (R_c + R_f): it follows
   the ball loads (preload, centrifugal force) the caller gives, and the film (speed).
2. Convection from the balls to the oil-air in the bearing cavity, h from Whitaker's sphere
   correlation with the ball's spin surface speed u = omega_ball D / 2, omega_ball =
   (d_m / 2D) omega (1 - gamma^2), gamma = D cos(alpha) / d_m (pure rolling, outer ring fixed;
   Harris and Kotzalas), on the ball surface Z pi D^2.

Roller bearings (cylindrical, tapered): each roller touches a race on a strip of length l (the roller's)
and Hertz half-width b = sqrt(8 Q R_x / (pi l E')) (line contact, E' = 2 E*; Johnson 1985, section 4.2,
R_x = (D/2)(1 -+ gamma)), taken as the ellipse of the same semi-axes l/2 and b in Holm's formula (for a long
strip K(e) -> ln(4 a / b): R = ln(2 l / b) / (pi k l), the constriction of a long strip); the film adds
h / (k_lub pi (l/2) b).  Convection of the rollers to the oil-air: a cylinder spinning at its roller speed
(:func:`spindlesim.thermal.convection.rotating_shaft_h` of the roller's diameter), on its mantle and ends.

Contact ellipses from the ball loads: Hamrock and Brewe's approximations (J. Lubr. Technol. 105
(1983) 171-177) of the Hertz solution, k = a/b = 1.0339 (R_y/R_x)^0.636, E(k) = 1.0003 + 0.5968
R_x/R_y, a = (6 k^2 E Q R / (pi E'))^(1/3), b = (6 E Q R / (pi k E'))^(1/3), 1/R = 1/R_x + 1/R_y,
with R_x = (D/2)(1 -+ gamma) (inner/outer race, rolling direction) and R_y = f D / (2 f - 1)
(across; f the groove conformity): :func:`spindlesim.contact.hertz.point_contact_semi_axes_estimate`, the one
routine of it, within a few per cent of the exact ellipse (:func:`spindlesim.contact.hertz.point_contact`, tested).
gamma = D cos(alpha) / d_m is :func:`spindlesim.bearings.rolling.pitch_ratio`.

Film thickness: :func:`central_film_thickness` gives Hamrock and Dowson's central film
(J. Lubr. Technol. 99 (1977) 264-276): H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)),
U = eta0 u / (E' R_x), G = alpha E', W = Q / (E' R_x^2), k = 1.0339 (R_y/R_x)^0.636, h_c = H_c R_x
(E' = 2 E*, u the mean entrainment speed).

docs/theory.md, "Ball bearing internal conductances".
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..contact.hertz import ellipticity_estimate, point_contact_semi_axes_estimate
from ..thermal.convection import rotating_shaft_h, whitaker_sphere_nusselt
from ..thermal.layout import BearingConductances, BearingSet
from ..thermal.properties import FluidProperties, air, clip_air_C
from .rolling import pitch_ratio

#: conductivity of a mineral spindle oil [W/(m K)] (0.12-0.15 for mineral oils)
OIL_CONDUCTIVITY_W_MK = 0.13


def ellipse_constriction_resistance(a_m, b_m, conductivity_W_mK: float):
    """K(e) / (2 pi k a) [K/W] of an isothermal ellipse on a half-space (a, b semi-axes, any order)."""
    from scipy.special import ellipk

    a = np.maximum(np.asarray(a_m, dtype=float), np.asarray(b_m, dtype=float))
    b = np.minimum(np.asarray(a_m, dtype=float), np.asarray(b_m, dtype=float))
    if np.any(b <= 0.0):
        raise ValueError("contact semi-axes must be > 0")
    return ellipk(1.0 - (b / a) ** 2) / (2.0 * math.pi * conductivity_W_mK * a)


def contact_conductance(a_m, b_m, k_ball_W_mK: float, k_race_W_mK: float, film_m=0.0,
                        k_lubricant_W_mK: float = OIL_CONDUCTIVITY_W_MK):
    """Conductance [W/K] of ball-race contacts: constriction on both sides plus the EHL film."""
    a = np.asarray(a_m, dtype=float)
    b = np.asarray(b_m, dtype=float)
    r = ellipse_constriction_resistance(a, b, 1.0) * (1.0 / k_ball_W_mK + 1.0 / k_race_W_mK)
    r = r + np.asarray(film_m, dtype=float) / (k_lubricant_W_mK * math.pi * a * b)
    return 1.0 / r


def race_radii(ball_diameter_m: float, pitch_diameter_m: float, contact_angle_rad: float, conformity: float,
               race: str) -> tuple[float, float]:
    """(R_x, R_y) [m] of the ball's contact with the ``race`` ("inner" or "outer")."""
    g = pitch_ratio(ball_diameter_m, contact_angle_rad, pitch_diameter_m)
    sign = {"inner": -1.0, "outer": 1.0}[race]
    return 0.5 * ball_diameter_m * (1.0 + sign * g), conformity * ball_diameter_m / (2.0 * conformity - 1.0)


def contact_ellipse_unit(rx_m: float, ry_m: float, e_prime_Pa: float) -> tuple[float, float]:
    """(a1, b1) with a = a1 Q^(1/3), b = b1 Q^(1/3) (a across the rolling direction): the ellipse of a unit load,
    :func:`spindlesim.contact.hertz.point_contact_semi_axes_estimate` (E* = E' / 2)."""
    along, across = point_contact_semi_axes_estimate(1.0, rx_m, ry_m, 0.5 * e_prime_Pa)
    return across, along


def ball_spin_surface_speed(speed_rad_s: float, ball_diameter_m: float, pitch_diameter_m: float,
                            contact_angle_rad: float) -> float:
    """omega_ball D / 2 [m/s], omega_ball = (d_m / 2D) omega (1 - gamma^2)."""
    g = pitch_ratio(ball_diameter_m, contact_angle_rad, pitch_diameter_m)
    w_ball = 0.5 * pitch_diameter_m / ball_diameter_m * abs(speed_rad_s) * (1.0 - g * g)
    return 0.5 * w_ball * ball_diameter_m


def ball_convection_h(ball_diameter_m: float, surface_speed_m_s: float, medium: FluidProperties) -> float:
    """h [W/(m^2 K)] between a ball and the bearing's oil-air (Whitaker's sphere correlation)."""
    re = surface_speed_m_s * ball_diameter_m / medium.kinematic_viscosity_m2_s
    return whitaker_sphere_nusselt(re, medium.prandtl) * medium.conductivity_W_mK / ball_diameter_m


def central_film_thickness(entrainment_speed_m_s: float, viscosity_Pa_s: float, pressure_viscosity_1_Pa: float,
                           e_prime_Pa: float, rx_m: float, ry_m: float, load_N: float) -> float:
    """Hamrock-Dowson central film thickness [m] of an EHL point contact (module docstring)."""
    if load_N <= 0.0 or entrainment_speed_m_s <= 0.0:
        return 0.0
    U = viscosity_Pa_s * entrainment_speed_m_s / (e_prime_Pa * rx_m)
    G = pressure_viscosity_1_Pa * e_prime_Pa
    W = load_N / (e_prime_Pa * rx_m * rx_m)
    k = ellipticity_estimate(rx_m, ry_m)
    return 2.69 * U ** 0.67 * G ** 0.53 * W ** -0.067 * (1.0 - 0.61 * math.exp(-0.73 * k)) * rx_m


def ball_bearing_conductances(*, speed_rad_s: float, balls: int, ball_diameter_m: float, pitch_diameter_m: float,
                              contact_angle_rad: float, inner_axes_m: tuple, outer_axes_m: tuple,
                              k_ball_W_mK: float, k_ring_W_mK: float, medium: FluidProperties,
                              film_inner_m=0.0, film_outer_m=0.0,
                              k_lubricant_W_mK: float = OIL_CONDUCTIVITY_W_MK) -> BearingConductances:
    """Conductances of a bearing whose ``balls`` (all rows) touch the races on ellipses with
    semi-axes ``inner_axes_m = (a, b)`` and ``outer_axes_m`` (scalars: every ball alike, or arrays
    of one entry per ball; an unloaded ball has a = b = 0 and conducts nothing through it)."""
    def ring(axes, film):
        a = np.broadcast_to(np.asarray(axes[0], dtype=float), (balls,))
        b = np.broadcast_to(np.asarray(axes[1], dtype=float), (balls,))
        f = np.broadcast_to(np.asarray(film, dtype=float), (balls,))
        on = (a > 0.0) & (b > 0.0)
        if not on.any():
            return 0.0
        return float(np.sum(contact_conductance(a[on], b[on], k_ball_W_mK, k_ring_W_mK, f[on], k_lubricant_W_mK)))

    u = ball_spin_surface_speed(speed_rad_s, ball_diameter_m, pitch_diameter_m, contact_angle_rad)
    h = ball_convection_h(ball_diameter_m, u, medium)
    return BearingConductances(ring(inner_axes_m, film_inner_m), ring(outer_axes_m, film_outer_m),
                               h * balls * math.pi * ball_diameter_m ** 2)


def line_contact_half_width(load_N, rx_m: float, length_m: float, e_prime_Pa: float):
    """Hertz half-width b [m] of a line contact: sqrt(8 Q R_x / (pi l E')) (module docstring); 0 unloaded."""
    q = np.maximum(np.asarray(load_N, dtype=float), 0.0)
    return np.sqrt(8.0 * q * rx_m / (math.pi * length_m * e_prime_Pa))


def roller_spin_speed(speed_rad_s: float, roller_diameter_m: float, pitch_diameter_m: float,
                      contact_angle_rad: float) -> float:
    """Roller spin [rad/s]: (d_m / 2D) omega (1 - gamma^2), gamma = D cos(alpha) / d_m (pure rolling)."""
    g = pitch_ratio(roller_diameter_m, contact_angle_rad, pitch_diameter_m)
    return 0.5 * pitch_diameter_m / roller_diameter_m * abs(speed_rad_s) * (1.0 - g * g)


def roller_bearing_conductances(*, speed_rad_s: float, rollers: int, roller_diameter_m: float, roller_length_m: float,
                                pitch_diameter_m: float, contact_angle_rad: float, inner_half_width_m,
                                outer_half_width_m, k_roller_W_mK: float, k_ring_W_mK: float, medium_h,
                                film_inner_m=0.0, film_outer_m=0.0,
                                k_lubricant_W_mK: float = OIL_CONDUCTIVITY_W_MK) -> BearingConductances:
    """Conductances of a roller bearing whose ``rollers`` (all rows) touch the races on strips of the
    roller length and half-widths ``inner_half_width_m`` / ``outer_half_width_m`` (per roller, or one for
    all; 0: unloaded); ``medium_h(diameter_m, spin_rad_s)``: h [W/(m^2 K)] of a spinning cylinder in the
    cavity."""
    half = 0.5 * roller_length_m

    def ring(widths, film):
        b = np.broadcast_to(np.asarray(widths, dtype=float), (rollers,))
        f = np.broadcast_to(np.asarray(film, dtype=float), (rollers,))
        on = b > 0.0
        if not on.any():
            return 0.0
        return float(np.sum(contact_conductance(np.full(int(on.sum()), half), b[on], k_roller_W_mK, k_ring_W_mK,
                                                f[on], k_lubricant_W_mK)))

    spin = roller_spin_speed(speed_rad_s, roller_diameter_m, pitch_diameter_m, contact_angle_rad)
    area = rollers * (math.pi * roller_diameter_m * roller_length_m + 0.5 * math.pi * roller_diameter_m ** 2)
    return BearingConductances(ring(inner_half_width_m, film_inner_m), ring(outer_half_width_m, film_outer_m),
                               medium_h(roller_diameter_m, spin) * area)


# ---- the families' contact paths: what the spindle's network asks a bearing set -----------------------------
def contact_modulus_prime(s: BearingSet) -> float:
    """E' = 2 E* [Pa] of the rolling elements on the rings of the set ``s``."""
    return 2.0 / ((1.0 - s.ring_poisson ** 2) / s.ring_E_Pa + (1.0 - s.ball_poisson ** 2) / s.ball_E_Pa)


@dataclass(frozen=True)
class BallContactPaths:
    """A ball set's paths (:class:`spindlesim.thermal.layout.ContactPaths`): Hertz point contacts whose ellipses
    scale as Q^(1/3) (``*_unit_m``: the semi-axes (across, along rolling) of a 1 N contact), and the balls'
    convection to the oil-air.  :meth:`of` computes them from the set."""

    inner_unit_m: tuple[float, float]
    outer_unit_m: tuple[float, float]
    elements: str = "balls"

    @classmethod
    def of(cls, s: BearingSet) -> "BallContactPaths":
        e_prime = contact_modulus_prime(s)
        args = (s.ball_diameter_m, s.pitch_diameter_m, s.contact_angle_rad)
        r_i, r_o = race_radii(*args, s.inner_conformity, "inner"), race_radii(*args, s.outer_conformity, "outer")
        return cls(contact_ellipse_unit(*r_i, e_prime), contact_ellipse_unit(*r_o, e_prime))

    def elements_mass_kg(self, s: BearingSet) -> float:
        return s.balls * s.ball.density_kg_m3 * math.pi * s.ball_diameter_m ** 3 / 6.0

    def conductances(self, s: BearingSet, speed_rad_s: float, inner_N, outer_N, film_inner_m, film_outer_m,
                     cavity_C: float) -> BearingConductances:
        (a1i, b1i), (a1o, b1o) = self.inner_unit_m, self.outer_unit_m
        qi, qo = np.maximum(inner_N, 0.0) ** (1.0 / 3.0), np.maximum(outer_N, 0.0) ** (1.0 / 3.0)
        return ball_bearing_conductances(
            speed_rad_s=speed_rad_s, balls=s.balls, ball_diameter_m=s.ball_diameter_m,
            pitch_diameter_m=s.pitch_diameter_m, contact_angle_rad=s.contact_angle_rad,
            inner_axes_m=(a1i * qi, b1i * qi), outer_axes_m=(a1o * qo, b1o * qo), k_ball_W_mK=s.ball.conductivity_W_mK,
            k_ring_W_mK=s.ring.conductivity_W_mK, medium=air(clip_air_C(cavity_C)), film_inner_m=film_inner_m,
            film_outer_m=film_outer_m)


@dataclass(frozen=True)
class RollerContactPaths:
    """A roller set's paths (:class:`spindlesim.thermal.layout.ContactPaths`): line contacts of the rollers'
    length ``length_m`` on rolling radii R_x (inner, outer) with the modulus E', and the rollers' convection
    as spinning cylinders.  :meth:`of` computes them from the set (the rollers' mean diameter its
    ``ball_diameter_m``, a tapered roller bearing's cup angle its contact angle)."""

    length_m: float
    inner_rx_m: float
    outer_rx_m: float
    e_prime_Pa: float
    elements: str = "rollers"

    def __post_init__(self) -> None:
        if self.length_m <= 0.0:
            raise ValueError("a roller set needs its roller length")

    @classmethod
    def of(cls, s: BearingSet, length_m: float) -> "RollerContactPaths":
        args = (s.ball_diameter_m, s.pitch_diameter_m, s.contact_angle_rad)
        return cls(length_m, race_radii(*args, s.inner_conformity, "inner")[0],
                   race_radii(*args, s.outer_conformity, "outer")[0], contact_modulus_prime(s))

    def elements_mass_kg(self, s: BearingSet) -> float:
        volume = 0.25 * math.pi * s.ball_diameter_m ** 2 * self.length_m
        return s.balls * s.ball.density_kg_m3 * volume

    def conductances(self, s: BearingSet, speed_rad_s: float, inner_N, outer_N, film_inner_m, film_outer_m,
                     cavity_C: float) -> BearingConductances:
        length, e_prime = self.length_m, self.e_prime_Pa
        return roller_bearing_conductances(
            speed_rad_s=speed_rad_s, rollers=s.balls, roller_diameter_m=s.ball_diameter_m, roller_length_m=length,
            pitch_diameter_m=s.pitch_diameter_m, contact_angle_rad=s.contact_angle_rad,
            inner_half_width_m=line_contact_half_width(inner_N, self.inner_rx_m, length, e_prime),
            outer_half_width_m=line_contact_half_width(outer_N, self.outer_rx_m, length, e_prime),
            k_roller_W_mK=s.ball.conductivity_W_mK, k_ring_W_mK=s.ring.conductivity_W_mK,
            medium_h=lambda d, w: rotating_shaft_h(d, w, clip_air_C(cavity_C + 10.0), clip_air_C(cavity_C)),
            film_inner_m=film_inner_m, film_outer_m=film_outer_m)


def ball_set(*args, **kwargs) -> BearingSet:
    """A ball :class:`~spindlesim.thermal.layout.BearingSet` (its arguments) with its :class:`BallContactPaths`."""
    s = BearingSet(*args, **kwargs)
    return replace(s, paths=BallContactPaths.of(s))


def roller_set(*args, roller_length_m: float, **kwargs) -> BearingSet:
    """A roller :class:`~spindlesim.thermal.layout.BearingSet` with its :class:`RollerContactPaths`."""
    s = BearingSet(*args, **kwargs)
    return replace(s, paths=RollerContactPaths.of(s, roller_length_m))
