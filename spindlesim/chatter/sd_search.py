"""The limit depth at every speed without a depth grid: brackets continued from the neighbouring speeds.

The stability map's march (:mod:`.sd_lobes`) evaluates the spectral radius rho at every depth of a grid from
zero up to the first unstable one, about forty evaluations a speed.  The lobes need only the first crossing of
rho = 1, and the neighbouring speeds know where it is:

1. Speeds are solved coarse to fine: every STRIDE-th speed first, then the speeds halfway between solved
   ones, and so on.  A speed's guess is its zero-order limit times the ratio of the semi-discretization's to
   the zero-order limit at its solved neighbours (geometric mean of the two), which follows the lobes' shape
   across a lobe's junction better than the neighbours' limits themselves; the first speeds start from the
   zero-order limit alone.
2. Bracket: rho at the guess times 1 -+ delta (delta = WARM_DELTA with neighbours, COLD_DELTA without), the
   bracket grown geometrically downwards while its lower end is unstable (to zero: rho at zero depth is the
   structure's own decay over a tooth period) and upwards while its upper end is stable (to the cap: the
   speed is then "capped").
3. The root by ITP with the critical multiplier followed (:func:`.sd_lobes._itp`) to the relative tolerance.
4. Below the root: a stable point of the lower end does not rule out a closed unstable region lower down (a
   period-doubling island at low immersion).  rho is evaluated at PROBES of the root; a probe at or above one
   gives a new bracket below (back to 3), and a probe that is a local maximum of rho within ``peak_check`` of
   one and rising above its lower neighbour (the march's island rule, PEAK_RISE) is maximised between its
   neighbours (bounded Brent), as on the map's grid.

About ten evaluations a speed instead of the march's forty; the limits are the same to the search tolerance
(tests/unit/test_chatter_search.py compares them with the march on the decks and the textbook cases).
"""

from __future__ import annotations

import logging

import numpy as np

__all__ = ["continued_limits", "STRIDE", "PROBES"]

log = logging.getLogger(__name__)

STRIDE = 8  # the first pass solves every STRIDE-th speed from the zero-order guess alone
COLD_DELTA = 0.25  # half-width of the first bracket, relative, without solved neighbours
WARM_DELTA = 0.03  # with them
PROBES = (0.25, 0.5, 0.75)  # fractions of the root at which a lower unstable region is looked for
PEAK_RISE = 1e-2  # as sd_lobes: a maximum must rise this much of 1 - rho above its lower neighbour
_FLOOR = 1e-3  # a lower end below this fraction of the guess is taken to zero depth


