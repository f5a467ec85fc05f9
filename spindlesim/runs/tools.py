"""``spindlesim tools``: the deck's tool library (``tools:``) coupled onto its spindle by receptance coupling
(``analysis.tool_library``) at one speed, the bearings at the spindle's thermal equilibrium there when the deck
has a ``spindle_thermal`` section; with a ``chatter:`` section each tool's lobes.  tools.h5 and PNGs.

Options: ``speed_rpm`` (default: the deck's operating speed), ``lobes`` (False: the receptances only).
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

log = logging.getLogger(__name__)


def study(loaded: Any, options: dict | None = None, progress=None):
    """The :class:`~spindlesim.analysis.tool_library.ToolLibraryStudy` of a loaded deck (module note)."""
    from ..analysis.points import OperatingPoints
    from ..analysis.tool_library import tool_library_study
    from ..deck import DeckError, deck_folder, require_rotor, require_section
    from ..deck.document import library_tools
    from ..model.thermal import build_spindle_thermal
    from ..model.tool_library import build_tool_library, with_tool
    from .common import operating_points, thermal_speed_limit, value_range

    opts = options or {}
    require_section(loaded, "tools", "tools", "a list of named tools (interface, holder, joint, tool)")
    require_rotor(loaded, "tools")
    d = loaded.deck
    shaft_nodes = len(d.shaft.elements) + 1
    bad = [loaded.issue((what, i, "node"), f"a {what[:-1]} on node {x.node} sits on the deck's holder or tool: the "
                                           f"tool library keeps {what} on the shaft's nodes 1..{shaft_nodes} only")
           for what in ("loads", "disks") for i, x in enumerate(getattr(d, what)) if x.node > shaft_nodes]
    if bad:
        raise DeckError(bad)
    tools = library_tools(d)
    speed = float(opts["speed_rpm"]) if opts.get("speed_rpm") is not None else float(d.operating.speed_rpm)
    points = operating_points(loaded)
    bearings = None
    if points.thermal is not None:  # the spindle's bearings at their temperatures at this speed
        bearings = points.thermal.rotor_at(points.thermal_state(speed).temperatures_C)[0].bearings
    spec, lobes_of, limit = None, [], None
    if d.chatter is not None and opts.get("lobes", True):
        from ..chatter import build_chatter

        spec, limit = build_chatter(d.chatter, deck_folder(loaded)), thermal_speed_limit(loaded)
        for name, section in tools:
            rotor = with_tool(d, section)
            thermal = build_spindle_thermal(d, rotor)
            lobes_of.append((name, OperatingPoints(rotor, thermal if thermal is not None and thermal.analyses != "none"
                                                   else None)))
    return tool_library_study(build_tool_library(d, tools), speed, value_range(d.frf.frequencies_hz), bearings,
                              lobes_of, spec, None if limit is None else limit[0], progress)


def run(loaded: Any, outdir: Path, run_info: Any, options: dict | None = None, progress=None):
    from ..output.drawing import draw
    from ..output.tools_plots import receptance_figure, lobes_figure
    from ..output.tools_writer import write_tools
    from .common import plots_wanted

    res = study(loaded, options, progress)
    if res.interrupted:  # Ctrl-C in the lobes: what was computed is written, marked incomplete
        import dataclasses

        run_info = dataclasses.replace(run_info, complete=False, incomplete_reason=res.interrupted)
    paths = [write_tools(outdir / "tools.h5", run_info, res)]
    if plots_wanted(options or {}):
        paths.append(draw(outdir / "tools_frf.png", receptance_figure, res.library, loaded.deck.title))
        if res.lobes:
            paths.append(draw(outdir / "tools_lobes.png", lobes_figure, res.lobes, loaded.deck.title))
    if res.interrupted:
        from .status import IncompleteRun

        raise IncompleteRun(f"tools: {res.interrupted}", paths, interrupted=True, result=res, noted=res.interrupted)
    from .status import Written

    return Written(res, tuple(paths))
