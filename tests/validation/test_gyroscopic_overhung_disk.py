"""Rigid disk at the tip of a massless Timoshenko cantilever: forward/backward whirl in closed form.

Tip flexibility (force F, moment M -> deflection r, slope s): a11 = L^3/(3EI) + L/(kappa G A),
a12 = L^2/(2EI), a22 = L/(EI). Whirling at w (w > 0 forward, w < 0 backward) the disk's effective
diametral inertia is Id - Ip Omega / w, so det(I - w^2 A diag(m, Id - Ip Omega/w)) = 0 gives a
quartic in w (e.g. Genta, Dynamics of Rotating Systems, 2005, section 4.3; Vance, Rotordynamics of
Turbomachinery, 1988, ch. 3). Compared with the FE model with a near-massless shaft.
"""

import numpy as np
import pytest

from spindlesim.fe.assembly import assemble_shaft
from tests.rotor_helpers import rotor_from

L, D, E, G = 0.4, 0.04, 210e9, 80e9
M_DISK, IP, ID = 5.0, 0.05, 0.03


def closed_form(speed_rad_s):
    A = np.pi * D**2 / 4
    I = np.pi * D**4 / 64
    kap = 6 * 1.3 / (7 + 6 * 0.3)
    a11 = L**3 / (3 * E * I) + L / (kap * G * A)
    a12 = L**2 / (2 * E * I)
    a22 = L / (E * I)
    W = speed_rad_s
    P = np.polynomial.Polynomial
    w = P([0, 1])
    Jw2 = ID * w**2 - IP * W * w  # (Id - Ip W / w) w^2
    poly = (1 - a11 * M_DISK * w**2) * (1 - a22 * Jw2) - a12**2 * M_DISK * w**2 * Jw2
    roots = poly.roots()
    roots = roots[np.abs(roots.imag) < 1e-6 * np.abs(roots).max()].real
    return np.sort(roots[roots > 0]), np.sort(-roots[roots < 0])


def fe_whirl(speed_rad_s):
    rows = "shaft:\n  elements:\n" + f"    - [{D * 1e3}, 0.0, {L * 1e3 / 4}, 1.0e-6, 210.0, 80.0, 0.3, 0.0]\n" * 4
    disk = f"disks:\n  - {{node: 5, mass_kg: {M_DISK}, Ip_kg_m2: {IP}, Id_kg_m2: {ID}}}\n"
    rotor = rotor_from(rows + disk)
    sh = assemble_shaft(rotor)
    free = np.arange(4, sh.M.shape[0])  # clamp node 1
    M = sh.M[np.ix_(free, free)]
    K = sh.stiffness(speed_rad_s)[np.ix_(free, free)]
    C = sh.damping(speed_rad_s)[np.ix_(free, free)]
    n = len(free)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    lam, vec = np.linalg.eig(A)
    keep = lam.imag > 1.0
    lam, vec = lam[keep], vec[:n, keep]
    fwd, bwd = [], []
    tip_x, tip_y = n - 4, n - 3
    for lk, v in zip(lam, vec.T):
        x, y = v[tip_x], v[tip_y]
        (fwd if abs(x + 1j * y) > abs(x - 1j * y) else bwd).append(lk.imag)
    return np.sort(fwd), np.sort(bwd)


@pytest.mark.parametrize("rpm", [0.0, 5000.0, 20000.0])
def test_forward_backward_split(rpm):
    W = rpm * np.pi / 30
    fwd_ref, bwd_ref = closed_form(W)
    fwd, bwd = fe_whirl(W)
    if rpm == 0:
        fwd, bwd = np.sort(np.concatenate([fwd, bwd]))[::2], np.sort(np.concatenate([fwd, bwd]))[1::2]
    np.testing.assert_allclose(fwd[:2], fwd_ref[:2], rtol=1e-5)
    np.testing.assert_allclose(bwd[:2], bwd_ref[:2], rtol=1e-5)
    if rpm > 0:
        assert fwd[0] > bwd[0]  # gyroscopic stiffening of forward whirl
