"""Has the recorded response settled, is its steady part long enough, is a Poincare set periodic?

Periodicity (``poincare_periodicity``): Poincare points (x, y at the record node) closer than a
tolerance are one place; the tolerance is ``REL_TOL`` of the orbit's peak-to-peak extent (the
steady part's largest peak-to-peak of x and y), never below the numerical noise of the positions
(``noise_m``).  A set is period-k when, for the least k <= ``MAX_PERIOD``, the points i, i + k,
i + 2k, ... lie within the tolerance of their mean for every i (k places visited in turn, each at
least twice).  A set of fewer than 2 ``MAX_PERIOD`` points that is not periodic is "too few points"
to tell; any other set is not periodic (quasi-periodic or chaotic: the points alone do not tell
which), and its distinct places are counted (``cluster_labels``: a point within the tolerance of an
earlier place belongs to it).

Settling (``assess_settling``): the steady part [settle_s, end] is judged on x and y of the record
node.  It has settled when the speed is constant and

1. the window holds at least ``MIN_PERIODS`` periods of its largest spectral line (else it is too
   short to judge: half-window statistics of fewer periods depend on where the periods are cut);
2. the Hann-weighted RMS of its second half (about that half's weighted mean) is within
   ``ENVELOPE_TOL`` of its first half's: a decaying free vibration or a growing whirl fails;
3. the weighted mean (orbit centre) moves between the halves by at most ``DRIFT_TOL`` of the
   vibration amplitude, sqrt(2) x the RMS of x and y together (a sinusoid's amplitude on one axis,
   sqrt(2) x the radius of a circular orbit): a creeping static position fails;
4. either the primary Poincare set is periodic, or no linear mode of the start state rings in
   it: a stable mode whose start-up free vibration exp(-sigma t) has not fallen below
   ``DECAY_TOL`` (3 time constants) by the start of the window while its frequency carries at
   least ``RING_FRACTION`` of the largest line (a lightly damped free vibration passes 2 and 3).

A response smaller than the numerical noise has nothing to settle.  Independently, a named
frequency (revolution, cage, passes) is resolved when it lies at least ``RESOLVE_BINS`` bins
(the Hann window's 6 dB bandwidth, Harris 1978) above 0 Hz: the window T = n / fs holds at least
two of its periods.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .spectrum import Spectrum

#: Poincare points closer than this fraction of the orbit's peak-to-peak extent are one place
REL_TOL = 1e-2
#: numerical noise of a recorded position: this fraction of its size, plus an absolute floor [m]
NOISE_REL = 1e-9
NOISE_ABS_M = 1e-15
#: longest period (in Poincare samples) called period-k
MAX_PERIOD = 8
#: the most points of a set classified (the last ones: the most settled)
MAX_POINTS = 2000
ENVELOPE_TOL = 0.05
DRIFT_TOL = 0.05
MIN_PERIODS = 8
DECAY_TOL = math.exp(-3.0)
RING_FRACTION = 0.05
RESOLVE_BINS = 2.0


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


@dataclass(frozen=True)
class LinearModes:
    """Modes of the system linearised at the start state: damped frequency, decay rate sigma = -Re(lambda)."""

    frequency_hz: np.ndarray
    decay_rate_1_s: np.ndarray

    @property
    def damping_ratio(self) -> np.ndarray:
        w = 2 * np.pi * self.frequency_hz
        return self.decay_rate_1_s / np.maximum(np.hypot(w, self.decay_rate_1_s), 1e-300)


def first_order_matrix(M: np.ndarray, K: np.ndarray, C: np.ndarray) -> np.ndarray:
    """A = [[0, I], [-M^-1 K, -M^-1 C]] of M x'' + C x' + K x = 0 (general M: the transient's matrices,
    constrained or reduced; ``analysis.modal.first_order`` is the rotor's, with M symmetric positive)."""
    n = M.shape[0]
    MiK, MiC = np.split(np.linalg.solve(M, np.hstack([K, C])), 2, axis=1)
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -MiK
    A[n:, n:] = -MiC
    return A


def linear_modes(M: np.ndarray, K: np.ndarray, C: np.ndarray) -> LinearModes:
    """Oscillating modes (one of each conjugate pair) of M x'' + C x' + K x = 0."""
    lam = np.linalg.eigvals(first_order_matrix(M, K, C))
    lam = lam[lam.imag > 1e-9 * np.maximum(np.abs(lam), 1.0)]
    return LinearModes(lam.imag / (2 * np.pi), -lam.real)


