"""Lobe diagram by semi-discretization: stability map and its boundary.

1. The spectral radius rho of the monodromy matrix (:mod:`spindlesim.chatter.semi_discretization`)
   is computed on a speed x depth grid (the stability map).
2. At every speed the boundary is the *first* depth at which rho reaches 1 going up from zero
   depth (a cut is always stable at zero depth).  Stable pockets above it (closed flip islands
   at low immersion) stay visible in the map and are counted in the notes; the limit depth is
   the one a user can trust from zero upwards.
3. Every local maximum of rho along the depth grid below that point which comes within
   ``peak_check`` (0.9) of 1 is maximised between its neighbours (bounded Brent), so an island
   thinner than the grid step is still caught when its peak shows in the grid values; then the
   bracketing interval is refined by the Illinois (modified regula falsi) iteration on
   rho(a) - 1 to a relative depth tolerance ``rtol``.  Refine the grid (``n_depths``) where
   islands must not be missed.
4. At the boundary the critical multiplier gives the kind (hopf/flip), the dominant chatter
   frequency and the lobe number; lobes are the boundary segments of one (kind, number).

Without a depth grid the range is set from the zero-order solution at the same speeds:
(0, 1.25 min(max a_ZOA, 3 min a_ZOA)] in ``n_depths`` equal steps.

Steps per tooth period: the discretised delay must resolve the chatter wave, of which there are
f tau per period (the lobe number), so by default every speed gets
m = max(min_steps, points_per_wave x f_top x tau) rounded up to a multiple of 10, f_top the highest
natural frequency among the modes with at least 5 % of the largest peak compliance (x 1.2; the
others do not chatter, and the structure itself is integrated exactly); ``steps`` fixes m for
all speeds.
"""

from __future__ import annotations

import logging

import numpy as np
from scipy.optimize import minimize_scalar

from .results import LobeCurve, LobeDiagram, StabilityMap
from .semi_discretization import SdProblem
from .state_space import ToolSource, as_state_space, tool_at_speeds

__all__ = ["semi_discretization_lobes", "boundary_from_map"]

log = logging.getLogger(__name__)
METHOD = "semi_discretization"


def _default_depths(process, tools, speeds, n_depths: int) -> np.ndarray:
    from .zero_order import zero_order_lobes  # range estimate only

    zoa = zero_order_lobes(process, tools if len(tools) > 1 else tools[0], speeds)
    env = zoa.limit_depth_m[np.isfinite(zoa.limit_depth_m)]
    if len(env) == 0:
        raise ValueError("cannot size the depth range: give depths_m or depth_max_m")
    top = 1.25 * min(env.max(), 3.0 * env.min())
    return np.linspace(top / n_depths, top, n_depths)


