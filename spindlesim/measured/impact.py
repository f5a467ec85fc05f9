"""The FRF of a tap test from its impacts: ``frf_from_impacts(records) -> ImpactFrf``.

Method (docs/theory.md, "FRF from impacts"):

1. Every impact is checked: a double hit (:func:`second_pulse`: after the hammer pulse has fallen under 5 % of
   its peak, the force rises again above ``double_hit_share``, 10 %, of it, anywhere in the record) or a
   clipped (overloaded) channel (pyFRF, :func:`~.frf_estimation.overloads`: three samples at the channel's
   largest magnitude) rejects it, with its reason; the others are averaged.
2. Windows, the same for every impact, applied to the records before the estimator:
   * force window: the force is kept from the record's start to the end of the longest hammer pulse plus
     one pulse length, then faded out with a half cosine over one pulse length, and zero after: the
     force channel's noise between the hit and the record's end is not taken for force;
   * exponential window e^(-decay t) on force and response alike, from the record's start: it is needed
     when the response has not died out within the record (leakage); the windowed FRF is then exactly the
     structure's with every pole moved by -decay (every damping ratio higher by decay / w_n), which the
     written FRF file says (``# exponential_window_decay_1_s``) and ``spindlesim fitmodes`` takes off.  By
     default (``decay_1_s=None``) it is applied only when the response over the records' last 5 % (less the
     noise measured before the hit) is above ``tail_limit`` (1 %) of its peak, with the decay that brings it
     to that level; 0 turns it off.
3. H1 = S_fx / S_ff averaged over the accepted impacts, and the ordinary coherence |S_fx|^2 / (S_ff S_xx),
   by pyFRF (:func:`~.frf_estimation.h1_and_coherence`), made a receptance [m/N].
"""

from __future__ import annotations

import logging
from typing import Sequence

import numpy as np

from . import frf_estimation
from .errors import MeasurementInputError
from .results import ImpactFrf, ImpactRecord, ImpactVerdict

__all__ = ["frf_from_impacts", "TAIL_SHARE", "TAIL_LIMIT"]

log = logging.getLogger(__name__)

#: the share of a record at its end over which the response's remaining level is measured
TAIL_SHARE = 0.05
#: the response level at the record's end (against its peak) above which the exponential window is applied
TAIL_LIMIT = 0.01


def frf_from_impacts(records: Sequence[ImpactRecord], *, direction: str | None = None,
                     decay_1_s: float | None = None, tail_limit: float = TAIL_LIMIT,
                     double_hit_share: float = 0.1, overload_samples: int = 3) -> ImpactFrf:
    """The receptance of the tap test whose impacts are ``records`` (module docstring).

    ``direction``: x or y (default: the records' own, else x); ``decay_1_s``: the exponential window (None:
    only where needed, 0: none)."""
    records = list(records)
    if not records:
        raise MeasurementInputError("no impact records")
    first = records[0]
    for r in records[1:]:
        if abs(r.dt_s - first.dt_s) > 1e-6 * first.dt_s:
            raise MeasurementInputError(f"{r.where}: time step {r.dt_s:.6g} s, the first record's is "
                                        f"{first.dt_s:.6g} s ({first.where}); every impact must be sampled alike")
        if len(r.force_N) != len(first.force_N):
            raise MeasurementInputError(f"{r.where}: {len(r.force_N)} samples, the first record has "
                                        f"{len(first.force_N)} ({first.where}); every impact must be as long")
        if r.kind != first.kind:
            raise MeasurementInputError(f"{r.where}: {r.kind} records, the first record has {first.kind} "
                                        f"({first.where})")
    direction = _direction(records, direction)
    verdicts = []
    for r in records:
        second = second_pulse(r.force_N, r.dt_s, double_hit_share)
        reasons = ((second,) if second else ()) + frf_estimation.overloads(r.force_N, r.response, r.kind, r.dt_s,
                                                                           overload_samples)
        verdicts.append(ImpactVerdict(r.where, not reasons, reasons, float(np.max(np.abs(r.force_N)))))
        if reasons:
            log.info("%s: left out (%s)", r.where, ", ".join(reasons))
    used = [r for r, v in zip(records, verdicts) if v.used]
    if not used:
        raise MeasurementInputError("every impact was rejected: " + "; ".join(
            f"{v.where}: {', '.join(v.reasons)}" for v in verdicts))
    n, dt = len(first.force_N), first.dt_s
    t = dt * np.arange(n)
    force = np.array([r.force_N for r in used])
    response = np.array([r.response for r in used])
    tail = tail_level(response, force)
    notes = []
    if decay_1_s is None:
        decay = _needed_decay(tail, tail_limit, t[-1])
        if decay:
            notes.append(f"the response over the records' last {100 * TAIL_SHARE:g} % is {100 * tail:.2g} % of its "
                         f"peak: exponential window e^(-{decay:.4g} t) applied (every damping ratio of the FRF is "
                         "higher by that decay / w_n; spindlesim fitmodes takes it off)")
    else:
        decay = float(decay_1_s)
        if decay < 0 or not np.isfinite(decay):
            raise MeasurementInputError(f"the exponential window's decay must be >= 0, got {decay_1_s}")
        if not decay and tail > tail_limit:
            notes.append(f"the response over the records' last {100 * TAIL_SHARE:g} % is still {100 * tail:.2g} % of "
                         "its peak and no exponential window was asked for: leakage near lightly damped modes")
        elif decay:
            notes.append(f"exponential window e^(-{decay:.4g} t) applied as asked (every damping ratio of the FRF is "
                         "higher by that decay / w_n; spindlesim fitmodes takes it off)")
    cut = force_window_end(force, dt)
    fw = force_window(n, cut, dt)
    ew = np.exp(-decay * t)
    f_hz, h, coh = frf_estimation.h1_and_coherence(force * fw * ew, response * ew, first.kind, dt)
    for note in notes:
        log.info("%s", note)
    return ImpactFrf(direction, f_hz, h, coh, tuple(verdicts), first.kind, dt, n, cut[0], decay, tail,
                     tuple(records), frf_estimation.frf_version(), tuple(notes))


