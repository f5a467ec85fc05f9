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


class RunContext:
    """One deck's runs: the loaded deck (its attributes read through: ``deck``, ``text``, ``source``, ``issue``
    ...) and what its analyses share, each built once on first use: the rotor at its operating points and the
    spindle's thermal speed limit.  ``run_analysis`` makes one per call; ``spindlesim run`` makes one for all
    its analyses, so they share the shaft's assembly and every static state."""

    def __init__(self, loaded):
        self.loaded = loaded
        self._points = None
        self._limit: tuple | None = None  # (value,) once known

    def __getattr__(self, name):  # the loaded deck's attributes
        return getattr(self.loaded, name)

    @property
    def points(self):
        """The deck's rotor at its operating points (:class:`~spindlesim.analysis.points.OperatingPoints`): the
        shaft assembled once, each static state solved once; with ``spindle_thermal: {analyses: steady}`` each at
        the spindle's thermal equilibrium of its speed."""
        if self._points is None:
            from ..analysis.points import OperatingPoints
            from ..model.build import build_rotor
            from ..model.thermal import build_spindle_thermal

            rotor = build_rotor(self.loaded.deck)
            model = build_spindle_thermal(self.loaded.deck, rotor)
            self._points = OperatingPoints(rotor, model if model is not None and model.analyses != "none" else None)
        return self._points

    def thermal_speed_limit(self) -> tuple[float, float] | None:
        """:func:`thermal_speed_limit` of the deck, solved once."""
        if self._limit is None:
            self._limit = (_solve_limit(self),)
        return self._limit[0]

    def remember_thermal_speed_limit(self, limit) -> None:
        self._limit = (limit,)


def context_of(loaded) -> RunContext:
    """``loaded`` itself when it is a run's context, else a context of its own (nothing shared)."""
    return loaded if isinstance(loaded, RunContext) else RunContext(loaded)


def operating_points(loaded):
    """The deck's rotor at its operating points, shared by the analyses of one run context (:class:`RunContext`);
    a plain loaded deck gets operating points of its own."""
    return context_of(loaded).points


def thermal_speed_limit(loaded) -> tuple[float, float] | None:
    """The spindle's thermal speed limit (highest speed found stable, lowest running away) [rpm] when the deck has
    a ``spindle_thermal`` section and a speed of its list runs away; None otherwise.  Solved once per run context
    (the equilibria from the lowest speed of ``spindle_thermal.speeds_rpm`` up, bisected to 2 %: the ``thermal``
    command's number), for the analyses that shade the speeds above it and never recommend them."""
    return context_of(loaded).thermal_speed_limit() if isinstance(loaded, RunContext) else _solve_limit(
        RunContext(loaded))


def thermal_speed_limit_aside(loaded):
    """:func:`thermal_speed_limit` computed in a forked process while the caller goes on
    (:class:`~spindlesim.analysis.aside.Aside`; ``result()`` waits for it and keeps it in the run context), or
    at once where it is known already or the deck has no ``spindle_thermal`` section."""
    from ..analysis.aside import Aside, Known, Then

    ctx = context_of(loaded)
    if getattr(ctx.loaded.deck, "spindle_thermal", None) is None or ctx._limit is not None:
        return Known(thermal_speed_limit(loaded))

    def kept(limit):
        ctx.remember_thermal_speed_limit(limit)
        return limit

    return Then(Aside(_solve_limit, ctx), kept)


def _solve_limit(ctx: RunContext) -> tuple[float, float] | None:
    d = ctx.loaded.deck
    if getattr(d, "spindle_thermal", None) is None:
        return None
    import dataclasses

    from ..analysis.points import OperatingPoints
    from ..analysis.thermal_study import thermal_study
    from ..model.thermal import build_spindle_thermal

    points = ctx.points
    model = build_spindle_thermal(d, points.rotor)
    steady = OperatingPoints(points.rotor, dataclasses.replace(model, analyses="steady"), shaft=points.shaft)
    speeds = sorted(model.speeds_rpm) or [float(d.operating.speed_rpm)]
    study = thermal_study(steady, speeds, quiet=True)
    if study.interrupted:
        raise KeyboardInterrupt
    return study.limit_rpm


def remember_thermal_speed_limit(loaded, limit: tuple[float, float] | None) -> None:
    """The ``thermal`` run's speed limit (the same equilibria :func:`thermal_speed_limit` solves), kept for the
    analyses of the same run context that shade the speeds above it."""
    if isinstance(loaded, RunContext):
        loaded.remember_thermal_speed_limit(limit)


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
