"""Campbell diagram: damped modes over a speed range, tracked between speeds by MAC.

Mode tracking: the modal assurance criterion between complex mode shapes,
MAC(a, b) = |a^H b|^2 / ((a^H a)(b^H b)), weighted by frequency proximity, is
maximised over assignments (Hungarian algorithm, scipy.optimize.linear_sum_assignment).
A critical speed is where the 1x line f = N/60 crosses a forward-whirl mode whose
amplification factor AF = 1/(2 zeta) is at least 2.5 (API 684: a crossing with
AF < 2.5 is critically damped and not a critical speed).
"""

from __future__ import annotations

import logging
from typing import Callable

import numpy as np
from scipy.optimize import linear_sum_assignment

from ..fe.assembly import assemble_shaft
from ..model.rotor import Rotor
from .modal import modal_from_matrices
from .operating import system_matrices
from .results import CampbellResult

log = logging.getLogger(__name__)


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """MAC matrix between mode sets a [m, n] and b [k, n] (complex)."""
    num = np.abs(a.conj() @ b.T) ** 2
    den = np.outer(np.sum(np.abs(a) ** 2, axis=1), np.sum(np.abs(b) ** 2, axis=1))
    return num / den


def solve_campbell(rotor: Rotor, speeds_rpm: np.ndarray, n_modes: int = 8,
                   progress: Callable[[int, int], None] | None = None) -> CampbellResult:
    speeds = np.asarray(speeds_rpm, float)
    shaft = assemble_shaft(rotor)
    n_track = n_modes
    extra = max(4, n_modes // 2)  # spare modes so a mode leaving the window can be replaced
    freq = np.full((len(speeds), n_track), np.nan)
    zeta = np.full_like(freq, np.nan)
    logdec = np.full_like(freq, np.nan)
    whirl = np.full(freq.shape, "", dtype=object)
    prev_shapes = None
    prev_freq = None
    for i, (s, m) in enumerate(zip(speeds, _modal_at_speeds(rotor, shaft, speeds, n_modes + extra))):
        shapes = m.mode_shape.reshape(len(m.frequency_hz), -1)
        if prev_shapes is None:
            take = np.arange(min(n_track, len(m.frequency_hz)))
            cols = take
        else:
            M = mac(prev_shapes, shapes)
            rel = np.abs(prev_freq[:, None] - m.frequency_hz[None, :]) / np.maximum(prev_freq[:, None], 1e-12)
            cost = -(M - 0.5 * np.minimum(rel, 1.0))
            rows_, cols_ = linear_sum_assignment(cost)
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
        valid = cols >= 0
        prev_shapes = shapes[cols[valid]] if prev_shapes is not None else shapes[: len(take)]
        prev_freq = m.frequency_hz[cols[valid]] if prev_freq is not None else m.frequency_hz[: len(take)]
        if progress is not None:
            progress(i + 1, len(speeds))
    crit, crit_mode = critical_speeds(speeds, freq, whirl, zeta)
    return CampbellResult(speed_rpm=speeds, frequency_hz=freq, log_dec=logdec, damping_ratio=zeta,
                          whirl=whirl.astype(str), critical_speeds_rpm=crit, critical_modes=crit_mode)


API684_MIN_AF = 2.5


def _modal_at_speeds(rotor: Rotor, shaft, speeds: np.ndarray, n_modes: int):
    """Modal results at every speed, computed on all cores (LAPACK releases the GIL; each thread
    uses single-threaded BLAS), yielded in speed order for the sequential mode tracking."""
    import os
    from concurrent.futures import ThreadPoolExecutor

    def one(s: float):
        sysm = system_matrices(rotor, s, shaft=shaft)
        return modal_from_matrices(sysm, rotor.dofs, rotor.node_z_m, n_modes, s)

    workers = min(len(speeds), os.cpu_count() or 1)
    if workers <= 1:
        yield from (one(s) for s in speeds)
        return
    with ThreadPoolExecutor(max_workers=workers) as ex:
        yield from ex.map(one, speeds)


def critical_speeds(speeds_rpm: np.ndarray, freq_hz: np.ndarray, whirl: np.ndarray,
                    damping_ratio: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Speeds where the 1x excitation line crosses a forward mode with AF = 1/(2 zeta) >= 2.5
    (linear interpolation between the speeds of the sweep)."""
    out, modes = [], []
    g = freq_hz - speeds_rpm[:, None] / 60.0
    for k in range(freq_hz.shape[1]):
        for i in range(len(speeds_rpm) - 1):
            a, b = g[i, k], g[i + 1, k]
            if not (np.isfinite(a) and np.isfinite(b)) or a * b > 0 or a == b:
                continue
            if "forward" not in (whirl[i, k], whirl[i + 1, k]):
                continue
            t = a / (a - b)
            if damping_ratio is not None:
                z = damping_ratio[i, k] + t * (damping_ratio[i + 1, k] - damping_ratio[i, k])
                if z > 0 and 1.0 / (2.0 * z) < API684_MIN_AF:
                    continue
            out.append(speeds_rpm[i] + t * (speeds_rpm[i + 1] - speeds_rpm[i]))
            modes.append(k)
    order = np.argsort(out)
    return np.asarray(out, float)[order], np.asarray(modes, int)[order]
