"""Newmark average-acceleration method with Newton iterations (any bearing).

beta = 1/4, gamma = 1/2: unconditionally stable, no numerical damping, exact energy balance for
linear undamped systems (Newmark 1959; Hughes, The Finite Element Method, 1987, ch. 9).  Each
step solves the nonlinear residual

    R(x1) = F(t1) + f_b(x1, v1, t1) - M a1 - C(Omega_1) v1 - K(Omega_1) x1 = 0,
    a1 = (x1 - x0 - h v0) / (beta h^2) - (1/(2 beta) - 1) a0,  v1 = v0 + h ((1 - gamma) a0 + gamma a1)

with the iteration matrix J = M / (beta h^2) + (C + C_t) gamma / (beta h) + K + K_t from the
bearings' tangents (the contract).  J is factorised once and kept while the iterations contract
well (modified Newton): it is refactorised within a step when an iteration shrinks the correction by
less than REFACTOR_RATIO, and at the start of a step when the previous one needed more than
SLOW_STEP iterations (a speed ramp changes J a little every step).  The bearings' tangents are
evaluated only when J is refactorised (the other iterations need their forces alone) and added block
by block; the shaft's K(Omega), C(Omega) are affine in the speed and formed from two precomputed
pairs.  (On the seed 003 spindle with its 3-lobe bearings, a run-up on linear bearings and the oil
whirl of tests/validation/test_one_model_oil_whirl.py this takes 45-50 % less time than factorising
with a 0.25 ratio and evaluating the tangents at every iteration; the trajectories agree to 1e-9 of
the response, the Newton tolerance.)  The iterations start from the acceleration extrapolated from
the last two steps, a1 = 2 a0 - a_-1 (a third fewer iterations than from zero new acceleration in an
oil whirl near the bore, benchmarks/bench_whirl.py); a step whose iterations fail from there is
solved once more from zero new acceleration with a fresh matrix, so the predictor never costs a
run.  The factors are LAPACK's getrf/getrs called directly (scipy's wrappers check their input at
every call, which took longer than the solve for a small rotor).  States between steps (Poincare
instants) are cubic Hermite interpolants of (x, v) at the two ends.
"""

from __future__ import annotations

import logging

import numpy as np
import scipy.linalg as sla
from scipy.linalg.lapack import dgetrf, dgetrs

from .result import Plan, Trajectory
from .system import RotorSystem

log = logging.getLogger(__name__)
BETA, GAMMA = 0.25, 0.5
#: refactorise J when an iteration's correction is more than this share of the previous one
REFACTOR_RATIO = 0.1
#: refactorise J at the start of a step after a step that needed more iterations than this
SLOW_STEP = 3


def hermite(t0, x0, v0, t1, x1, v1, tp):
    """(x, v) at tp in [t0, t1] from the cubic Hermite interpolant of the end states."""
    h = t1 - t0
    s = (tp - t0) / h
    s2, s3 = s * s, s * s * s
    x = (2 * s3 - 3 * s2 + 1) * x0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * x1 + (s3 - s2) * h * v1
    v = ((6 * s2 - 6 * s) * x0 + (3 * s2 - 4 * s + 1) * h * v0 + (-6 * s2 + 6 * s) * x1 + (3 * s2 - 2 * s) * h * v1) / h
    return x, v


def _factor(J: np.ndarray, t: float) -> tuple[np.ndarray, np.ndarray]:
    """LU factors of the iteration matrix (LAPACK getrf; what ``scipy.linalg.lu_factor`` returns)."""
    lu, piv, info = dgetrf(J)
    if info > 0:
        raise np.linalg.LinAlgError(f"singular iteration matrix at t = {t:.6g} s")
    return lu, piv


