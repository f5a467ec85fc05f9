"""Time response of the FE rotor with nonlinear bearing reactions (seed 001 eq. 41).

    M q'' + C(Omega) q' + K(Omega) q = F(t) + sum_b f_b(q_b, q_b', t)

integrated with the Newmark average-acceleration rule (beta = 1/4, gamma = 1/2:
unconditionally stable, no numerical damping, exact energy balance for linear
undamped systems) and Newton iterations on the nonlinear bearing forces, whose
tangent K_t = -df/dq, C_t = -df/dq' enters the iteration matrix

    J = M / (beta dt^2) + (C + C_t) gamma / (beta dt) + K + K_t.

Bearings that are linear are in K and C already; nonlinear ones implement
``force_and_tangent(q_b, v_b, t) -> (f, K_t, C_t)`` on their ``dof_names``.
A run that stops early (Newton failure, non-finite state, Ctrl-C) returns what it
computed with ``complete=False`` and the reason.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
import scipy.linalg as sla

from ..fe.assembly import assemble_shaft, load_vector, system_matrices
from ..model.rotor import Rotor

log = logging.getLogger(__name__)
BETA, GAMMA = 0.25, 0.5


@dataclass(frozen=True)
class RotorTransientResult:
    time_s: np.ndarray
    displacement_m: np.ndarray  # [t, recorded node, dof] in the rotor's DOF order
    recorded_nodes: np.ndarray  # 0-based
    dof_names: tuple[str, ...]
    bearing_force_N: np.ndarray  # [t, nonlinear bearing, dof] force on the shaft
    complete: bool
    reason: str
    newton_iterations: np.ndarray  # per step


def unbalance_force(rotor: Rotor, node: int, unbalance_kg_m: float, phase_rad: float = 0.0):
    """F(t) of a rotating unbalance m e at 0-based ``node``: m e W^2 (cos(W t + a), sin(W t + a))."""
    W = rotor.speed_rad_s
    ix, iy = rotor.dofs.index(node, "x"), rotor.dofs.index(node, "y")
    amp = unbalance_kg_m * W**2

    def force(t: float, out: np.ndarray) -> None:
        out[ix] += amp * np.cos(W * t + phase_rad)
        out[iy] += amp * np.sin(W * t + phase_rad)

    return force


def integrate(rotor: Rotor, t_end: float, dt: float, nonlinear: Sequence = (),
              forces: Sequence[Callable[[float, np.ndarray], None]] = (), q0: np.ndarray | None = None,
              v0: np.ndarray | None = None, record_nodes: Sequence[int] | None = None, include_static: bool = True,
              tol: float = 1e-10, max_newton: int = 30,
              progress: Callable[[int, int], None] | None = None) -> RotorTransientResult:
    """Integrate from t = 0 to ``t_end`` with step ``dt`` (Newmark average acceleration + Newton)."""
    shaft = assemble_shaft(rotor)
    sysm = system_matrices(rotor, shaft, rotor.speed_rad_s)
    M, C, K = sysm.M, sysm.C, sysm.K
    n = sysm.size
    dofs = rotor.dofs
    Q0 = load_vector(rotor, shaft) if include_static else np.zeros(n)
    b_idx = [np.array([dofs.index(b.node, d) for d in b.dof_names]) for b in nonlinear]
    nodes = np.arange(rotor.n_nodes) if record_nodes is None else np.asarray(record_nodes, int)
    rec_idx = np.array([[dofs.index(nd, d) for d in dofs.names] for nd in nodes])
    n_steps = int(round(t_end / dt))
    time = np.arange(n_steps + 1) * dt
    hist = np.full((n_steps + 1, len(nodes), dofs.per_node), np.nan)
    bforce = np.full((n_steps + 1, len(nonlinear), max((len(i) for i in b_idx), default=0)), np.nan)
    iters = np.zeros(n_steps + 1, int)
    q = np.zeros(n) if q0 is None else np.array(q0, float)
    v = np.zeros(n) if v0 is None else np.array(v0, float)

    def external(t: float) -> np.ndarray:
        F = Q0.copy()
        for f in forces:
            f(t, F)
        return F

    def bearing_terms(q_, v_, t):
        f = np.zeros(n)
        Kt = np.zeros((n, n))
        Ct = np.zeros((n, n))
        fb = []
        for b, idx in zip(nonlinear, b_idx):
            fi, ki, ci = b.force_and_tangent(q_[idx], v_[idx], t)
            f[idx] += fi
            Kt[np.ix_(idx, idx)] += ki
            Ct[np.ix_(idx, idx)] += ci
            fb.append(fi)
        return f, Kt, Ct, fb

    fnl, Kt, Ct, fb = bearing_terms(q, v, 0.0)
    a = sla.solve(M, external(0.0) + fnl - C @ v - K @ q, assume_a="pos")
    hist[0] = q[rec_idx]
    for j, fi in enumerate(fb):
        bforce[0, j, : len(fi)] = fi
    c0, c1 = 1.0 / (BETA * dt**2), GAMMA / (BETA * dt)
    complete, reason = True, ""
    lin = M * c0 + C * c1 + K
    lu_lin = sla.lu_factor(lin) if not nonlinear else None
    try:
        for k in range(1, n_steps + 1):
            t = time[k]
            F = external(t)
            qn = q + dt * v + dt**2 * (0.5 - BETA) * a  # predictor (zero new acceleration)
            for it in range(1, max_newton + 1):
                an = c0 * (qn - q) - v / (BETA * dt) - (0.5 / BETA - 1.0) * a
                vn = v + dt * ((1 - GAMMA) * a + GAMMA * an)
                if nonlinear:
                    fnl, Kt, Ct, fb = bearing_terms(qn, vn, t)
                    R = F + fnl - M @ an - C @ vn - K @ qn
                    dq = sla.solve(lin + Kt + c1 * Ct, R, check_finite=False)
                else:
                    R = F - M @ an - C @ vn - K @ qn
                    dq = sla.lu_solve(lu_lin, R, check_finite=False)
                qn = qn + dq
                if not np.all(np.isfinite(qn)):
                    raise FloatingPointError(f"non-finite state at t = {t:.6g} s")
                scale = max(np.max(np.abs(qn)), 1e-12)
                if np.max(np.abs(dq)) <= tol * scale or (not nonlinear):
                    break
            else:
                raise ArithmeticError(f"Newton did not converge at t = {t:.6g} s in {max_newton} iterations "
                                      f"(last correction {np.max(np.abs(dq)):.3g} m); try a smaller time step")
            an = c0 * (qn - q) - v / (BETA * dt) - (0.5 / BETA - 1.0) * a
            vn = v + dt * ((1 - GAMMA) * a + GAMMA * an)
            q, v, a = qn, vn, an
            hist[k] = q[rec_idx]
            if nonlinear:
                for j, fi in enumerate(fb):
                    bforce[k, j, : len(fi)] = fi
            iters[k] = it
            if progress is not None and (k % max(1, n_steps // 100) == 0 or k == n_steps):
                progress(k, n_steps)
    except (ArithmeticError, FloatingPointError, KeyboardInterrupt) as exc:
        complete = False
        reason = "interrupted by the user" if isinstance(exc, KeyboardInterrupt) else str(exc)
        log.warning("transient stopped early: %s", reason)
        last = int(np.max(np.flatnonzero(np.isfinite(hist[:, 0, 0])))) + 1
        time, hist, bforce, iters = time[:last], hist[:last], bforce[:last], iters[:last]
    return RotorTransientResult(time_s=time, displacement_m=hist, recorded_nodes=nodes, dof_names=dofs.names,
                                bearing_force_N=bforce, complete=complete, reason=reason, newton_iterations=iters)


def static_equilibrium(rotor: Rotor, nonlinear: Sequence, q0: np.ndarray | None = None, tol: float = 1e-10,
                       max_iter: int = 50) -> np.ndarray:
    """K q - sum_b f_b(q_b) = Q (point loads, gravity) by Newton with the bearings' tangent stiffness.

    Raises ArithmeticError naming the residual when Newton does not converge.
    """
    shaft = assemble_shaft(rotor)
    sysm = system_matrices(rotor, shaft, rotor.speed_rad_s)
    K, n, dofs = sysm.K, sysm.size, rotor.dofs
    Q = load_vector(rotor, shaft)
    b_idx = [np.array([dofs.index(b.node, d) for d in b.dof_names]) for b in nonlinear]
    q = np.zeros(n) if q0 is None else np.array(q0, float)
    scale_f = max(np.max(np.abs(Q)), 1.0)
    for it in range(1, max_iter + 1):
        R = Q - K @ q
        J = K.copy()
        for b, idx in zip(nonlinear, b_idx):
            f, kt, _ = b.force_and_tangent(q[idx], np.zeros(len(idx)), 0.0)
            R[idx] += f
            J[np.ix_(idx, idx)] += kt
        dq = np.linalg.solve(J, R)
        # damp large first steps (contact stiffness is strongly nonlinear near zero load)
        step = 1.0
        q = q + step * dq
        if np.max(np.abs(R)) <= tol * scale_f * 1e3 and np.max(np.abs(dq)) <= tol * max(np.max(np.abs(q)), 1e-9):
            return q
    raise ArithmeticError(f"static equilibrium with nonlinear bearings did not converge in {max_iter} Newton "
                          f"iterations (residual {np.max(np.abs(R)):.3g} N)")