def _levels(S: int) -> list[np.ndarray]:
    """Speed indices in the order solved: every STRIDE-th (and the last), then halving the gaps."""
    done = np.zeros(S, bool)
    out = []
    first = np.unique(np.r_[np.arange(0, S, STRIDE), S - 1])
    out.append(first)
    done[first] = True
    stride = STRIDE
    while not done.all():
        stride = max(stride // 2, 1)
        new = np.flatnonzero(~done & (np.arange(S) % stride == 0)) if stride > 1 else np.flatnonzero(~done)
        if len(new):
            out.append(new)
            done[new] = True
    return out


def _neighbour_ratio(ratio: np.ndarray, idx: np.ndarray) -> np.ndarray:
    """Geometric mean of the nearest finite ratios left and right of each index (NaN: none)."""
    S = len(ratio)
    known = np.flatnonzero(np.isfinite(ratio))
    out = np.full(len(idx), np.nan)
    if not len(known):
        return out
    pos = np.searchsorted(known, idx)
    left = known[np.clip(pos - 1, 0, len(known) - 1)]
    right = known[np.clip(pos, 0, len(known) - 1)]
    lr = np.log(ratio[left])
    rr = np.log(ratio[right])
    has_l, has_r = left < idx, (right > idx) & (right < S)
    both = has_l & has_r
    out[both] = np.exp(0.5 * (lr[both] + rr[both]))
    out[has_l & ~has_r] = np.exp(lr[has_l & ~has_r])
    out[has_r & ~has_l] = np.exp(rr[has_r & ~has_l])
    return out


def _bracket(prob, idx, guess, delta, cap, rho0):
    """Brackets (lo, hi, f_lo, f_hi, M_lo, mu_hi) of rho = 1 around ``guess``; hi = inf where stable up to the
    cap.  M_lo the largest multipliers at lo (NaN at zero depth), mu_hi the largest at hi."""
    if np.any(rho0 >= 1.0):
        raise ValueError("the structure alone is unstable (spectral radius at zero depth >= 1)")
    E = len(idx)
    lo = guess * (1.0 - delta)
    hi = np.minimum(guess * (1.0 + delta), cap)
    lo = np.minimum(lo, 0.999 * hi)
    M = prob.multipliers(np.r_[idx, idx], np.r_[lo, hi])
    M_lo, M_hi = M[:E], M[E:]
    f_lo, f_hi = np.abs(M_lo[:, 0]) - 1.0, np.abs(M_hi[:, 0]) - 1.0
    step = np.full(E, 1.0 + 2.0 * delta)
    while True:
        down = f_lo >= 0  # the lower end is unstable already: move the bracket down
        up = (f_hi < 0) & (hi < cap * (1 - 1e-12))  # the upper end is stable: move it up, to the cap at most
        if not (down.any() or up.any()):
            break
        to_zero = down & (lo / step < _FLOOR * guess)
        if to_zero.any():  # the lower end at zero depth: rho0 (stable unless the structure is not)
            hi[to_zero], f_hi[to_zero], M_hi[to_zero] = lo[to_zero], f_lo[to_zero], M_lo[to_zero]
            lo[to_zero], f_lo[to_zero] = 0.0, rho0[to_zero] - 1.0
            M_lo[to_zero] = np.nan
            down &= ~to_zero
        sel = np.flatnonzero(down | up)
        if not len(sel):
            break
        d = down[sel]
        new = np.where(d, lo[sel] / step[sel], np.minimum(hi[sel] * step[sel], cap))
        Mn = prob.multipliers(idx[sel], new)
        fn = np.abs(Mn[:, 0]) - 1.0
        sd, su = sel[d], sel[~d]
        hi[sd], f_hi[sd], M_hi[sd] = lo[sd], f_lo[sd], M_lo[sd]
        lo[sd], f_lo[sd], M_lo[sd] = new[d], fn[d], Mn[d]
        lo[su], f_lo[su], M_lo[su] = hi[su], f_hi[su], M_hi[su]
        hi[su], f_hi[su], M_hi[su] = new[~d], fn[~d], Mn[~d]
        step[sel] = step[sel] ** 2
    capped = f_hi < 0
    hi[capped] = np.inf
    return lo, hi, f_lo, f_hi, M_lo, M_hi[:, 0]


def _below(prob, idx, root, rho0, peak_check):
    """Brackets of an unstable region below each root (NaN where none): a probe at or above one, or a local
    maximum of rho among the probes that comes within ``peak_check`` of one and is unstable at its maximum."""
    E, P = len(idx), len(PROBES)
    lo, hi = np.full(E, np.nan), np.full(E, np.nan)
    f_lo, f_hi = np.full(E, np.nan), np.full(E, np.nan)
    if not P:
        return lo, hi, f_lo, f_hi
    depths = root[:, None] * np.asarray(PROBES)[None, :]
    rho = np.abs(prob.multipliers(np.repeat(idx, P), depths.ravel())[:, 0]).reshape(E, P)
    ext = np.concatenate([rho0[:, None], rho, np.ones((E, 1))], axis=1)
    dext = np.concatenate([np.zeros((E, 1)), depths, root[:, None]], axis=1)
    for e in range(E):
        for j in range(1, P + 1):
            if ext[e, j] >= 1.0:  # unstable at a probe: the first crossing is below it
                lo[e], hi[e], f_lo[e], f_hi[e] = dext[e, j - 1], dext[e, j], ext[e, j - 1] - 1.0, ext[e, j] - 1.0
                break
            r, left, right = ext[e, j], ext[e, j - 1], ext[e, j + 1]
            if r < peak_check or r < left or not r >= right or not r - min(left, right) > PEAK_RISE * (1.0 - r):
                continue
            s = int(idx[e])
            from scipy.optimize import minimize_scalar  # here: scipy.optimize takes 0.3 s to import

            res = minimize_scalar(lambda a: -prob.spectral_radius(np.array([s]), np.array([a]))[0],
                                  bounds=(dext[e, j - 1], dext[e, j + 1]), method="bounded",
                                  options={"xatol": 1e-4 * dext[e, j + 1]})
            if -res.fun >= 1.0:
                lo[e], hi[e], f_lo[e], f_hi[e] = dext[e, j - 1], res.x, ext[e, j - 1] - 1.0, -res.fun - 1.0
                log.info("instability found below the continued limit at %.0f rpm", prob.speeds[s])
                break
    return lo, hi, f_lo, f_hi


def continued_limits(prob, zoa_guess: np.ndarray, cap: float, rho0: np.ndarray, rtol: float,
                     peak_check: float, close: bool = False) -> dict:
    """Limit depth, d rho / d a at it (the last bracket's), kind, chatter frequency and lobe number at every
    speed of ``prob`` (a :class:`~spindlesim.chatter.sd_lobes._Grouped`); ``zoa_guess`` [S] the zero-order
    limits (NaN: none, the cap's tenth is tried), ``rho0`` [S] the spectral radius at zero depth; ``close``: the
    guesses are limits found already (with fewer steps): every bracket starts narrow, from its own guess."""
    from .sd_lobes import _itp

    S = len(zoa_guess)
    base = np.where(np.isfinite(zoa_guess) & (zoa_guess > 0), zoa_guess, 0.1 * cap)
    out = {"limit": np.full(S, np.nan), "freq": np.full(S, np.nan), "kind": np.full(S, "", dtype="<U4"),
           "lobe": np.full(S, -1), "slope": np.full(S, np.nan)}
    ratio = np.full(S, np.nan)
    for idx in ([np.arange(S)] if close else _levels(S)):
        r = np.ones(len(idx)) if close else _neighbour_ratio(ratio, idx)
        warm = np.isfinite(r)
        guess = np.minimum(base[idx] * np.where(warm, r, 1.0), cap)
        delta = np.where(warm, WARM_DELTA, COLD_DELTA)
        lo, hi, f_lo, f_hi, M_lo, mu_hi = _bracket(prob, idx, guess, delta, cap, rho0[idx])
        hit = np.isfinite(hi)
        root, slope = np.full(len(idx), np.nan), np.full(len(idx), np.nan)
        if hit.any():
            root[hit], slope[hit] = _itp(prob, idx[hit], lo[hit], hi[hit], f_lo[hit], f_hi[hit], rtol,
                                         M_lo[hit], mu_hi[hit])
        check = hit.copy()
        for _ in range(len(PROBES) + 1):  # a region found below is itself checked below
            c = np.flatnonzero(check)
            if not len(c):
                break
            blo, bhi, bf_lo, bf_hi = _below(prob, idx[c], root[c], rho0[idx[c]], peak_check)
            found = np.isfinite(bhi)
            check[:] = False
            if found.any():
                f = c[found]
                root[f], slope[f] = _itp(prob, idx[f], blo[found], bhi[found], bf_lo[found], bf_hi[found], rtol)
                check[f] = True
        out["limit"][idx], out["slope"][idx] = root, slope
        capped = ~hit
        ratio[idx[hit]] = root[hit] / base[idx[hit]]
        ratio[idx[capped]] = cap / base[idx[capped]]  # at least that: the neighbours start from the cap
        done = np.flatnonzero(hit)
        for e, cm in zip(done, prob.criticals(idx[done], root[done])):
            out["freq"][idx[e]], out["kind"][idx[e]], out["lobe"][idx[e]] = cm.chatter_frequency_hz, cm.kind, cm.lobe
    return out