@dataclass(frozen=True)
class Settling:
    """Whether the steady part of a run has settled and what its spectrum resolves (module note)."""

    settled: bool
    start_s: float  # first sample of the steady part
    duration_s: float  # n / fs: the spectrum's window
    resolution_hz: float  # fs / n: the spectrum's bin
    envelope_change: float  # RMS of the second half / first half - 1
    centre_drift: float  # |centre 2 - centre 1| / vibration amplitude
    dominant_hz: float  # the largest line (above 0 Hz)
    dominant_periods: float  # its periods in the window
    ringing_mode_hz: float  # a linear mode still ringing in the window (NaN: none)
    ringing_mode_decay: float  # exp(-sigma t_settle) of that mode
    unresolved: tuple[tuple[str, float], ...]  # named frequencies within RESOLVE_BINS of 0 Hz
    note: str  # "settled: ..." or "not settled: <the reasons>"
    resolution_note: str = ""  # "window too short for ... Hz resolution: ..." ("" when all are resolved)

    @property
    def resolved(self) -> bool:
        return not self.unresolved


def _halves(xy: np.ndarray) -> tuple[float, float, float]:
    """(RMS 1, RMS 2, centre distance) of the two halves, Hann-weighted, x and y together."""
    h = len(xy) // 2
    out = []
    for part in (xy[:h], xy[len(xy) - h:]):
        w = 0.5 - 0.5 * np.cos(2 * np.pi * (np.arange(h) + 0.5) / h)
        m = w @ part / w.sum()
        out.append((math.sqrt(float(np.sum(w @ (part - m) ** 2)) / w.sum()), m))
    return out[0][0], out[1][0], float(np.linalg.norm(out[1][1] - out[0][1]))


def _ringing(spec: Spectrum, modes: LinearModes | None, settle_s: float, peak: float):
    """(frequency, exp(-sigma t), line amplitude, damping ratio) of the strongest stable linear mode that
    has not decayed by ``settle_s`` and has a line (a local maximum of the spectrum, at least
    RING_FRACTION of the largest) within RESOLVE_BINS bins of its frequency; None when there is none."""
    if modes is None or spec.frequency_hz.size < 3:
        return None
    f, A = spec.frequency_hz, np.max(spec.amplitude, axis=1)
    df = spec.resolution_hz
    line = np.zeros(f.size, bool)
    line[1:-1] = (A[1:-1] >= A[:-2]) & (A[1:-1] >= A[2:]) & (A[1:-1] >= RING_FRACTION * peak)
    best = None
    for fm, s, z in zip(modes.frequency_hz, modes.decay_rate_1_s, modes.damping_ratio):
        left = math.exp(-max(s, 0.0) * settle_s)
        if s < 0 or left <= DECAY_TOL:
            continue  # unstable (judged by the envelope) or decayed
        near = line & (np.abs(f - fm) <= RESOLVE_BINS * df)
        if near.any():
            a = float(A[near].max())
            if best is None or a > best[2]:
                best = (float(fm), left, a, float(z))
    return best


def _pct(x: float) -> str:
    """A fraction as a percentage to two digits; below 0.01 % (the steadiness tests' noise) "under 0.01 %"."""
    p = 100 * x
    if abs(p) < 0.01:
        return "under 0.01 %"
    return f"{p:.0f} %" if abs(p) >= 10 else f"{p:.2g} %"


def _damping(zeta: float) -> str:
    return "undamped" if zeta < 1e-9 else f"damping ratio {zeta:.2g}"


def _dur(t: float) -> str:
    return f"{t * 1e3:.3g} ms" if t < 0.1 else f"{t:.3g} s"


