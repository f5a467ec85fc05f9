"""Roller equilibrium of seed 001 eqs. 33-35, all rollers at once (batched Newton-Raphson).

For roller r with ring motion w_r (see ``geometry``) the unknowns are u_r = (u_x, u_z, phi)
and the residual is the generalised force on the roller

    res(u) = sum_c Q_c(delta_c) A_u,c + f_inertia,  delta = A_w w - A_u u - gap,

whose three rows are eq. 33 (along the roller radial e_x), eq. 34 (along the roller
axis e_a) and eq. 35 (moment about the mass centre: the tilting moments T_i, T_o of
eq. 30 and the rib moment), with f_inertia = (Fc cos gamma, -Fc sin gamma, -Mg) from
eqs. 31-32.  Its Jacobian is -K_uu with K_uu = sum_c k_c A_u,c A_u,c^T (k = dQ/ddelta), so a
Newton step is Delta u = K_uu^-1 res: 3x3 systems solved for every roller together
(one batched LAPACK call).  A roller without contact has K_uu = 0; a tiny diagonal
regularisation (it never changes the converged residual) and a step cap keep it put; the
rib approach may grow at most to the largest raceway approach (or double) in one step.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from .geometry import DtrbGeometry

log = logging.getLogger(__name__)

REFERENCE_APPROACH_M = 1e-6  # secant stiffness of the starting guess
REGULARISATION = 1e-10       # relative to the diagonal of the reference K_uu
STEP_CAP_M = 5e-6            # largest change of any approach in one Newton step (or 2x the largest approach)


@dataclass(frozen=True)
class ContactOperators:
    """Products of the contact vectors reused by every solve (one per geometry)."""

    AuAu: np.ndarray   # (C, 9)
    AwAu: np.ndarray   # (C, 9) rows: w index, columns: u index
    AwAw: np.ndarray   # (C, 9)
    reg: np.ndarray    # (3,) regularisation of K_uu
    guess_Kinv: np.ndarray  # (3, 3) inverse of the reference K_uu
    guess_Mwu: np.ndarray   # (3, 3) sum k_ref A_w A_u^T
    guess_gap: np.ndarray   # (3,) sum k_ref gap A_u
    AuK: np.ndarray         # (C, 3) K_c A_u,c: res = sum_c d_c^n_c AuK_c
    AuAuKn: np.ndarray      # (C, 9) K_c n_c A_u A_u^T: K_uu = sum_c d_c^(n_c - 1) AuAuKn_c


def operators(geom: DtrbGeometry) -> ContactOperators:
    Au, Aw = geom.A_u, geom.A_w
    AuAu = np.einsum("ci,cj->cij", Au, Au).reshape(-1, 9)
    AwAu = np.einsum("ci,cj->cij", Aw, Au).reshape(-1, 9)
    AwAw = np.einsum("ci,cj->cij", Aw, Aw).reshape(-1, 9)
    k_ref = geom.stiffness * geom.exponent * REFERENCE_APPROACH_M ** (geom.exponent - 1.0)
    K_ref = (k_ref @ AuAu).reshape(3, 3)
    reg = REGULARISATION * np.diag(K_ref)
    Mwu = (k_ref @ AwAu).reshape(3, 3)
    return ContactOperators(AuAu, AwAu, AwAw, reg, np.linalg.inv(K_ref), Mwu, (k_ref * geom.gap_m) @ Au,
                            geom.stiffness[:, None] * Au, (geom.stiffness * geom.exponent)[:, None] * AuAu)


@dataclass(frozen=True)
class RollerSolution:
    u: np.ndarray       # (R, 3) roller displacements (u_x, u_z, phi)
    delta: np.ndarray   # (R, C) contact approaches [m]
    Q: np.ndarray       # (R, C) contact loads [N] (slice loads q dl for the line contacts)
    k: np.ndarray       # (R, C) dQ/ddelta [N/m]
    iterations: int
    converged: bool
    residual_N: float   # largest force residual


def initial_guess(ops: ContactOperators, W: np.ndarray, f_inertia: np.ndarray) -> np.ndarray:
    """Roller positions balancing linear (secant) springs on every contact: a centred start."""
    rhs = W @ ops.guess_Mwu - ops.guess_gap + f_inertia
    return rhs @ ops.guess_Kinv.T


def contact_loads(geom: DtrbGeometry, delta: np.ndarray):
    """(Q, k) of every contact: line slices Q = K d^(10/9) (eq. 23), rib Q = K_f d^(3/2) (eq. 28).

    Same values as :func:`spindlesim.contact.hertz.power_law`, with the exponents specialised (one scalar
    power d^(1/9) and a square root; the fractional power dominates the cost)."""
    S2 = 2 * geom.n_slices
    d = np.maximum(delta, 0.0)
    t = np.power(d, 1.0 / 9.0)  # the rib column is overwritten below
    Kl = geom.stiffness[0]
    Q = d * t
    Q *= Kl
    k = t * (Kl * 10.0 / 9.0)
    dr = d[:, S2]
    sq = np.sqrt(dr)
    Kf = geom.stiffness[S2]
    Q[:, S2] = Kf * dr * sq
    k[:, S2] = (1.5 * Kf) * sq
    return Q, k


def solve_rollers(geom: DtrbGeometry, ops: ContactOperators, W: np.ndarray, f_inertia: np.ndarray,
                  u0: np.ndarray | None = None, tol_m: float = 1e-11, max_iter: int = 60) -> RollerSolution:
    """Newton-Raphson on eqs. 33-35 for every roller; ``W`` (R, 3) the ring motion per roller.

    Converged when no contact approach changes by more than ``tol_m`` in a step, or when the
    steps shrink quadratically and the next one would be below 1e-13 m; the last step is
    still taken and the returned state (delta, Q, k) is evaluated at the returned u.
    """
    Au, Aw, gap = geom.A_u, geom.A_w, geom.gap_m
    AuT = np.ascontiguousarray(Au.T)
    base = W @ Aw.T - gap  # (R, C): approach with the roller at rest
    u = initial_guess(ops, W, f_inertia) if u0 is None else np.array(u0, float)
    diag = np.array([0, 4, 8])
    converged = False
    it = 0
    change = np.zeros(1)
    prev_step = np.inf
    S2 = 2 * geom.n_slices
    for it in range(1, max_iter + 1):
        delta = base - u @ AuT
        d = np.maximum(delta, 0.0)
        t = np.power(d, 1.0 / 9.0)        # d^(n-1) of the line slices (eq. 23) ...
        t[:, S2] = np.sqrt(d[:, S2])      # ... and of the rib (eq. 28)
        res = (d * t) @ ops.AuK + f_inertia
        Kuu = t @ ops.AuAuKn
        Kuu[:, diag] += ops.reg
        du = np.linalg.solve(Kuu.reshape(-1, 3, 3), res[:, :, None])[:, :, 0]
        dd = du @ AuT  # change of -delta
        change = np.abs(dd).max(axis=1)
        cap = np.maximum(STEP_CAP_M, 2.0 * delta.max(axis=1))
        scale = np.minimum(1.0, cap / np.maximum(change, 1e-300))
        # the rib (stiffness ~ sqrt(delta)) must not be driven far past the raceway approaches:
        # Newton from a deep rib overlap only shrinks it by 1/3 per step
        rib_new = delta[:, S2] - dd[:, S2]
        lim = np.maximum(np.maximum(2.0 * delta[:, S2], delta[:, :S2].max(axis=1)), 1e-9)
        bad = rib_new > lim
        if bad.any():
            scale[bad] = np.minimum(scale[bad], (lim[bad] - delta[bad, S2]) / (-dd[bad, S2]))
        u = u + du * scale[:, None]
        step = float(change.max())
        # converged: a tiny step, or a step in the quadratic regime whose successor
        # (~ step^2 / previous step) would be below 1e-13 m; the step itself is taken
        if step < tol_m or (step < 1e-8 and step * step < 1e-13 * prev_step and scale.min() == 1.0):
            converged = True
            break
        prev_step = step
    if not converged:
        log.warning("DTRB roller Newton did not converge in %d iterations (largest step %.3g m)",
                    max_iter, float(change.max()))
    delta = base - u @ AuT
    Q, k = contact_loads(geom, delta)
    res = Q @ Au + f_inertia
    resid = float(np.abs(res[:, :2]).max()) if len(res) else 0.0
    return RollerSolution(u, delta, Q, k, it, converged, resid)
