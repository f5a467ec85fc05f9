"""The ``spindle_thermal`` analysis (a spindle's thermal model: rolling bearings, motor, housing), registered on its
own and run by ``spindlesim thermal`` on a deck with a ``spindle_thermal:`` section (its file is the command's,
thermal.h5; spindlesim/registry.py).

At each speed of ``spindle_thermal.speeds_rpm`` (default: the operating speed), from the lowest up, the
spindle's thermal equilibrium (``analysis.spindle_thermal``): heat per source, every network node's
temperature, each bearing's operating preload (row thrust), contact angles, stiffness and axial offset,
the tool tip's axial drift.  A speed at which the arrangement runs away ends the list: it is the speed
limit of that arrangement, written into the file and the summary (not a failure of the run).  With
``warm_up``: the same quantities through the speed steps in time from the cold spindle, with the first
natural frequencies of the rotor at each instant and, with a ``chatter:`` section whose FRF comes from the
rotor, the stable depth of cut at each instant's speed (``analysis.warm_up_chatter``): ``analysis.thermal_study`` computes it all,
this run writes thermal.h5 (group /spindle_thermal), draws the PNGs and hands back the study (its summary's input).
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

from .status import Written

log = logging.getLogger(__name__)


def run(loaded: Any, outdir: Path, run_info: Any, options: dict | None = None, progress=None) -> Written:
    """The spindle's thermal study (:class:`~spindlesim.analysis.thermal_study.ThermalStudy`), thermal.h5 and its
    figures; a part that failed or was interrupted: :class:`~.status.IncompleteRun` with the partial study."""
    import dataclasses

    from ..analysis.points import OperatingPoints
    from ..analysis.thermal_study import thermal_study
    from ..deck import require_rotor
    from ..model.thermal import build_spindle_thermal
    from ..output.drawing import draw
    from ..output.thermal_plots import speeds_figure, warm_up_figure
    from ..output.thermal_writer import tabulate, write_spindle_thermal
    from .common import operating_points

    require_rotor(loaded, "thermal")
    opts = options or {}
    d = loaded.deck
    points = operating_points(loaded)
    model = build_spindle_thermal(d, points.rotor)
    if points.thermal is None or model.analyses != "steady":  # the equilibria the command lists: a model of its own
        points = OperatingPoints(points.rotor, dataclasses.replace(model, analyses="steady"))
    speeds = [float(opts["speed_rpm"])] if opts.get("speed_rpm") is not None else \
        sorted(model.speeds_rpm) or [float(d.operating.speed_rpm)]
    res = thermal_study(points, speeds, model.warm_up, _depth_through(loaded), progress)
    if opts.get("speed_rpm") is None and not res.interrupted:  # the deck's speeds: the limit the others shade
        from .common import remember_thermal_speed_limit

        remember_thermal_speed_limit(loaded, res.limit_rpm)
    for m in res.missing:
        log.warning("%s", m)
    why = "; ".join(([res.interrupted] if res.interrupted else []) + list(res.missing))
    if why:  # a part of the analysis failed or was interrupted: what was computed is written, marked incomplete
        run_info = dataclasses.replace(run_info, complete=False, incomplete_reason=why)
    paths = [write_spindle_thermal(outdir / "thermal.h5", run_info, model, res)]
    runaway = res.runaway[0] if res.runaway else None
    if res.states:
        table = tabulate(res.states, model.bearings, runaway_rpm=runaway, limit_rpm=res.limit_rpm)
        paths.append(draw(outdir / "thermal_speeds.png", speeds_figure, table, d.title))
    warm = res.warm_up
    if warm is not None:
        table = tabulate(warm.states, model.bearings, frequency_hz=warm.frequency_hz, in_time=True,
                         depth_m=None if warm.stable_depth is None else warm.stable_depth.depth_m)
        paths.append(draw(outdir / "thermal_warm_up.png", warm_up_figure, table, d.title))
    if why:
        from .status import IncompleteRun

        what = res.interrupted or f"{len(res.missing)} part(s) not computed: {res.missing[0]}"
        raise IncompleteRun(f"thermal: {what}", paths, interrupted=bool(res.interrupted), result=res,
                            noted=run_info.incomplete_reason)
    return Written(res, tuple(paths))


def _depth_through(loaded):
    """``(points, instants) -> StableDepth`` through the warm-up when the deck's chatter section takes its FRF from
    the rotor (a measured or modal FRF does not change with the spindle's temperatures), else None."""
    d = loaded.deck
    if getattr(d, "chatter", None) is None:
        return None
    from ..analysis.warm_up_chatter import stable_depth_through
    from ..chatter import build_chatter
    from ..deck import deck_folder

    spec = build_chatter(d.chatter, deck_folder(loaded))
    if spec.frf_source != "rotor":
        return None
    return lambda points, instants: stable_depth_through(points, instants, spec.process, spec.method,
                                                         spec.method_options)
