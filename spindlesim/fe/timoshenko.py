"""Timoshenko shaft element after Nelson (1980), seed 003 eq. 17.

Each bending plane uses the interdependent (shear-corrected) cubic shape
functions with Phi = 12 E I / (kappa G A L^2):

    translation  w(xi)   = N(xi)  [w1, s1, w2, s2],   rotation s(xi) = Nr(xi) [w1, s1, w2, s2]

with s the section rotation (s = dw/dz when Phi = 0). Element matrices are the
energy integrals, evaluated with 4-point Gauss quadrature (exact: integrands are
polynomials of degree <= 6):

    M_T = int rho A N^T N,           M_R = int rho I Nr^T Nr
    K_B = int E I Nr'^T Nr' + kappa G A (N' - Nr)^T (N' - Nr)
    K_A = int P N'^T N'                (axial force P, tension positive)

The two planes are scattered into the lateral DOFs (x, y, theta_x, theta_y):
the x-z plane carries (x, theta_y) with s = theta_y, the y-z plane carries
(y, theta_x) with s = -theta_x (right-hand rotations about +x and +y). The
gyroscopic matrix G (polar inertia 2 rho I per length) and the circulatory
matrix K_C of internal damping couple the planes. Equation of motion of one
element (seed 003 eq. 17, Omega = spin speed):

    (M_T + M_R) q'' + (eta_v K_B + Omega G) q'
        + [(1 + eta_h)/sqrt(1 + eta_h^2) K_B + K_A + (eta_v Omega + eta_h/sqrt(1 + eta_h^2)) K_C] q = Q

(seed 003 writes -K_A with compression positive; here tension is positive.)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(4)
_XI = 0.5 * (_GAUSS_X + 1.0)  # on [0, 1]
_WXI = 0.5 * _GAUSS_W

# planar DOF [w1, s1, w2, s2] -> local lateral index (x, y, theta_x, theta_y per node) and sign
_XZ_INDEX = np.array([0, 3, 4, 7])
_XZ_SIGN = np.array([1.0, 1.0, 1.0, 1.0])
_YZ_INDEX = np.array([1, 2, 5, 6])
_YZ_SIGN = np.array([1.0, -1.0, 1.0, -1.0])


def shape_functions(xi: np.ndarray, length: np.ndarray, phi: np.ndarray):
    """Return N, dN/dz, Nr, dNr/dz with shape (n_elem, n_xi, 4)."""
    xi = np.asarray(xi)[None, :]
    L = np.asarray(length)[:, None]
    p = np.asarray(phi)[:, None]
    d = 1.0 + p
    N = np.stack(
        [
            (1 - 3 * xi**2 + 2 * xi**3 + p * (1 - xi)) / d,
            L * (xi - 2 * xi**2 + xi**3 + p * (xi - xi**2) / 2) / d,
            (3 * xi**2 - 2 * xi**3 + p * xi) / d,
            L * (-(xi**2) + xi**3 + p * (xi**2 - xi) / 2) / d,
        ],
        axis=-1,
    )
    dN = np.stack(
        [
            (-6 * xi + 6 * xi**2 - p) / d / L,
            (1 - 4 * xi + 3 * xi**2 + p * (1 - 2 * xi) / 2) / d,
            (6 * xi - 6 * xi**2 + p) / d / L,
            (-2 * xi + 3 * xi**2 + p * (2 * xi - 1) / 2) / d,
        ],
        axis=-1,
    )
    Nr = np.stack(
        [
            6 * (xi**2 - xi) / (L * d),
            (1 - 4 * xi + 3 * xi**2 + p * (1 - xi)) / d,
            -6 * (xi**2 - xi) / (L * d),
            (-2 * xi + 3 * xi**2 + p * xi) / d,
        ],
        axis=-1,
    )
    dNr = np.stack(
        [
            6 * (2 * xi - 1) / (L**2 * d),
            (-4 + 6 * xi - p) / (L * d),
            -6 * (2 * xi - 1) / (L**2 * d),
            (-2 + 6 * xi + p) / (L * d),
        ],
        axis=-1,
    )
    return N, dN, Nr, dNr


@dataclass(frozen=True)
class PlanarMatrices:
    """Per-plane 4x4 element matrices, shape (n_elem, 4, 4)."""

    mass_translational: np.ndarray
    mass_rotary: np.ndarray
    rotary_unit: np.ndarray  # int Nr^T Nr dz (times rho I gives mass_rotary)
    stiffness_bending: np.ndarray
    stiffness_axial: np.ndarray
    load_unit: np.ndarray  # int N dz, shape (n_elem, 4): consistent load of a unit distributed force


def planar_matrices(
    length, area, second_moment, density, youngs, shear_modulus, kappa, axial_force
) -> PlanarMatrices:
    """Timoshenko element matrices of one bending plane for every element at once."""
    L = np.asarray(length, float)
    A = np.asarray(area, float)
    I = np.asarray(second_moment, float)
    density, youngs, shear_modulus, kappa, axial_force = (
        np.asarray(v, float) for v in (density, youngs, shear_modulus, kappa, axial_force)
    )
    phi = 12 * youngs * I / (kappa * shear_modulus * A * L**2)
    N, dN, Nr, dNr = shape_functions(_XI, L, phi)
    w = _WXI[None, :, None, None] * L[:, None, None, None]  # dz = L dxi
    outer = lambda a, b: a[..., :, None] * b[..., None, :]  # noqa: E731
    NtN = (w * outer(N, N)).sum(axis=1)
    NrtNr = (w * outer(Nr, Nr)).sum(axis=1)
    dNrdNr = (w * outer(dNr, dNr)).sum(axis=1)
    gam = dN - Nr
    shear = (w * outer(gam, gam)).sum(axis=1)
    dNdN = (w * outer(dN, dN)).sum(axis=1)
    load = (_WXI[None, :, None] * L[:, None, None] * N).sum(axis=1)
    col = lambda v: np.asarray(v, float)[:, None, None]  # noqa: E731
    return PlanarMatrices(
        mass_translational=col(density * A) * NtN,
        mass_rotary=col(density * I) * NrtNr,
        rotary_unit=NrtNr,
        stiffness_bending=col(youngs * I) * dNrdNr + col(kappa * shear_modulus * A) * shear,
        stiffness_axial=col(axial_force) * dNdN,
        load_unit=load,
    )


def _scatter_same(planar: np.ndarray) -> np.ndarray:
    """Place one planar matrix into both planes of the 8x8 lateral element (uncoupled planes)."""
    n = planar.shape[0]
    out = np.zeros((n, 8, 8))
    for idx, sign in ((_XZ_INDEX, _XZ_SIGN), (_YZ_INDEX, _YZ_SIGN)):
        out[:, idx[:, None], idx[None, :]] += planar * sign[:, None] * sign[None, :]
    return out


def _scatter_cross(planar: np.ndarray) -> np.ndarray:
    """S_x^T P S_y - S_y^T P S_x: the skew coupling between planes used by G and K_C."""
    n = planar.shape[0]
    out = np.zeros((n, 8, 8))
    Sx = np.zeros((4, 8))
    Sy = np.zeros((4, 8))
    Sx[np.arange(4), _XZ_INDEX] = _XZ_SIGN
    Sy[np.arange(4), _YZ_INDEX] = _YZ_SIGN
    out += np.einsum("ia,nij,jb->nab", Sx, planar, Sy)
    out -= np.einsum("ia,nij,jb->nab", Sy, planar, Sx)
    return out


@dataclass(frozen=True)
class ElementMatrices:
    """8x8 lateral element matrices, shape (n_elem, 8, 8), DOFs (x, y, theta_x, theta_y) at both nodes."""

    mass: np.ndarray  # M_T + M_R
    gyroscopic: np.ndarray  # G (skew), multiply by Omega
    stiffness_bending: np.ndarray  # K_B
    stiffness_axial: np.ndarray  # K_A (tension positive)
    circulatory: np.ndarray  # K_C (skew), from K_B
    gravity_unit: np.ndarray  # (n_elem, 8): consistent nodal loads of rho A g along -y per (m/s^2)


def lateral_element_matrices(
    length, area, second_moment, density, youngs, shear_modulus, kappa, axial_force
) -> ElementMatrices:
    """Nelson's 8x8 Timoshenko element matrices for every element."""
    p = planar_matrices(length, area, second_moment, density, youngs, shear_modulus, kappa, axial_force)
    polar_per_length = 2.0 * np.asarray(density, float) * np.asarray(second_moment, float)
    # theta_x row gets +Ip*Omega*theta_y' as for a disk (Id th_x'' + Ip W th_y' = M_x)
    gyroscopic = _scatter_cross(polar_per_length[:, None, None] * p.rotary_unit)
    circulatory = _scatter_cross(p.stiffness_bending)
    grav = np.zeros((len(p.load_unit), 8))
    grav[:, _YZ_INDEX] = -(np.asarray(density, float) * np.asarray(area, float))[:, None] * p.load_unit * _YZ_SIGN
    return ElementMatrices(
        mass=_scatter_same(p.mass_translational + p.mass_rotary),
        gyroscopic=gyroscopic,
        stiffness_bending=_scatter_same(p.stiffness_bending),
        stiffness_axial=_scatter_same(p.stiffness_axial),
        circulatory=circulatory,
        gravity_unit=grav,
    )
