"""Constrained conjugate-gradient solver for the normal contact problem.

Polonsky and Keer, Wear 231 (1999) 206-219, "A numerical method for solving rough
contact problems based on the multi-level multi-summation and conjugate gradient
techniques", algorithm of section 3 (here with DC-FFT instead of multi-level
summation for the deflection, Liu, Wang and Liu 2000).

Discrete problem on cells i with pressure p_i >= 0 (seed 001 eqs. 42, 44, 46):

    e_i = h_i + u_i(p) - delta,   u = K p,
    e_i = 0 where p_i > 0,   e_i >= 0 where p_i = 0,
    dA * sum_i p_i = W,

with h the initial separation, u the combined elastic deflection and delta the rigid
approach (a Lagrange multiplier of the load constraint).  Each iteration minimises the
complementary energy over the current contact set by a conjugate-gradient step with the
mean of the gap removed (this keeps the load), projects p onto p >= 0, re-admits
overlapping cells with zero pressure (and then restarts the conjugate direction) and
rescales to the load.  Convergence: dA * sum |p_new - p_old| / W < tol.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Callable

import numpy as np

log = logging.getLogger(__name__)

__all__ = ["CGMSolution", "solve_cgm", "ContactNotConverged"]


class ContactNotConverged(RuntimeError):
    """Raised when the constrained CG iteration does not reach its tolerance."""


@dataclass(frozen=True)
class CGMSolution:
    """Raw solver output: pressure [Pa], rigid approach [m], separation [m], iterations."""

    pressure: np.ndarray
    approach: float
    separation: np.ndarray
    iterations: int
    error: float


def solve_cgm(
    apply_k: Callable[[np.ndarray], np.ndarray],
    gap: np.ndarray,
    load: float,
    cell_area: float,
    mask: np.ndarray | None = None,
    tol: float = 1e-9,
    max_iter: int = 2000,
    p_init: np.ndarray | None = None,
) -> CGMSolution:
    """Solve the load-controlled frictionless normal contact (Polonsky-Keer CGM).

    Parameters
    ----------
    apply_k : deflection operator, pressure [Pa] -> displacement [m] (same shape).
    gap : initial separation h [m] at the cell centres (any additive constant).
    load : normal load W [N] (for 2D problems a load per length [N/m]).
    cell_area : area of one cell dA [m^2] (2D: cell width [m]).
    mask : cells that may carry pressure (material present); default all.
    tol : relative L1 change of the pressure between iterations, scaled by the load.
    """
    h = np.asarray(gap, dtype=float)
    if load <= 0.0:
        raise ValueError("load must be positive")
    allowed = np.ones(h.shape, bool) if mask is None else np.asarray(mask, bool)
    if not allowed.any():
        raise ValueError("no cell may carry pressure")
    if p_init is None:
        # start on the cells that overlap at the mean approach of a Hertz-like guess:
        # the allowed cells with the smallest gaps, uniform pressure
        p = np.where(allowed, 1.0, 0.0)
    else:
        p = np.where(allowed, np.maximum(np.asarray(p_init, float), 0.0), 0.0)
    p *= load / (cell_area * p.sum())

    t = np.zeros_like(p)
    g_old = 1.0
    restart = True
    err = np.inf
    g_mean = 0.0
    for it in range(1, max_iter + 1):
        u = apply_k(p)
        g = u + h
        contact = p > 0.0
        g_mean = float(g[contact].mean())
        g -= g_mean
        G = float(np.dot(g[contact], g[contact]))
        if restart:
            t = np.where(contact, g, 0.0)
        else:
            t = np.where(contact, g + (G / g_old) * t, 0.0)
        g_old = G if G > 0.0 else 1.0
        r = apply_k(t)
        r -= float(r[contact].mean())
        denom = float(np.dot(r[contact], t[contact]))
        tau = float(np.dot(g[contact], t[contact])) / denom if denom != 0.0 else 0.0
        p_old = p.copy()
        p = np.where(contact, p - tau * t, 0.0)
        p = np.maximum(p, 0.0)
        overlap = (p <= 0.0) & (g < 0.0) & allowed
        restart = bool(overlap.any())
        if restart:
            p[overlap] -= tau * g[overlap]
        total = cell_area * p.sum()
        if total <= 0.0:
            raise ContactNotConverged("pressure vanished during the iteration")
        p *= load / total
        err = cell_area * float(np.abs(p - p_old).sum()) / load
        if err < tol:
            u = apply_k(p)
            approach = float(np.mean((h + u)[p > 0.0]))
            log.debug("CGM converged in %d iterations (error %.2e)", it, err)
            return CGMSolution(p, approach, h + u - approach, it, err)
    raise ContactNotConverged(
        f"contact CGM did not converge in {max_iter} iterations (error {err:.2e})"
    )
