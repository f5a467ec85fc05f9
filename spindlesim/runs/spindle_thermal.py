"""``spindlesim thermal`` on a spindle with a ``spindle_thermal:`` section (ball bearings, motor, housing).

At each speed of ``spindle_thermal.speeds_rpm`` (default: the operating speed), from the lowest up, the
spindle's thermal equilibrium (``analysis.spindle_thermal``): heat per source, every network node's
temperature, each bearing's operating preload (row thrust), contact angles, stiffness and axial offset,
the tool tip's axial drift.  A speed at which the arrangement runs away ends the list: it is the speed
limit of that arrangement, written into the file and the summary (not a failure of the run).  With
``warm_up``: the same quantities through the speed steps in time from the cold spindle, with the first
natural frequencies of the rotor at each instant and, with a ``chatter:`` section whose FRF comes from the
rotor, the minimum stable depth of cut (``analysis.warm_up_chatter``).  thermal.h5 (group /spindle_thermal) and PNGs.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np

log = logging.getLogger(__name__)

#: natural frequencies reported through a warm-up
WARM_UP_MODES = 4


def run(loaded: Any, outdir: Path, run_info: Any, options: dict | None = None, progress=None) -> list[Path]:
    from ..analysis.modal import modal_from_matrices
    from ..analysis.spindle_thermal import ThermalRunawayError, speed_limit
    from ..deck import require_rotor
    from ..output.drawing import draw
    from ..output.thermal_plots import speeds_figure, warm_up_figure
    from ..output.thermal_writer import SpeedSeries, WarmUpSeries, tabulate, write_spindle_thermal
    from .common import operating_points

    require_rotor(loaded, "thermal")
    opts = options or {}
    d = loaded.deck
    points = operating_points(loaded)
    from ..analysis.points import OperatingPoints
    from ..model.thermal import build_spindle_thermal

    model = build_spindle_thermal(d, points.rotor)
    if points.thermal is None or model.analyses != "steady":  # the equilibria the command lists: a model of its own
        import dataclasses

        points = OperatingPoints(points.rotor, dataclasses.replace(model, analyses="steady"))
    speeds = [float(opts["speed_rpm"])] if opts.get("speed_rpm") is not None else \
        sorted(model.speeds_rpm) or [float(d.operating.speed_rpm)]
    states, runaway = [], None
    for k, rpm in enumerate(speeds):
        try:
            states.append(points.thermal_state(rpm))
        except ThermalRunawayError as exc:
            runaway = (rpm, str(exc))
            log.warning("%s", exc)
            break
        if progress is not None:
            progress(k + 1, len(speeds) + (1 if model.warm_up is not None else 0))
    limit = None
    if runaway is not None and states:  # the speed limit of the arrangement, to 2 %
        limit = speed_limit(points.thermal, states[-1], runaway[0])
        log.info("thermal speed limit between %.0f and %.0f rpm", *limit)
    warm, missing = None, []
    if model.warm_up is not None:
        w = model.warm_up
        try:
            instants = points.thermal.warm_up(w.times_s, w.speeds_rpm, w.duration_s, w.samples)
        except ThermalRunawayError as exc:
            runaway = runaway or (float("nan"), f"warm-up: {exc}")
            instants = ()
        freqs = []
        r = points.rotor
        for ts in instants:
            f = np.full(WARM_UP_MODES, np.nan)
            try:
                m = modal_from_matrices(points.system(ts.operating), r.dofs, r.node_z_m, WARM_UP_MODES, ts.speed_rpm)
                f[:len(m.frequency_hz)] = m.frequency_hz
            except (np.linalg.LinAlgError, ArithmeticError, ValueError) as exc:
                missing.append(f"warm-up natural frequencies at {ts.time_s / 60.0:.1f} min ({ts.speed_rpm:g} rpm) "
                               f"failed: {exc}")
            freqs.append(f)
        if instants:
            depth = None
            try:
                depth = _minimum_depth(loaded, points, instants)
            except (np.linalg.LinAlgError, ArithmeticError, ValueError) as exc:
                missing.append(f"warm-up minimum stable depth of cut failed: {exc}")
            if depth is not None:
                missing.extend(f"warm-up minimum stable depth of cut: {m}" for m in depth.failures)
            warm = WarmUpSeries(instants, np.array(freqs), depth)
    series = SpeedSeries(tuple(states), runaway, limit)
    if missing:  # a part of the analysis failed: what was computed is written, marked incomplete
        import dataclasses

        for m in missing:
            log.warning("%s", m)
        run_info = dataclasses.replace(run_info, complete=False, incomplete_reason="; ".join(missing))
    paths = [write_spindle_thermal(outdir / "thermal.h5", run_info, model, series, warm)]
    if states:
        table = tabulate(states, model.bearings, runaway_rpm=runaway[0] if runaway else None, limit_rpm=limit)
        paths.append(draw(outdir / "thermal_speeds.png", speeds_figure, table, d.title))
    if warm is not None:
        table = tabulate(warm.states, model.bearings, frequency_hz=warm.frequency_hz, in_time=True,
                         min_depth_m=None if warm.minimum_depth is None else warm.minimum_depth.depth_m)
        paths.append(draw(outdir / "thermal_warm_up.png", warm_up_figure, table, d.title))
    if missing:
        from .status import IncompleteRun

        raise IncompleteRun(f"thermal: {len(missing)} part(s) not computed: {missing[0]}", paths)
    return paths


def _minimum_depth(loaded, points, instants):
    """The minimum stable depth through the warm-up when the deck's chatter section takes its FRF from the
    rotor (a measured or modal FRF does not change with the spindle's temperatures), else None."""
    d = loaded.deck
    if getattr(d, "chatter", None) is None:
        return None
    from ..analysis.warm_up_chatter import minimum_depth_through
    from ..chatter import build_chatter

    base = Path(loaded.source).parent if not loaded.source.startswith("<") else Path.cwd()
    spec = build_chatter(d.chatter, base)
    if spec.frf_source != "rotor":
        return None
    return minimum_depth_through(points, instants, spec.process, spec.speeds_rpm)
