"""Initial separation (gap) h(x, y) of roller/raceway and ball contacts, seed 001 eq. 42.

Axes: x across the contact (rolling direction), y along the roller axis, y = 0 at the
roller's mid-length.  Gaps are in metres, shifted so that the smallest gap over the
roller is zero (the additive constant only changes the reported approach).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from .hertz import line_contact

__all__ = ["RollerProfile", "equivalent_radius", "profile_drop", "roller_gap", "ball_gap"]

ProfileKind = Literal["straight", "crowned", "logarithmic"]


def equivalent_radius(roller_radius_m: float, raceway_radius_m: float = math.inf,
                      raceway: Literal["inner", "outer", "flat"] = "inner") -> float:
    """Equivalent radius R' [m] in the rolling direction.

    1/R' = 1/r_roller + 1/R_race on an inner (convex) raceway, 1/r_roller - 1/R_race on
    an outer (concave) raceway, 1/r_roller on a flat (Harris, Rolling Bearing Analysis,
    ch. 2; curvature sum in the plane of rolling).
    """
    if roller_radius_m <= 0:
        raise ValueError("roller radius must be positive")
    if raceway == "flat" or math.isinf(raceway_radius_m):
        return roller_radius_m
    if raceway_radius_m <= 0:
        raise ValueError("raceway radius must be positive")
    if raceway == "inner":
        inv = 1.0 / roller_radius_m + 1.0 / raceway_radius_m
    elif raceway == "outer":
        if raceway_radius_m <= roller_radius_m:
            raise ValueError("outer raceway radius must exceed the roller radius")
        inv = 1.0 / roller_radius_m - 1.0 / raceway_radius_m
    else:
        raise ValueError(f"raceway must be 'inner', 'outer' or 'flat', not {raceway!r}")
    return 1.0 / inv


@dataclass(frozen=True)
class RollerProfile:
    """Axial profile of a roller of effective length ``length_m``.

    kind:
      - ``straight``: no crown;
      - ``crowned``: circular crown, drop y^2 / (2 R_crown) from the mid-length
        (seed 001 eq. 1, the (z - l/2)^2 / 2R term);
      - ``logarithmic``: Lundberg's profile in the Johns-Gohar form (Johns and Gohar,
        Tribology International 14 (1981) 131-136),
        drop = Q_d / (pi l E*) ln(1 / (1 - (1 - (2 b_d / l)^2) (2 y / l)^2)),
        with Q_d the design load and b_d its Hertz half-width (finite drop at the ends).
    ``end_radius_m`` > 0 rounds each end with a corner arc of that radius tangent to the
    profile (drop r - sqrt(r^2 - s^2), s the distance into the rounded zone); 0 gives
    sharp ends.
    """

    length_m: float
    kind: ProfileKind = "straight"
    crown_radius_m: float | None = None
    design_load_N: float | None = None
    end_radius_m: float = 0.0

    def __post_init__(self) -> None:
        if self.length_m <= 0:
            raise ValueError("roller length must be positive")
        if self.kind == "crowned" and not (self.crown_radius_m and self.crown_radius_m > 0):
            raise ValueError("a crowned profile needs crown_radius_m > 0")
        if self.kind == "logarithmic" and not (self.design_load_N and self.design_load_N > 0):
            raise ValueError("a logarithmic profile needs design_load_N > 0")
        if self.kind not in ("straight", "crowned", "logarithmic"):
            raise ValueError(f"unknown profile kind {self.kind!r}")
        if self.end_radius_m < 0 or 2 * self.end_radius_m > self.length_m:
            raise ValueError("end radius must be in [0, length/2]")

    @property
    def sharp_ends(self) -> bool:
        return self.end_radius_m == 0.0


def profile_drop(y_m: np.ndarray, profile: RollerProfile, r_eq_m: float, e_star_pa: float) -> np.ndarray:
    """Profile drop [m] at axial positions ``y_m`` (inf beyond the roller ends)."""
    y = np.abs(np.asarray(y_m, dtype=float))
    half = 0.5 * profile.length_m
    drop = np.zeros_like(y)
    if profile.kind == "crowned":
        drop = y * y / (2.0 * profile.crown_radius_m)
    elif profile.kind == "logarithmic":
        q = profile.design_load_N
        b_d, _ = line_contact(q / profile.length_m, r_eq_m, e_star_pa)
        c = 1.0 - min((b_d / half) ** 2, 1.0)
        s = np.clip(y / half, 0.0, 1.0)
        drop = q / (math.pi * profile.length_m * e_star_pa) * np.log(1.0 / (1.0 - c * s * s))
    rc = profile.end_radius_m
    if rc > 0.0:
        s = np.clip(y - (half - rc), 0.0, rc)
        drop = drop + rc - np.sqrt(rc * rc - s * s)
    return np.where(y <= half * (1.0 + 1e-12), drop, np.inf)


def roller_gap(x_m: np.ndarray, y_m: np.ndarray, r_eq_m: float, profile: RollerProfile,
               e_star_pa: float, tilt_rad: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Gap h [m] and material mask on the grid (x_m, y_m) (1D cell-centre vectors).

    h = x^2 / (2 R') + drop(y) - y tan(tilt): a positive tilt closes the gap at the
    +y end (misalignment of the roller axis in the plane of the contact normal).
    """
    X, Y = np.meshgrid(np.asarray(x_m, float), np.asarray(y_m, float), indexing="ij")
    drop = profile_drop(Y, profile, r_eq_m, e_star_pa)
    mask = np.isfinite(drop)
    h = X * X / (2.0 * r_eq_m) + np.where(mask, drop, 0.0) - Y * math.tan(tilt_rad)
    h = np.where(mask, h - h[mask].min(), h.max())
    return h, mask


def ball_gap(x_m: np.ndarray, y_m: np.ndarray, rx_m: float, ry_m: float) -> np.ndarray:
    """Gap h = x^2/(2 Rx) + y^2/(2 Ry) [m] of a point contact (equivalent radii)."""
    X, Y = np.meshgrid(np.asarray(x_m, float), np.asarray(y_m, float), indexing="ij")
    return X * X / (2.0 * rx_m) + Y * Y / (2.0 * ry_m)
