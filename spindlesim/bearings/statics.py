"""The one damped Newton of the statics, and the equilibrium of one bearing alone under a load.

:func:`damped_newton` solves R(x) = 0 by Newton's method with Levenberg-Marquardt damping and a step
acceptance test: the step dx solves (J + lambda D) dx = R (J the tangent, D a diagonal scale: given,
or the diagonal of J), is capped per unknown, and is taken only when it does not raise the merit (a
norm of R); lambda shrinks after a step taken and grows after one refused, so far from the root the
steps turn towards the residual and near it they are Newton's.  Contact laws Q = K delta^n have zero
stiffness at first touch and a roller in its clearance has none at all, so the plain Newton matrix
can be singular; the damping vanishes at convergence.  The ball set (``ball/equilibrium.py``), the
DTRB ring (``dtrb/bearing.py``), :func:`equilibrium_under_load` and the rotor's static equilibrium
(``spindlesim.analysis.operating``: undamped at first, a refused step halved before the damping grows,
a bearing that refuses a position is a refused step) use it.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class NewtonResult:
    """Where :func:`damped_newton` stopped: x, its residual R, tangent J and ``data`` (what the
    evaluation returned beside them), the steps taken and whether the test of convergence passed."""

    x: np.ndarray
    R: np.ndarray
    J: np.ndarray
    data: Any
    iterations: int
    converged: bool


def damped_newton(evaluate: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, Any]], x0: np.ndarray, *,
                  converged: Callable[[np.ndarray, Any], bool], merit: Callable[[np.ndarray], float],
                  cap: np.ndarray | float, damping: np.ndarray | None = None, lam0: float = 1e-3,
                  shrink: float = 0.2, lam_min: float = 1e-14, grow: float = 8.0, lam_max: float = 1e12,
                  max_iter: int = 200, stalled: Callable[[np.ndarray, float, float], bool] | None = None,
                  evaluated: tuple[np.ndarray, np.ndarray, Any] | None = None,
                  floor: Callable[[np.ndarray, Any], bool] | None = None, lam_restart: float = 1e-6,
                  backtrack: int = 0, refuse: tuple[type[BaseException], ...] = ()) -> NewtonResult:
    """Levenberg-Marquardt damped Newton with step acceptance (module note).

    ``evaluate(x) -> (R, J, data)``: residual, tangent (the step solves (J + lam D) dx = R) and anything
    the caller keeps; ``converged(R, data)`` ends the solve (checked before each step); ``merit(R)``: a
    step is taken when finite and not above the current merit (to 1e-12 of it); ``cap``: the largest
    step per unknown (a step beyond it is scaled down whole); ``damping``: D (None: |diag J|, zeros
    raised to 1e-6 of its largest); lambda starts at ``lam0`` (0: undamped), is multiplied by ``shrink``
    (not below ``lam_min``) after a step taken and by ``grow`` after one refused (or a singular matrix;
    from 0 to ``lam_restart``), and the solve gives up beyond ``lam_max`` or after ``max_iter`` iterations;
    ``backtrack``: a refused step is halved up to that many times before lambda grows (a line search);
    ``refuse``: exceptions of ``evaluate`` at a trial point that refuse the step (a bearing that cannot
    take that position); ``stalled(R, merit_before, merit_after)``: a step taken that ends the solve (at
    the round-off floor of the residual); ``evaluated``: ``evaluate(x0)`` when the caller has it;
    ``floor(R, data)``: when a step is refused, the current point is at the round-off floor of the
    residual (noise of an inner solve): the solve ends there.
    Returns the last point taken; the caller raises its own error when ``converged`` is False.
    """
    x = np.array(x0, float)
    cap = np.broadcast_to(np.asarray(cap, float), x.shape)
    R, J, data = evaluate(x) if evaluated is None else evaluated
    m = merit(R)
    lam = lam0
    it = 0
    for it in range(1, max_iter + 1):
        if converged(R, data):
            return NewtonResult(x, R, J, data, it - 1, True)
        D = _diagonal(J) if damping is None else damping
        try:
            step = np.linalg.solve(J + lam * np.diag(D), R)
        except np.linalg.LinAlgError:
            step = None
        if step is not None:
            big = float(np.max(np.abs(step) / cap))
            if big > 1.0:
                step = step / big
            for _ in range(backtrack + 1):
                trial = x + step
                try:
                    Rt, Jt, dt = evaluate(trial)
                except refuse as exc:
                    log.debug("damped Newton: step refused (%s)", exc)
                    step = 0.5 * step
                    continue
                mt = merit(Rt)
                if np.all(np.isfinite(Rt)) and mt <= m * (1.0 + 1e-12):
                    break
                step = 0.5 * step
            else:
                trial = None
            if trial is not None:
                before = m
                x, R, J, data, m = trial, Rt, Jt, dt, mt
                lam = max(lam * shrink, lam_min) if lam > 0.0 else 0.0
                if stalled is not None and stalled(R, before, m):
                    return NewtonResult(x, R, J, data, it, True)
                continue
        if floor is not None and floor(R, data):
            return NewtonResult(x, R, J, data, it, True)
        lam = lam * grow if lam > 0.0 else lam_restart
        if lam > lam_max:
            break
    return NewtonResult(x, R, J, data, it, False)


def _diagonal(J: np.ndarray) -> np.ndarray:
    d = np.abs(np.diag(J))
    return np.where(d > 0, d, max(float(d.max()) if d.size else 1.0, 1.0) * 1e-6)


class BearingEquilibriumError(ArithmeticError):
    """No equilibrium of a bearing under a load was found."""


def equilibrium_under_load(force_and_tangent: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]],
                           load: np.ndarray, q0: np.ndarray, length_scale: np.ndarray | float,
                           name: str = "bearing", tol: float = 1e-10, max_iter: int = 200,
                           max_step: float | np.ndarray | None = None) -> np.ndarray:
    """q with force(q) + load_padded = 0; ``force_and_tangent(q) -> (f, K_t)``.

    ``load`` acts on the leading DOFs (the node's); ``length_scale`` is a typical displacement
    per DOF (convergence and step limits); ``max_step`` caps each Newton step per DOF.
    """
    q = np.array(q0, float)
    n = q.size
    W = np.zeros(n)
    W[: len(load)] = load
    scale = np.broadcast_to(np.asarray(length_scale, float), (n,))
    cap = scale * 20.0 if max_step is None else np.broadcast_to(np.asarray(max_step, float), (n,))
    f_scale = max(float(np.max(np.abs(load))), 1.0)

    def evaluate(x):
        f, K = force_and_tangent(x)
        return f + W, K, None

    def at_floor(r, before, after):  # stalled at the round-off floor of the forces
        return after > 0.5 * before and np.max(np.abs(r)) <= 1e-6 * f_scale

    out = damped_newton(evaluate, q, converged=lambda r, _: np.max(np.abs(r)) <= tol * f_scale,
                        merit=lambda r: float(np.linalg.norm(r)), cap=cap, max_iter=max_iter, stalled=at_floor)
    if out.converged:
        return out.x
    raise BearingEquilibriumError(
        f"bearing {name!r}: no equilibrium under the load {np.round(np.asarray(load, float), 6).tolist()} N "
        f"(damped Newton, {max_iter} iterations; residual {np.max(np.abs(out.R)):.3g} N)")