def assess_settling(time_s: np.ndarray, xy: np.ndarray, sample_rate_hz: float, spectrum: Spectrum, *,
                    settle_s: float, end_s: float, constant_speed: bool = True, periodic: bool | None = None,
                    modes: LinearModes | None = None, named_hz: dict | None = None) -> Settling:
    """Judge the steady part ``time_s``, ``xy`` [t, 2] (t >= settle_s) of a run that ended at ``end_s``;
    ``spectrum`` is its amplitude spectrum, ``periodic`` whether its primary Poincare set is periodic
    (None: no set), ``modes`` the linear modes of the start state, ``named_hz`` the frequencies the
    outputs name (module note)."""
    n = len(time_s)
    xy = np.asarray(xy, float).reshape(n, -1) if n else np.zeros((0, 2))
    nan = float("nan")
    T = float(n / sample_rate_hz) if n else 0.0
    df = spectrum.resolution_hz if spectrum.frequency_hz.size > 1 else (1.0 / T if T > 0 else nan)
    named = {k: float(v) for k, v in (named_hz or {}).items() if v > 0}
    unresolved = tuple((k, v) for k, v in named.items() if not (np.isfinite(df) and v >= RESOLVE_BINS * df))
    reasons: list[str] = []
    change = drift = f_dom = periods = nan
    ring = None
    quiet = False
    if not constant_speed:
        reasons.append("the speed varies: a run-up or run-down has no steady state")
    if n < 4:
        reasons.append(f"no steady part: the run stopped at {end_s:.4g} s, the steady part starts at {settle_s:.4g} s")
    else:
        _, noise = orbit_scale(xy)
        r1, r2, dc = _halves(xy)
        amp = math.sqrt(2.0) * max(r1, r2)
        drift = dc / max(amp, noise)
        quiet = amp <= noise
        if quiet:  # nothing vibrates: only a creeping position can be unsettled
            change = 0.0
            if dc > noise:
                reasons.append(f"the position creeps by {dc:.3g} m between the halves of the steady part")
        else:
            change = r2 / r1 - 1.0 if r1 > 0 else math.inf
            A = np.max(spectrum.amplitude, axis=1) if spectrum.frequency_hz.size > 1 else np.zeros(1)
            i = int(np.argmax(A[1:])) + 1 if A.size > 1 else 0
            f_dom = float(spectrum.frequency_hz[i]) if i else nan
            periods = float(f_dom * T) if i else 0.0
            if not periods >= MIN_PERIODS:
                reasons.append(f"too short to judge: the {_dur(T)} steady part holds {periods:.3g} "
                               f"period{'' if periods == 1 else 's'} of its largest line ({f_dom:.4g} Hz), "
                               f"{MIN_PERIODS} are needed")
            else:
                if abs(change) > ENVELOPE_TOL:
                    reasons.append(f"the vibration {'decays' if change < 0 else 'grows'}: its RMS is "
                                   f"{_pct(abs(change))} {'lower' if change < 0 else 'higher'} in the second half of "
                                   "the steady part")
                if drift > DRIFT_TOL:
                    reasons.append(f"the orbit centre moves by {_pct(drift)} of the vibration amplitude between the "
                                   "halves of the steady part")
                ring = None if periodic else _ringing(spectrum, modes, settle_s, float(A[i]))
                if ring is not None:
                    reasons.append(f"the free vibration of the start has not died out: the linear mode at "
                                   f"{ring[0]:.4g} Hz ({_damping(ring[3])}) keeps exp(-sigma t) = "
                                   f"{_pct(ring[1])} of its start amplitude at {settle_s:.4g} s and its line is "
                                   f"{_pct(ring[2] / float(A[i]))} of the largest")
    settled = not reasons
    if not settled:
        note = "not settled: " + "; ".join(reasons)
    elif quiet:
        note = "settled: no vibration above the numerical noise"
    else:
        note = (f"settled: the halves of the steady part agree (RMS {_pct(change)}, centre moved by "
                f"{_pct(drift)} of the amplitude)" + ("; the primary Poincare set is periodic" if periodic else ""))
    resolution = ""
    if unresolved:
        need = RESOLVE_BINS / min(v for _, v in unresolved)
        resolution = (f"window too short for {df:.3g} Hz resolution: "
                      + ", ".join(f"{k} ({v:.4g} Hz)" for k, v in unresolved)
                      + f" within {RESOLVE_BINS:g} bins of 0 Hz (a steady part of {_dur(need)} resolves "
                      + ("it)" if len(unresolved) == 1 else "them)"))
    return Settling(settled, float(time_s[0]) if n else nan, T, df, change, drift, f_dom, periods,
                    ring[0] if ring else nan, ring[1] if ring else nan, unresolved, note, resolution)
