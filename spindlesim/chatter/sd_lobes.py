"""Lobe diagram by semi-discretization: the first depth at which the cut turns unstable, at every speed.

1. Steps per tooth period, per speed: m = max(min_steps, points_per_wave x f_top x tau,
   steps_in_cut / cut fraction), rounded up to a multiple of 10 and at most ``max_steps`` (the floor
   in the cut may exceed it, up to HARD_MAX_STEPS).  f_top is 1.2 x the highest mode with at least
   5 % of the largest peak compliance (the others do not chatter; the structure itself is
   integrated exactly); the floor keeps ``steps_in_cut`` (20) steps inside a short cut (at 5 %
   immersion about 6 steps of the plain rule fell in the cut, and flip boundaries came out
   1.5-1.9 % high).  ``steps`` fixes m for all speeds.
2. Depths: ``depths_m`` as given; or ``n_depths`` up to ``depth_max_m``, which is then also the
   cap; by default ``n_depths`` up to 1.25 min(max a_ZOA, 3 min a_ZOA) from the zero-order solution,
   extended for the speeds still stable there by doubling (``n_depths`` / 2 points a time) up to the
   cap CAP_FACTOR x min a_ZOA (or ``depth_cap_m``: speeds added to a diagram keep its cap).  A speed stable up to the cap is "capped": its limit is NaN and at
   least the cap, and the notes list it.
3. The spectral radius rho of the monodromy matrix is evaluated going up the depths, all speeds
   still stable together, until it reaches 1 (the first unstable depth; one more depth above is
   evaluated so that the stability map shows the crossing).  A cut is always stable at zero depth;
   the limit is the one a user can trust from zero upwards.
4. Every local maximum of rho below that point which comes within ``peak_check`` (0.9) of 1 is
   maximised between its neighbours (bounded Brent), so an island thinner than the grid step is
   caught when its peak shows in the grid values; then the bracket is refined by the ITP method
   (an interpolation with bisection's worst case) to a relative depth tolerance ``rtol``: rho(a) - 1 decides
   the side, the interpolation follows the multiplier that is unstable at the bracket's upper end.
5. At the boundary the critical multiplier gives the kind (hopf/flip), the dominant chatter
   frequency and the lobe number; lobes are the boundary segments of one (kind, number).
6. Error control: rho at the limit with about half the steps estimates the depth's discretisation
   error (second-order convergence, over the slope d rho / d a of the last bracket: large on a steep
   lobe flank, where rho crosses 1 at a shallow angle).  A speed whose estimate exceeds ERROR_TOL
   (0.5 %), or whose chatter wave got fewer than half the ``points_per_wave``, is solved again with
   enough steps (for 0.2 %).

A large tool-point model (a rotor's) is replaced by its dominant modes and the static rest
(:mod:`spindlesim.chatter.sd_model`), checked on the zero-order lobes.
"""

from __future__ import annotations

import logging

import numpy as np

from .results import LobeCurve, LobeDiagram, StabilityMap, speed_runs
from .sd_model import models_for_sd
from .semi_discretization import N_MULTIPLIERS, SdProblem, parallel_map, workers
from .tool import ToolSeries, ToolSource, as_state_space, tool_series

__all__ = ["semi_discretization_lobes", "CAP_FACTOR", "STEPS_IN_CUT", "HARD_MAX_STEPS"]