def integrate(system: RotorSystem, x0: np.ndarray, v0: np.ndarray, plan: Plan, targets: np.ndarray,
              progress=None, tol: float = 1e-10, max_newton: int = 40, **_) -> Trajectory:
    """Integrate from t = 0 over ``plan``; states at the sorted instants ``targets`` by interpolation."""
    h, every = plan.step_s, plan.steps_per_sample
    N = system.size
    M = system.M
    prof = system.profile
    c0, c1 = 1.0 / (BETA * h * h), GAMMA / (BETA * h)
    K0, K1, C0, C1 = system.speed_affine
    X = np.full((plan.n_samples + 1, N), np.nan)
    V = np.full_like(X, np.nan)
    iters = np.zeros(plan.n_samples + 1, int)
    pt, px, pv = [], [], []
    x, v = np.array(x0, float), np.array(v0, float)
    W = prof.speed(0.0)
    K, C = K0 + W * K1, C0 + W * C1
    f = system.forces(x, v, 0.0)
    a = sla.solve(M, system.external(0.0) + f - C @ v - K @ x, assume_a="sym")
    X[0], V[0] = x, v
    ti = int(np.searchsorted(targets, 0.0, side="left"))
    while ti < len(targets) and targets[ti] <= 0.0:
        pt.append(0.0); px.append(x.copy()); pv.append(v.copy())
        ti += 1
    a_old = a
    lu = None
    complete, reason = True, ""
    k, it = 0, 0
    total = plan.n_steps
    report = max(1, total // 200)

    def newton(xn: np.ndarray, t1: float, F1: np.ndarray, fresh: bool) -> tuple[np.ndarray, int]:
        """x1 solving R(x1) = 0 from the start ``xn`` (modified Newton, module note); (x1, iterations)."""
        nonlocal lu
        prev = np.inf
        for n_it in range(1, max_newton + 1):
            an = c0 * (xn - x) - v / (BETA * h) - (0.5 / BETA - 1.0) * a
            vn = v + h * ((1.0 - GAMMA) * a + GAMMA * an)
            if fresh or lu is None:
                J = M * c0 + C * c1 + K
                Ct = np.zeros((N, N))
                f = system.forces_and_tangents(xn, vn, t1, J, Ct)
                J += c1 * Ct
                lu = _factor(J, t1)
                fresh = False
            else:
                f = system.forces(xn, vn, t1)
            R = F1 + f - M @ an - C @ vn - K @ xn
            dx = dgetrs(*lu, R)[0]  # LAPACK directly: scipy's lu_solve checks cost more than the solve
            xn = xn + dx
            step = float(np.max(np.abs(dx)))
            if not np.isfinite(step):
                raise FloatingPointError(f"non-finite state at t = {t1:.6g} s")
            if step <= tol * max(float(np.max(np.abs(xn))), 1e-9):
                return xn, n_it
            if step > REFACTOR_RATIO * prev:  # slow contraction: a fresh iteration matrix
                fresh = True
            prev = step
        raise ArithmeticError(f"Newton did not converge at t = {t1:.6g} s in {max_newton} iterations "
                              f"(last correction {step:.3g}); try a smaller time step")

    try:
        for k in range(1, total + 1):
            t0, t1 = (k - 1) * h, k * h
            if not prof.constant:
                W = prof.speed(t1)
                K, C = K0 + W * K1, C0 + W * C1
            F1 = system.external(t1)
            # predictor: the acceleration extrapolated from the last two steps
            xn = x + h * v + h * h * ((0.5 - BETA) * a + BETA * (2.0 * a - a_old))
            try:
                xn, it = newton(xn, t1, F1, it > SLOW_STEP)
            except (ArithmeticError, ValueError):  # once more from zero new acceleration, with a fresh matrix
                xn, it = newton(x + h * v + h * h * (0.5 - BETA) * a, t1, F1, True)
                it += max_newton
            an = c0 * (xn - x) - v / (BETA * h) - (0.5 / BETA - 1.0) * a
            vn = v + h * ((1.0 - GAMMA) * a + GAMMA * an)
            while ti < len(targets) and targets[ti] <= t1 + 1e-12 * h:
                xp, vp = hermite(t0, x, v, t1, xn, vn, min(targets[ti], t1))
                pt.append(targets[ti]); px.append(xp); pv.append(vp)
                ti += 1
            x, v, a, a_old = xn, vn, an, a
            if k % every == 0:
                j = k // every
                X[j], V[j], iters[j] = x, v, it
            if progress is not None and (k % report == 0 or k == total):
                progress(k / total, t1)
    except (ArithmeticError, FloatingPointError, ValueError, np.linalg.LinAlgError, KeyboardInterrupt) as exc:
        complete = False
        reason = "interrupted by the user" if isinstance(exc, KeyboardInterrupt) else str(exc)
        if not isinstance(exc, KeyboardInterrupt):
            reason = f"at t = {k * h:.6g} s: {reason}" if "t =" not in reason else reason
        log.warning("transient stopped early: %s", reason)
    n = int(np.max(np.flatnonzero(np.isfinite(X[:, 0])))) + 1
    time = np.arange(plan.n_samples + 1) * h * every
    return Trajectory(time[:n], X[:n], V[:n], np.asarray(pt), np.asarray(px).reshape(-1, N),
                      np.asarray(pv).reshape(-1, N), complete, reason, iters[:n])
