"""What ``spindlesim chatter`` computes, as one frozen result: the lobes of a built ``chatter:`` section with the
tool-point FRF where the section takes it from (modal parameters, measured files, or the rotor of the deck: at
its operating speed, or recomputed at every speed of the diagram when the bearings' coefficients change over it
or the section says so), the time-domain checks, and, with the FRF per speed, the lobes of the deck speed's FRF
for comparison (every ``COMPARE_EVERY``-th speed).  The recommendation and the minimum stay at or below the
spindle's thermal speed limit when one is given.
"""

from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Callable

from ..chatter import run_chatter, stability_lobes
from ..chatter.section import ChatterSpec
from ..chatter.tool import ToolSeries, for_simulation
from .aside import Aside, Known
from .points import OperatingPoints
from .tool_point import coefficients_change, tool_point_model, tool_point_series

log = logging.getLogger(__name__)

#: the lobes of the FRF at the deck speed, drawn for comparison, are solved at every this-many-th speed
COMPARE_EVERY = 4
#: what a study interrupted in the lobes has of them
NO_LOBES = "not computed (interrupted)"


@dataclass(frozen=True, eq=False)
class ChatterStudy:
    """The lobes and their checks (``result``: a :class:`~spindlesim.chatter.ChatterResult`), the section as run
    (``spec``, the added simulations included), the comparison at the deck speed (``at_deck``), the rotor's
    tool-point model at the deck speed (``deck_tool``; None for a tap test or a file) and where the FRF came
    from (``info``: frf_source, frf_at_each_speed and why, deck_speed_rpm, node, model)."""

    result: Any
    spec: ChatterSpec
    at_deck: Any = None
    deck_tool: Any = None
    info: dict = field(default_factory=dict)
    #: why the study is incomplete (the user pressed Ctrl-C: where, and what is kept); empty when complete.
    #: Interrupted in the lobes themselves, ``result`` is None and ``tool`` holds the tool-point models solved
    interrupted: str = ""
    #: the tool series of the lobes (:class:`~spindlesim.chatter.tool.ToolSeries`; the result's when there is one)
    tool: Any = None

    @property
    def shown_tool(self):
        """The tool point whose FRF the file holds and the figure draws: the deck speed's, else the first of the
        series the lobes used (the one tool of a tap test or a file)."""
        return self.deck_tool if self.deck_tool is not None else self.tool.first

    # ---- named results --------------------------------------------------------------------------------
    @property
    def min_limit_depth_m(self) -> float:
        m = self.result.minimum
        return float("nan") if m is None else m[1]

    @property
    def recommended_speed_rpm(self) -> float:
        r = self.result.recommendation
        return float("nan") if r is None else r.speed_rpm


def _rotor_tools(points: OperatingPoints, spec: ChatterSpec, deck_rpm: float, exact: bool, progress):
    """(tool series for the lobes, tool at the deck speed, provenance) from the rotor at its operating points; a
    series per speed computes the tool-point models at the speeds added in unresolved pockets."""
    rotor = points.rotor
    per_speed, reason = spec.frf_at_each_speed, "deck"
    if per_speed is None:
        per_speed, reason = coefficients_change(points, spec.speeds_rpm), "bearing coefficients"
    info = {"frf_source": "rotor", "frf_at_each_speed": bool(per_speed), "deck_speed_rpm": deck_rpm,
            "frf_at_each_speed_reason": reason}
    if rotor.tool_tip is None:
        log.info("the deck has no tool section: the cutting point is node 1")
    if per_speed:
        series = tool_point_series(points, spec.speeds_rpm, exact=exact, progress=progress)
        info.update(node=series.node, model=series.model)
        deck_tool = tool_point_model(points, deck_rpm) if deck_rpm > 0 else series.models[0]
        more = lambda speeds: tool_point_series(points, speeds, exact=exact).models  # noqa: E731
        return ToolSeries(series.speeds_rpm, series.models, more), deck_tool, info
    if deck_rpm <= 0:
        raise ValueError("chatter with the FRF at the deck speed needs operating.speed_rpm > 0 "
                         "(or frf_at_each_speed: true)")
    deck_tool = tool_point_model(points, deck_rpm)
    info.update(node=(rotor.tool_tip + 1) if rotor.tool_tip is not None else 1, model="full state space")
    return ToolSeries.constant(deck_tool), deck_tool, info