log = logging.getLogger(__name__)
METHOD = "semi_discretization"
#: points per wave at 1.2 x the highest significant mode: with the extrapolation as accurate as 30 without it
#: (milling spindle, 40 speeds against 60 points per wave and a 0.1 % error control: within 0.10 % against 0.08 %)
POINTS_PER_WAVE = 12.0
CAP_FACTOR = 20.0  # default depth cap: this many times the smallest zero-order limit
ERROR_TOL = 5e-3  # estimated relative depth error above which a speed is solved again with more steps
#: with the extrapolation, the correction above which a speed is solved again with more steps (so far from
#: the step count's asymptotic range the extrapolation is not trusted)
CORRECTION_TOL = 2e-2
STEPS_IN_CUT = 20
HARD_MAX_STEPS = 2000
#: ITP's truncation kappa_1 times the first bracket's width (kappa_2 = 2).  The method's usual 0.2 makes its first
#: step nearly a bisection; the followed multiplier is smooth, and the interpolation alone lands close to the root
#: (milling deck, 200 speeds: 4.4 evaluations a speed after the bracket with 0.2 and regula falsi, 2.9 with 0.002
#: and the inverse quadratic step, the limits equal to the search tolerance).  The truncation is at least half the
#: tolerance, so that a step from an estimate that has converged on one side lands past the root and closes the
#: bracket: without it the last brackets shrank to 1e-9 of the depth, where the followed multiplier's rounding
#: (1e-11) made the slope d|mu|/da over them, and the extrapolation's correction that divides by it, wrong by 60 %
ITP_KAPPA1 = 2e-3
PEAK_RISE = 1e-2  # a local maximum of rho on the grid is searched when it rises this much of 1 - rho above a neighbour


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
        return np.abs(self.multipliers(s_idx, depth)[:, 0])

    def multipliers(self, s_idx, depth) -> np.ndarray:
        """The largest multipliers [E, N_MULTIPLIERS] (largest first; NaN where a model has fewer)."""
        s_idx, depth = np.asarray(s_idx), np.asarray(depth, float)
        out = np.full((len(s_idx), N_MULTIPLIERS), np.nan, complex)
        pieces = self._pieces(s_idx)
        mults = SdProblem.batches((prob, self.local[s_idx[p]], depth[p]) for prob, p in pieces)
        for (_, p), mu in zip(pieces, mults):
            out[p, :mu.shape[1]] = mu
        return out

    def _pieces(self, s_idx: np.ndarray) -> list:
        """(problem, positions in ``s_idx``): each step count's speeds, shared among the workers."""
        pieces = []
        for g, prob in enumerate(self.problems):
            idx = np.flatnonzero(self.group[s_idx] == g)
            if len(idx):
                pieces += [(prob, p) for p in np.array_split(idx, min(len(idx), workers()))]
        return pieces

    def critical(self, s: int, depth: float):
        return self.criticals(np.array([s]), np.array([depth]))[0]

    def criticals(self, s_idx, depth) -> list:
        """The critical multipliers (:class:`~.semi_discretization.CriticalMultiplier`) at (speed, depth)
        pairs, shared among the workers as :meth:`multipliers`."""
        s_idx, depth = np.asarray(s_idx), np.asarray(depth, float)
        out = [None] * len(s_idx)
        pieces = self._pieces(s_idx)
        got = SdProblem.batches(((prob, self.local[s_idx[p]], depth[p]) for prob, p in pieces), "criticals")
        for (_, p), cms in zip(pieces, got):
            for i, cm in zip(p, cms):
                out[i] = cm
        return out


#: step counts are rounded up to this ladder (multiples of 10, about 15 % apart above 100), so that
#: speeds share a count and are solved together
_LADDER = np.unique(np.r_[np.arange(10, 100, 10), 10 * np.round(10 * 1.15 ** np.arange(40))]).astype(int)


def _round_steps(m: np.ndarray, max_steps: int, floor: np.ndarray) -> np.ndarray:
    m = np.maximum(np.minimum(m, max_steps), floor)
    if np.any(floor > HARD_MAX_STEPS):
        log.warning("a cut this short needs more than %d steps per tooth period; using %d", HARD_MAX_STEPS,
                    HARD_MAX_STEPS)
    m = np.minimum(m, HARD_MAX_STEPS)
    return _LADDER[np.minimum(np.searchsorted(_LADDER, m), len(_LADDER) - 1)]


def _auto_steps(process, models, speeds, points_per_wave, min_steps, max_steps, steps_in_cut) -> np.ndarray:
    f_top = 1.2 * max(md.frequency_hz for mdl in models for md in mdl.significant_modes(0.05))
    m = np.maximum(min_steps, np.ceil(points_per_wave * f_top * process.tooth_period_s(speeds)))
    return _round_steps(m, max_steps, _floor(process, len(speeds), steps_in_cut))


def _floor(process, S: int, steps_in_cut: int) -> np.ndarray:
    return np.full(S, np.ceil(steps_in_cut / process.cut_fraction))


