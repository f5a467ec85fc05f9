"""The band of a measured FRF worth fitting: where its coherence says the measurement holds."""

from __future__ import annotations

import numpy as np

__all__ = ["coherent_band", "COHERENCE_LEVEL", "COHERENCE_WINDOW"]

#: the coherence the band's samples reach (as a running median)
COHERENCE_LEVEL = 0.9
#: samples of the running median: a narrow dip (an antiresonance) inside the band does not split it
COHERENCE_WINDOW = 21


def coherent_band(frequency_hz: np.ndarray, coherence: np.ndarray, level: float = COHERENCE_LEVEL,
                  window: int = COHERENCE_WINDOW) -> tuple[float, float] | None:
    """(low, high) [Hz]: from the lowest to the highest frequency above 0 where the running median of the
    coherence over ``window`` samples is at least ``level``; None when no sample is (or no coherence is
    known).  An impact test's receptance at low frequencies, where the accelerometer's noise is divided
    by w^2, is left out this way."""
    f = np.asarray(frequency_hz, float)
    c = np.asarray(coherence, float)
    keep = (f > 0) & np.isfinite(c)
    if np.count_nonzero(keep) < 2:
        return None
    f, c = f[keep], c[keep]
    half = max(0, min(window, len(c)) // 2)
    padded = np.pad(c, half, mode="edge")
    med = np.median(np.lib.stride_tricks.sliding_window_view(padded, 2 * half + 1), axis=1)
    good = np.flatnonzero(med >= level)
    if len(good) < 2:
        return None
    return float(f[good[0]]), float(f[good[-1]])
