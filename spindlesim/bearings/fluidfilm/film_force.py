"""Dynamic fluid-film force: exact dimensional force and tangent from the Reynolds LCP.

Dimensional Reynolds equation (isoviscous, incompressible; e.g. Hamrock, Schmid & Jacobson,
Fundamentals of Fluid Film Lubrication, 2nd ed., eq. 7.58; Childs, Turbomachinery
Rotordynamics, 1993, ch. 2)::

    div(h^3 grad p) = 6 mu omega R dh/dx + 12 mu dh/dt

With ``H = h/Cb``, ``zeta = z/R`` and ``p = (mu R^2/Cb^2) Pi`` this is::

    d/dtheta(H^3 dPi/dtheta) + d/dzeta(H^3 dPi/dzeta) = 6 omega dH/dtheta + 12 dH/dt

whose right-hand side is *linear in the rates* ``omega`` and ``dH/dt = -(x' cos + y' sin)/Cb``.
``Pi`` has units 1/s; with ``omega > 0`` it is ``omega P`` of :mod:`reynolds` (whose scaling
divides by omega), but written this way ``omega = 0`` (pure squeeze film, e.g. at the start of
a run-up) and ``omega < 0`` need no special case.  The discrete problem is the one of
:class:`~spindlesim.bearings.fluidfilm.reynolds.ReynoldsSolver` (same grid, conductances,
Couette fluxes and squeeze term) with the right-hand side::

    b = omega b_couette(X, Y) + 12 (X_r cos(theta) + Y_r sin(theta)) area,   X_r = x'/Cb

and the Swift-Stieber condition is the LCP ``Pi >= 0, A Pi - b >= 0, Pi (A Pi - b) = 0``,
solved exactly by the same primal-dual active-set method.  The force on the shaft and its
tangent (exact derivatives of the discrete solution for a fixed full-film set, as in
:mod:`reynolds`)::

    F   = (mu R^4 / Cb^2) f,          f = -int int Pi (cos, sin) dtheta dzeta
    K_t = -dF/dq = -(mu R^4 / Cb^3) df/dX,    C_t = -dF/dv = -(mu R^4 / Cb^3) df/dX_r

For ``omega > 0`` and ``v = 0`` this is exactly ``F = mu omega R^4/Cb^2 f(X, Y)`` and
``K_t, C_t`` = :func:`coefficients.dimensional` of the static solver at the same point.

Axisymmetric bores (360 deg plain, ``geometry.axisymmetric``) are solved as in
:mod:`equilibrium`: in the line-of-centres frame (journal on +x, the film of ``feed="max_film"``
starting at the maximum film), rotated back to x, y.  The model is then ``F(q, v) =
R(gamma) f_l(eps, R(-gamma) v)`` and its tangent includes the rotation of the frame with the
journal (the film start moves with the line of centres)::

    dF/dq = R [ J_p[:, 0] e_r^T + (S f_l - J_r S v_l) e_t^T / eps ],   dF/dv = R J_r R^T

with ``S = [[0, -1], [1, 0]]``, ``e_r``, ``e_t`` the radial and tangential unit vectors.  For
``feed="periodic"`` the bracket tends to Lund's fixed-boundary column as the grid is refined
(0.75 % of max|K| apart at e/Cb 0.58 on a 96 x 8 grid); for ``"max_film"`` it differs also by
the motion of the film start (1.4 %).  ``C_t`` and the radial column of ``K_t`` are Lund's.  At
``eps = 0`` the frame is taken along +x and the ``1/eps`` term dropped (the max-film model is
discontinuous there: the film start jumps with the direction of the journal).
"""

from __future__ import annotations

import functools
import logging
import math
from dataclasses import dataclass

import numpy as np

from spindlesim.bearings.fluidfilm.geometry import BearingGeometry
from spindlesim.bearings.fluidfilm.reynolds import (
    DEFAULT_AXIAL,
    DEFAULT_CIRCUMFERENTIAL,
    ReynoldsError,
    ReynoldsSolver,
    _film_at,
)

log = logging.getLogger(__name__)

