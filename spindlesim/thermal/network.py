"""Lumped thermal network: nodes, conductances, coolant advection; steady solve and energy balance.

Each node i has a heat capacity C_i [J/K] and a temperature T_i [degC]; a node with a fixed
temperature is a boundary (ambient air, coolant inlet).  The heat balance of the free nodes is::

    C_i dT_i/dt = Q_i - sum_k G_ik (T_i - T_k) - sum_{u -> i} W_ui (T_i - T_u)

with G_ik [W/K] the conductance of a link i--k and W_ui = m_dot c_p [W/K] the heat-capacity flow of an
advection link u -> i (coolant carried from node u to node i).  The advection term is the upwind
"fluid node" model: the fluid leaves a node at that node's temperature, so a link enters only the
equation of its downstream node and the matrix is not symmetric.  Mass is conserved at every free
fluid node (inflow = outflow, checked), and a node with inflow and no outflow is an outlet whose
stream leaves the network.  In matrix form, with K the network matrix, C dT/dt = Q - K T.

Values per evaluation: every conductance, advection link and boundary has a name; a solve takes
overrides ``{name: value}`` (speed-dependent convection, flow rate, inlet temperature), or a
callable of the temperature vector that returns them (temperature-dependent properties).

Steady state: K_ff T_f = Q_f - K_fb T_b (f free, b fixed), dense LU up to ``DENSE_MAX`` free nodes,
sparse LU above.  With callables the solve iterates (``picard``: freeze the values at the last
iterate and solve; ``newton``: finite-difference Jacobian of the residual, backtracking on its norm)
until the largest temperature change is below ``tol_K``; otherwise
:class:`ThermalConvergenceError` names the iteration count, the change and the node where it is
largest.  The transient solvers are in :mod:`spindlesim.thermal.transient`.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field
from typing import Callable, Mapping, Sequence, Union

import numpy as np

log = logging.getLogger(__name__)

#: free-node count above which the steady solve uses a sparse LU
DENSE_MAX = 400

Values = Union[Mapping[str, float], None]
SourceSpec = Union[Mapping[str, float], np.ndarray, Sequence[float], Callable, None]


class ThermalConvergenceError(RuntimeError):
    """An iterative thermal solve did not converge; the message says what and where."""


@dataclass(frozen=True)
class Node:
    """One lumped body. ``fixed_C`` set: a boundary node held at that temperature [degC]."""

    name: str
    capacity_J_K: float = 0.0
    fixed_C: float | None = None


@dataclass(frozen=True)
class Conductance:
    """Heat path a -- b of conductance ``value_W_K`` (default name ``"a--b"``)."""

    a: str
    b: str
    value_W_K: float
    name: str = ""


@dataclass(frozen=True)
class Advection:
    """Coolant carried from ``upstream`` to ``downstream``: heat-capacity flow m_dot c_p [W/K]."""

    upstream: str
    downstream: str
    capacity_rate_W_K: float
    name: str = ""


@dataclass(frozen=True)
class EnergyBalance:
    """Heat flows [W] at one state: generated in the free nodes, removed to each boundary
    (conduction into it, plus the coolant's enthalpy rise m_dot c_p (T_out - T_in) charged to the
    inlet the stream comes from), and stored = generated - removed (zero at steady state)."""

    generated_W: float
    removed_W: dict[str, float]
    stored_W: float

    @property
    def removed_total_W(self) -> float:
        return float(sum(self.removed_W.values()))

    @property
    def relative_imbalance(self) -> float:
        """|stored| / generated (meaningful at steady state)."""
        return abs(self.stored_W) / max(abs(self.generated_W), 1e-300)


@dataclass(frozen=True)
class SteadyState:
    """Temperatures of all nodes [degC] in the network's node order, and how they were found."""

    names: tuple[str, ...]
    temperatures_C: np.ndarray
    iterations: int = 1
    method: str = "linear"

    def __getitem__(self, name: str) -> float:
        return float(self.temperatures_C[self.names.index(name)])

    def as_dict(self) -> dict[str, float]:
        return {n: float(t) for n, t in zip(self.names, self.temperatures_C)}


def _link_name(x) -> str:
    return x.name or (f"{x.a}--{x.b}" if isinstance(x, Conductance) else f"{x.upstream}->{x.downstream}")


