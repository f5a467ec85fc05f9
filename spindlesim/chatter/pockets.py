"""Stability pockets of a lobe diagram and the speed to recommend.

A pocket is a local maximum of the limit-depth envelope between two lobes (a speed grid point higher
than its neighbours, or a run of equal points such as speeds stable up to the depth cap, which
count at the cap).  Its peak is usually a cusp where two lobes cross, with steep flanks either side;
a speed there is not robust.  So each pocket is described by a depth and the contiguous speed
interval around its peak where the limit stays at or above that depth (ends interpolated linearly
between grid speeds): the depth is a stated fraction (``POCKET_LEVEL``, 90 %) of the peak, lowered
where needed until the interval spans at least +-``MIN_TOLERANCE`` (1 %) of the peak speed (spindle
speed control, and the lobes' own uncertainty: a 1 % error in a natural frequency moves them by
1 %).  The recommendation is the middle of the interval of the deepest pocket, with that depth
and half the interval as the tolerable speed error: a speed within it keeps the limit at or above
the depth, as far as the speed grid resolves the diagram.  Between grid speeds the limit is only
interpolated, so a pocket whose interval holds fewer than ``MIN_GRID_SPEEDS`` (3) grid speeds (a
cusp between two grid points) is recommended only when no pocket is resolved.  A maximum at either
end of the speed range is not a pocket (the limit may go on rising beyond it).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .results import LobeDiagram

__all__ = ["Pocket", "stability_pockets", "best_pocket", "POCKET_LEVEL", "MIN_TOLERANCE", "MIN_GRID_SPEEDS"]

POCKET_LEVEL = 0.9
MIN_TOLERANCE = 0.01
MIN_GRID_SPEEDS = 3


@dataclass(frozen=True)
class Pocket:
    """One stability pocket (SI depths, speeds in rpm)."""

    peak_speed_rpm: float
    peak_depth_m: float  # at least this where ``capped``
    depth_m: float  # the depth the interval keeps: POCKET_LEVEL x peak, or less for +-MIN_TOLERANCE
    speed_min_rpm: float
    speed_max_rpm: float
    grid_speeds: int  # speed grid points inside the interval
    capped: bool  # the peak is the depth cap (stable up to the largest depth searched)
    level: float = POCKET_LEVEL  # depth_m / peak_depth_m

    @property
    def speed_rpm(self) -> float:
        """The recommended speed: the middle of the interval."""
        return 0.5 * (self.speed_min_rpm + self.speed_max_rpm)

    @property
    def width_rpm(self) -> float:
        return self.speed_max_rpm - self.speed_min_rpm

    @property
    def tolerance_rpm(self) -> float:
        """The speed error the recommendation tolerates (half the width)."""
        return 0.5 * self.width_rpm


def _edge(n: np.ndarray, L: np.ndarray, inside: int, outside: int, level: float) -> float:
    """Speed between grid points ``inside`` (L >= level) and ``outside`` (L < level) where L = level."""
    a, b = L[inside], L[outside]
    t = (a - level) / (a - b) if a != b else 0.0
    return float(n[inside] + t * (n[outside] - n[inside]))


def _interval(n: np.ndarray, L: np.ndarray, i: int, j: int, lv: float) -> tuple[float, float, int]:
    """Speeds where L >= lv contiguously around the plateau i..j (ends interpolated), grid points inside."""
    lo, hi = i, j
    while lo - 1 >= 0 and L[lo - 1] >= lv:
        lo -= 1
    while hi + 1 < len(n) and L[hi + 1] >= lv:
        hi += 1
    s_lo = float(n[0]) if lo == 0 else _edge(n, L, lo, lo - 1, lv)
    s_hi = float(n[-1]) if hi == len(n) - 1 else _edge(n, L, hi, hi + 1, lv)
    return s_lo, s_hi, hi - lo + 1


def stability_pockets(diagram: LobeDiagram, level: float = POCKET_LEVEL,
                      tolerance: float = MIN_TOLERANCE) -> tuple[Pocket, ...]:
    """Every pocket of the diagram, deepest first (module docstring)."""
    n = np.asarray(diagram.speed_rpm, float)
    L = np.array(diagram.limit_depth_m, float)
    capped = np.asarray(diagram.capped, bool) & ~np.isfinite(L)
    if np.isfinite(diagram.depth_cap_m):
        L[capped] = diagram.depth_cap_m
    out = []
    i = 1
    while i < len(n) - 1:
        j = i
        while j + 1 < len(n) and L[j + 1] == L[i]:
            j += 1  # a plateau i..j
        if j + 1 < len(n) and np.isfinite(L[i]) and L[i - 1] < L[i] and L[j + 1] < L[i]:
            peak, k = float(L[i]), (i + j) // 2
            want = 2 * tolerance * n[k]
            lv_hi = level * peak
            s_lo, s_hi, inside = _interval(n, L, i, j, lv_hi)
            if s_hi - s_lo < want:  # lower the depth until the interval spans +-tolerance (bisection)
                lv_lo = 0.0
                for _ in range(50):
                    mid = 0.5 * (lv_lo + lv_hi)
                    a, b, _c = _interval(n, L, i, j, mid)
                    lv_lo, lv_hi = (mid, lv_hi) if b - a >= want else (lv_lo, mid)
                lv_hi = lv_lo
                s_lo, s_hi, inside = _interval(n, L, i, j, lv_hi)
            out.append(Pocket(float(n[k]), peak, float(lv_hi), s_lo, s_hi, inside, bool(capped[i:j + 1].any()),
                              float(lv_hi / peak)))
        i = j + 1
    return tuple(sorted(out, key=lambda p: -p.depth_m))


def best_pocket(pockets: tuple[Pocket, ...]) -> Pocket | None:
    """The deepest pocket resolved by the speed grid (at least MIN_GRID_SPEEDS grid speeds in its
    interval), else the deepest of all; None without pockets."""
    resolved = [p for p in pockets if p.grid_speeds >= MIN_GRID_SPEEDS]
    pool = resolved or list(pockets)
    return pool[0] if pool else None