def _direction(records: list[ImpactRecord], direction: str | None) -> str:
    stated = {r.direction for r in records if r.direction}
    if direction is not None:
        if direction not in ("x", "y"):
            raise MeasurementInputError(f"direction must be x or y, not {direction!r}")
        if stated - {direction}:
            log.warning("the records say direction %s; taken as %s (--direction)", ", ".join(sorted(stated)), direction)
        return direction
    if len(stated) > 1:
        raise MeasurementInputError(f"the records are in directions {', '.join(sorted(stated))}: one tap test is one "
                                    "direction")
    return stated.pop() if stated else "x"


def tail_level(response: np.ndarray, force: np.ndarray | None = None) -> float:
    """How far the response still rings at the record's end: its mean square over the last ``TAIL_SHARE`` of
    the record, less the noise's measured before the hit (the samples before the force pulse starts, when
    there are at least 16), against the square of its peak; averaged over the impacts, as an RMS share."""
    r = np.atleast_2d(response)
    k = max(1, int(round(TAIL_SHARE * r.shape[1])))
    peak2 = np.max(np.abs(r), axis=1) ** 2
    excess = np.mean(r[:, -k:] ** 2, axis=1)
    if force is not None:
        for i, f in enumerate(np.atleast_2d(force)):
            start = pulse_start(f) - 2
            if start >= 16:
                pre = r[i, :start]
                excess[i] = max(excess[i] - np.mean((pre - pre.mean()) ** 2), 0.0)
    return float(np.sqrt(np.mean(excess / np.where(peak2 > 0, peak2, 1.0))))


def second_pulse(force: np.ndarray, dt_s: float, share: float = 0.1, level: float = 0.05) -> str:
    """A double hit: where the force, outside the hammer pulse (from its start to where it falls under ``level``
    of its peak), reaches ``share`` of the peak again; "" when it does not."""
    a = np.abs(np.asarray(force, float))
    p = int(np.argmax(a))
    after = np.flatnonzero(a[p:] < level * a[p])
    end = p + (int(after[0]) if len(after) else len(a) - p)
    outside = a.copy()
    outside[pulse_start(a, level):end] = 0.0
    k = int(np.argmax(outside))
    if outside[k] < share * a[p]:
        return ""
    return (f"double hit: a second pulse {1e3 * (k - p) * dt_s:+.3g} ms from the first at "
            f"{100 * outside[k] / a[p]:.0f} % of its force")


def pulse_start(force: np.ndarray, level: float = 0.05) -> int:
    """The sample where the hammer pulse starts: the last one before the force's peak under ``level`` of it."""
    a = np.abs(force)
    p = int(np.argmax(a))
    below = np.flatnonzero(a[:p + 1] < level * a[p])
    return int(below[-1]) if len(below) else 0


def _needed_decay(tail: float, limit: float, duration_s: float) -> float:
    """The decay [1/s] that brings the tail to ``limit`` at the record's end (0 when it is there already)."""
    if tail <= limit:
        return 0.0
    return float(np.log(tail / limit) / ((1 - TAIL_SHARE / 2) * duration_s))


def force_window_end(force: np.ndarray, dt_s: float, level: float = 0.05) -> tuple[float, float]:
    """(time where the force window starts to fade, fade length) [s]: the end of the longest pulse (where the
    force falls under ``level`` of its peak, after the peak) plus one pulse length; the fade is one pulse
    length (at least 4 samples)."""
    ends, widths = [], []
    for f in np.atleast_2d(force):
        a = np.abs(f)
        p = int(np.argmax(a))
        after = np.flatnonzero(a[p:] < level * a[p])
        e = p + (int(after[0]) if len(after) else len(f) - 1 - p)
        ends.append(e)
        widths.append(max(e - pulse_start(f, level), 4))
    width = max(widths)
    return (max(ends) + width) * dt_s, width * dt_s


def force_window(n: int, cut: tuple[float, float], dt_s: float) -> np.ndarray:
    """1 up to ``cut[0]``, a half cosine down to 0 over ``cut[1]``, 0 after."""
    t = dt_s * np.arange(n)
    start, fade = cut
    w = np.ones(n)
    ramp = (t > start) & (t < start + fade)
    w[ramp] = 0.5 * (1 + np.cos(np.pi * (t[ramp] - start) / fade))
    w[t >= start + fade] = 0.0
    return w
