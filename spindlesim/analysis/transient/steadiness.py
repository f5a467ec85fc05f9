"""Is a Poincare set periodic?

Periodicity (``poincare_periodicity``): Poincare points (x, y at the record node) closer than a
tolerance are one place; the tolerance is ``REL_TOL`` of the orbit's peak-to-peak extent (the
steady part's largest peak-to-peak of x and y), never below the numerical noise of the positions
(``noise_m``).  A set is period-k when, for the least k <= ``MAX_PERIOD``, the points i, i + k,
i + 2k, ... lie within the tolerance of their mean for every i (k places visited in turn, each at
least twice).  A set of fewer than 2 ``MAX_PERIOD`` points that is not periodic is "too few points"
to tell; any other set is not periodic (quasi-periodic or chaotic: the points alone do not tell
which), and its distinct places are counted (``cluster_labels``: a point within the tolerance of an
earlier place belongs to it).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Poincare points closer than this fraction of the orbit's peak-to-peak extent are one place
REL_TOL = 1e-2
#: numerical noise of a recorded position: this fraction of its size, plus an absolute floor [m]
NOISE_REL = 1e-9
NOISE_ABS_M = 1e-15
#: longest period (in Poincare samples) called period-k
MAX_PERIOD = 8
#: the most points of a set classified (the last ones: the most settled)
MAX_POINTS = 2000


@dataclass(frozen=True)
class Periodicity:
    """What a Poincare set's points say (module note)."""

    kind: str  # "period" | "not periodic" | "too few points" | "no points"
    period: int  # k of a period-k set, else 0
    distinct: int  # places at the tolerance
    points: int  # points classified
    tolerance_m: float
    spread_m: float  # largest distance of a point from the set's mean
    extent_m: float  # the orbit's peak-to-peak extent the tolerance refers to

    @property
    def periodic(self) -> bool:
        return self.kind == "period"

    @property
    def label(self) -> str:
        if self.kind == "period":
            return f"period-{self.period}"
        if self.kind == "not periodic":
            return "not periodic (quasi-periodic or chaotic)"
        return self.kind

    @property
    def relative_tolerance(self) -> float:
        return self.tolerance_m / self.extent_m if self.extent_m > 0 else float("nan")


def orbit_scale(xy: np.ndarray) -> tuple[float, float]:
    """(peak-to-peak extent, numerical noise) of the positions xy [t, 2] of the steady part [m]."""
    p = np.asarray(xy, float)
    if not p.size:
        return 0.0, NOISE_ABS_M
    return float(np.max(np.ptp(p, axis=0))), NOISE_ABS_M + NOISE_REL * float(np.max(np.abs(p)))


def cluster_labels(points: np.ndarray, tol: float) -> np.ndarray:
    """Place of each point: the nearest earlier place within ``tol``, else a new one (in order)."""
    p = np.asarray(points, float)
    reps = np.empty_like(p)
    labels = np.empty(len(p), int)
    k = 0
    for i, q in enumerate(p):
        if k:
            d = np.sqrt(np.sum((reps[:k] - q) ** 2, axis=1))
            j = int(np.argmin(d))
            if d[j] <= tol:
                labels[i] = j
                continue
        reps[k] = q
        labels[i] = k
        k += 1
    return labels


def _period(p: np.ndarray, tol: float) -> int:
    """The least k <= MAX_PERIOD such that the points i, i + k, i + 2k, ... lie within ``tol`` of their
    mean for every i (each of the k places visited at least twice); 0 when there is none."""
    for k in range(1, min(MAX_PERIOD, len(p) // 2) + 1):
        if all(np.max(np.linalg.norm(g - g.mean(axis=0), axis=1)) <= tol for g in (p[j::k] for j in range(k))):
            return k
    return 0


def poincare_periodicity(xy: np.ndarray, extent_m: float, noise_m: float = NOISE_ABS_M) -> Periodicity:
    """Period-k, not periodic, or too few points (module note) of Poincare points xy [k, 2]."""
    p = np.asarray(xy, float)[-MAX_POINTS:]
    n = len(p)
    tol = max(REL_TOL * extent_m, noise_m)
    if n == 0:
        return Periodicity("no points", 0, 0, 0, tol, float("nan"), extent_m)
    spread = float(np.max(np.linalg.norm(p - p.mean(axis=0), axis=1)))
    k = _period(p, tol)
    if k:
        return Periodicity("period", k, k, n, tol, spread, extent_m)
    distinct = int(cluster_labels(p, tol).max()) + 1
    return Periodicity("too few points" if n < 2 * MAX_PERIOD else "not periodic", 0, distinct, n, tol, spread,
                       extent_m)
