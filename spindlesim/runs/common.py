"""Small helpers the runs share."""

from __future__ import annotations

import numpy as np


def plots_wanted(opts: dict) -> bool:
    """PNGs unless options say ``plots: False`` (sweeps skip per-case plots by default)."""
    return bool(opts.get("plots", True))


def first(*values):
    """The first value that is not None (0 is a valid speed)."""
    return next((v for v in values if v is not None), None)


def value_range(r) -> np.ndarray:
    """A deck range {start, stop, count} or an explicit list, as an array."""
    if isinstance(r, (list, tuple, np.ndarray)):
        return np.asarray(r, float)
    return np.linspace(r.start, r.stop, r.count)
