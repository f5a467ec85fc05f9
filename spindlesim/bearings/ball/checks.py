"""What a ball state says about itself: which race controls the ball (Jones' criterion), and whether
the contact ellipse runs over the shoulder of its groove (truncation).

Jones' race-control criterion (Jones 1959/1960; Harris and Kotzalas 2007, *Advanced Concepts*, ch. 2):
a contact in full spin slip resists spin with the moment M_s = (3/8) mu Q a E(k) (a the semi-axis
across the rolling direction, E the complete elliptic integral of the second kind of the ellipse's
eccentricity k^2 = 1 - (b/a)^2).  If the ball rolls without spin on the outer race, the inner
contact slips and puts M_si on the ball along n_i; the outer contact must hold its component along
n_o, M_si cos(a_i - a_o).  So outer-race control is possible when M_so >= M_si cos(a_i - a_o) and
inner-race control when M_si >= M_so cos(a_i - a_o); with the same mu at both contacts mu cancels.
When both hold the criterion does not decide (the contacts are about equal).

Truncation: in the meridional plane the groove is an arc of radius r = f D about its curvature
centre, and a contact at angle a is centred at the point of that arc at a from the radial
direction.  The Hertz ellipse's semi-axis a_H lies along the groove (across rolling), so the
contact reaches the angle a + asin(a_H / r) (the edge of the ellipse projected back onto the arc).
The shoulder of height h above the groove bottom ends at the angle theta_s = arccos(1 - h / r)
(same centre, same reference).  The contact is truncated when a + asin(a_H / r) > theta_s: the
pressure there is no longer Hertz's (edge stress).  Checked on the thrust side (the high shoulder
of an angular-contact ring; either side of a deep-groove ring); a ball running on the other side of
an angular-contact groove is warned about separately.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.special import ellipe

#: default shoulder height of both rings as a fraction of the ball diameter (docs/theory.md, "Truncation")
TYPICAL_SHOULDER_FRACTION = 0.3

OUTER, EITHER, INNER = 1, 0, -1


@dataclass(frozen=True)
class Shoulders:
    """Thrust-side shoulder of each ring: the angle at its groove centre where the groove ends [rad],
    and the height above the groove bottom it corresponds to [m]; ``source`` says where they came from."""

    inner_angle_rad: float
    outer_angle_rad: float
    inner_height_m: float
    outer_height_m: float
    source: str = "deck"


def shoulder_angle(height_m: float, groove_radius_m: float) -> float:
    """theta_s = arccos(1 - h / r); ValueError unless 0 < h < r (a shoulder above the groove centre)."""
    if not 0.0 < height_m < groove_radius_m:
        raise ValueError(f"a shoulder height must lie between 0 and the groove radius {groove_radius_m * 1e3:.4g} mm "
                         f"(the groove ends at 90 deg there), not {height_m * 1e3:.4g} mm")
    return math.acos(1.0 - height_m / groove_radius_m)


def shoulder_height(angle_rad: float, groove_radius_m: float) -> float:
    return groove_radius_m * (1.0 - math.cos(angle_rad))


def shoulders_of(geometry, inner_height_m=None, outer_height_m=None, inner_angle_rad=None,
                 outer_angle_rad=None) -> Shoulders:
    """Shoulders from heights or angles (per ring, one of the two); a ring given neither takes
    TYPICAL_SHOULDER_FRACTION of the ball diameter."""
    D = geometry.ball_diameter_m
    out, defaulted = {}, []
    for side, r, h, a in (("inner", geometry.inner_groove_radius_m, inner_height_m, inner_angle_rad),
                          ("outer", geometry.outer_groove_radius_m, outer_height_m, outer_angle_rad)):
        if h is not None and a is not None:
            raise ValueError(f"give the {side} shoulder as a height or as an angle, not both")
        if a is not None:
            if not 0.0 < a < 0.5 * math.pi:
                raise ValueError(f"the {side} shoulder angle must lie between 0 and 90 deg")
            out[side] = (a, shoulder_height(a, r))
            continue
        if h is None:
            h = TYPICAL_SHOULDER_FRACTION * D
            defaulted.append(side)
        out[side] = (shoulder_angle(h, r), h)
    source = "deck" if not defaulted else (
        f"{' and '.join(defaulted)} at the typical {TYPICAL_SHOULDER_FRACTION:g} D (no shoulder in the deck)")
    return Shoulders(out["inner"][0], out["outer"][0], out["inner"][1], out["outer"][1], source)


def edge_angles_deg(contact_angle_deg, semi_axis_m, groove_radius_m: float, symmetric: bool) -> np.ndarray:
    """Angle the ellipse reaches on the side of the shoulder it is checked against [deg]: a + asin(a_H / r)
    on the thrust side; for a symmetric (deep-groove) groove on the side the ball runs on, a - asin(a_H / r)
    when a < 0."""
    alpha = np.asarray(contact_angle_deg, float)
    half = np.degrees(np.arcsin(np.minimum(np.asarray(semi_axis_m, float) / groove_radius_m, 1.0)))
    return alpha + np.where(symmetric & (alpha < 0.0), -half, half)


def truncated(edge_deg, shoulder_rad: float, load_N, symmetric: bool) -> np.ndarray:
    """Loaded contacts whose ellipse runs over the shoulder (for a symmetric groove on either side: the
    other side has the same shoulder)."""
    edge = np.asarray(edge_deg, float)
    return (np.asarray(load_N) > 0.0) & ((np.abs(edge) if symmetric else edge) > math.degrees(shoulder_rad))


def elliptic_E(geometry) -> tuple[float, float]:
    """E(k) of the inner and outer contact ellipses (their b/a does not change with the load)."""
    return tuple(float(ellipe(1.0 - (u.b1 / u.a1) ** 2)) for u in (geometry.inner, geometry.outer))


def spin_moments(geometry, Qi, Qo, semi_inner, semi_outer) -> tuple[np.ndarray, np.ndarray]:
    """(3/8) Q a E(k) at the inner and outer contacts [N m]: the full-slip spin moment per unit friction
    coefficient."""
    Ei, Eo = elliptic_E(geometry)
    return (0.375 * np.asarray(Qi) * np.asarray(semi_inner)[..., 0] * Ei,
            0.375 * np.asarray(Qo) * np.asarray(semi_outer)[..., 0] * Eo)


def race_control_criterion(Msi, Mso, contact_angle_inner_deg, contact_angle_outer_deg) -> np.ndarray:
    """Per ball: OUTER (1) when only outer-race control is possible, INNER (-1) when only inner, EITHER (0)
    when both are (module docstring)."""
    c = np.cos(np.radians(np.asarray(contact_angle_inner_deg) - np.asarray(contact_angle_outer_deg)))
    outer_ok = Mso >= Msi * c
    inner_ok = Msi >= Mso * c
    return np.where(outer_ok & ~inner_ok, OUTER, np.where(inner_ok & ~outer_ok, INNER, EITHER)).astype(np.int8)
