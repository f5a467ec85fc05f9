"""Campbell diagram: damped modes over a speed range, tracked between speeds by MAC.

Mode tracking: the modal assurance criterion between complex mode shapes,
MAC(a, b) = |a^H b|^2 / ((a^H a)(b^H b)), weighted by frequency proximity, is
maximised over assignments (Hungarian algorithm, scipy.optimize.linear_sum_assignment, see
:func:`assign`).
Crossings (:mod:`.resonance`): every tracked mode (forward, backward, mixed, axial) against every
excitation order asked for (1x, 2x, a cutter's tooth-passing order), each with its API 684
amplification factor AF = 1/(2 zeta) and separation margin from the operating range.  A critical
speed is a 1x crossing with AF >= 2.5 of a mode that is not backward lateral (a crossing with AF < 2.5
is critically damped).
"""

from __future__ import annotations

import dataclasses
import functools
import logging
import time
from typing import Callable

import numpy as np

from ..model.rotor import Rotor
from .modal import modal_from_matrices
from .points import OperatingPoints
from .prefetch import ModalPrefetch
from .reduced import checked_basis, first_basis, usable_cores
from .resonance import Crossings, find_crossings
from .results import CampbellResult

log = logging.getLogger(__name__)


def assign(cost: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(rows, columns): every row of ``cost`` to its own column at the least total cost.

    When each row's minimum is strict and in a column of its own, that is the assignment: the sum
    of the row minima bounds every assignment from below, and only this one reaches it.  Between
    neighbouring speeds that is the usual case, and it spares importing scipy.optimize (a quarter
    of a second, more than a whole Campbell diagram of a linear rotor); otherwise the Hungarian
    algorithm (scipy.optimize.linear_sum_assignment) decides.
    """
    cost = np.asarray(cost, float)
    rows = np.arange(cost.shape[0])
    if cost.shape[0] <= cost.shape[1]:
        best = np.argmin(cost, axis=1) if cost.shape[1] else np.zeros(0, int)
        if len(np.unique(best)) == len(best):
            two = np.partition(cost, 1, axis=1)[:, :2] if cost.shape[1] > 1 else None
            if two is None or np.all(two[:, 0] < two[:, 1]):
                return rows, best
    from scipy.optimize import linear_sum_assignment

    return linear_sum_assignment(cost)


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """MAC matrix between mode sets a [m, n] and b [k, n] (complex)."""
    num = np.abs(a.conj() @ b.T) ** 2
    den = np.outer(np.sum(np.abs(a) ** 2, axis=1), np.sum(np.abs(b) ** 2, axis=1))
    return num / den


def solve_campbell(rotor: "Rotor | OperatingPoints", speeds_rpm: np.ndarray, n_modes: int = 8,
                   progress: Callable[[int, int], None] | None = None,
                   frozen_rpm: float | None = None, exact: bool = False, orders=(1.0,),
                   operating: tuple[float, float] | None = None) -> CampbellResult:
    """Tracked modes over ``speeds_rpm``; the bearings are linearised at the static state of every
    speed, or with ``frozen_rpm`` held at their coefficients of that speed (gyroscopics still vary).
    The modes come from the reduced model (``reduced``), or with ``exact`` from the full state-space
    QR solution at every speed.  The crossings of the excitation ``orders`` with the tracked modes are
    judged against the ``operating`` range (minimum operating, maximum continuous speed [rpm]).
    ``progress(done, total)`` counts the static states (the costly part; the modes follow at once).
    Given :class:`.points.OperatingPoints`, its assembly, states and reduced basis are reused (a frozen
    comparison reads the states and the basis of the diagram before it).  A failing speed, or Ctrl-C,
    ends the diagram at the speeds solved before it (``incomplete_reason``, ``interrupted``)."""
    points = OperatingPoints.of(rotor)
    guess = _Guess(points, n_modes + max(4, n_modes // 2))
    try:
        return _campbell(points, speeds_rpm, n_modes, progress, frozen_rpm, exact, guess, orders, operating)
    finally:
        guess.cancel()  # a failure or Ctrl-C before the prefetched modes were used: stop their thread


def _campbell(points, speeds_rpm, n_modes, progress, frozen_rpm, exact, guess, orders, operating) -> CampbellResult:
    speeds = np.asarray(speeds_rpm, float)
    done = [0]

    def tick():
        done[0] += 1
        if progress is not None:
            progress(done[0], len(speeds))

    stopped, interrupted = "", False
    if frozen_rpm is None:
        on_state = guess.add if not exact and len(speeds) >= 3 and usable_cores() >= 2 else None
        sweep = points.along(speeds, tick, on_state, what="Campbell diagram")
        speeds, states, stopped, interrupted = sweep.speeds_rpm, sweep.states, sweep.stopped, sweep.interrupted
        key = ("campbell", float(speeds[0]), float(speeds[-1]))
    else:  # the bearings' state at frozen_rpm, the shaft (gyroscopics) at every speed
        states = points.held(frozen_rpm, speeds)
        key = ("campbell", float(speeds[0]), float(speeds[-1]), "held", float(frozen_rpm))
        if progress is not None:
            progress(len(speeds), len(speeds))
    model, modal = _modal_at_speeds(points, speeds, n_modes + max(4, n_modes // 2), states, exact,
                                    n_check=n_modes, guess=guess, key=key)
    tracked = track_modes(modal, len(speeds), n_modes)
    freq, zeta, logdec, whirl = tracked.frequency_hz, tracked.damping_ratio, tracked.log_dec, tracked.whirl
    crossings = find_crossings(speeds, freq, zeta, whirl, orders, operating)
    crit = critical_speed_crossings(crossings)
    return CampbellResult(speed_rpm=speeds, frequency_hz=freq, log_dec=logdec, damping_ratio=zeta,
                          whirl=whirl.astype(str), critical_speeds_rpm=crossings.speed_rpm[crit],
                          critical_modes=crossings.mode[crit], model=model, incomplete_reason=stopped,
                          crossings=crossings, interrupted=interrupted)


@dataclasses.dataclass(frozen=True)
class TrackedModes:
    """Modes followed over speeds: [speed, mode] arrays (NaN / "" where a mode is not tracked), and with
    ``shapes`` the tracked mode shapes [speed, mode, entries] (NaN where not tracked)."""

    frequency_hz: np.ndarray
    damping_ratio: np.ndarray
    log_dec: np.ndarray
    whirl: np.ndarray
    shapes: np.ndarray | None = None


def track_modes(modal, n_speeds: int, n_track: int, tick: Callable[[], None] | None = None,
                keep_shapes: bool = False) -> TrackedModes:
    """Follow ``n_track`` modes through the modal results of consecutive speeds (an iterable of
    ModalResult) by MAC with a frequency-jump penalty, the assignment by :func:`assign`; spare modes
    (more in each result than tracked) replace a mode that leaves the window."""
    freq = np.full((n_speeds, n_track), np.nan)
    zeta = np.full_like(freq, np.nan)
    logdec = np.full_like(freq, np.nan)
    whirl = np.full(freq.shape, "", dtype=object)
    kept = None
    prev_shapes = None
    prev_freq = None
    for i, m in enumerate(modal):
        shapes = m.mode_shape.reshape(len(m.frequency_hz), -1)
        if kept is None and keep_shapes:
            kept = np.full((n_speeds, n_track, shapes.shape[1]), np.nan, complex)
        if prev_shapes is None:
            take = np.arange(min(n_track, len(m.frequency_hz)))
            cols = take
        else:
            M = mac(prev_shapes, shapes)
            rel = np.abs(prev_freq[:, None] - m.frequency_hz[None, :]) / np.maximum(prev_freq[:, None], 1e-12)
            cost = -(M - 0.5 * np.minimum(rel, 1.0))
            rows_, cols_ = assign(cost)
            cols = np.full(len(prev_freq), -1)
            cols[rows_] = cols_
            take = np.arange(len(prev_freq))
        for k, c in zip(take, cols):
            if c < 0 or c >= len(m.frequency_hz):
                continue
            freq[i, k] = m.frequency_hz[c]
            zeta[i, k] = m.damping_ratio[c]
            logdec[i, k] = m.log_dec[c]
            whirl[i, k] = m.whirl[c]
            if kept is not None:
                kept[i, k] = shapes[c]
        valid = cols >= 0
        prev_shapes = shapes[cols[valid]] if prev_shapes is not None else shapes[: len(take)]
        prev_freq = m.frequency_hz[cols[valid]] if prev_freq is not None else m.frequency_hz[: len(take)]
        if tick is not None:
            tick()
    return TrackedModes(freq, zeta, logdec, whirl, kept)


def critical_speed_crossings(c: Crossings) -> np.ndarray:
    """Which crossings are critical speeds of the 1x (unbalance) line: AF >= 2.5 (API 684) and not a
    backward lateral mode (an unbalance drives forward whirl; a backward mode only through support
    anisotropy, and is listed with the other crossings)."""
    return (c.order == 1.0) & c.critical & np.array([w != "backward" for w in c.whirl], bool)


def _modal_at_speeds(points, speeds: np.ndarray, n_modes: int, states, exact: bool = False,
                     n_check: int | None = None, guess: "_Guess | None" = None, key: tuple | None = None):
    """(description of the model used, iterator over the modal results at every speed).  The speeds
    are solved on all cores (LAPACK releases the GIL; each thread uses single-threaded BLAS) and
    yielded in speed order for the sequential mode tracking; ``guess`` holds the modes prefetched
    while the states were found, used when its basis passes the check.  The reduced basis is the
    operating points' (``key``: what it was checked for); a diagram with another key tries the last
    Campbell basis first (a frozen comparison: the same rotor, other bearing coefficients)."""
    from concurrent.futures import ThreadPoolExecutor

    rotor, shaft = points.rotor, points.shaft
    expand, model = None, "full state space"
    # the prefetched modes are finished first (the check below holds the interpreter: nothing would run
    # beside it) and kept only when their basis passes the check
    prefetched = guess.finish() if guess is not None else None
    basis = None
    if not exact:
        first = guess.basis if guess is not None else None
        key = ("campbell",) if key is None else key
        basis = points.basis(key + (n_modes, n_check), lambda: checked_basis(
            rotor, shaft, list(states), n_modes, n_check, first=first, candidate=points.last_basis("campbell")))
    if prefetched is not None and basis is not None and basis is guess.basis:
        return f"reduced: {basis.size} of {shaft.M.shape[0]} coordinates", iter(prefetched)
    if basis is None:
        matrices = [functools.partial(points.system, st) for st in states]
    else:
        matrices = [functools.partial(basis.system, st) for st in states]
        expand = basis.T
        model = f"reduced: {basis.size} of {shaft.M.shape[0]} coordinates"

    def one(k: int):
        return modal_from_matrices(matrices[k](), rotor.dofs, rotor.node_z_m, n_modes, speeds[k], expand)

    def chunk(ks):
        return [one(k) for k in ks]

    def results():
        # a small reduced eigenproblem (~0.5 ms) costs less than handing it to a thread: the threads then
        # take contiguous runs of speeds (one hand-off each); a full model's speeds go one by one
        workers = min(len(speeds), usable_cores())
        if workers <= 1:
            yield from (one(k) for k in range(len(speeds)))
            return
        with ThreadPoolExecutor(max_workers=workers) as ex:
            if expand is not None and expand.shape[1] <= 100:
                for part in ex.map(chunk, np.array_split(np.arange(len(speeds)), workers)):
                    yield from part
            else:
                yield from ex.map(one, range(len(speeds)))

    return model, results()


class _Guess:
    """The modes of each static state solved as it is found (:mod:`.prefetch`), on the basis the
    reduced model tries first, built at the first state.

    Only when the states are costly: from the time between the first two states (a bearing solved at
    every speed: ball sets about 5 ms, fluid films 15 ms), above ``MIN_STATE_S``; a rotor on linear
    bearings (0.4 ms a state) has nothing to hide its modes behind, and two threads contending for
    the interpreter would cost more than they save (its speeds then go to the cores in runs)."""

    MIN_STATE_S = 2e-3

    def __init__(self, points, n_modes: int):
        self.rotor, self.shaft, self.n_modes = points.rotor, points.shaft, n_modes
        self.basis = None
        self._prefetch: ModalPrefetch | None = None
        self._first: list = []  # the first state, held until the second tells how long a state takes
        self._decided = False

    def add(self, state, rpm: float) -> None:
        if not self._decided:
            if not self._first:
                self._first = [(state, rpm), time.perf_counter()]
                return
            self._decided = True
            (first, first_rpm), t0 = self._first
            self._first = []
            if time.perf_counter() - t0 < self.MIN_STATE_S:
                return
            self.basis = first_basis(self.rotor, self.shaft, first, self.n_modes)
            if self.basis is None:
                return
            b, r = self.basis, self.rotor
            self._prefetch = ModalPrefetch(
                lambda st, s: modal_from_matrices(b.system(st), r.dofs, r.node_z_m, self.n_modes, s, b.T))
            self._prefetch.add(first, first_rpm)
        if self._prefetch is not None:
            self._prefetch.add(state, rpm)

    def finish(self) -> list | None:
        """Every state's modes on the guessed basis (this thread helps with the last ones), or None."""
        if self._prefetch is None:
            return None
        out = self._prefetch.finish()
        self._prefetch = None
        return out

    def cancel(self) -> None:
        if self._prefetch is not None:
            self._prefetch.cancel()
            self._prefetch = None
