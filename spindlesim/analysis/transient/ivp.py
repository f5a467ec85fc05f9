"""scipy's adaptive methods (RK45, DOP853, Radau, BDF, LSODA) on the first-order system.

An independent cross-check of the fixed-step methods: same equations (``system``), the bearing
forces from the contract in Python, the tolerance the user gives.  Samples and Poincare states
come from the methods' dense output.
"""

from __future__ import annotations

import logging

import numpy as np
import scipy.linalg as sla

from .result import Plan, Trajectory
from .system import RotorSystem

log = logging.getLogger(__name__)


def integrate(system: RotorSystem, x0: np.ndarray, v0: np.ndarray, plan: Plan, targets: np.ndarray,
              progress=None, method: str = "DOP853", rtol: float = 1e-8, atol: float | None = None,
              chunks: int = 40, **_) -> Trajectory:
    from scipy.integrate import solve_ivp  # here: the cross-check methods only (0.1 s of imports)

    N = system.size
    lu = sla.cho_factor(system.M)
    prof = system.profile

    def rhs(t, y):
        x, v = y[:N], y[N:]
        W = prof.speed(t)
        f, _, _, _ = system.bearing_forces(x, v, t, with_tangent=False)
        F = system.external(t) + f - system.stiffness(W) @ x - system.damping(W) @ v
        return np.concatenate([v, sla.cho_solve(lu, F)])

    y = np.concatenate([x0, v0]).astype(float)
    scale = np.maximum(np.abs(y), 1e-9)
    atol = rtol * scale if atol is None else atol
    T = plan.n_samples * plan.steps_per_sample * plan.step_s
    grid = np.arange(plan.n_samples + 1) * plan.steps_per_sample * plan.step_s
    edges = np.linspace(0.0, T, max(1, chunks) + 1)
    ts, ys, pts, pys = [grid[:1]], [y[None, :]], [], []
    complete, reason = True, ""
    for i, (ta, tb) in enumerate(zip(edges[:-1], edges[1:])):
        try:  # the chunk, its samples and the progress line: a Ctrl-C anywhere in them ends here
            sol = solve_ivp(rhs, (ta, tb), y, method=method, rtol=rtol, atol=atol, dense_output=True)
            if sol.status != 0 or not np.all(np.isfinite(sol.y)):
                complete, reason = False, f"{method} stopped in [{ta:.6g}, {tb:.6g}] s: {sol.message}"
                break
            sel = (grid > ta) & (grid <= tb * (1 + 1e-12))
            psel = (targets > ta - 1e-15) & (targets <= tb)
            if i > 0:
                psel &= targets > ta
            got = (grid[sel], sol.sol(grid[sel]).T if sel.any() else None,
                   targets[psel], sol.sol(targets[psel]).T if psel.any() else None)
        except KeyboardInterrupt:
            complete, reason = False, f"interrupted by the user at t = {ta:.6g} s"
            break
        except (ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            complete, reason = False, f"integration failed at t = {ta:.6g} s: {exc}"
            break
        if got[1] is not None:
            ts.append(got[0]); ys.append(got[1])
        if got[3] is not None:
            pts.append(got[2]); pys.append(got[3])
        y = sol.y[:, -1].copy()
        try:
            if progress is not None:
                progress(tb / T, tb)
        except KeyboardInterrupt:
            complete, reason = False, f"interrupted by the user at t = {tb:.6g} s"
            break
    t_out = np.concatenate(ts)
    Y = np.concatenate(ys)
    PT = np.concatenate(pts) if pts else np.zeros(0)
    PY = np.concatenate(pys) if pys else np.zeros((0, 2 * N))
    return Trajectory(t_out, Y[:, :N], Y[:, N:], PT, PY[:, :N], PY[:, N:], complete, reason, np.zeros(len(t_out), int))