def boundary_from_map(rho: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index of the first unstable depth per speed (-1 if none) and the count of stable pockets
    above it (rho[s, d] over increasing depths)."""
    unstable = rho >= 1.0
    first = np.where(unstable.any(axis=1), np.argmax(unstable, axis=1), -1)
    pockets = np.zeros(len(first), int)
    for s, j in enumerate(first):
        if j >= 0:
            u = unstable[s, j:]
            pockets[s] = int(np.count_nonzero(u[:-1] & ~u[1:]))
    return first, pockets


class _Grouped:
    """Speeds grouped by their number of steps per period, one SdProblem per group."""

    def __init__(self, process, models, speeds, steps: np.ndarray, order: int):
        self.steps = steps
        self.group = np.empty(len(speeds), int)
        self.local = np.empty(len(speeds), int)
        self.speeds = speeds
        self.problems = []
        for g, m in enumerate(np.unique(steps)):
            sel = np.flatnonzero(steps == m)
            mods = models if len(models) == 1 else [models[i] for i in sel]
            self.problems.append(SdProblem(process, mods, speeds[sel], int(m), order))
            self.group[sel], self.local[sel] = g, np.arange(len(sel))

    def spectral_radius(self, s_idx, depth) -> np.ndarray:
        s_idx, depth = np.asarray(s_idx), np.asarray(depth, float)
        out = np.empty(len(s_idx))
        for g, prob in enumerate(self.problems):
            sel = self.group[s_idx] == g
            if sel.any():
                out[sel] = prob.spectral_radius(self.local[s_idx[sel]], depth[sel])
        return out

    def critical(self, s: int, depth: float):
        return self.problems[self.group[s]].critical(int(self.local[s]), depth)


def _auto_steps(process, models, speeds, points_per_wave, min_steps, max_steps) -> np.ndarray:
    f_top = 1.2 * max(md.frequency_hz for mdl in models for md in mdl.significant_modes(0.05))
    m = np.ceil(points_per_wave * f_top * process.tooth_period_s(speeds))
    m = 10 * np.ceil(np.clip(m, min_steps, max_steps) / 10)
    return m.astype(int)


def _brackets(prob, depths, rho, rho0, first, peak_check):
    """Bracket of the first crossing of rho = 1 per speed (hi = inf where none).

    Besides the first grid point with rho >= 1, every local maximum of rho(a) below it that
    comes within ``peak_check`` of 1 is maximised (bounded Brent) within its two grid intervals:
    a narrow island between grid depths is found that way."""
    S, D = rho.shape
    lo, hi = np.zeros(S), np.full(S, np.inf)
    f_lo, f_hi = rho0 - 1.0, np.full(S, np.nan)
    ext = np.concatenate([rho0[:, None], rho], axis=1)  # ext[:, j + 1] = rho at depths[j]
    dext = np.concatenate([[0.0], depths])
    for s in range(S):
        j_first = first[s] if first[s] >= 0 else D
        for j in range(min(j_first, D - 1)):
            r = ext[s, j + 1]
            if r < peak_check or r < ext[s, j] or r < ext[s, j + 2]:
                continue
            res = minimize_scalar(lambda a: -prob.spectral_radius(np.array([s]), np.array([a]))[0],
                                  bounds=(dext[j], dext[j + 2]), method="bounded",
                                  options={"xatol": 1e-4 * dext[j + 2]})
            if -res.fun >= 1.0:
                lo[s], f_lo[s] = dext[j], ext[s, j] - 1.0
                hi[s], f_hi[s] = res.x, -res.fun - 1.0
                log.info("instability found between grid depths at %.0f rpm", prob.speeds[s])
                break
        if not np.isfinite(hi[s]) and first[s] >= 0:
            j = first[s]
            lo[s], f_lo[s] = dext[j], ext[s, j] - 1.0
            hi[s], f_hi[s] = depths[j], rho[s, j] - 1.0
    return lo, hi, f_lo, f_hi


def _illinois(prob, s_idx, lo, hi, f_lo, f_hi, rtol: float, max_iter: int = 40):
    """Vectorised Illinois iteration for rho(a) = 1 with f = rho - 1, f_lo < 0 <= f_hi."""
    lo, hi, f_lo, f_hi = (np.array(v, float) for v in (lo, hi, f_lo, f_hi))
    side = np.zeros(len(lo), int)
    active = np.ones(len(lo), bool)
    for _ in range(max_iter):
        active &= (hi - lo) > rtol * hi
        if not active.any():
            break
        a = np.flatnonzero(active)
        x = hi[a] - f_hi[a] * (hi[a] - lo[a]) / (f_hi[a] - f_lo[a])
        x = np.clip(x, lo[a] + 1e-3 * (hi[a] - lo[a]), hi[a] - 1e-3 * (hi[a] - lo[a]))
        fx = prob.spectral_radius(s_idx[a], x) - 1.0
        up = fx >= 0
        i_up, i_dn = a[up], a[~up]
        hi[i_up], f_hi[i_up] = x[up], fx[up]
        f_lo[i_up[side[i_up] == 1]] *= 0.5
        side[i_up] = 1
        lo[i_dn], f_lo[i_dn] = x[~up], fx[~up]
        f_hi[i_dn[side[i_dn] == -1]] *= 0.5
        side[i_dn] = -1
    return 0.5 * (lo + hi)


def semi_discretization_lobes(process, tool: ToolSource, speeds_rpm: np.ndarray, *,
                              steps: int | None = None, order: int = 1, points_per_wave: float = 30.0,
                              min_steps: int = 30, max_steps: int = 400, depths_m: np.ndarray | None = None,
                              depth_max_m: float | None = None, n_depths: int = 40,
                              rtol: float = 1e-4, peak_check: float = 0.9,
                              fit_options: dict | None = None,
                              **_ignored) -> LobeDiagram:
    """Stability map and limit depth by semi-discretization (``steps`` per tooth period)."""
    speeds = np.asarray(speeds_rpm, float)
    tools, per_speed = tool_at_speeds(tool, speeds)
    used = tools if per_speed else tools[:1]
    models = [as_state_space(t, **(fit_options or {})) for t in used]
    m_s = (np.full(len(speeds), int(steps)) if steps is not None
           else _auto_steps(process, models, speeds, points_per_wave, min_steps, max_steps))
    prob = _Grouped(process, models, speeds, m_s, order)
    if depths_m is not None:
        depths = np.sort(np.asarray(depths_m, float))
    elif depth_max_m is not None:
        depths = np.linspace(depth_max_m / n_depths, depth_max_m, n_depths)
    else:
        depths = _default_depths(process, models, speeds, n_depths)
    if depths[0] <= 0:
        raise ValueError("depths must be positive")
    S, D = len(speeds), len(depths)
    s_grid = np.repeat(np.arange(S), D)
    rho = prob.spectral_radius(s_grid, np.tile(depths, S)).reshape(S, D)
    rho0 = prob.spectral_radius(np.arange(S), np.full(S, 1e-3 * depths[0]))
    first, pockets = boundary_from_map(rho)
    lo, hi, f_lo, f_hi = _brackets(prob, depths, rho, rho0, first, peak_check)
    limit = np.full(S, np.nan)
    freq = np.full(S, np.nan)
    kind = np.full(S, "", dtype="<U4")
    lobe_no = np.full(S, -1)
    hit = np.flatnonzero(np.isfinite(hi))
    if len(hit):
        limit[hit] = _illinois(prob, hit, lo[hit], hi[hit], f_lo[hit], f_hi[hit], rtol)
        for s in hit:
            cm = prob.critical(int(s), float(limit[s]))
            freq[s], kind[s], lobe_no[s] = cm.chatter_frequency_hz, cm.kind, cm.lobe
    lobes = []
    for kd, k in sorted({(kind[s], lobe_no[s]) for s in hit}, key=lambda t: (t[0], -t[1])):
        sel = (kind == kd) & (lobe_no == k)
        lobes.append(LobeCurve(int(k), speeds, np.where(sel, limit, np.nan), np.where(sel, freq, np.nan), str(kd)))
    notes = []
    if len(hit) < S:
        notes.append(f"{S - len(hit)} speed(s) stable over the whole depth range "
                     f"(up to {depths[-1] * 1e3:.4g} mm): limit set to NaN")
    if np.any(pockets):
        notes.append(f"{int(np.sum(pockets > 0))} speed(s) regain stability above the first "
                     "boundary within the map (islands); the limit is the first crossing")
    smap = StabilityMap(speeds, depths, rho, m_s, order)
    return LobeDiagram(speeds, limit, freq, tuple(lobes), METHOD, process.describe(), kind, smap,
                       per_speed, tuple(notes))
