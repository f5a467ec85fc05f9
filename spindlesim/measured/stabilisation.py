"""Which poles of a stabilisation diagram are physical modes: the rule (pure numpy, no library).

A parametric estimator (LSCF) fitted at increasing model orders returns, at each order, the poles of the
structure plus computational poles that model noise and the band's edges.  A structural pole comes back
at every order at nearly the same frequency, damping and residue; a computational one wanders.  The rule,
with the defaults of :class:`StabilityCriteria` (docs/theory.md, "Modal identification"):

1. Candidates at each order: poles with Im lambda > 0 inside the band and |zeta| < ``max_damping`` (0.3);
   negative damping is kept here so that a stable computational pole of negative damping is reported as
   such, not silently lost.
2. A candidate is *stable* when the previous order has a candidate within ``frequency_tol`` (1 %) in
   frequency (the nearest one is its match), within ``damping_tol`` (5 %) of that match's damping ratio
   (and 1e-4 absolute, for very light damping), and whose residue differs by at most ``residue_tol``
   (10 %) of its modulus: the residue is the single-reference form of the mode shape, so this is the MAC
   criterion of a single FRF (a single-reference MAC is 1 for any pole and would test nothing).
3. Stable candidates linked to their matches form *tracks* through the orders; a track with at least
   ``min_stable`` (5) stable poles is a mode.  Tracks whose median frequencies are within
   ``frequency_tol`` of each other are the same mode (a track broken by one noisy order and resumed);
   the longest is kept.  Two modes closer than ``frequency_tol`` are therefore one mode.
4. The pole representing a mode is the one of its track nearest to the track's median frequency and
   damping (robust against an order at either end of the track that drifts).

Physical checks on the chosen poles (negative damping, residue of the wrong sign for a direct FRF,
a peak too small to matter) are made by the identification after the final residues are known.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

__all__ = ["StabilityCriteria", "Candidates", "Track", "candidates", "classify", "tracks", "modes_from_tracks",
           "NEW", "STABLE_FREQUENCY", "STABLE_DAMPING", "STABLE"]

#: status of a candidate pole in the diagram: new (no match), frequency stable, frequency and damping
#: stable, stable (frequency, damping and residue)
NEW, STABLE_FREQUENCY, STABLE_DAMPING, STABLE = 0, 1, 2, 3


@dataclass(frozen=True)
class StabilityCriteria:
    """The tolerances of the rule (module docstring)."""

    frequency_tol: float = 0.01
    damping_tol: float = 0.05
    damping_abs_tol: float = 1e-4
    residue_tol: float = 0.10
    min_stable: int = 5
    max_damping: float = 0.3
    top_share: float = 0.25

    def __post_init__(self) -> None:
        for name in ("frequency_tol", "damping_tol", "residue_tol", "max_damping", "top_share"):
            if not 0.0 < getattr(self, name) < 1.0:
                raise ValueError(f"{name} must be in (0, 1), got {getattr(self, name)}")
        if self.min_stable < 2:
            raise ValueError(f"min_stable must be at least 2, got {self.min_stable}")


@dataclass(frozen=True, eq=False)
class Candidates:
    """The candidate poles of one model order: their index among that order's poles, frequency [Hz],
    damping ratio and residue (complex, m/N rad/s)."""

    order: int
    index: np.ndarray
    frequency_hz: np.ndarray
    damping_ratio: np.ndarray
    residue: np.ndarray


def candidates(order: int, poles: np.ndarray, band_hz: tuple[float, float], max_damping: float) -> Candidates:
    """The poles of one order that may be modes of the band (rule step 1); residues are filled in later."""
    p = np.asarray(poles, complex)
    wn = np.abs(p)
    with np.errstate(divide="ignore", invalid="ignore"):
        zeta = np.where(wn > 0, -p.real / wn, np.inf)
    f = wn / (2 * np.pi)
    keep = (p.imag > 0) & (f >= band_hz[0]) & (f <= band_hz[1]) & (np.abs(zeta) < max_damping)
    idx = np.flatnonzero(keep)
    idx = idx[np.argsort(f[idx])]
    return Candidates(order, idx, f[idx], zeta[idx], np.full(len(idx), np.nan + 0j))


def classify(cur: Candidates, prev: Candidates | None, c: StabilityCriteria) -> tuple[np.ndarray, np.ndarray]:
    """(status [NEW .. STABLE], index of the match in ``prev`` or -1) of every candidate of ``cur``."""
    n = len(cur.index)
    status = np.full(n, NEW, dtype=np.int8)
    match = np.full(n, -1, dtype=np.int64)
    if prev is None or not len(prev.index) or not n:
        return status, match
    for i in range(n):
        j = int(np.argmin(np.abs(prev.frequency_hz - cur.frequency_hz[i])))
        if abs(cur.frequency_hz[i] - prev.frequency_hz[j]) > c.frequency_tol * prev.frequency_hz[j]:
            continue
        match[i] = j
        status[i] = STABLE_FREQUENCY
        dz = abs(cur.damping_ratio[i] - prev.damping_ratio[j])
        if dz > max(c.damping_tol * abs(prev.damping_ratio[j]), c.damping_abs_tol):
            continue
        status[i] = STABLE_DAMPING
        a, b = cur.residue[i], prev.residue[j]
        if np.isfinite(a) and np.isfinite(b) and abs(a - b) <= c.residue_tol * abs(b):
            status[i] = STABLE
    return status, match


@dataclass(frozen=True)
class Track:
    """A run of stable poles through consecutive orders: (order position, candidate position) pairs."""

    members: tuple[tuple[int, int], ...]
    frequency_hz: float  # median over the track
    damping_ratio: float  # median over the track
    representative: tuple[int, int]  # the member nearest to the medians
    stable: int = 0  # stable poles of the mode: this track's and those of the tracks merged into it

    @property
    def length(self) -> int:
        return len(self.members)


def tracks(cands: list[Candidates], status: list[np.ndarray], match: list[np.ndarray]) -> list[Track]:
    """Chains of stable poles (rule step 3): a stable pole continues the chain of its match."""
    chains: dict[tuple[int, int], list[tuple[int, int]]] = {}
    for o in range(len(cands)):
        taken: dict[int, int] = {}  # match -> candidate of this order that continues it (the nearest)
        for i in np.flatnonzero(status[o] == STABLE):
            j = int(match[o][i])
            if j in taken:
                k = taken[j]
                if abs(cands[o].frequency_hz[i] - cands[o - 1].frequency_hz[j]) >= \
                        abs(cands[o].frequency_hz[k] - cands[o - 1].frequency_hz[j]):
                    continue
            taken[j] = int(i)
        for j, i in taken.items():
            chain = chains.pop((o - 1, j), None) or []
            chains[(o, i)] = chain + [(o, i)]
    out = []
    for members in chains.values():
        f = np.array([cands[o].frequency_hz[i] for o, i in members])
        z = np.array([cands[o].damping_ratio[i] for o, i in members])
        fm, zm = float(np.median(f)), float(np.median(z))
        dist = np.abs(f - fm) / fm + np.abs(z - zm) / max(abs(zm), 1e-6) * 0.1
        out.append(Track(tuple(members), fm, zm, members[int(np.argmin(dist))]))
    return out


def modes_from_tracks(found: list[Track], n_orders: int, c: StabilityCriteria) -> list[Track]:
    """The tracks that are modes (rule steps 3 and 4), one per mode, by ascending frequency; ``n_orders``:
    the number of model orders of the diagram."""
    top = (n_orders - 1) * (1.0 - c.top_share)
    alive = sorted((t for t in found if t.members[-1][0] >= top), key=lambda t: -t.length)
    kept: list[Track] = []
    for t in alive:
        if all(abs(t.frequency_hz - k.frequency_hz) > c.frequency_tol * k.frequency_hz for k in kept):
            kept.append(t)
    modes = []
    for k in kept:
        count = sum(t.length for t in found if abs(t.frequency_hz - k.frequency_hz) <= c.frequency_tol * k.frequency_hz
                    and (t is k or t not in kept))
        if count >= c.min_stable:
            modes.append(replace(k, stable=count))
    return sorted(modes, key=lambda t: t.frequency_hz)
