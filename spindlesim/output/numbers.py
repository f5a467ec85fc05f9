"""Numbers as an engineer reads them: no round-off noise, no digits finer than the result resolves.

* :func:`clean` sets to 0 what lies below the solution's noise, judged against the largest value of the
  same quantity (a bearing reaction of 3e-14 N beside one of 1.5 N is the solver's round-off, not a force);
* :func:`g` formats like ``f"{v:.4g}"`` but never prints ``-0``;
* :func:`with_resolution` prints a value measured to +- ``half_width`` (an FFT line: half a bin) with the
  uncertainty to one significant digit (two when it starts with 1) and the value to the same decimal.
"""

from __future__ import annotations

import math

import numpy as np

#: relative to the largest value of a quantity, what a double-precision solve of a rotor model cannot
#: resolve (round-off times the stiffness matrix's condition); anything smaller is printed as 0
NOISE = 1e-9


def clean(values, reference: float | None = None, rel: float = NOISE) -> np.ndarray:
    """``values`` (float array) with every entry at or below ``rel`` x ``reference`` set to +0;
    ``reference`` defaults to the largest magnitude among ``values``."""
    v = np.asarray(values, float)
    ref = float(np.max(np.abs(v), initial=0.0)) if reference is None else abs(float(reference))
    return np.where(np.abs(v) <= rel * ref, 0.0, v) + 0.0  # + 0.0: -0 becomes +0


def g(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant digits, 0 for a negative zero."""
    return f"{float(value) + 0.0:.{digits}g}"


def with_resolution(value: float, half_width: float, unit: str = "") -> str:
    """``value +/- half_width`` with as many decimals as ``half_width`` supports (``266.68 +/- 2.78``
    reads ``267 +/- 3``)."""
    u = abs(float(half_width))
    if not (math.isfinite(u) and u > 0):
        return f"{value:.5g}" + (f" {unit}" if unit else "")
    decimals = -math.floor(math.log10(u))
    if round(u, decimals) >= 10.0 ** -decimals * 10:  # 9.7 rounds up to 10: one decimal fewer
        decimals -= 1
    if f"{round(u, decimals):.{max(decimals, 0)}f}".lstrip("0.").startswith("1"):
        decimals += 1  # a leading 1 keeps a second digit (+/- 0.14, not +/- 0.1)
    v, w = round(float(value), decimals), round(u, decimals)
    d = max(decimals, 0)
    return f"{v:.{d}f} +/- {w:.{d}f}" + (f" {unit}" if unit else "")
