"""Transient of a thermal network (warm-up): C dT/dt = Q(t, T) - K(t, T) T.

Two integrators:

- ``"BDF"`` / ``"Radau"``: :func:`scipy.integrate.solve_ivp` on the free nodes with the Jacobian
  -C^-1 K_ff (exact for a linear network; with temperature-dependent callables it is the frozen-
  coefficient Jacobian, which the implicit methods only use for their Newton iterations, so the
  result still meets ``rtol``/``atol``).  Every free node needs a heat capacity > 0.
- ``"implicit_euler"``: fixed steps of at most ``dt_s``, (C/h + K) T_n+1 = C/h T_n + Q_n+1 - K_fb T_b,
  first order, unconditionally stable, nodes of zero capacity allowed (algebraic rows).  The
  discrete energy balance C (T_n+1 - T_n) = h (Q - removed)_n+1 holds to rounding, so the stored
  heat equals the time sum of generated minus removed exactly (a check of the bookkeeping).  With
  callables each step iterates (Picard) to ``tol_K``.

Time dependence: ``sources``, ``conductances`` are callables ``f(t, T)``, ``capacity_rates`` and
``boundary`` callables ``f(t)`` (or constants).  ``breakpoints`` are times where they jump (speed
steps, e.g. a :class:`StepProfile` as in the variable-speed tests of ISO 230-3): the integration
restarts there, and inside a segment [t_a, t_b] a callable is never evaluated at t_b itself but at
the float just below it, so a right-continuous step profile gives the segment's own value.
"""

from __future__ import annotations

import bisect
import logging
import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from .network import EnergyBalance, Network, ThermalConvergenceError, _balance, _solve

log = logging.getLogger(__name__)

METHODS = ("BDF", "Radau", "implicit_euler")


@dataclass(frozen=True)
class StepProfile:
    """Piecewise-constant quantity (e.g. spindle speed [rpm]): ``values[k]`` from ``times_s[k]`` on
    (right-continuous); ``times_s[0]`` is the start, the later times are the breakpoints."""

    times_s: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self):
        object.__setattr__(self, "times_s", tuple(float(t) for t in self.times_s))
        object.__setattr__(self, "values", tuple(float(v) for v in self.values))
        if not self.times_s or len(self.times_s) != len(self.values):
            raise ValueError("a step profile needs as many step times as values (at least one)")
        if any(b <= a for a, b in zip(self.times_s, self.times_s[1:])):
            raise ValueError("step times must increase")

    def __call__(self, t: float) -> float:
        return self.values[max(0, bisect.bisect_right(self.times_s, t) - 1)]

    def before(self, t: float) -> float:
        """The value just before ``t`` (left limit; at a step time the value before the step)."""
        return self.values[max(0, bisect.bisect_left(self.times_s, t) - 1)]

    @property
    def breakpoints(self) -> tuple[float, ...]:
        return self.times_s[1:]


@dataclass(frozen=True)
class TransientResult:
    """Node temperatures [degC] (rows: times) and the heat flows at each output time."""

    names: tuple[str, ...]
    times_s: np.ndarray
    temperatures_C: np.ndarray          # (n_times, n_nodes)
    generated_W: np.ndarray             # (n_times,)
    removed_W: dict[str, np.ndarray]    # boundary name -> (n_times,)
    capacities_J_K: np.ndarray          # (n_nodes,)
    method: str
    steps: int                          # implicit Euler: steps; BDF/Radau: right-hand-side evaluations

    def __getitem__(self, name: str) -> np.ndarray:
        return self.temperatures_C[:, self.names.index(name)]

    @property
    def final_C(self) -> np.ndarray:
        return self.temperatures_C[-1]

    def stored_J(self) -> np.ndarray:
        """Heat stored since the start, sum C_i (T_i(t) - T_i(0)), per output time."""
        return (self.temperatures_C - self.temperatures_C[0]) @ self.capacities_J_K

    def net_heat_J(self, rule: str = "trapezoid") -> np.ndarray:
        """Time integral of generated - removed from the start ('trapezoid', or 'right' for the
        implicit Euler steps, whose own balance uses the end-of-step flows)."""
        net = self.generated_W - sum(self.removed_W.values())
        dt = np.diff(self.times_s)
        inc = dt * (0.5 * (net[1:] + net[:-1]) if rule == "trapezoid" else net[1:])
        return np.concatenate(([0.0], np.cumsum(inc)))