_S = np.array([[0.0, -1.0], [1.0, 0.0]])  # d R(gamma) / d gamma = R(gamma) S


@functools.lru_cache(maxsize=32)
def reynolds_solver(geometry: BearingGeometry, n_circ: int, n_axial: int) -> ReynoldsSolver:
    """Grid and sparse pattern of a (frozen) geometry and grid size, built once."""
    return ReynoldsSolver(geometry, n_circ, n_axial)


def force_scale(geometry: BearingGeometry, viscosity_Pa_s: float) -> float:
    """``mu R^4 / Cb^2``: dimensional force [N] per unit of dimensionless-rate force [1/s]."""
    return viscosity_Pa_s * geometry.radius_m**4 / geometry.clearance_m**2


def rotation(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


def lcp_active_set(solver: ReynoldsSolver, gc: np.ndarray, ga: np.ndarray, diag: np.ndarray,
                   b: np.ndarray, guess: np.ndarray | None = None, max_iter: int = 200):
    """Exact LCP solution ``P >= 0, A P - b >= 0, P (A P - b) = 0`` of the solver's operator.

    The primal-dual active-set iteration of :meth:`ReynoldsSolver.solve` (Hintermueller, Ito &
    Kunisch 2003), for an arbitrary right-hand side.  Returns ``(P, full_film, factor, it)``
    with ``factor`` the solve function of A on the final full-film set (or None).
    """
    n = solver.grid.n_unknown
    inactive = np.ones(n, dtype=bool) if guess is None else guess.copy()
    factor = None
    P = np.zeros(n)
    for it in range(1, max_iter + 1):
        P = np.zeros(n)
        factor = None
        if inactive.any():
            factor = solver._factor(gc, ga, diag, inactive)
            P[inactive] = factor(b[inactive])
        lam = solver._apply_face_operator(gc, ga, P) - b
        lam[inactive] = 0.0
        new_inactive = ~((lam - diag * P) > 0.0)
        if np.array_equal(new_inactive, inactive):
            break
        inactive = new_inactive
    else:
        raise ReynoldsError(f"active-set iteration did not converge in {max_iter} steps")
    P[~inactive] = 0.0
    return P, inactive, factor, it


@dataclass(frozen=True)
class RateSolution:
    """Film for the rate form of the Reynolds equation (all rates in 1/s).

    ``force`` is ``f`` of the module docstring (N per ``mu R^4/Cb^2``), ``jac_position`` =
    df/dX, ``jac_rate`` = df/dX_r (X_r = x'/Cb), for the fixed full-film set.
    """

    X: float
    Y: float
    pressure: np.ndarray  # Pi on the grid unknowns [1/s]
    force: np.ndarray
    jac_position: np.ndarray
    jac_rate: np.ndarray
    full_film: np.ndarray
    min_film: float
    iterations: int


def solve_rates(solver: ReynoldsSolver, X: float, Y: float, omega: float, Xr: float, Yr: float,
                full_film_guess: np.ndarray | None = None) -> RateSolution:
    """Solve ``A Pi = omega b_couette + 12 (Xr cos + Yr sin) area`` as an LCP, with derivatives.

    Same discrete operator as :meth:`ReynoldsSolver.solve`; that method is the special case
    ``omega = 1`` (with ``Xr, Yr`` its ``Xdot, Ydot``).
    """
    geo, g = solver.geometry, solver.grid
    Hc, Ha, Hmid = solver.film_heights(X, Y)
    gc, ga = solver._conductances(Hc, Ha)
    diag = solver._diagonal(gc, ga)
    area = g.node_area
    b = omega * solver._face_divergence(6.0 * Hc * g.cf_w)
    if Xr or Yr:
        b = b + 12.0 * (Xr * solver._cos_n + Yr * solver._sin_n) * area
    P, inactive, factor, it = lcp_active_set(solver, gc, ga, diag, b, full_film_guess)
    wgt = 2.0 * area
    cw, sw = solver._cos_n * wgt, solver._sin_n * wgt
    force = -np.array([cw @ P, sw @ P])
    jp = np.zeros((2, 2))
    jr = np.zeros((2, 2))
    idx = np.flatnonzero(inactive)
    if idx.size:
        rhs = []
        for cq_c, cq_a in ((solver._cos_cf, solver._cos_af), (solver._sin_cf, solver._sin_af)):
            db = omega * solver._face_divergence(-6.0 * cq_c * g.cf_w)
            dgc = -3.0 * Hc**2 * cq_c * g.cf_w / g.cf_dtheta
            dga = -3.0 * Ha**2 * cq_a * g.af_dtheta / g.af_dzeta
            rhs.append(db - solver._apply_face_operator(dgc, dga, P))
        rhs.append(12.0 * solver._cos_n * area)
        rhs.append(12.0 * solver._sin_n * area)
        dP = factor(np.stack([r[idx] for r in rhs], axis=1))
        cols = -np.stack([cw[idx] @ dP, sw[idx] @ dP])  # (2, 4)
        jp, jr = cols[:, :2].copy(), cols[:, 2:].copy()
    return RateSolution(X=X, Y=Y, pressure=P, force=force, jac_position=jp, jac_rate=jr,
                        full_film=inactive, min_film=float(min(Hc.min(), Hmid.min())), iterations=it)


class DimensionalFilmForce:
    """Base of the film force models: ``dimensionless(X, X_r, omega) -> (f, df/dX, df/dX_r)`` given by
    the model, turned into SI here."""

    geometry: BearingGeometry

    def dimensionless(self, X: np.ndarray, Xr: np.ndarray, omega: float):
        raise NotImplementedError

    def force_and_tangent(self, q_m, v_m_s, omega_rad_s: float, viscosity_Pa_s: float):
        """(f [N], K_t = -df/dq [N/m], C_t = -df/dv [N s/m]) on the shaft, x-y frame."""
        c = self.geometry.clearance_m
        X = np.asarray(q_m, dtype=float) / c
        Xr = np.asarray(v_m_s, dtype=float) / c
        f, jp, jr = self.dimensionless(X, Xr, float(omega_rad_s))
        s = force_scale(self.geometry, viscosity_Pa_s)
        return s * f, -(s / c) * jp, -(s / c) * jr


class ExactFilmForce(DimensionalFilmForce):
    """Dimensional film force and tangent from a full Reynolds LCP solve per call.

    Keeps the last full-film set as the warm start of the next call (one active-set step
    when the journal has moved little, as between Newton iterates).
    """

    def __init__(self, geometry: BearingGeometry, n_circ: int = DEFAULT_CIRCUMFERENTIAL,
                 n_axial: int = DEFAULT_AXIAL) -> None:
        self.geometry = geometry
        self.solver = reynolds_solver(geometry, n_circ, n_axial)
        self._guess: np.ndarray | None = None

    def dimensionless(self, X: np.ndarray, Xr: np.ndarray, omega: float):
        """(f, df/dX, df/dX_r) in the x, y frame for X = q/Cb, X_r = v/Cb, rates in 1/s."""
        X = np.asarray(X, dtype=float)
        Xr = np.asarray(Xr, dtype=float)
        if not self.geometry.axisymmetric:
            sol = solve_rates(self.solver, X[0], X[1], omega, Xr[0], Xr[1], self._guess)
            self._guess = sol.full_film
            return sol.force, sol.jac_position, sol.jac_rate
        eps = float(math.hypot(X[0], X[1]))
        gamma = math.atan2(X[1], X[0]) if eps > 0.0 else 0.0
        R = rotation(gamma)
        vl = R.T @ Xr
        sol = solve_rates(self.solver, eps, 0.0, omega, vl[0], vl[1], self._guess)
        self._guess = sol.full_film
        f = R @ sol.force
        Jr = R @ sol.jac_rate @ R.T
        if eps > 0.0:
            e_r = np.array([math.cos(gamma), math.sin(gamma)])
            e_t = np.array([-e_r[1], e_r[0]])
            tang = (_S @ sol.force - sol.jac_rate @ (_S @ vl)) / eps
            Jp = R @ (np.outer(sol.jac_position[:, 0], e_r) + np.outer(tang, e_t))
        else:
            Jp = R @ sol.jac_position @ R.T
        return f, Jp, Jr