def chatter_study(spec: ChatterSpec, points: OperatingPoints | None = None, deck_rpm: float = 0.0,
                  exact: bool = False, simulate: tuple[tuple[float, float], ...] = (),
                  speed_limit_rpm: "float | None | Aside" = None,
                  progress: Callable[[int, int], None] | None = None, stability_map: bool = False) -> ChatterStudy:
    """The module note's study of ``spec``; ``points``: the deck's rotor at its operating points (needed when the
    FRF comes from the rotor), ``deck_rpm`` its operating speed, ``simulate`` more (speed rpm, depth m) checks in
    time beside the section's, ``stability_map`` the semi-discretization's map even where the section does not ask
    for it; ``speed_limit_rpm`` the thermal speed limit, or an :class:`~.aside.Aside` computing it meanwhile.  The
    comparison's lobes are computed aside while the lobes at every speed are (:mod:`.aside`)."""
    sims = tuple(spec.simulation_points) + tuple((float(s), float(a)) for s, a in simulate)
    info: dict[str, Any] = {"frf_source": spec.frf_source}
    opts = dict(spec.method_options)
    if stability_map:
        opts["stability_map"] = True
    limit = speed_limit_rpm if hasattr(speed_limit_rpm, "result") else Known(speed_limit_rpm)
    deck_tool, compare = None, Known(None)
    try:
        if spec.frf_source == "rotor":
            if points is None:
                raise ValueError("frf: rotor needs the rotor's operating points")
            tool, deck_tool, info = _rotor_tools(points, spec, float(deck_rpm), exact, progress)
            if info["frf_at_each_speed"]:  # the comparison: every COMPARE_EVERY-th speed, meanwhile
                compare = Aside(_compare, spec.process, deck_tool, spec.speeds_rpm[::COMPARE_EVERY], spec.method,
                                opts | {"stability_map": False})
        else:
            tool = ToolSeries.constant(spec.tool)
    except BaseException:
        limit.cancel()
        raise
    spec = dataclasses.replace(spec, simulation_points=sims, method_options=MappingProxyType(opts))
    try:
        result = run_chatter(spec, tool, simulation_tool=tool.mapped(for_simulation) if sims else None)
    except KeyboardInterrupt:  # in the lobes: the tool-point FRF is what was computed
        compare.cancel()
        limit.cancel()
        why = (f"interrupted by the user in the lobes ({spec.process.method_for(spec.method).replace('_', ' ')}): "
               "the tool-point FRF is written, no lobes")
        log.warning("chatter: %s", why)
        return ChatterStudy(None, spec, None, deck_tool, info, why, tool)
    except BaseException:
        compare.cancel()
        limit.cancel()
        raise
    try:
        result = dataclasses.replace(result, speed_limit_rpm=limit.result())
    except KeyboardInterrupt:
        compare.cancel()
        limit.cancel()
        why = ("interrupted by the user while the thermal speed limit was solved: the lobes are written without it "
               "(the recommendation and the minimum over the whole speed range)")
        log.warning("chatter: %s", why)
        return ChatterStudy(result, spec, None, deck_tool, info, why, result.tool)
    at_deck = None
    if result.interrupted:
        compare.cancel()
    else:
        try:
            at_deck = compare.result()
        except KeyboardInterrupt:
            compare.cancel()
            why = ("interrupted by the user in the lobes of the deck speed's FRF (the comparison): the lobes are "
                   "written, the comparison not")
            log.warning("chatter: %s", why)
            return ChatterStudy(result, spec, None, deck_tool, info, why, result.tool)
    return ChatterStudy(result, spec, at_deck, deck_tool, info, result.interrupted, result.tool)


def _compare(process, tool, speeds_rpm, method, options: dict):
    """The lobes of the deck speed's FRF (the comparison), as :func:`~spindlesim.chatter.stability_lobes`."""
    return stability_lobes(process, tool, speeds_rpm, method, **options)
