"""The ``chatter`` analysis: deck section ``chatter:`` -> stability lobes -> chatter.h5 and PNGs.

Where the tool-point FRF comes from is the deck's choice (``chatter.frf``): the rotor of the deck
(its tool tip, else node 1), modal parameters of a tap test, or measured FRF files.  From the rotor
the FRF is taken at the deck speed, or recomputed at every speed of the diagram
(``frf_at_each_speed``; by default whenever the bearings' coefficients change over the speed
range); the lobes at the deck speed are then computed too and drawn on the same plot, so the
effect of the speed-dependent modes is in view.  Options: ``simulate`` = [(speed rpm, depth mm),
...] time-domain checks added to the deck's.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np

log = logging.getLogger(__name__)

#: the lobes of the FRF at the deck speed, drawn for comparison, are solved at every this-many-th speed
COMPARE_EVERY = 4


def run(loaded: Any, outdir: Path, run_info: Any, options: dict | None = None, progress=None) -> list[Path]:
    from ..chatter import build_chatter, run_chatter, stability_lobes
    from ..chatter.state_space import for_simulation
    from ..chatter.section import ChatterSpec

    from ..deck import require_section
    from .common import operating_points

    d = loaded.deck
    require_section(loaded, "chatter", "chatter", "operation, cutting coefficients, speeds_rpm, frf")
    base = Path(loaded.source).parent if not loaded.source.startswith("<") else Path.cwd()
    spec: ChatterSpec = build_chatter(d.chatter, base)
    opts = options or {}
    points = tuple(spec.simulation_points) + tuple((float(s), 1e-3 * float(a)) for s, a in opts.get("simulate") or ())
    info: dict[str, Any] = {"frf_source": spec.frf_source}
    deck_tool = tools_at = None
    if spec.frf_source == "rotor":
        from ..deck import require_rotor

        require_rotor(loaded, "chatter")  # a located deck error (exit 2) without shaft, bearings or operating
        tool, deck_tool, info = _rotor_tools(loaded, spec, bool(opts.get("exact")), progress)
        if isinstance(tool, list):
            from ..analysis.tool_point import tool_point_series

            def tools_at(speeds):  # the tool-point model at speeds added in unresolved pockets
                return tool_point_series(operating_points(loaded), speeds, exact=bool(opts.get("exact"))).models
    else:
        tool = spec.tool
    sim_tool = for_simulation(tool) if points else None
    spec = ChatterSpec(spec.process, spec.speeds_rpm, spec.method, spec.frf_source, spec.tool,
                       spec.frf_at_each_speed, spec.method_options, points, spec.simulation_options)
    from .common import thermal_speed_limit

    limit = thermal_speed_limit(loaded)
    result = run_chatter(spec, tool, simulation_tool=sim_tool, tools_at=tools_at,
                         speed_limit_rpm=None if limit is None else limit[0])
    at_deck = None
    if deck_tool is not None and info["frf_at_each_speed"]:  # the comparison: every COMPARE_EVERY-th speed
        at_deck = stability_lobes(spec.process, deck_tool, spec.speeds_rpm[::COMPARE_EVERY], spec.method,
                                  **dict(spec.method_options))
    return _write(outdir, run_info, spec, result, at_deck, result.tool, deck_tool, info)


def _rotor_tools(loaded, spec, exact: bool, progress):
    """(tool for the lobes, tool at the deck speed, provenance) from the deck's rotor at its operating points
    (each speed's state solved once, shared with the other analyses of the run)."""
    from ..analysis.tool_point import coefficients_change, tool_point_model, tool_point_series
    from .common import operating_points

    points = operating_points(loaded)
    rotor = points.rotor
    deck_rpm = float(loaded.deck.operating.speed_rpm)
    speeds = spec.speeds_rpm
    per_speed = spec.frf_at_each_speed
    reason = "deck"
    if per_speed is None:
        per_speed, reason = coefficients_change(points, speeds), "bearing coefficients"
    info = {"frf_source": "rotor", "frf_at_each_speed": bool(per_speed), "deck_speed_rpm": deck_rpm,
            "frf_at_each_speed_reason": reason}
    if rotor.tool_tip is None:
        log.info("the deck has no tool section: the cutting point is node 1")
    if per_speed:
        series = tool_point_series(points, speeds, exact=exact, progress=progress)
        info.update(node=series.node, model=series.model)
        deck_tool = tool_point_model(points, deck_rpm) if deck_rpm > 0 else series.models[0]
        return list(series.models), deck_tool, info
    if deck_rpm <= 0:
        raise ValueError("chatter with the FRF at the deck speed needs operating.speed_rpm > 0 "
                         "(or frf_at_each_speed: true)")
    deck_tool = tool_point_model(points, deck_rpm)
    info.update(node=(rotor.tool_tip + 1) if rotor.tool_tip is not None else 1, model="full state space")
    return deck_tool, deck_tool, info


def _write(outdir, run_info, spec, result, at_deck, tool, deck_tool, info) -> list[Path]:
    from ..chatter.plots import frf_figure, simulation_figure, stability_map_figure
    from ..output.chatter_writer import write_chatter
    from ..output.drawing import draw

    paths = [write_chatter(outdir / "chatter.h5", run_info, spec, result, at_deck, tool, deck_tool, info)]
    dg = result.diagram
    paths.append(draw(outdir / "chatter_lobes.png", lobes_figure, dg, result.simulations, at_deck,
                      info.get("deck_speed_rpm"), result.recommendation, result.speed_limit_rpm))
    shown = deck_tool if deck_tool is not None else (tool[0] if isinstance(tool, list) else tool)
    if shown is not None:
        paths.append(draw(outdir / "chatter_frf.png", frf_figure, shown, terms=("xx", "yy", "xy")))
    if dg.stability_map is not None:
        paths.append(draw(outdir / "chatter_stability_map.png", stability_map_figure, dg))
    for k, sim in enumerate(result.simulations):
        paths.append(draw(outdir / f"chatter_simulation_{k + 1}.png", simulation_figure, sim))
    return paths


def lobes_figure(diagram, simulations, at_deck=None, deck_speed_rpm=None, recommendation=None, speed_limit_rpm=None):
    """The lobe diagram; with ``at_deck`` (the lobes from the FRF at the deck speed) drawn over it, dashed; the
    speeds above the spindle's thermal speed limit shaded."""
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