def _at(t: float, end: float) -> float:
    return t if t < end else float(np.nextafter(end, -math.inf))


def solve_transient(net: Network, initial_C, t_end_s: float, *, sources=None, conductances=None,
                    capacity_rates=None, boundary=None, breakpoints: Sequence[float] = (), method: str = "BDF",
                    rtol: float = 1e-6, atol: float = 1e-6, dt_s: float | None = None,
                    t_eval: Sequence[float] | None = None, max_step: float = math.inf,
                    tol_K: float = 1e-8, max_iter: int = 50, t_start_s: float = 0.0) -> TransientResult:
    """Integrate the network from ``initial_C`` (scalar or per node; boundary nodes take their own
    value) at ``t_start_s`` to ``t_end_s``.  Output at the ``t_eval`` times for BDF/Radau, at every
    step for implicit Euler, and always at the start, the end and both sides of every breakpoint (a
    breakpoint time appears twice: the flows jump there, the temperatures do not)."""
    if method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}")
    if not t_end_s > t_start_s:
        raise ValueError("t_end_s must be after t_start_s")
    c = net._c
    fixed_mask = c["is_fixed"]
    cuts = sorted({float(b) for b in breakpoints if t_start_s < b < t_end_s})
    edges = [float(t_start_s)] + cuts + [float(t_end_s)]

    def state_values(t: float, T: np.ndarray):
        """(q, G, W, T with the boundary values at t) for the full temperature vector T."""
        w = capacity_rates(t) if callable(capacity_rates) else capacity_rates
        b = boundary(t) if callable(boundary) else boundary
        _, W, Tb = net.values(None, w, b)
        T = T.copy()
        T[fixed_mask] = Tb[fixed_mask]
        g = conductances(t, T) if callable(conductances) else conductances
        G, _, _ = net.values(g, None, None)
        q = net.source_vector(sources(t, T) if callable(sources) else sources)
        return q, G, W, T

    T0 = np.broadcast_to(np.asarray(initial_C, dtype=float), (c["n"],)).copy()
    T0 = state_values(t_start_s, T0)[3]
    if method == "implicit_euler":
        if dt_s is None or not dt_s > 0:
            raise ValueError("implicit_euler needs a step dt_s > 0")
        linear = not any(callable(x) for x in (sources, conductances, capacity_rates, boundary))
        records, steps = _implicit_euler(net, T0, edges, state_values, dt_s, linear, tol_K, max_iter)
    else:
        frozen_jac = not callable(conductances) and not callable(capacity_rates)
        records, steps = _ivp(net, T0, edges, state_values, method, rtol, atol, t_eval, max_step, frozen_jac)
    n_out = len(records)
    gen = np.empty(n_out)
    removed = {name: np.empty(n_out) for name in net.boundary_names}
    for j, (_, tt, T) in enumerate(records):
        q, G, W, T = state_values(tt, T)
        bal = _balance(net, T, q, G, W)
        gen[j] = bal.generated_W
        for name in removed:
            removed[name][j] = bal.removed_W[name]
    times = np.array([r[0] for r in records])
    temps = np.array([r[2] for r in records])
    return TransientResult(net.names, times, temps, gen, removed, c["C"].copy(), method, steps)


