"""Fixed steps that land on the output grid and on the Poincare instants (exact stepping).

The step h is chosen so that the output interval 1/fs is a whole number of steps and, when the
run has a primary period 1/f_p (the roller pass, or the revolution), so that the period is a
whole number of output intervals:

    1/f_p = M / fs,   1/fs = s h,   h <= h_max

Every sample and every Poincare point of that period then falls on a step: no interpolation
(issue 4: "exact stepping").
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

from .result import Plan
from .steadiness import first_order_matrix


def plan_steps(duration_s: float, max_step_s: float, sample_rate_hz: float, pass_frequency_hz: float
               ) -> tuple[Plan, int]:
    """(plan, M): the largest h <= max_step_s that lands on every sample and Poincare instant.

    The sample rate is rounded to a whole number M of samples per period (at least one), so the
    actual rate can differ from the request by up to f_p/2; M = 0 when there is no period.
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
    return Plan(step_s=dt / s, steps_per_sample=s, n_samples=n), M


def stability_step_s(M: np.ndarray, K: np.ndarray, C: np.ndarray, margin: float = 2.0) -> float:
    """h = margin / rho(A) for x' = A x, A = [[0, I], [-M^-1 K, -M^-1 C]] (the tangent system).

    Classical RK4 is stable for h |lambda| up to 2.83 on the imaginary axis and 2.79 on the
    negative real axis (Hairer and Wanner, Solving ODEs II, sec. IV.2); margin 2 keeps a lightly
    damped stiff mode at |R| about 0.75 per step.
    """
    rho = float(np.max(np.abs(np.linalg.eigvals(first_order_matrix(M, K, C)))))
    return margin / rho if rho > 0 else np.inf

