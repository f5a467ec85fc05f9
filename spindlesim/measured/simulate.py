"""Simulated impacts of a tap test (a virtual hammer and accelerometer on a known receptance): for the
tests, the validation and the example files of decks/taptest/, never taken for a measurement.

The hammer's force is a half-sine pulse; the response is the inverse FFT of H(f) (j w)^p F(f) on a grid
``pad`` times longer than the record (so that the slowly decaying modes do not wrap around), cut to the
record; noise is normal and white on both channels, its RMS a share of the channel's peak.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from .results import ImpactRecord

__all__ = ["hammer_pulse", "simulate_impact", "simulate_impacts"]

_POWER = {"displacement": 0, "velocity": 1, "acceleration": 2}


def hammer_pulse(t: np.ndarray, at_s: float, width_s: float, peak_N: float) -> np.ndarray:
    """A half-sine force pulse of ``width_s`` starting at ``at_s`` [N]."""
    x = (t - at_s) / width_s
    return np.where((x >= 0) & (x <= 1), peak_N * np.sin(np.pi * np.clip(x, 0, 1)), 0.0)


def simulate_impact(receptance: Callable[[np.ndarray], np.ndarray], rate_hz: float, samples: int, *,
                    kind: str = "acceleration", at_s: float = 0.005, width_s: float = 3e-4, peak_N: float = 500.0,
                    second_hit: tuple[float, float] | None = None, force_noise: float = 0.0,
                    response_noise: float = 0.0, clip_share: float | None = None, pad: int = 8,
                    rng: np.random.Generator | None = None, where: str = "simulated") -> ImpactRecord:
    """One impact on the structure of ``receptance(f_hz) -> H [m/N]``.  ``second_hit``: (delay [s], share of
    the first pulse's peak) of a double hit; noises: RMS shares of each channel's peak; ``clip_share``: the
    response clipped at that share of its peak (an overload)."""
    rng = rng if rng is not None else np.random.default_rng()
    dt = 1.0 / rate_hz
    m = pad * samples
    t = dt * np.arange(m)
    force = hammer_pulse(t, at_s, width_s, peak_N)
    if second_hit is not None:
        force = force + hammer_pulse(t, at_s + second_hit[0], width_s, second_hit[1] * peak_N)
    f = np.fft.rfftfreq(m, dt)
    with np.errstate(divide="ignore", invalid="ignore"):
        h = np.asarray(receptance(f), complex)  # the static compliance too: a displacement keeps its offset
    h[~np.isfinite(h)] = 0.0
    response = np.fft.irfft(np.fft.rfft(force) * h * (2j * np.pi * f) ** _POWER[kind], n=m)[:samples]
    force = force[:samples]
    peak = np.max(np.abs(response))
    force = force + force_noise * np.max(np.abs(force)) * rng.standard_normal(samples)
    response = response + response_noise * peak * rng.standard_normal(samples)
    if clip_share is not None:  # the converter's full scale: noise and all are clipped
        response = np.clip(response, -clip_share * peak, clip_share * peak)
    return ImpactRecord(force, response, kind, dt, where)


def simulate_impacts(receptance: Callable[[np.ndarray], np.ndarray], rate_hz: float, samples: int, count: int,
                     *, seed: int = 0, double_hit: int | None = None, overload: int | None = None,
                     **kwargs) -> list[ImpactRecord]:
    """``count`` impacts (peak force varied +-20 %), the impact numbered ``double_hit`` (1-based) with a second
    hit 1.5 ms after the first at 40 % of its force, ``overload`` with its response clipped at 70 %."""
    rng = np.random.default_rng(seed)
    peak = kwargs.pop("peak_N", 500.0)
    out = []
    for k in range(1, count + 1):
        out.append(simulate_impact(receptance, rate_hz, samples, peak_N=peak * (1 + 0.2 * rng.uniform(-1, 1)),
                                   second_hit=(1.5e-3, 0.4) if k == double_hit else None,
                                   clip_share=0.7 if k == overload else None, rng=rng,
                                   where=f"simulated impact {k}", **kwargs))
    return out
