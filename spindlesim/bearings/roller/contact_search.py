"""Roller to outer race contact search, seed 000 eqs. 18-29 (planar form).

The housing body j carries the frame A_j (identity for a fixed housing).  For
roller i at r_i:

    d_ji  = r_i - r_j                                  (eq. 18)
    d'_ji = A_j^T d_ji                                 (eq. 19)
    l     = sqrt(d'_x^2 + d'_y^2)                      (eq. 20)
    D_j   = [f', g', h'],  f' = [d'_x/l, d'_y/l, 0], g' = [0, 0, 1], h' = f' x g'   (eqs. 21-24)
    s'_j  = (R_j1 + v) f'                              (eq. 25)
    k'    = d'_ji - s'_j,  k'' = D_j^T k'              (eqs. 26-27)
    contact if sqrt(k''_x^2 + k''_y^2) < R_i,  delta = R_i - sqrt(k''_x^2 + k''_y^2)   (eqs. 28-29)

R_j1 is the undeformed inner radius of the outer race and v the outward
radial displacement of the race surface on the line through the roller (the
segment motion plus the eq. 17 deflection, ``SegmentedRing.surface_operator``).
In the plane the axial component k''_y (along g') vanishes.  The roller
centre lies inside the race, k''_x < 0, so eq. 29 reads delta = R_i + k''_x;
we keep this signed form so a deeply penetrating roller cannot read as a
shallow contact.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class OuterContact:
    psi_rad: np.ndarray  # angle of the contact line in the housing frame
    normal: np.ndarray  # f' in the inertial frame [k, 2] (outward, from housing centre to roller)
    distance_m: np.ndarray  # l, eq. 20
    penetration_m: np.ndarray  # delta, eq. 29 (negative: gap)
    in_contact: np.ndarray  # eq. 28


def housing_frame_position(roller_xy: np.ndarray, housing_xy: np.ndarray | None = None,
                           housing_angle_rad: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """d'_ji in the housing frame (eqs. 18-19) and A_j; roller_xy [k, 2]."""
    c, s = np.cos(housing_angle_rad), np.sin(housing_angle_rad)
    A = np.array([[c, -s], [s, c]])
    d = np.asarray(roller_xy, float) - (np.zeros(2) if housing_xy is None else np.asarray(housing_xy, float))
    return d @ A, A  # rows: A^T d


def outer_race_contact(roller_xy: np.ndarray, roller_radius_m: float, race_inner_radius_m: float,
                       surface_displacement_m: np.ndarray, housing_xy: np.ndarray | None = None,
                       housing_angle_rad: float = 0.0) -> OuterContact:
    """Contact of rollers [k, 2] with the deformed outer race, eqs. 18-29."""
    dp, A = housing_frame_position(roller_xy, housing_xy, housing_angle_rad)
    l = np.hypot(dp[:, 0], dp[:, 1])  # eq. 20
    fp = dp / l[:, None]  # eq. 22 (planar part)
    hp = np.column_stack([fp[:, 1], -fp[:, 0]])  # eq. 24: f' x g' with g' = z
    sp = (race_inner_radius_m + surface_displacement_m)[:, None] * fp  # eq. 25
    kp = dp - sp  # eq. 26
    kx = np.sum(fp * kp, axis=1)  # eq. 27 (k''_x); k''_y (axial) = 0 in the plane
    kz = np.sum(hp * kp, axis=1)  # k''_z, zero by construction
    dist = np.hypot(kx, 0.0 * kz)
    in_contact = dist < roller_radius_m  # eq. 28
    delta = roller_radius_m + kx  # eq. 29 with k''_x < 0 (roller inside the race)
    return OuterContact(psi_rad=np.arctan2(dp[:, 1], dp[:, 0]), normal=fp @ A.T, distance_m=l,
                        penetration_m=delta, in_contact=in_contact & (delta > 0))
