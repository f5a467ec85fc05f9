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


_LIMITS: dict[int, tuple] = {}


def thermal_speed_limit(loaded) -> tuple[float, float] | None:
    """The spindle's thermal speed limit (highest speed found stable, lowest running away) [rpm] when the deck has
    a ``spindle_thermal`` section and a speed of its list runs away; None otherwise.  Solved once per deck (the
    equilibria from the lowest speed of ``spindle_thermal.speeds_rpm`` up, bisected to 2 %: the ``thermal``
    command's number), for the analyses that shade the speeds above it and never recommend them."""
    d = loaded.deck
    if getattr(d, "spindle_thermal", None) is None:
        return None
    got = _LIMITS.get(id(loaded))
    if got is None or got[0] is not loaded:
        import dataclasses

        from ..analysis.points import OperatingPoints
        from ..analysis.thermal_study import thermal_study
        from ..model.thermal import build_spindle_thermal

        points = operating_points(loaded)
        model = build_spindle_thermal(d, points.rotor)
        steady = OperatingPoints(points.rotor, dataclasses.replace(model, analyses="steady"), shaft=points.shaft)
        speeds = sorted(model.speeds_rpm) or [float(d.operating.speed_rpm)]
        study = thermal_study(steady, speeds, quiet=True)
        if study.interrupted:
            raise KeyboardInterrupt
        remember_thermal_speed_limit(loaded, study.limit_rpm)
        got = _LIMITS[id(loaded)]
    return got[1]


def remember_thermal_speed_limit(loaded, limit: tuple[float, float] | None) -> None:
    """The ``thermal`` run's speed limit (the same equilibria :func:`thermal_speed_limit` solves), kept for the
    analyses of the same run that shade the speeds above it."""
    _LIMITS.clear()
    _LIMITS[id(loaded)] = (loaded, limit)


def measurement_run_info(paths, command_line: str | None = None):
    """The provenance of a run on measurement files (``fitmodes``, ``impact``): their text as the "deck" (each
    file's name and SHA-256 first; a binary file by its digest alone), their paths as its source."""
    import hashlib
    from pathlib import Path

    from ..output.hdf5 import RunInfo

    parts, digest = [], hashlib.sha256()
    for p in map(Path, paths):
        raw = p.read_bytes()
        digest.update(raw)
        own = hashlib.sha256(raw).hexdigest()
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            text = f"(binary, {len(raw)} bytes)\n"
        parts.append(f"# ===== {p.name} (sha256 {own}) =====\n{text}")
    kw = {} if command_line is None else {"command_line": command_line}
    return RunInfo(deck_text="".join(parts), deck_source=", ".join(str(p) for p in paths),
                   deck_sha256=digest.hexdigest(), **kw)
