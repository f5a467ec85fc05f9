"""Pieces of the classical RK4 step shared by the compiled model loops (numba).

numba cannot cache a loop that receives the right-hand side as an argument, so
each model has its own short loop (``rigid_race_kernel.rk4``,
``flexible_race_kernel.rk4``); the arithmetic they share lives here.

    y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4)     (Kutta 1901)
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, inline="always")
def stage(y, c, k, out):
    """out = y + c k (the argument of the next stage)."""
    for a in range(y.size):
        out[a] = y[a] + c * k[a]


@njit(cache=True, inline="always")
def advance(y, h, k1, k2, k3, k4):
    """y += h/6 (k1 + 2 k2 + 2 k3 + k4), in place."""
    for a in range(y.size):
        y[a] += h / 6.0 * (k1[a] + 2.0 * k2[a] + 2.0 * k3[a] + k4[a])


@njit(cache=True, inline="always")
def store(samples, row, y):
    """samples[row] = y; True if every entry is finite."""
    finite = True
    for a in range(y.size):
        samples[row, a] = y[a]
        finite = finite and np.isfinite(y[a])
    return finite