@dataclass(frozen=True)
class Network:
    """Nodes, conductances and advection links; compiled to index arrays once at construction."""

    nodes: tuple[Node, ...]
    conductances: tuple[Conductance, ...] = ()
    advections: tuple[Advection, ...] = ()
    _c: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "nodes", tuple(self.nodes))
        object.__setattr__(self, "conductances", tuple(self.conductances))
        object.__setattr__(self, "advections", tuple(self.advections))
        object.__setattr__(self, "_c", _compile(self))

    # ------------------------------------------------------------------ lookup
    @property
    def names(self) -> tuple[str, ...]:
        return self._c["names"]

    @property
    def free_names(self) -> tuple[str, ...]:
        return tuple(self.names[i] for i in self._c["order"][: self._c["nf"]])

    @property
    def boundary_names(self) -> tuple[str, ...]:
        return tuple(self.names[i] for i in self._c["order"][self._c["nf"]:])

    def index(self, name: str) -> int:
        try:
            return self._c["index"][name]
        except KeyError:
            raise KeyError(f"no node {name!r} in the thermal network") from None

    def capacities(self) -> np.ndarray:
        return np.array([n.capacity_J_K for n in self.nodes])

    def source_vector(self, sources: SourceSpec) -> np.ndarray:
        """Q [W] per node in node order from a mapping ``{node: W}`` or an array; sources on
        boundary nodes are refused (the boundary absorbs them)."""
        n = len(self.nodes)
        if sources is None:
            return np.zeros(n)
        if isinstance(sources, Mapping):
            q = np.zeros(n)
            for name, w in sources.items():
                q[self.index(name)] += float(w)
        else:
            q = np.asarray(sources, dtype=float)
            if q.shape != (n,):
                raise ValueError(f"source vector has shape {q.shape}, the network has {n} nodes")
        if np.any(q[self._c["fixed_idx"]] != 0.0):
            bad = [self.names[i] for i in self._c["fixed_idx"] if q[i] != 0.0]
            raise ValueError(f"heat sources on boundary nodes {bad}: put them on a free node")
        if not np.all(np.isfinite(q)):
            raise ValueError("heat sources must be finite")
        return q

    # ------------------------------------------------------------------ values per evaluation
    def values(self, conductances: Values = None, capacity_rates: Values = None,
               boundary: Values = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(G per conductance, W per advection, T per node) with the overrides applied."""
        c = self._c
        G = c["G0"] if not conductances else _override(c["G0"], c["g_index"], conductances, "conductance")
        W = c["W0"] if not capacity_rates else _override(c["W0"], c["w_index"], capacity_rates, "advection link")
        if capacity_rates:
            _check_flows(self, W)
        Tb = c["T0"]
        if boundary:
            Tb = Tb.copy()
            for name, t in boundary.items():
                i = self.index(name)
                if self.nodes[i].fixed_C is None:
                    raise ValueError(f"{name!r} is not a boundary node")
                Tb[i] = float(t)
        return G, W, Tb

    def matrix(self, G: np.ndarray, W: np.ndarray) -> np.ndarray:
        """Full network matrix K (node order permuted: free nodes first), dense."""
        c = self._c
        n = c["n"]
        w = np.concatenate((G, G, -G, -G, W, -W))
        return np.bincount(c["flat"], weights=w, minlength=n * n).reshape(n, n)

    def permuted(self, x: np.ndarray) -> np.ndarray:
        return x[self._c["order"]]

    def unpermuted(self, xp: np.ndarray) -> np.ndarray:
        out = np.empty_like(xp)
        out[self._c["order"]] = xp
        return out

    # ------------------------------------------------------------------ steady state
    def solve_steady(self, sources: SourceSpec = None, *, conductances=None, capacity_rates: Values = None,
                     boundary: Values = None, method: str = "picard", tol_K: float = 1e-8,
                     max_iter: int = 100, relaxation: float = 1.0,
                     initial_C: np.ndarray | float | None = None) -> SteadyState:
        """Steady temperatures.  ``sources`` and ``conductances`` may be callables of the full
        temperature vector (node order) returning what they would otherwise be (``sources``: a
        mapping or array; ``conductances``: a mapping of overrides); then the solve iterates."""
        nonlinear = callable(sources) or callable(conductances)
        if not nonlinear:
            G, W, Tb = self.values(conductances, capacity_rates, boundary)
            T = self._linear(self.source_vector(sources), G, W, Tb)
            return SteadyState(self.names, T)
        if method not in ("picard", "newton"):
            raise ValueError("method must be 'picard' or 'newton'")
        _, _, Tb = self.values(None, capacity_rates, boundary)
        T = _initial(self, Tb, initial_C)

        def evaluate(T):
            q = self.source_vector(sources(T) if callable(sources) else sources)
            g = conductances(T) if callable(conductances) else conductances
            G, W, _ = self.values(g, capacity_rates, boundary)
            return q, G, W

        if method == "picard":
            return self._picard(T, Tb, evaluate, tol_K, max_iter, relaxation)
        return self._newton(T, Tb, evaluate, tol_K, max_iter)

    def _linear(self, q: np.ndarray, G: np.ndarray, W: np.ndarray, Tb: np.ndarray) -> np.ndarray:
        c = self._c
        nf = c["nf"]
        order = c["order"]
        K = self.matrix(G, W)
        tb = Tb[order[nf:]]
        rhs = q[order[:nf]] - K[:nf, nf:] @ tb
        tf = _solve(K[:nf, :nf], rhs, self)
        T = Tb.copy()
        T[order[:nf]] = tf
        return T

    def _picard(self, T, Tb, evaluate, tol, max_iter, relaxation) -> SteadyState:
        change = math.inf
        for it in range(1, max_iter + 1):
            q, G, W = evaluate(T)
            Tn = self._linear(q, G, W, Tb)
            d = Tn - T
            T = T + relaxation * d
            change = float(np.max(np.abs(d))) if d.size else 0.0
            if change <= tol:
                return SteadyState(self.names, T, it, "picard")
        raise self._not_converged("picard", max_iter, d, tol)

    def _newton(self, T, Tb, evaluate, tol, max_iter) -> SteadyState:
        c = self._c
        free = c["order"][: c["nf"]]

        def residual(T):
            q, G, W = evaluate(T)
            K = self.unpermuted_matrix(G, W)
            return (K @ T - q)[free]

        r = residual(T)
        d = np.zeros_like(T)
        for it in range(1, max_iter + 1):
            J = np.empty((free.size, free.size))
            for j, node in enumerate(free):
                h = 1e-6 * max(1.0, abs(T[node]))
                Tp = T.copy()
                Tp[node] += h
                J[:, j] = (residual(Tp) - r) / h
            step = _solve(J, -r, self)
            lam, norm0 = 1.0, float(np.linalg.norm(r))
            while True:
                Tn = T.copy()
                Tn[free] += lam * step
                rn = residual(Tn)
                if np.linalg.norm(rn) <= (1.0 - 1e-4 * lam) * norm0 or lam < 1e-3:
                    break
                lam *= 0.5
            d = Tn - T
            T, r = Tn, rn
            if float(np.max(np.abs(d))) <= tol:
                return SteadyState(self.names, T, it, "newton")
        raise self._not_converged("newton", max_iter, d, tol)

    def unpermuted_matrix(self, G: np.ndarray, W: np.ndarray) -> np.ndarray:
        """K in node order (rows: the heat balance of each node)."""
        Kp = self.matrix(G, W)
        inv = np.empty_like(self._c["order"])
        inv[self._c["order"]] = np.arange(self._c["n"])
        return Kp[np.ix_(inv, inv)]

    def _not_converged(self, method: str, iterations: int, d: np.ndarray, tol: float) -> ThermalConvergenceError:
        i = int(np.argmax(np.abs(d)))
        msg = (f"steady thermal state did not converge ({method}, {iterations} iterations): last temperature "
               f"change {abs(d[i]):.3g} K at node {self.names[i]!r}, tolerance {tol:g} K")
        log.warning(msg)
        return ThermalConvergenceError(msg)

    # ------------------------------------------------------------------ energy balance
    def heat_flows(self, temperatures_C: np.ndarray, sources: SourceSpec = None, *, conductances: Values = None,
                   capacity_rates: Values = None) -> EnergyBalance:
        """Energy balance at a state (all node temperatures, node order).  Callables are evaluated
        at that state (steady-state signature)."""
        T = np.asarray(temperatures_C, dtype=float)
        q = self.source_vector(sources(T) if callable(sources) else sources)
        g = conductances(T) if callable(conductances) else conductances
        G, W, _ = self.values(g, capacity_rates, None)
        return _balance(self, T, q, G, W)

    energy_balance = heat_flows


def _balance(net: Network, T: np.ndarray, q: np.ndarray, G: np.ndarray, W: np.ndarray) -> EnergyBalance:
    c = net._c
    fixed = c["is_fixed"]
    removed = {net.names[i]: 0.0 for i in c["fixed_idx"]}
    ia, ib = c["ia"], c["ib"]
    for k in np.flatnonzero(fixed[ia] ^ fixed[ib]):
        b, f = (ia[k], ib[k]) if fixed[ia[k]] else (ib[k], ia[k])
        removed[net.names[b]] += float(G[k] * (T[f] - T[b]))
    iu, idn = c["iu"], c["id"]
    for k in range(iu.size):
        removed[c["inlet_of"][k]] += float(W[k] * (T[idn[k]] - T[iu[k]]))
    generated = float(q.sum())
    return EnergyBalance(generated, removed, generated - float(sum(removed.values())))


def _override(base: np.ndarray, index: dict, values: Mapping[str, float], what: str) -> np.ndarray:
    out = base.copy()
    for name, v in values.items():
        try:
            out[index[name]] = float(v)
        except KeyError:
            raise KeyError(f"no {what} named {name!r} in the thermal network") from None
    if np.any(out < 0.0) or not np.all(np.isfinite(out)):
        raise ValueError(f"{what} values must be finite and >= 0")
    return out


def _solve(A: np.ndarray, b: np.ndarray, net: Network) -> np.ndarray:
    if b.size == 0:
        return b
    try:
        if A.shape[0] <= DENSE_MAX:
            return np.linalg.solve(A, b)
        from scipy.sparse import csc_matrix
        from scipy.sparse.linalg import splu
        return splu(csc_matrix(A)).solve(b)
    except (np.linalg.LinAlgError, RuntimeError) as exc:
        raise ThermalConvergenceError(f"thermal network matrix is singular ({exc}); a free node or group of "
                                      f"nodes has no path to a boundary at these conductance values") from exc


def _initial(net: Network, Tb: np.ndarray, initial_C) -> np.ndarray:
    if initial_C is None:
        fixed = Tb[net._c["fixed_idx"]]
        T = Tb.copy()
        T[~net._c["is_fixed"]] = float(np.mean(fixed)) if fixed.size else 20.0
        return T
    T = np.broadcast_to(np.asarray(initial_C, dtype=float), Tb.shape).copy()
    T[net._c["is_fixed"]] = Tb[net._c["is_fixed"]]
    return T


def _check_flows(net: Network, W: np.ndarray) -> None:
    c = net._c
    n = c["n"]
    inflow = np.bincount(c["id"], weights=W, minlength=n)
    outflow = np.bincount(c["iu"], weights=W, minlength=n)
    for i in range(n):
        if c["is_fixed"][i] or outflow[i] == 0.0:
            continue
        if inflow[i] == 0.0:
            raise ValueError(f"advection out of {net.names[i]!r}, which has no inflow (an inlet must be a boundary node)")
        if abs(inflow[i] - outflow[i]) > 1e-9 * max(inflow[i], outflow[i]):
            raise ValueError(f"coolant flow not conserved at {net.names[i]!r}: in {inflow[i]:g} W/K, "
                             f"out {outflow[i]:g} W/K")


def _compile(net: Network) -> dict:
    names = tuple(n.name for n in net.nodes)
    if not names:
        raise ValueError("a thermal network needs at least one node")
    index = {name: i for i, name in enumerate(names)}
    if len(index) != len(names):
        dup = sorted({x for x in names if names.count(x) > 1})
        raise ValueError(f"duplicate node names: {dup}")
    for nd in net.nodes:
        if not (math.isfinite(nd.capacity_J_K) and nd.capacity_J_K >= 0.0):
            raise ValueError(f"node {nd.name!r}: heat capacity must be finite and >= 0")
        if nd.fixed_C is not None and not math.isfinite(nd.fixed_C):
            raise ValueError(f"node {nd.name!r}: fixed temperature must be finite")
    n = len(names)
    is_fixed = np.array([nd.fixed_C is not None for nd in net.nodes])

    def idx(name: str, what: str) -> int:
        if name not in index:
            raise ValueError(f"{what} refers to an unknown node {name!r}")
        return index[name]

    ia, ib, G0, g_index = [], [], [], {}
    for k, cd in enumerate(net.conductances):
        nm = _link_name(cd)
        a, b = idx(cd.a, f"conductance {nm!r}"), idx(cd.b, f"conductance {nm!r}")
        if a == b:
            raise ValueError(f"conductance {nm!r} connects {cd.a!r} to itself")
        if not (math.isfinite(cd.value_W_K) and cd.value_W_K >= 0.0):
            raise ValueError(f"conductance {nm!r}: value must be finite and >= 0")
        if nm in g_index:
            raise ValueError(f"duplicate conductance name {nm!r}")
        g_index[nm] = k
        ia.append(a), ib.append(b), G0.append(cd.value_W_K)
    iu, idn, W0, w_index = [], [], [], {}
    for k, ad in enumerate(net.advections):
        nm = _link_name(ad)
        u, d = idx(ad.upstream, f"advection {nm!r}"), idx(ad.downstream, f"advection {nm!r}")
        if u == d:
            raise ValueError(f"advection {nm!r} loops on {ad.upstream!r}")
        if is_fixed[d]:
            raise ValueError(f"advection {nm!r} flows into boundary node {ad.downstream!r}: the outlet is "
                             "implicit (a node with inflow and no outflow)")
        if not (math.isfinite(ad.capacity_rate_W_K) and ad.capacity_rate_W_K >= 0.0):
            raise ValueError(f"advection {nm!r}: capacity rate must be finite and >= 0")
        if nm in w_index:
            raise ValueError(f"duplicate advection name {nm!r}")
        w_index[nm] = k
        iu.append(u), idn.append(d), W0.append(ad.capacity_rate_W_K)
    ia, ib, iu, idn = (np.asarray(x, dtype=np.int64) for x in (ia, ib, iu, idn))
    order = np.concatenate((np.flatnonzero(~is_fixed), np.flatnonzero(is_fixed)))
    pos = np.empty(n, dtype=np.int64)
    pos[order] = np.arange(n)
    pa, pb, pu, pd = pos[ia], pos[ib], pos[iu], pos[idn]
    flat = np.concatenate((pa * n + pa, pb * n + pb, pa * n + pb, pb * n + pa, pd * n + pd, pd * n + pu))
    T0 = np.array([nd.fixed_C if nd.fixed_C is not None else 0.0 for nd in net.nodes], dtype=float)
    c = dict(names=names, index=index, n=n, nf=int((~is_fixed).sum()), is_fixed=is_fixed,
             fixed_idx=np.flatnonzero(is_fixed), order=order, ia=ia, ib=ib, iu=iu, id=idn,
             G0=np.asarray(G0, dtype=float), W0=np.asarray(W0, dtype=float), g_index=g_index, w_index=w_index,
             flat=flat, T0=T0, C=np.array([nd.capacity_J_K for nd in net.nodes]))
    c["inlet_of"] = _inlets(names, is_fixed, iu, idn)
    _anchor_check(names, is_fixed, ia, ib, iu, idn)
    object.__setattr__(net, "_c", c)
    _check_flows(net, c["W0"])
    return c


def _inlets(names, is_fixed, iu, idn) -> list[str]:
    """Boundary name each advection link's stream comes from (joined with '+' when several feed it)."""
    n = len(names)
    parent = list(range(n))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for u, d in zip(iu, idn):
        parent[find(u)] = find(d)
    sources: dict[int, list[str]] = {}
    for u in iu:
        if is_fixed[u]:
            sources.setdefault(find(u), [])
            if names[u] not in sources[find(u)]:
                sources[find(u)].append(names[u])
    out = []
    for u in iu:
        s = sources.get(find(u))
        if not s:
            raise ValueError(f"coolant path through {names[u]!r} has no inlet boundary node")
        out.append("+".join(s))
    return out


def _anchor_check(names, is_fixed, ia, ib, iu, idn) -> None:
    """Every free node must reach a boundary (through conductances, or downstream of advection)."""
    anchored = is_fixed.copy()
    changed = True
    while changed:
        changed = False
        for a, b in zip(ia, ib):
            if anchored[a] != anchored[b]:
                anchored[a] = anchored[b] = True
                changed = True
        for u, d in zip(iu, idn):
            if anchored[u] and not anchored[d]:
                anchored[d] = True
                changed = True
    if not anchored.all():
        bad = [names[i] for i in np.flatnonzero(~anchored)]
        raise ValueError(f"nodes without a heat path to any boundary node: {bad}")