def _zoa_scale(process, model, zoa) -> tuple[float, float]:
    """(smallest, largest) finite zero-order limit; 1 / (|K0| max |H|) when there is none (the
    zero-order limit is at least half that)."""
    env = zoa.limit_depth_m[np.isfinite(zoa.limit_depth_m)]
    if len(env):
        return float(env.min()), float(env.max())
    h = np.linalg.norm(model.receptance(2 * np.pi * model.frequency_grid()), 2, axis=(1, 2)).max()
    a = 1.0 / (np.linalg.norm(process.mean_directional(), 2) * h)
    return a, a


class _Depths:
    """The depth grid: fixed, or grown by doubling up to the cap."""

    def __init__(self, depths: np.ndarray, cap: float, growth: int):
        if depths[0] <= 0:
            raise ValueError("depths must be positive")
        self.values, self.cap, self.growth = depths, float(cap), growth

    def extend(self) -> bool:
        top = self.values[-1]
        if self.growth <= 0 or top >= self.cap * (1 - 1e-12):
            return False
        new = np.linspace(top, min(2 * top, self.cap), self.growth + 1)[1:]
        self.values = np.concatenate([self.values, new])
        return True


def _march(prob: _Grouped, grid: _Depths, mu0: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """rho [S, D] (NaN where not evaluated), the index of the first unstable depth (-1: none) and the
    largest multipliers at that depth and the one below it [S, 2, k] (index 1: the first unstable;
    ``mu0`` [S, k] those near zero depth)."""
    S = len(mu0)
    rho = np.full((S, len(grid.values)), np.nan)
    last = np.full((S, 2, N_MULTIPLIERS), np.nan, complex)
    last[:, 1] = mu0
    first = np.full(S, -1)
    pending = np.ones(S, bool)
    extra = np.zeros(S, bool)
    j = 0
    while pending.any() or extra.any():
        if j >= len(grid.values):
            if not pending.any() or not grid.extend():
                break
            rho = np.concatenate([rho, np.full((S, len(grid.values) - rho.shape[1]), np.nan)], axis=1)
        idx = np.flatnonzero(pending | extra)
        mu = prob.multipliers(idx, np.full(len(idx), grid.values[j]))
        rho[idx, j] = np.abs(mu[:, 0])
        now = pending[idx]
        last[idx[now], 0] = last[idx[now], 1]
        last[idx[now], 1] = mu[now]
        extra[:] = False
        hit = pending & (rho[:, j] >= 1.0)
        first[hit] = j
        pending &= ~hit
        extra[hit] = j + 1 < len(grid.values)
        j += 1
    return rho, first, last


def _brackets(prob, depths, rho, rho0, first, peak_check):
    """Bracket of the first crossing of rho = 1 per speed (hi = inf where none).

    Besides the first grid point with rho >= 1, every local maximum of rho(a) below it that
    comes within ``peak_check`` of 1 is maximised (bounded Brent) within its two grid intervals:
    a narrow island between grid depths is found that way.  A maximum must rise above its lower
    neighbour by PEAK_RISE of its distance to 1 (an island midway between two grid depths raises both
    alike): a nearly undamped mode holds rho within 1e-4 of 1 over many depths, its modulus drifting
    by 1e-8 (the milling deck: 25 searches of about 10 evaluations each, none finding anything, on
    maxima 1e-4 to 5e-4 of their distance to 1 above their neighbours), while the grid signature of
    an island is a rise of a tenth of that distance or more."""
    S, D = rho.shape
    lo, hi = np.zeros(S), np.full(S, np.inf)
    f_lo, f_hi = rho0 - 1.0, np.full(S, np.nan)
    ext = np.concatenate([rho0[:, None], rho], axis=1)  # ext[:, j + 1] = rho at depths[j]
    dext = np.concatenate([[0.0], depths])
    for s in range(S):
        last = first[s] if first[s] >= 0 else int(np.count_nonzero(np.isfinite(rho[s])))
        for j in range(min(last, D - 1)):
            r = ext[s, j + 1]
            left, right = ext[s, j], ext[s, j + 2]
            if r < peak_check or r < left or not r >= right or not r - min(left, right) > PEAK_RISE * (1.0 - r):
                continue
            from scipy.optimize import minimize_scalar  # here: scipy.optimize takes 0.3 s to import

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


def _follow(M_lo: np.ndarray, mu_hi: np.ndarray, f_lo: np.ndarray) -> np.ndarray:
    """|mu| - 1 of the multiplier among ``M_lo`` [E, k] nearest ``mu_hi`` [E] (the one that is unstable at the
    bracket's upper end), at most ``f_lo``; ``f_lo`` where either is unknown (NaN)."""
    d = np.abs(M_lo - mu_hi[:, None])
    d = np.where(np.isfinite(d), d, np.inf)
    j = np.argmin(d, axis=1)
    g = np.abs(M_lo[np.arange(len(j)), j]) - 1.0
    return np.where(np.isfinite(d[np.arange(len(j)), j]), np.minimum(g, f_lo), f_lo)


def _interpolated(a, b, c, fa, fb, fc) -> np.ndarray:
    """The root's estimate from the bracket (a, b) and the end it replaced last, c: inverse quadratic
    interpolation through the three where it falls inside the bracket, else regula falsi on (a, b)."""
    with np.errstate(all="ignore"):
        x_q = (a * fb * fc / ((fa - fb) * (fa - fc)) + b * fa * fc / ((fb - fa) * (fb - fc))
               + c * fa * fb / ((fc - fa) * (fc - fb)))
    x_f = (b * fa - a * fb) / (fa - fb)
    return np.where(np.isfinite(x_q) & (x_q > a) & (x_q < b), x_q, x_f)


def _itp(prob, s_idx, lo, hi, f_lo, f_hi, rtol: float, M_lo=None, mu_hi=None, n0: int = 1):
    """Root of f = rho - 1 in each bracket (f_lo < 0 <= f_hi) by the ITP method (Oliveira and
    Takahashi, ACM TOMS 47 (2020) 5): an interpolation (:func:`_interpolated`), truncated (by ITP_KAPPA1)
    and projected so that no bracket needs more than n0 steps beyond bisection's.  rho is the largest of
    several multipliers' moduli, so it has kinks, and a nearly undamped mode can hold it a hair below 1 up
    to where the chatter mode overtakes it, which would stall an interpolation on rho itself: the
    interpolation follows the multiplier that is unstable at the upper end (at the lower end the one nearest
    it, ``M_lo`` [E, k] the largest multipliers there, ``mu_hi`` [E] the largest at the upper end; NaN:
    unknown, rho is used), while rho alone decides which end a trial depth replaces.  Returns the roots and
    d|mu| / d a of the followed multiplier over the last brackets."""
    a, b, fa, fb = (np.array(v, float) for v in (lo, hi, f_lo, f_hi))
    E, k = len(a), N_MULTIPLIERS
    M_lo = np.full((E, k), np.nan, complex) if M_lo is None else np.array(M_lo, complex)
    mu_hi = np.full(E, np.nan, complex) if mu_hi is None else np.array(mu_hi, complex)
    ga = _follow(M_lo, mu_hi, fa)
    eps = 0.5 * rtol * b
    n_max = np.ceil(np.log2(np.maximum((b - a) / (2 * eps), 1.0))).astype(int) + n0
    k1 = ITP_KAPPA1 / np.maximum(b - a, 1e-300)
    xc, gc = np.full(E, np.nan), np.full(E, np.nan)  # the end replaced last (inverse quadratic interpolation)
    active = (b - a) > 2 * eps
    j = 0
    while active.any():
        i = np.flatnonzero(active)
        w = b[i] - a[i]
        x_half = 0.5 * (a[i] + b[i])
        r = np.maximum(eps[i] * 2.0 ** (n_max[i] - j) - 0.5 * w, 0.0)
        delta = np.maximum(k1[i] * w * w, 0.5 * eps[i])  # at least half the tolerance: a step past the root
        x_f = _interpolated(a[i], b[i], xc[i], ga[i], fb[i], gc[i])
        sigma = np.sign(x_half - x_f)
        x_t = np.where(delta <= np.abs(x_half - x_f), x_f + sigma * delta, x_half)
        x = np.where(np.abs(x_t - x_half) <= r, x_t, x_half - sigma * r)
        M = prob.multipliers(s_idx[i], x)
        fx = np.abs(M[:, 0]) - 1.0
        up = fx >= 0
        xc[i] = np.where(up, b[i], a[i])
        gc[i] = np.where(up, fb[i], ga[i])
        b[i[up]], fb[i[up]], mu_hi[i[up]] = x[up], fx[up], M[up, 0]
        a[i[~up]], fa[i[~up]], M_lo[i[~up]] = x[~up], fx[~up], M[~up]
        ga[i] = _follow(M_lo[i], mu_hi[i], fa[i])
        active &= (b - a) > 2 * eps
        j += 1
    return 0.5 * (a + b), (fb - ga) / np.maximum(b - a, 1e-300)


def _solve(process, models, speeds, m_s, grid: _Depths, order, rtol, peak_check) -> dict:
    """Boundary, kind, frequency and lobe number at every speed for the step counts ``m_s``."""
    prob = _Grouped(process, models, speeds, m_s, order)
    S = len(speeds)
    mu0 = prob.multipliers(np.arange(S), np.full(S, 1e-3 * grid.values[0]))
    rho0 = np.abs(mu0[:, 0])
    rho, first, last = _march(prob, grid, mu0)
    depths = grid.values[:rho.shape[1]]
    lo, hi, f_lo, f_hi = _brackets(prob, depths, rho, rho0, first, peak_check)
    on_grid = (first >= 0) & (hi == depths[np.maximum(first, 0)])  # else an island's peak, or none
    out = {"limit": np.full(S, np.nan), "freq": np.full(S, np.nan), "kind": np.full(S, "", dtype="<U4"),
           "lobe": np.full(S, -1), "slope": np.full(S, np.nan), "rho": rho, "depths": depths}
    hit = np.flatnonzero(np.isfinite(hi))
    if len(hit):
        M_lo = np.where(on_grid[hit, None], last[hit, 0], np.nan)
        mu_hi = np.where(on_grid[hit], last[hit, 1, 0], np.nan)
        out["limit"][hit], out["slope"][hit] = _itp(prob, hit, lo[hit], hi[hit], f_lo[hit], f_hi[hit], rtol,
                                                    M_lo, mu_hi)
        for s, cm in zip(hit, prob.criticals(hit, out["limit"][hit])):
            out["freq"][s], out["kind"][s], out["lobe"][s] = cm.chatter_frequency_hz, cm.kind, cm.lobe
    return out


def _search(process, models, speeds, m_s, guess, cap, order, rtol, peak_check, close: bool = False) -> dict:
    """As :func:`_solve`, by the continued brackets of :mod:`.sd_search` (no stability map)."""
    from .sd_search import continued_limits

    prob = _Grouped(process, models, speeds, m_s, order)
    tau = process.tooth_period_s(speeds)
    rates = np.array([np.max(np.linalg.eigvals(mdl.A).real) for mdl in models])
    rho0 = np.exp((rates if len(models) > 1 else np.full(len(speeds), rates[0])) * tau)  # zero depth: free decay
    res = continued_limits(prob, guess, cap, rho0, rtol, peak_check, close=close)
    res.update(rho=None, depths=None)
    return res


def _steps_needed(process, models, speeds, m_s, res, order, points_per_wave, error_tol) -> np.ndarray:
    """Steps each speed needs (0: its m will do): a chatter wave resolved by fewer than half the
    points per wave, or an estimated depth error above ``error_tol``.  The estimate: rho at the limit
    with about half the steps, rho_h; second-order convergence puts the error of rho at m at
    (rho_h - 1) / (q^2 - 1), q = m / m_h, and that of the depth at it over a d rho / d a."""
    S = len(speeds)
    need = np.zeros(S, int)
    hit = np.flatnonzero(np.isfinite(res["limit"]) & np.isfinite(res["slope"]) & (res["slope"] > 0))
    waves = points_per_wave * res["freq"] * process.tooth_period_s(speeds)
    few = np.isfinite(waves) & (m_s < 0.5 * waves)
    need[few] = np.ceil(waves[few])
    if len(hit) and np.isfinite(error_tol):
        m_h = _LADDER[np.maximum(np.searchsorted(_LADDER, m_s[hit] // 2), 0)]
        m_h = np.where(m_h >= m_s[hit], m_s[hit] // 2, m_h)
        prob = _Grouped(process, models if len(models) == 1 else [models[i] for i in hit], speeds[hit],
                        np.maximum(m_h, 4), order)
        rho_h = prob.spectral_radius(np.arange(len(hit)), res["limit"][hit])
        q2 = (m_s[hit] / np.maximum(m_h, 4)) ** 2
        corr = (rho_h - 1.0) / (q2 - 1.0) / (res["slope"][hit] * res["limit"][hit])
        err = np.abs(corr)
        bad = err > error_tol
        need[hit[bad]] = np.maximum(need[hit[bad]], np.ceil(m_s[hit[bad]] * np.sqrt(err[bad] / (0.4 * error_tol))))
        res["error"], res["correction"] = np.full(S, np.nan), np.full(S, np.nan)
        res["error"][hit], res["correction"][hit] = err, corr
    return need


def _merge_rows(base: dict, redo: dict, sel: np.ndarray) -> None:
    for key in ("limit", "freq", "kind", "lobe", "slope"):
        base[key][sel] = redo[key]
    if base["rho"] is None:
        return
    D = max(base["rho"].shape[1], redo["rho"].shape[1])
    for d in (base, redo):
        if d["rho"].shape[1] < D:
            d["rho"] = np.concatenate([d["rho"], np.full((len(d["rho"]), D - d["rho"].shape[1]), np.nan)], axis=1)
    base["rho"][sel] = redo["rho"]
    if len(redo["depths"]) > len(base["depths"]):
        base["depths"] = redo["depths"]


def semi_discretization_lobes(process, tool: ToolSource, speeds_rpm: np.ndarray, *,
                              steps: int | None = None, order: int = 1, points_per_wave: float = POINTS_PER_WAVE,
                              min_steps: int = 30, max_steps: int = 400, steps_in_cut: int = STEPS_IN_CUT,
                              depths_m: np.ndarray | None = None, depth_max_m: float | None = None,
                              depth_cap_m: float | None = None, n_depths: int = 40, rtol: float = 1e-4, peak_check: float = 0.9,
                              error_tol: float = ERROR_TOL, reduce_model: bool = True,
                              fit_options: dict | None = None, stability_map: bool = False,
                              extrapolate: bool = True,
                              **_ignored) -> LobeDiagram:
    """Limit depth by semi-discretization (module docstring); with ``stability_map`` (or ``depths_m``) by the
    march over the depth grid, whose spectral radii the diagram keeps, else by brackets continued from the
    neighbouring speeds (:mod:`.sd_search`, the same limits to the search tolerance ``rtol``).

    ``error_tol``: the estimated relative depth error above which a speed is solved again with more
    steps (``np.inf``: no error control, the plain discretisation); ``reduce_model``: replace a large
    model by its dominant modes and the rest's compliance (:mod:`~spindlesim.chatter.sd_model`)."""
    from .zero_order import zero_order_lobes  # depth range and the model-reduction check

    speeds = np.asarray(speeds_rpm, float)
    series = tool_series(tool, speeds)
    per_speed = series.speed_dependent
    used = series.along(speeds) if per_speed else [series.first]
    models = [as_state_space(t, **(fit_options or {})) for t in used]
    notes = []

    # each model's FRF on its own grid, once: the zero-order lobes and the model reduction's check both use it
    frfs = parallel_map(lambda mdl: mdl.frf(), models)
    sd_models, model_note = (models_for_sd(models, process.mean_directional(), frfs=frfs) if reduce_model
                             else (models, ""))
    if model_note:
        notes.append(model_note)
    want_map = stability_map or depths_m is not None
    # the default depth range and the searches' guesses
    zoa = zero_order_lobes(process, ToolSeries(speeds, tuple(frfs)) if per_speed else ToolSeries.constant(frfs[0]),
                           speeds)
    del frfs  # (tens of MB for a rotor's models at 200 speeds; the search allocates its own)
    if depths_m is not None:
        grid = _Depths(np.sort(np.asarray(depths_m, float)), float(np.max(depths_m)), 0)
    elif depth_max_m is not None:
        grid = _Depths(np.linspace(depth_max_m / n_depths, depth_max_m, n_depths), depth_max_m, 0)
    else:
        a_min, a_max = _zoa_scale(process, models[0], zoa)
        cap = CAP_FACTOR * a_min if depth_cap_m is None else float(depth_cap_m)
        top = min(1.25 * min(a_max, 3.0 * a_min), cap)
        grid = _Depths(np.linspace(top / n_depths, top, n_depths), cap, max(2, n_depths // 2))
    fixed = steps is not None
    m_s = (np.full(len(speeds), int(steps)) if fixed
           else _auto_steps(process, sd_models, speeds, points_per_wave, min_steps, max_steps, steps_in_cut))
    if fixed and steps * process.cut_fraction < steps_in_cut:
        log.warning("%d steps per tooth period put %.1f steps in the cut (fewer than %d)", steps,
                    steps * process.cut_fraction, steps_in_cut)
    if want_map:
        res = _solve(process, sd_models, speeds, m_s, grid, order, rtol, peak_check)
    else:
        res = _search(process, sd_models, speeds, m_s, zoa.limit_depth_m, grid.cap, order, rtol, peak_check)
    extrapolate = extrapolate and not fixed and order == 1 and np.isfinite(error_tol)
    if not fixed:  # too few points on the chatter wave, or too large an error estimate: again, finer
        tol = max(error_tol, CORRECTION_TOL) if extrapolate else error_tol
        need = _steps_needed(process, sd_models, speeds, m_s, res, order, points_per_wave, tol)
        redo = np.flatnonzero(need > m_s)
        if len(redo):
            m_new = _round_steps(np.minimum(need[redo], np.maximum(4 * m_s[redo], max_steps)), HARD_MAX_STEPS,
                                 m_s[redo])
            log.info("%d speed(s) solved again with more steps per period", len(redo))
            sub = sd_models if not per_speed else [sd_models[i] for i in redo]
            if want_map:
                again = _solve(process, sub, speeds[redo], m_new, _Depths(grid.values.copy(), grid.cap, 0), order,
                               rtol, peak_check)
            else:  # from the limits found, which are close
                again = _search(process, sub, speeds[redo], m_new, res["limit"][redo], grid.cap, order, rtol,
                                peak_check, close=True)
            _merge_rows(res, again, redo)
            m_s = m_s.copy()
            m_s[redo] = m_new
            if extrapolate:  # the corrections with the new steps
                _steps_needed(process, sub, speeds[redo], m_new, again, order, points_per_wave, tol)
                res["correction"][redo] = again["correction"]
    if extrapolate:  # Richardson: the limit of the converged discretization, second order
        res["limit"] = res["limit"] * (1.0 + np.nan_to_num(res["correction"]))
    limit, freq, kind, lobe_no = res["limit"], res["freq"], res["kind"], res["lobe"]
    hit = np.flatnonzero(np.isfinite(limit))
    lobes = []
    for kd, k in sorted({(kind[s], lobe_no[s]) for s in hit}, key=lambda t: (t[0], -t[1])):
        sel = (kind == kd) & (lobe_no == k)
        lobes.append(LobeCurve(int(k), speeds, np.where(sel, limit, np.nan), np.where(sel, freq, np.nan), str(kd)))
    capped = ~np.isfinite(limit)
    if capped.any():
        notes.append(f"{int(capped.sum())} speed(s) stable up to the depth cap {grid.cap * 1e3:.4g} mm, the "
                     f"largest depth searched (the limit is at least that; NaN in limit_depth_m): "
                     f"{speed_runs(speeds[capped])}")
    notes.append(f"steps per tooth period {m_s.min()}-{m_s.max()} (at least {steps_in_cut} in the cut "
                 f"unless fixed; the cut is {100 * process.cut_fraction:.3g} % of the tooth period)")
    smap = StabilityMap(speeds, res["depths"], res["rho"], m_s, order) if want_map else None
    return LobeDiagram(speeds, limit, freq, tuple(lobes), METHOD, process.describe(), kind, smap,
                       per_speed, tuple(notes), capped=capped, depth_cap_m=grid.cap, steps_per_period=m_s)
