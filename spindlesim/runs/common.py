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


_POINTS: dict[int, tuple] = {}


def operating_points(loaded):
    """The deck's rotor at its operating points (:class:`~spindlesim.analysis.points.OperatingPoints`),
    shared by every analysis of one run: the shaft assembled once, each static state solved once; with
    ``spindle_thermal: {analyses: steady}`` each at the spindle's thermal equilibrium of its speed.  One
    deck is kept at a time (a run or a sweep case reads one)."""
    got = _POINTS.get(id(loaded))
    if got is None or got[0] is not loaded:
        from ..analysis.points import OperatingPoints
        from ..model.build import build_rotor
        from ..model.thermal import build_spindle_thermal

        _POINTS.clear()
        rotor = build_rotor(loaded.deck)
        model = build_spindle_thermal(loaded.deck, rotor)
        thermal = model if model is not None and model.analyses != "none" else None
        got = (loaded, OperatingPoints(rotor, thermal))
        _POINTS[id(loaded)] = got
    return got[1]
