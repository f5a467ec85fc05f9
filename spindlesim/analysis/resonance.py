"""Resonances inside a requested range: grids refined where the modes are, crossings of excitation
orders with the modes over speed, and the API 684 judgement of each crossing.

Refinement.  A lightly damped mode's peak is ~zeta f wide (half-power band f_n (1 +- zeta)), far
narrower than a grid of a few Hz or a few hundred rpm.  Around every mode in range the grid gets the
points ``centre + half_width * BAND_STEPS``: seven of them inside the half-power band, six more out
to three half-widths, and the exact peak of a single mode; the user's points are kept (sorted,
unique) and the added ones are marked so the user's grid can be recovered.

Crossings.  An excitation of order n (1x unbalance, 2x, the tooth-passing order of a cutter) at
spindle speed N has the frequency n N / 60; it crosses mode k where g_k(N) = f_k(N) - n N / 60
changes sign (f_k the damped natural frequency of the tracked mode).

API 684 (2nd ed., SP6.8.2.1 and SP6.8.2.10; the same rules as API 617):

* amplification factor AF = N_c / (N_2 - N_1) from the half-power points of a response peak, or
  from the damped eigenvalue AF = 1 / (2 zeta) (= pi / log dec to O(zeta^2));
* AF < 2.5: critically damped, no separation margin required;
* AF >= 2.5 and the critical speed below the minimum operating speed N_min: SM >= min(16,
  17 (1 - 1 / (AF - 1.5))) % of N_min; above the maximum continuous speed N_mc: SM >= min(26,
  10 + 17 (1 - 1 / (AF - 1.5))) % of N_mc.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

API684_MIN_AF = 2.5
#: offsets from a resonance's centre in half-power half-widths (zeta f): seven inside [-1, 1]
BAND_STEPS = np.array([-3.0, -2.0, -1.5, -1.0, -0.6, -0.3, 0.0, 0.3, 0.6, 1.0, 1.5, 2.0, 3.0])
#: below this damping ratio a mode counts as undamped: its centre (an infinite peak) is not sampled
UNDAMPED_ZETA = 1e-9
#: the half-width of an (almost) undamped mode's band, relative to its frequency
MIN_HALF_WIDTH = 1e-6


def amplification_factor(zeta) -> np.ndarray:
    """API 684 AF from the damping ratio, 1 / (2 zeta); NaN where zeta <= 0 (an unstable mode)."""
    z = np.asarray(zeta, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(z > 0, 1.0 / (2.0 * np.where(z > 0, z, 1.0)), np.nan)


def required_separation_margin(af: float, below: bool) -> float:
    """API 684 separation margin [fraction of the operating-range edge] for a critical speed with
    amplification factor ``af`` below (``below``) the minimum operating speed or above the maximum
    continuous speed; 0 when AF < 2.5 (critically damped)."""
    if not np.isfinite(af) or af < API684_MIN_AF:
        return 0.0
    base = 17.0 * (1.0 - 1.0 / (af - 1.5))
    return (min(16.0, base) if below else min(26.0, 10.0 + base)) / 100.0


def refine_grid(grid, centres, half_widths, exact=()) -> tuple[np.ndarray, np.ndarray]:
    """(points, added): the user's ``grid`` with ``centre + half_width * BAND_STEPS`` for every
    resonance, its skirts (offsets of 6, 12, 24 ... half-widths, up to the user's spacing there, so a
    plot shows the peak's shape) and the ``exact`` peak points, kept within the grid's span, sorted
    and unique; ``added`` is True where a point is not one of the user's."""
    grid = np.unique(np.asarray(grid, float))
    lo, hi = float(grid[0]), float(grid[-1])
    extra = [np.asarray(exact, float).ravel()]
    for c, w in zip(np.ravel(centres), np.ravel(half_widths)):
        extra.append(c + w * BAND_STEPS)
        j = int(np.clip(np.searchsorted(grid, c), 1, max(len(grid) - 1, 1)))
        gap = float(grid[j] - grid[j - 1]) if len(grid) > 1 else 0.0
        if w > 0 and gap > 0:
            far = 3.0 * w * 2.0 ** np.arange(1, 1 + max(int(np.floor(np.log2(gap / (3.0 * w)))), 0))
            extra.append(c + np.concatenate([-far, far]))
    new = np.concatenate(extra) if extra else np.zeros(0)
    new = new[np.isfinite(new) & (new >= lo) & (new <= hi)]
    points = np.unique(np.concatenate([grid, new]))
    return points, ~np.isin(points, grid)


def frequency_refinement(grid_hz, undamped_hz, zeta) -> tuple[np.ndarray, np.ndarray]:
    """(points, added): an FRF grid refined around every mode (undamped frequency f_n = |lambda| / 2 pi,
    damping ratio zeta) whose band reaches into the grid's span: half-width zeta f_n about f_n, plus
    the damped frequency f_n sqrt(1 - zeta^2) and a single mode's receptance peak f_n sqrt(1 - 2 zeta^2)."""
    fn = np.asarray(undamped_hz, float)
    z = np.abs(np.asarray(zeta, float))
    damped = z >= UNDAMPED_ZETA
    zd, fd = z[damped], fn[damped]
    peaky = zd < 1 / np.sqrt(2)
    exact = np.concatenate([fd * np.sqrt(np.clip(1 - zd**2, 0, None)), fd[peaky] * np.sqrt(1 - 2 * zd[peaky] ** 2)])
    pts, added = refine_grid(grid_hz, fn, np.maximum(z, MIN_HALF_WIDTH) * fn, exact)
    if not damped.all():  # an undamped mode's centre is an infinite peak: its band only
        drop = added & np.isin(pts, fn[~damped])
        pts, added = pts[~drop], added[~drop]
    return pts, added


@dataclass(frozen=True)
class Crossings:
    """Where excitation-order lines cross tracked modes, one entry per crossing (ascending speed).

    Fractions (not %) for the margins; ``separation_margin`` is positive outside the operating
    range (from its nearer edge, relative to that edge) and negative inside it."""

    speed_rpm: np.ndarray
    order: np.ndarray  # excitation order n: f = n N / 60
    mode: np.ndarray  # 0-based tracked mode (column of the Campbell arrays)
    frequency_hz: np.ndarray  # n N_c / 60
    damping_ratio: np.ndarray
    whirl: tuple[str, ...]
    slope_hz_per_rpm: np.ndarray  # d f_k / d N at the crossing
    amplification_factor: np.ndarray  # 1 / (2 zeta); NaN for an unstable mode
    required_margin: np.ndarray  # API 684 (0 where AF < 2.5)
    separation_margin: np.ndarray  # NaN without an operating range
    min_operating_rpm: float | None = None
    max_continuous_rpm: float | None = None
    orders: tuple[float, ...] = ()  # the excitation orders looked at (crossed or not)

    def __len__(self) -> int:
        return len(self.speed_rpm)

    @property
    def critical(self) -> np.ndarray:
        """API 684: a crossing with AF >= 2.5 (or an unstable mode) is a critical speed."""
        af = self.amplification_factor
        return np.where(np.isfinite(af), af >= API684_MIN_AF, True)

    @property
    def meets_api684(self) -> np.ndarray:
        sm = self.separation_margin
        return ~self.critical | (np.isfinite(sm) & (sm >= self.required_margin - 1e-12))


def find_crossings(speeds_rpm, freq_hz, zeta, whirl, orders=(1.0,), operating=None) -> Crossings:
    """Sign changes of f_k(N) - n N / 60 between neighbouring speeds for every tracked mode (columns
    of ``freq_hz`` [speed, mode]) and every order n, located by linear interpolation; ``operating``
    = (N_min, N_mc) rpm gives the separation margins."""
    s = np.asarray(speeds_rpm, float)
    rows = []
    for n in orders:
        g = freq_hz - n * s[:, None] / 60.0
        for k in range(freq_hz.shape[1]):
            for i in range(len(s) - 1):
                a, b = g[i, k], g[i + 1, k]
                if not (np.isfinite(a) and np.isfinite(b)) or s[i + 1] == s[i]:
                    continue
                if not (a == 0 or a * b < 0 or (b == 0 and i == len(s) - 2)):
                    continue
                t = 0.0 if a == 0 else (1.0 if b == 0 else a / (a - b))
                sc = s[i] + t * (s[i + 1] - s[i])
                z = zeta[i, k] + t * (zeta[i + 1, k] - zeta[i, k])
                w = whirl[i, k] if t < 0.5 else whirl[i + 1, k]
                slope = (freq_hz[i + 1, k] - freq_hz[i, k]) / (s[i + 1] - s[i])
                rows.append((sc, float(n), k, n * sc / 60.0, z, str(w), slope))
    rows.sort(key=lambda r: (r[0], r[1], r[2]))
    return crossings_from(rows, operating, orders)


def crossings_from(rows, operating=None, orders=(1.0,)) -> Crossings:
    """Crossings from (speed, order, mode, frequency, zeta, whirl, slope) rows, with AF and margins."""
    cols = list(zip(*rows)) if rows else [()] * 7
    z = np.asarray(cols[4], float)
    af = amplification_factor(z)
    c = Crossings(speed_rpm=np.asarray(cols[0], float), order=np.asarray(cols[1], float),
                  mode=np.asarray(cols[2], int), frequency_hz=np.asarray(cols[3], float), damping_ratio=z,
                  whirl=tuple(cols[5]), slope_hz_per_rpm=np.asarray(cols[6], float), amplification_factor=af,
                  required_margin=np.zeros(len(z)), separation_margin=np.full(len(z), np.nan),
                  orders=tuple(float(n) for n in orders))
    return with_margins(c, operating)


def with_margins(c: Crossings, operating=None) -> Crossings:
    """The crossings judged against the operating range (N_min, N_mc) rpm (API 684 SP6.8.2.10)."""
    if operating is None or not np.all(np.isfinite(operating)) or min(operating) <= 0:
        return dataclasses.replace(c, required_margin=np.zeros(len(c)), separation_margin=np.full(len(c), np.nan),
                                   min_operating_rpm=None, max_continuous_rpm=None)
    lo, hi = float(min(operating)), float(max(operating))
    sep = np.empty(len(c))
    need = np.empty(len(c))
    for j, (nc, af) in enumerate(zip(c.speed_rpm, c.amplification_factor)):
        below = nc < lo or (nc <= hi and (nc - lo) / lo <= (hi - nc) / hi)  # inside: judged from the nearer edge
        sep[j] = (lo - nc) / lo if below else (nc - hi) / hi
        need[j] = required_separation_margin(af if np.isfinite(af) else np.inf, below)
    return dataclasses.replace(c, required_margin=need, separation_margin=sep, min_operating_rpm=lo,
                               max_continuous_rpm=hi)


def half_power_af(x: np.ndarray, amp: np.ndarray, i_peak: int) -> tuple[float, float, float]:
    """(AF, x_1, x_2) of the peak of ``amp`` at ``i_peak`` from its half-power points (amplitude
    peak / sqrt 2, linear interpolation): AF = x_peak / (x_2 - x_1) (API 684 SP6.8.2.1); NaN when
    the curve does not fall to the half-power level on both sides within the data."""
    level = amp[i_peak] / np.sqrt(2.0)
    left = np.flatnonzero(amp[:i_peak] < level)
    right = np.flatnonzero(amp[i_peak + 1:] < level)
    if not len(left) or not len(right):
        return float("nan"), float("nan"), float("nan")
    i, j = left[-1], i_peak + 1 + right[0]
    x1 = x[i] + (level - amp[i]) * (x[i + 1] - x[i]) / (amp[i + 1] - amp[i])
    x2 = x[j - 1] + (level - amp[j - 1]) * (x[j] - x[j - 1]) / (amp[j] - amp[j - 1])
    return float(x[i_peak] / (x2 - x1)), float(x1), float(x2)
