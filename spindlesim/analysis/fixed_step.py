"""Fixed-step RK4 with exact stepping onto the output grid and the Poincare instants.

The step h is chosen so that the output interval 1/fs is a whole number of
steps and, when the system has a roller-pass frequency f_rp, so that the
varying-compliance period 1/f_rp is a whole number of output intervals:

    1/f_rp = M / fs,   1/fs = s h,   h <= h_max

Every sample and every Poincare point then falls on a step: no interpolation
(issue 4: "exact stepping").  ``Stepper`` is the signature of the compiled
loops in ``bearings/rolling/*_kernel.py``; ``python_rk4`` gives the same for any
``rhs(t, y)`` (tests, and models without a compiled kernel).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

#: stepper(y, t0, h, n_steps, every, samples) -> (rows written, status 0 ok / 1 non-finite); y advanced in place
Stepper = Callable[[np.ndarray, float, float, int, int, np.ndarray], tuple[int, int]]


@dataclass(frozen=True)
class StepPlan:
    step_s: float  # h
    steps_per_sample: int  # s
    samples_per_pass: int  # M (0 when there is no roller-pass period)
    n_samples: int  # samples after t = 0 (the initial state is sample 0 besides)

    @property
    def sample_interval_s(self) -> float:
        return self.step_s * self.steps_per_sample

    @property
    def sample_rate_hz(self) -> float:
        return 1.0 / self.sample_interval_s


def plan_steps(duration_s: float, max_step_s: float, sample_rate_hz: float, pass_frequency_hz: float) -> StepPlan:
    """Largest h <= max_step_s that lands on every sample and Poincare instant (module note).

    The sample rate is rounded to a whole number M of samples per roller pass
    (at least one), so the actual rate can differ from the request by up to f_rp/2.
    """
    if not (max_step_s > 0 and sample_rate_hz > 0 and duration_s > 0):
        raise ValueError("step, sample rate and duration must be positive")
    if pass_frequency_hz > 0:
        M = max(1, round(sample_rate_hz / pass_frequency_hz))
        dt = 1.0 / (M * pass_frequency_hz)
    else:
        M, dt = 0, 1.0 / sample_rate_hz
    s = max(1, math.ceil(dt / max_step_s * (1.0 - 1e-12)))
    n = int(math.floor(duration_s / dt + 1e-9))
    return StepPlan(step_s=dt / s, steps_per_sample=s, samples_per_pass=M, n_samples=n)


def python_rk4(rhs: Callable[[float, np.ndarray], np.ndarray]) -> Stepper:
    """Classical RK4 (Kutta 1901) in Python for any rhs(t, y); same contract as the compiled loops."""

    def stepper(y: np.ndarray, t0: float, h: float, n_steps: int, every: int, samples: np.ndarray) -> tuple[int, int]:
        row = 0
        for i in range(n_steps):
            t = t0 + i * h
            k1 = rhs(t, y)
            k2 = rhs(t + 0.5 * h, y + 0.5 * h * k1)
            k3 = rhs(t + 0.5 * h, y + 0.5 * h * k2)
            k4 = rhs(t + h, y + h * k3)
            y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
            if (i + 1) % every == 0:
                samples[row] = y
                row += 1
                if not np.all(np.isfinite(y)):
                    return row, 1
        return row, 0

    return stepper


def stability_step_s(rhs: Callable[[float, np.ndarray], np.ndarray], y: np.ndarray, scale: np.ndarray,
                     t: float = 0.0, margin: float = 2.0) -> float:
    """h = margin / rho(J), rho the spectral radius of the Jacobian of rhs at (t, y).

    Classical RK4 is stable for h |lambda| up to 2.83 on the imaginary axis and
    2.79 on the negative real axis (Hairer and Wanner, Solving ODEs II, sec. IV.2);
    margin 2 keeps a lightly damped stiff mode at |R| about 0.75 per step.  J by
    central differences with steps scale * 1e-4.
    """
    n = y.size
    J = np.empty((n, n))
    d = np.asarray(scale, float) * 1e-4
    for k in range(n):
        e = np.zeros(n)
        e[k] = d[k]
        J[:, k] = (rhs(t, y + e) - rhs(t, y - e)) / (2.0 * d[k])
    rho = float(np.max(np.abs(np.linalg.eigvals(J))))
    return margin / rho if rho > 0 else np.inf
