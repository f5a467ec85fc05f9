"""Geometry of a back-to-back double-row tapered roller bearing (seed 001 section 2-1, Figs. 1-3).

Frames.  Bearing frame (X, Y, Z), Z along the shaft, origin O at the bearing centre.
Row 1 lies at Z < 0 and row 2 at Z > 0 (the seed's upper/lower signs); the rollers'
large ends face outwards (back-to-back, "O" arrangement), so the pressure cones
point away from the bearing centre.  Each roller j of row k sits at the azimuth
psi_j (eq. 3) in its meridional plane (rho radial, zeta axial).  Row 2 is the mirror
image of row 1: in the row-local axial coordinate zeta~ = s_k Z (s_1 = +1, s_2 = -1)
both rows have identical geometry, which is what the arrays below describe.

Row-local geometry (row 1, zeta~ = Z), angles as in seed 001 Fig. 1:

- alpha: cup (outer raceway) half-cone angle, beta = gamma - eps the cone (inner
  raceway) angle, eps the roller half-cone angle, gamma = alpha - eps the angle of
  the roller axis to the bearing axis.
- C = (rm, -rc): centre of the roller's large end (eq. 4 at z = 0); the roller axis
  e_a = (-sin gamma, cos gamma) points from the large end to the small end, the roller
  radial direction e_x = (cos gamma, sin gamma) towards the cup (eq. 16).
- Apex condition: every cone meets the bearing axis at one point, rm = r_L sin gamma / tan eps
  (r_race(0) = r_L in eq. 2), so eps follows from the pitch diameter.
- Roller radius at the station z from the large end, crowned profile of eq. 1:
  r_w(z) = r_L - z tan eps - (z - l/2)^2 / (2 R).
- Contact normals (direction of the force on the roller): cone N_i = (cos beta, sin beta),
  cup N_o = -(cos alpha, sin alpha), rib N_f = (-sin theta, cos theta) (eqs. 20-22; the
  rib normal makes the angle gamma - theta with the roller axis as in eqs. 33-34).
- The large end is a sphere of radius Rs whose centre S = C + Rs cos(lambda) e_a lies on the
  roller axis (eq. 6), sin(lambda) = r_L / Rs; the rib touches it at P_f = S - Rs N_f.

Linearised kinematics (small displacements, as eqs. 10-16 to first order).  The inner
ring's rigid motion seen in a meridional plane is a translation (a_r, a_z) and an
in-plane rotation theta about O; a roller's motion is (u_x, u_z, phi) along e_x, e_a
and about its mass centre G.  The approach of a contact point P with normal N is

    delta = A_w . w - A_u . u - gap,   w = (a_r, a_z, theta), u = (u_x, u_z, phi)

with A_w = (N_rho, N_zeta, N_rho P_zeta - N_zeta P_rho) (zero for the fixed cup) and
A_u = (N.e_x, N.e_a, N_rho (P_zeta - G_zeta) - N_zeta (P_rho - G_rho)).

Contact laws (seed 001 eqs. 23-29, constants from :mod:`spindlesim.contact.hertz`).  A roller
slice carries q = (K / l) delta^(10/9) per unit length with K = pi E' l^(8/9) / 7.358^(10/9),
E' = 2 E* (eq. 26; within 3 % of Palmgren's law for one roller/raceway contact, a reduced
modulus E* in place of E' would halve K).  The rib touches the spherical large end in a Hertz
point contact Q_f = K_f delta_f^(3/2); the seed gives its constant only through the
conformity (eq. 29), here K_f is the exact elliptical-contact constant (complete elliptic
integrals, Johnson 1985 eqs. 4.39-4.41).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...contact.hertz import (EXPONENT_LINE, EXPONENT_POINT, combined_modulus, line_contact_constant,
                              point_contact_constant)


@dataclass(frozen=True)
class DtrbGeometry:
    """Bearing and roller geometry in SI, plus the per-contact arrays of one row (row-local)."""

    rollers_per_row: int
    n_slices: int
    cup_angle_rad: float          # alpha
    cone_angle_rad: float         # beta
    roller_half_angle_rad: float  # eps
    roller_axis_angle_rad: float  # gamma
    rib_angle_rad: float          # theta
    end_cap_half_angle_rad: float # lambda
    large_end_radius_m: float     # r_L = D_l / 2
    roller_length_m: float        # l
    large_end_centre_radius_m: float  # rm (seed: radius of the large-end centre)
    large_end_offset_m: float     # rc: axial distance of the large-end centre from O
    pitch_diameter_m: float       # diameter of the circle through the roller mid-points
    crown_radius_m: float         # R of eq. 1 (inf: straight roller)
    end_sphere_radius_m: float    # Rs
    youngs_modulus_Pa: float
    poisson: float
    density_kg_m3: float
    E_prime_Pa: float             # eq. 26
    line_constant: float          # K of eq. 25 [N/m^(10/9)]
    rib_constant: float           # K_f of eq. 28 [N/m^1.5]
    rib_cf: float                 # c_f of eq. 28 (dimensionless)
    rib_conformity: float         # kappa of eq. 29
    roller_mass_kg: float
    roller_polar_inertia_kg_m2: float
    mass_centre_from_large_end_m: float  # zc (eq. 30)
    mass_centre_radius_m: float          # radius of G (eq. 31 uses it for rm)
    cage_ratio: float             # Omega_c / Omega_i (outer ring fixed, pure rolling)
    spin_ratio: float             # |Omega_w| / Omega_i (roller spin relative to the cage)
    # per-contact arrays, row-local, order: S inner slices, S outer slices, 1 rib
    slice_z_m: np.ndarray         # (S,) slice centres from the large end
    slice_width_m: float          # Delta l
    point_m: np.ndarray           # (C, 2) contact points (rho, zeta~)
    normal: np.ndarray            # (C, 2)
    A_w: np.ndarray               # (C, 3)
    A_u: np.ndarray               # (C, 3)
    gap_m: np.ndarray             # (C,)
    stiffness: np.ndarray         # (C,) K of Q = K delta^n per contact point
    exponent: np.ndarray          # (C,)

    @property
    def n_contacts(self) -> int:
        return 2 * self.n_slices + 1

    def inner(self, a: np.ndarray) -> np.ndarray:
        return a[..., : self.n_slices]

    def outer(self, a: np.ndarray) -> np.ndarray:
        return a[..., self.n_slices: 2 * self.n_slices]

    def rib(self, a: np.ndarray) -> np.ndarray:
        return a[..., 2 * self.n_slices]

    def profile_radius_m(self, z_m: np.ndarray) -> np.ndarray:
        """r_w(z) of seed 001 eq. 1 (crowned roller radius along its axis)."""
        z = np.asarray(z_m, float)
        crown = 0.0 if math.isinf(self.crown_radius_m) else (z - 0.5 * self.roller_length_m) ** 2 / (2 * self.crown_radius_m)
        return self.large_end_radius_m - z * math.tan(self.roller_half_angle_rad) - crown


def _apex_half_angle(alpha: float, r_L: float, length: float, pitch_radius: float) -> float:
    """eps from the apex condition rm = r_L sin(gamma)/tan(eps), rm - (l/2) sin(gamma) = dm/2."""
    eps = 0.0
    for _ in range(100):
        gamma = alpha - eps
        new = math.atan(r_L * math.sin(gamma) / (pitch_radius + 0.5 * length * math.sin(gamma)))
        if abs(new - eps) < 1e-15:
            return new
        eps = new
    return eps


def _mass_properties(r_L: float, tan_eps: float, length: float, rho: float, n: int = 2001):
    """Mass, polar moment and mass-centre station of the (uncrowned) truncated cone roller."""
    z = np.linspace(0.0, length, n)
    r = r_L - z * tan_eps
    w = np.full(n, length / (n - 1))
    w[0] = w[-1] = 0.5 * w[0]
    a2, a4 = np.sum(w * r ** 2), np.sum(w * r ** 4)
    mass = rho * math.pi * a2
    zc = float(np.sum(w * z * r ** 2) / a2)
    return mass, 0.5 * rho * math.pi * a4, zc


def dtrb_geometry(*, rollers_per_row: int, cup_angle_deg: float, pitch_diameter_m: float,
                  large_end_diameter_m: float, roller_length_m: float, large_end_offset_m: float,
                  crown_radius_m: float = math.inf, end_sphere_ratio: float = 0.9,
                  rib_contact_height_ratio: float = 0.5, youngs_modulus_Pa: float = 208e9,
                  poisson: float = 0.3, density_kg_m3: float = 7850.0, n_slices: int = 30) -> DtrbGeometry:
    """Build the geometry from catalogue-style data (all SI except the angle).

    ``end_sphere_ratio``: Rs / (rm / sin gamma), the large-end sphere radius over the
    distance from the large-end centre to the apex.  ``rib_contact_height_ratio``: the
    distance of the rib contact point from the roller axis over r_L (fixes theta:
    Rs sin(gamma - theta) = ratio r_L).
    """
    if rollers_per_row < 3 or n_slices < 1:
        raise ValueError("need at least 3 rollers per row and 1 slice")
    alpha = math.radians(cup_angle_deg)
    if not 0.0 < alpha < math.pi / 3:
        raise ValueError("cup angle must be in (0, 60) deg")
    r_L, l = 0.5 * large_end_diameter_m, roller_length_m
    eps = _apex_half_angle(alpha, r_L, l, 0.5 * pitch_diameter_m)
    gamma = alpha - eps
    beta = gamma - eps
    rm = r_L * math.sin(gamma) / math.tan(eps)
    apex = rm / math.sin(gamma)
    Rs = end_sphere_ratio * apex
    if Rs <= r_L:
        raise ValueError("end sphere radius must exceed the large-end radius")
    lam = math.asin(r_L / Rs)
    h_f = rib_contact_height_ratio * r_L
    theta = gamma - math.asin(h_f / Rs)
    rc = large_end_offset_m

    e_a = np.array([-math.sin(gamma), math.cos(gamma)])
    e_x = np.array([math.cos(gamma), math.sin(gamma)])
    C = np.array([rm, -rc])
    S = n_slices
    dl = l / S
    zs = (np.arange(S) + 0.5) * dl
    r_cone = r_L - zs * math.tan(eps)
    P_in = C + zs[:, None] * e_a - r_cone[:, None] * e_x
    P_out = C + zs[:, None] * e_a + r_cone[:, None] * e_x
    N_in = np.array([math.cos(beta), math.sin(beta)])
    N_out = -np.array([math.cos(alpha), math.sin(alpha)])
    N_f = np.array([-math.sin(theta), math.cos(theta)])
    S_centre = C + Rs * math.cos(lam) * e_a
    P_f = S_centre - Rs * N_f

    mass, Iw, zc = _mass_properties(r_L, math.tan(eps), l, density_kg_m3)
    G = C + zc * e_a

    points = np.vstack([P_in, P_out, P_f[None, :]])
    normals = np.vstack([np.tile(N_in, (S, 1)), np.tile(N_out, (S, 1)), N_f[None, :]])
    A_u = np.column_stack([normals @ e_x, normals @ e_a,
                           normals[:, 0] * (points[:, 1] - G[1]) - normals[:, 1] * (points[:, 0] - G[0])])
    A_w = np.column_stack([normals[:, 0], normals[:, 1],
                           normals[:, 0] * points[:, 1] - normals[:, 1] * points[:, 0]])
    A_w[S: 2 * S] = 0.0  # the cup is fixed
    crown = np.zeros(S) if math.isinf(crown_radius_m) else (zs - 0.5 * l) ** 2 / (2.0 * crown_radius_m)
    gap = np.concatenate([crown, crown, [0.0]])

    E_prime = 2.0 * combined_modulus(youngs_modulus_Pa, poisson)  # seed 001 eq. 26: E' = 2 E*
    K_line = line_contact_constant(l, E_prime)
    # rib: sphere Rs against a cone whose circumferential radius of curvature is rho_f / sin(theta)
    # (the normal line from P_f meets the axis there, on the roller's side: concave rib).
    R_circ = P_f[0] / math.sin(theta)
    c_gen, c_circ = 1.0 / Rs, 1.0 / Rs - 1.0 / R_circ
    if c_circ <= 0.0:
        raise ValueError("roller end sphere does not fit the rib (Rs >= rib curvature radius)")
    E_star = 0.5 * E_prime
    K_rib = point_contact_constant(c_gen, c_circ, E_star)
    kappa = (rm / Rs - math.sin(gamma) * math.cos(lam)) / math.sin(theta)
    stiffness = np.concatenate([np.full(2 * S, K_line * dl / l), [K_rib]])
    exponent = np.concatenate([np.full(2 * S, EXPONENT_LINE), [EXPONENT_POINT]])

    # pure rolling at the roller mid-station (apex condition: the same everywhere)
    rho_i, rho_o = P_in[:, 0].mean(), P_out[:, 0].mean()
    cage = rho_i / (rho_i + rho_o)
    r_mid = r_L - 0.5 * l * math.tan(eps)
    spin = rho_o * cage / r_mid
    return DtrbGeometry(
        rollers_per_row=int(rollers_per_row), n_slices=int(S), cup_angle_rad=alpha, cone_angle_rad=beta,
        roller_half_angle_rad=eps, roller_axis_angle_rad=gamma, rib_angle_rad=theta, end_cap_half_angle_rad=lam,
        large_end_radius_m=r_L, roller_length_m=l, large_end_centre_radius_m=rm, large_end_offset_m=rc,
        pitch_diameter_m=pitch_diameter_m, crown_radius_m=float(crown_radius_m), end_sphere_radius_m=Rs,
        youngs_modulus_Pa=youngs_modulus_Pa, poisson=poisson, density_kg_m3=density_kg_m3,
        E_prime_Pa=E_prime, line_constant=K_line, rib_constant=K_rib,
        rib_cf=K_rib / (E_prime * math.sqrt(Rs)), rib_conformity=kappa,
        roller_mass_kg=mass, roller_polar_inertia_kg_m2=Iw, mass_centre_from_large_end_m=zc,
        mass_centre_radius_m=float(G[0]), cage_ratio=cage, spin_ratio=spin,
        slice_z_m=zs, slice_width_m=dl, point_m=points, normal=normals, A_w=A_w, A_u=A_u,
        gap_m=gap, stiffness=stiffness, exponent=exponent,
    )
