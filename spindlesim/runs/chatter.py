"""The ``chatter`` analysis: deck section ``chatter:`` -> stability lobes -> chatter.h5 and PNGs.

Where the tool-point FRF comes from is the deck's choice (``chatter.frf``): the rotor of the deck
(its tool tip, else node 1), modal parameters of a tap test, or measured FRF files.  From the rotor
the FRF is taken at the deck speed, or recomputed at every speed of the diagram
(``frf_at_each_speed``; by default whenever the bearings' coefficients change over the speed
range); the lobes at the deck speed are then computed too and drawn on the same plot, so the
effect of the speed-dependent modes is in view.  Options: ``simulate`` = [(speed rpm, depth mm),
...] time-domain checks added to the deck's; ``map``: the semi-discretization's stability map too.  ``analysis.chatter_study`` computes it all; this run writes and
draws.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

log = logging.getLogger(__name__)


def run(loaded: Any, outdir: Path, run_info: Any, options: dict | None = None, progress=None):
    from ..analysis.aside import Then
    from ..analysis.chatter_study import chatter_study
    from ..chatter import build_chatter
    from ..deck import deck_folder, require_rotor, require_section
    from .common import operating_points, thermal_speed_limit_aside

    d = loaded.deck
    require_section(loaded, "chatter", "chatter", "operation, cutting coefficients, speeds_rpm, frf")
    spec = build_chatter(d.chatter, deck_folder(loaded))
    opts = options or {}
    points = None
    if spec.frf_source == "rotor":
        require_rotor(loaded, "chatter")  # a located deck error (exit 2) without shaft, bearings or operating
        points = operating_points(loaded)
    limit = thermal_speed_limit_aside(loaded)  # (highest stable, lowest running away) or None, solved meanwhile
    st = chatter_study(spec, points, float(d.operating.speed_rpm) if d.operating is not None else 0.0,
                       bool(opts.get("exact")), tuple((float(s), 1e-3 * float(a)) for s, a in opts.get("simulate") or ()),
                       Then(limit, lambda got: None if got is None else got[0]), progress, bool(opts.get("map")))
    if not st.interrupted:
        from .status import Written

        return Written(st, tuple(_write(outdir, run_info, st.spec, st.result, st.at_deck, st.shown_tool, st.info)))
    import dataclasses  # Ctrl-C: what was computed is written, marked incomplete (exit 130)

    from .status import IncompleteRun

    run_info = dataclasses.replace(run_info, complete=False, incomplete_reason=st.interrupted)
    if st.result is not None:
        paths = _write(outdir, run_info, st.spec, st.result, st.at_deck, st.shown_tool, st.info)
    else:
        paths = _write_tool_point(outdir, run_info, st)
    raise IncompleteRun(f"chatter: {st.interrupted}", paths, interrupted=True, result=st, noted=st.interrupted)


def _write_tool_point(outdir, run_info, st) -> list[Path]:
    from ..chatter.plots import frf_figure
    from ..output.chatter_writer import write_chatter_tool_point
    from ..output.drawing import draw

    paths = [write_chatter_tool_point(outdir / "chatter.h5", run_info, st.spec, st.tool, st.shown_tool, st.info)]
    paths.append(draw(outdir / "chatter_frf.png", frf_figure, st.shown_tool, terms=("xx", "yy", "xy")))
    return paths


def _write(outdir, run_info, spec, result, at_deck, shown, info) -> list[Path]:
    from ..chatter.plots import frf_figure, simulation_figure, stability_map_figure
    from ..output.chatter_writer import write_chatter
    from ..output.drawing import draw

    # the figures first: a figure process draws them while this one writes the file
    dg = result.diagram
    figures = [draw(outdir / "chatter_lobes.png", lobes_figure, dg, result.simulations, at_deck,
                    info.get("deck_speed_rpm"), result.recommendation, result.speed_limit_rpm),
               draw(outdir / "chatter_frf.png", frf_figure, shown, terms=("xx", "yy", "xy"))]
    if dg.stability_map is not None:
        figures.append(draw(outdir / "chatter_stability_map.png", stability_map_figure, dg))
    for k, sim in enumerate(result.simulations):
        figures.append(draw(outdir / f"chatter_simulation_{k + 1}.png", simulation_figure, sim))
    return [write_chatter(outdir / "chatter.h5", run_info, spec, result, at_deck, shown, info)] + figures


def lobes_figure(diagram, simulations, at_deck=None, deck_speed_rpm=None, recommendation=None, speed_limit_rpm=None):
    """The lobe diagram; with ``at_deck`` (the lobes from the FRF at the deck speed) drawn over it, dashed; the
    speeds above the spindle's thermal speed limit shaded."""
    from ..analysis.chatter_study import COMPARE_EVERY
    from ..chatter.plots import lobe_diagram_figure
    from ..output.figures import shade_above_speed_limit

    fig = lobe_diagram_figure(diagram, simulations=simulations, recommendation=recommendation)
    if speed_limit_rpm is not None:
        shade_above_speed_limit(fig.axes, speed_limit_rpm)
    if at_deck is not None:
        ax = fig.axes[0]
        ax.plot(at_deck.speed_rpm, 1e3 * at_deck.limit_depth_m, color="0.35", lw=1.1, ls="--",
                label=f"FRF at the deck speed ({deck_speed_rpm:g} rpm; every {COMPARE_EVERY}th speed)")
        ax.legend(loc="upper left", fontsize="small")
    return fig
