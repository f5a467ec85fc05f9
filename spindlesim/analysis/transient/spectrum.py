"""Windowed amplitude spectrum and Poincare sampling of a transient response.

Spectrum: the steady part of a uniformly sampled signal, mean removed, times
a Hann window; single-sided amplitude 2 |X_k| / sum(w) so that a sinusoid of
amplitude A that falls on a bin reads A (coherent-gain correction; Harris,
Proc. IEEE 66, 1978).  Bin spacing is fs / n.

Poincare map: the state sampled once per forcing period.  For a bearing with N
rolling elements the varying compliance repeats every 1/(N f_cage) (seed 000
section 5; Harsha and Kankar 2004), so the samples are t_k = t_0 + k/(N f_cage),
taken from the integrator's dense output rather than from the stored grid.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Spectrum:
    frequency_hz: np.ndarray  # [f]
    amplitude: np.ndarray  # [f, channels], same unit as the signal

    @property
    def resolution_hz(self) -> float:
        return float(self.frequency_hz[1] - self.frequency_hz[0]) if self.frequency_hz.size > 1 else float("nan")

    def dominant_frequency_hz(self, channel: int, fmin_hz: float = 0.0) -> float:
        """Frequency of the largest line at or above fmin_hz in one channel."""
        sel = self.frequency_hz >= fmin_hz
        i = int(np.argmax(np.where(sel, self.amplitude[:, channel], -np.inf)))
        return float(self.frequency_hz[i])


def amplitude_spectrum(signal: np.ndarray, sample_rate_hz: float) -> Spectrum:
    """Hann-windowed single-sided amplitude spectrum of signal [t, channels] (or [t])."""
    x = np.asarray(signal, dtype=float)
    if x.ndim == 1:
        x = x[:, None]
    n = x.shape[0]
    if n < 4:
        return Spectrum(np.zeros(0), np.zeros((0, x.shape[1])))
    w = 0.5 - 0.5 * np.cos(2.0 * np.pi * np.arange(n) / n)  # periodic Hann
    xw = (x - x.mean(axis=0)) * w[:, None]
    X = np.fft.rfft(xw, axis=0)
    amp = 2.0 * np.abs(X) / w.sum()
    amp[0] *= 0.5
    freq = np.fft.rfftfreq(n, d=1.0 / sample_rate_hz)
    return Spectrum(frequency_hz=freq, amplitude=amp)


def poincare_times(t_start: float, t_end: float, period_s: float, t_origin: float = 0.0) -> np.ndarray:
    """Sampling instants t_origin + k period in [t_start, t_end]."""
    k0 = int(np.ceil((t_start - t_origin) / period_s - 1e-9))
    k1 = int(np.floor((t_end - t_origin) / period_s + 1e-9))
    return t_origin + period_s * np.arange(k0, k1 + 1)


def poincare_spread(points: np.ndarray) -> float:
    """Largest distance of Poincare points [k, d] from their mean (0 for a period-1 orbit)."""
    p = np.asarray(points, dtype=float)
    if p.shape[0] == 0:
        return float("nan")
    return float(np.max(np.linalg.norm(p - p.mean(axis=0), axis=1)))


def distinct_points(points: np.ndarray, tol: float) -> int:
    """Number of clusters of Poincare points closer than tol (period-k detection)."""
    reps: list[np.ndarray] = []
    for p in np.asarray(points, dtype=float):
        if not any(np.linalg.norm(p - r) <= tol for r in reps):
            reps.append(p)
    return len(reps)
