"""Uniform cell grids, nested (coarse-to-fine) solution and post-processing of p(x, y)."""

from __future__ import annotations

import logging
from typing import Callable

import numpy as np

from .influence import HalfSpace3D
from .solver import CGMSolution, solve_cgm

log = logging.getLogger(__name__)

GapFn = Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]


def cell_centres(lo: float, hi: float, n: int) -> np.ndarray:
    """n cell centres of a uniform partition of [lo, hi]."""
    d = (hi - lo) / n
    return lo + (np.arange(n) + 0.5) * d


def nested_solve(gap_fn: GapFn, x_lo: float, x_hi: float, y_lo: float, y_hi: float,
                 nx: int, ny: int, e_star: float, load: float, tol: float,
                 min_cells: int = 32) -> tuple[np.ndarray, np.ndarray, CGMSolution]:
    """Solve on (nx, ny) cells, starting from the solution on a 2x coarser grid.

    The coarse pressure, repeated onto the 2 x 2 fine cells of each coarse cell, is the
    initial guess of the fine CGM (nested iteration); this roughly halves the number of
    fine-grid iterations.  ``gap_fn(x, y)`` returns (gap [m], mask) on the cell centres.
    """
    x = cell_centres(x_lo, x_hi, nx)
    y = cell_centres(y_lo, y_hi, ny)
    h, mask = gap_fn(x, y)
    p0 = None
    if nx % 2 == 0 and ny % 2 == 0 and nx // 2 >= min_cells and ny // 2 >= min_cells:
        _, _, coarse = nested_solve(gap_fn, x_lo, x_hi, y_lo, y_hi, nx // 2, ny // 2,
                                    e_star, load, tol * 10.0, min_cells)
        p0 = np.repeat(np.repeat(coarse.pressure, 2, axis=0), 2, axis=1)
    dx, dy = (x_hi - x_lo) / nx, (y_hi - y_lo) / ny
    op = HalfSpace3D(nx, ny, dx, dy, e_star)
    sol = solve_cgm(op.apply, h, load, dx * dy, mask=mask, tol=tol, p_init=p0)
    log.debug("grid %dx%d: %d iterations", nx, ny, sol.iterations)
    return x, y, sol


def edge_positions(x: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Left and right contact edges in x [m] for every column of p (NaN if no contact).

    Near a smooth contact edge p ~ sqrt(distance), so p^2 is linear there: the edge is
    where p^2, extrapolated from the last two contact cells, reaches zero (limited to
    one cell beyond the last loaded cell centre).
    """
    dx = x[1] - x[0]
    nx, ny = p.shape
    left = np.full(ny, np.nan)
    right = np.full(ny, np.nan)
    p2 = p * p
    for j in range(ny):
        idx = np.flatnonzero(p[:, j] > 0.0)
        if idx.size == 0:
            continue
        i0, i1 = idx[0], idx[-1]
        right[j] = x[i1] + _extension(p2[i1, j], p2[i1 - 1, j] if i1 - 1 >= 0 else 0.0, dx)
        left[j] = x[i0] - _extension(p2[i0, j], p2[i0 + 1, j] if i0 + 1 < nx else 0.0, dx)
    return left, right


def _extension(p2_last: float, p2_prev: float, dx: float) -> float:
    if p2_prev > p2_last:
        return float(min(dx * p2_last / (p2_prev - p2_last), dx))
    return 0.5 * dx


def value_at_x0(x: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Linear interpolation of every column of p at x = 0."""
    i = int(np.clip(np.searchsorted(x, 0.0) - 1, 0, len(x) - 2))
    w = (0.0 - x[i]) / (x[i + 1] - x[i])
    return (1.0 - w) * p[i, :] + w * p[i + 1, :]
