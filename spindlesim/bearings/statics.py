"""Equilibrium of one bearing alone under a load: what ``linearized`` of a nonlinear bearing needs.

Finds q (node DOFs followed by internal DOFs) with f(q) + [W, 0] = 0 for the bearing's
``force_and_tangent`` by Newton's method with Levenberg-Marquardt damping: contact laws
Q = K delta^n have zero stiffness at first touch and a roller in its clearance has none at
all, so the plain Newton matrix can be singular; the damping lambda D (D the diagonal of the
tangent, or a given scale) shrinks as the residual falls and vanishes at convergence.
The rotor's own static equilibrium is ``spindlesim.analysis.operating``.
"""

from __future__ import annotations

from typing import Callable

import numpy as np


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
    lam = 1e-3
    f, K = force_and_tangent(q)
    r = f + W
    rn = np.linalg.norm(r)
    for it in range(1, max_iter + 1):
        if np.max(np.abs(r)) <= tol * f_scale:
            return q
        d = np.abs(np.diag(K))
        d = np.where(d > 0, d, max(float(d.max()) if d.size else 1.0, 1.0) * 1e-6)
        try:
            step = np.linalg.solve(K + lam * np.diag(d), r)
        except np.linalg.LinAlgError:
            lam *= 10.0
            continue
        big = np.max(np.abs(step) / cap)
        if big > 1.0:
            step /= big
        trial = q + step
        ft, Kt = force_and_tangent(trial)
        rt = ft + W
        rtn = np.linalg.norm(rt)
        if np.all(np.isfinite(rt)) and rtn < rn * (1.0 + 1e-12) + 1e-300:
            stalled = rtn > 0.5 * rn
            q, f, K, r, rn = trial, ft, Kt, rt, rtn
            lam = max(lam * 0.2, 1e-14)
            if stalled and np.max(np.abs(r)) <= 1e-6 * f_scale:  # at the round-off floor of the forces
                return q
        else:
            lam = lam * 8.0
            if lam > 1e12:
                break
    raise BearingEquilibriumError(
        f"bearing {name!r}: no equilibrium under the load {np.round(np.asarray(load, float), 6).tolist()} N "
        f"(damped Newton, {max_iter} iterations; residual {np.max(np.abs(r)):.3g} N)")