def _ivp(net, T0, edges, state_values, method, rtol, atol, t_eval, max_step, frozen_jac):
    from scipy.integrate import solve_ivp

    c = net._c
    nf, order = c["nf"], c["order"]
    free, fixed = order[:nf], order[nf:]
    C = c["C"][free]
    if np.any(C <= 0.0):
        bad = [net.names[i] for i in free[C <= 0.0]]
        raise ValueError(f"{method} needs a heat capacity > 0 on every free node; none on {bad} "
                         "(give them one, or use method='implicit_euler')")
    inv_C = 1.0 / C
    want = np.asarray(sorted(t_eval), dtype=float) if t_eval is not None else np.empty(0)
    records, evaluations = [], 0
    T = T0.copy()
    for a, b in zip(edges[:-1], edges[1:]):
        work = T.copy()

        def rhs(t, y):
            work[free] = y
            q, G, W, Tf = state_values(_at(t, b), work)
            K = net.matrix(G, W)
            return inv_C * (q[free] - K[:nf, :nf] @ y - K[:nf, nf:] @ Tf[fixed])

        def jac(t, y):
            work[free] = y
            _, G, W, _ = state_values(_at(t, b), work)
            return -inv_C[:, None] * net.matrix(G, W)[:nf, :nf]

        J = jac(a, T[free]) if frozen_jac else jac
        te = np.concatenate(([a], want[(want > a) & (want < b)], [b]))
        sol = solve_ivp(rhs, (a, b), T[free], method=method, t_eval=te, jac=J, rtol=rtol, atol=atol,
                        max_step=max_step)
        if not sol.success:
            msg = f"thermal transient failed in [{a:g}, {b:g}] s ({method}): {sol.message}"
            log.warning(msg)
            raise ThermalConvergenceError(msg)
        evaluations += int(sol.nfev)
        for k in range(sol.t.size):
            Tk = T.copy()
            Tk[free] = sol.y[:, k]
            Tk = state_values(_at(sol.t[k], b), Tk)[3]
            records.append((float(sol.t[k]), _at(sol.t[k], b), Tk))
        T = records[-1][2].copy()
    return records, evaluations


def _implicit_euler(net, T0, edges, state_values, dt, linear, tol, max_iter):
    from scipy.linalg import lu_factor, lu_solve

    c = net._c
    nf, order = c["nf"], c["order"]
    free, fixed = order[:nf], order[nf:]
    C = c["C"][free]
    records, steps = [], 0
    T = T0.copy()
    for a, b in zip(edges[:-1], edges[1:]):
        records.append((a, a, T.copy()))
        n = max(1, math.ceil((b - a) / dt - 1e-9))
        h = (b - a) / n
        lu = Kfb = None
        for s in range(1, n + 1):
            t = a + (b - a) * s / n
            tt = _at(t, b)
            Tn = T.copy()
            change = 0.0
            for _ in range(max_iter):
                q, G, W, Tn = state_values(tt, Tn)
                rhs = C / h * T[free] + q[free]
                if lu is None or not linear:
                    K = net.matrix(G, W)
                    Kfb = K[:nf, nf:]
                    A = K[:nf, :nf] + np.diag(C / h)
                    if linear:
                        lu = lu_factor(A)
                y = lu_solve(lu, rhs - Kfb @ Tn[fixed]) if linear else _solve(A, rhs - Kfb @ Tn[fixed], net)
                change = float(np.max(np.abs(y - Tn[free]))) if nf else 0.0
                Tn[free] = y
                if linear or change <= tol:
                    break
            else:
                msg = (f"implicit Euler step to t = {t:g} s did not converge in {max_iter} iterations "
                       f"(last change {change:.3g} K, tolerance {tol:g} K)")
                log.warning(msg)
                raise ThermalConvergenceError(msg)
            T = Tn
            steps += 1
            records.append((t, tt, T.copy()))
    return records, steps


def energy_at(result: TransientResult, k: int) -> EnergyBalance:
    """The energy balance recorded in ``result`` at output ``k`` (stored = generated - removed)."""
    removed = {name: float(v[k]) for name, v in result.removed_W.items()}
    g = float(result.generated_W[k])
    return EnergyBalance(g, removed, g - sum(removed.values()))
