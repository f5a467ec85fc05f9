"""Static equilibrium of the journal for a given load (dimensionless).

The film force on the journal is ``F = mu omega R^4 / Cb^2 * f(X, Y)`` (see
:mod:`reynolds`); equilibrium under the load ``w`` that the shaft puts on the bearing
is ``F = -w``, i.e. ``f(X, Y) = f_target = -w Cb^2 / (mu omega R^4)``.

- General bearings (multilobe, grooved plain): Newton's method on (X, Y) with the exact
  Jacobian of the discrete film force (fixed full-film set) and step halving that keeps
  the journal off the bore and the residual decreasing.
- Plain 360 deg bearing without grooves: axisymmetric, solved in the line-of-centres
  frame (the film starts at the maximum film thickness, Raimondi & Boyd 1958): a
  safeguarded Newton / bisection on the eccentricity ratio for ``|f(eps)| = |f_target|``,
  then a rotation that aligns the force with the load.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, replace

import numpy as np

from spindlesim.bearings.fluidfilm.reynolds import FilmSolution, ReynoldsError, ReynoldsSolver

log = logging.getLogger(__name__)


class EquilibriumError(RuntimeError):
    """No static equilibrium found (load too large for the film, or no convergence)."""


@dataclass(frozen=True)
class Equilibrium:
    """Journal position and film at equilibrium (Jacobians already in the x, y frame)."""

    film: FilmSolution
    X: float  # e_x / Cb
    Y: float  # e_y / Cb
    iterations: int
    #: rotation from the grid frame of ``film.pressure`` to the x, y frame (axisymmetric
    #: bearings are solved in the line-of-centres frame)
    rotation_rad: float = 0.0
    #: full-film set on the solver's grid (warm start of a neighbouring state)
    grid_full_film: np.ndarray | None = None


def _rot(psi: float) -> np.ndarray:
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, -s], [s, c]])


def solve_axisymmetric(solver: ReynoldsSolver, target: np.ndarray, tol: float = 1e-9,
                       max_iter: int = 60, initial_eps: float | None = None,
                       full_film_guess: np.ndarray | None = None) -> Equilibrium:
    """Equilibrium of a 360 deg plain bearing whose film starts at the maximum film.

    ``solver`` must be built on a single land starting at theta = pi (the maximum film
    when the journal is displaced along +x), see :func:`plain_geometry` with
    ``grooves=0``.
    """
    fmag = float(np.hypot(*target))
    if fmag <= 0:
        raise EquilibriumError("zero load: the centred journal carries no load")
    lo, hi = 0.0, 1.0
    eps = 0.5 if initial_eps is None or not 0.0 < initial_eps < 1.0 else initial_eps
    guess = full_film_guess
    sol = None
    for it in range(1, max_iter + 1):
        try:
            sol = solver.solve(eps, 0.0, guess)
        except ReynoldsError:
            hi = eps
            eps = 0.5 * (lo + hi)
            continue
        guess = sol.full_film
        m = float(np.hypot(*sol.force))
        r = m - fmag
        if r < 0:
            lo = eps
        else:
            hi = eps
        if abs(r) <= tol * fmag:
            break
        dm = float(sol.force @ sol.jac_position[:, 0]) / m
        new = eps - r / dm if dm > 0 else -1.0
        if not lo < new < hi:
            new = 0.5 * (lo + hi)
        if hi - lo < 1e-13:
            break
        eps = new
    else:
        raise EquilibriumError(f"eccentricity iteration did not converge ({max_iter} steps)")
    if hi >= 1.0 - 1e-12 and eps > 0.999:
        raise EquilibriumError("load too large: the journal reaches the bore")
    f = sol.force
    if solver.geometry.lands[0].periodic:
        # a film closed on itself has no feed: the bearing is invariant under rotation, and a
        # tangential step turns the force with the journal, df/dY = S f / eps (S = [[0, -1], [1, 0]]).
        # The grid's own difference tends to it as the grid is refined (0.75 % of max|K| apart at
        # e/Cb 0.58 on 96 x 8); this is the tangent of the transient's film force
        # (film_force.ExactFilmForce), so static, modal and transient share one model.
        jp = sol.jac_position.copy()
        jp[:, 1] = np.array([-f[1], f[0]]) / eps
        sol = replace(sol, jac_position=jp)
    psi = math.atan2(target[1], target[0]) - math.atan2(f[1], f[0])
    Rm = _rot(psi)
    pos = Rm @ np.array([eps, 0.0])
    film = replace(sol, X=float(pos[0]), Y=float(pos[1]), force=Rm @ f,
                   jac_position=Rm @ sol.jac_position @ Rm.T,
                   jac_velocity=Rm @ sol.jac_velocity @ Rm.T)
    log.debug("axisymmetric equilibrium eps=%.6f in %d iterations", eps, it)
    return Equilibrium(film=film, X=float(pos[0]), Y=float(pos[1]), iterations=it,
                       rotation_rad=psi, grid_full_film=sol.full_film)


def solve_newton(solver: ReynoldsSolver, target: np.ndarray, initial=(0.0, 0.0),
                 tol: float = 1e-9, max_iter: int = 60,
                 full_film_guess: np.ndarray | None = None, initial_solution=None) -> Equilibrium:
    """Newton iteration on the journal position for ``f(X, Y) = target``; ``initial_solution`` is the
    film already solved at ``initial`` (dimensionless: the same for any viscosity, speed and load), so
    a neighbouring operating point starts without solving it again."""
    fmag = float(np.hypot(*target))
    if fmag <= 0:
        raise EquilibriumError("zero load")
    x = np.asarray(initial, dtype=float).copy()
    if not np.any(x):
        # start slightly displaced along the load (the journal moves towards the load
        # direction, which is opposite to the film force on it)
        x = -0.05 * target / fmag
    same = initial_solution is not None and np.allclose([initial_solution.X, initial_solution.Y], x,
                                                        rtol=1e-12, atol=1e-15)  # m -> Cb units round-off
    sol = initial_solution if same else solver.solve(x[0], x[1], full_film_guess)
    if same:
        x = np.array([initial_solution.X, initial_solution.Y])
    guess = sol.full_film
    res = sol.force - target
    for it in range(1, max_iter + 1):
        rn = float(np.hypot(*res))
        if rn <= tol * fmag:
            break
        J = sol.jac_position
        try:
            step = -np.linalg.solve(J, res)
        except np.linalg.LinAlgError:
            step = -0.05 * res / max(rn, 1e-300)
        # keep steps modest compared with the film (Newton from far away overshoots)
        sn = float(np.hypot(*step))
        if sn > 0.25:
            step *= 0.25 / sn
        alpha = 1.0
        for _ in range(30):
            trial = x + alpha * step
            try:
                tsol = solver.solve(trial[0], trial[1], guess)
            except ReynoldsError:
                alpha *= 0.5
                continue
            tres = tsol.force - target
            if float(np.hypot(*tres)) < (1.0 - 1e-4 * alpha) * rn or alpha < 1e-6:
                break
            alpha *= 0.5
        else:
            raise EquilibriumError("line search failed: the journal cannot carry the load")
        x, sol, res, guess = trial, tsol, tres, tsol.full_film
    else:
        raise EquilibriumError(
            f"Newton iteration on the journal position did not converge in {max_iter} steps "
            f"(residual {float(np.hypot(*res)) / fmag:.2e} of the load)")
    if sol.min_film < 1e-3:
        raise EquilibriumError("load too large: minimum film below 0.1 % of Cb")
    log.debug("Newton equilibrium X=%.6f Y=%.6f in %d iterations", x[0], x[1], it)
    return Equilibrium(film=sol, X=float(x[0]), Y=float(x[1]), iterations=it,
                       grid_full_film=sol.full_film)
