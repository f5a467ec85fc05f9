"""Driver: one entry point for every process and method.

The process resolves the method (``auto`` included: oriented FRF for turning, boring and
grinding; for milling zero order where the directional matrix is constant over the tooth period
and its average exact, semi-discretization everywhere else) and the method is looked up in a
table, so the driver never asks which method or process it has.  The diagram carries the
process's word on the choice (``selection``), and the result the stability pockets found in it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Callable

import logging

import numpy as np

from .pockets import Pocket, best_pocket, stability_pockets
from .refine import refine_pockets
from .results import LobeDiagram, SimulationResult
from .sd_lobes import semi_discretization_lobes
from .section import ChatterSpec
from .simulation import simulate
from .tool import ToolSeries, ToolSource, tool_series
from .turning import turning_lobes
from .zero_order import zero_order_lobes

__all__ = ["METHODS", "stability_lobes", "ChatterResult", "run_chatter"]

log = logging.getLogger(__name__)

METHODS: dict[str, Callable[..., LobeDiagram]] = {
    "oriented_frf": turning_lobes,
    "zero_order": zero_order_lobes,
    "semi_discretization": semi_discretization_lobes,
}


def stability_lobes(process, tool: ToolSource, speeds_rpm, method: str = "auto", **options) -> LobeDiagram:
    """Lobe diagram of ``process`` for the tool-point ``tool`` at ``speeds_rpm``.

    ``tool``: a :class:`~spindlesim.chatter.tool.ToolSeries`, or what :func:`~spindlesim.chatter.tool.tool_series`
    makes one of (a model or FRF the same at every speed, a sequence with one per speed, a callable
    ``tool(speed_rpm)``).  ``options`` go to the
    method (e.g. ``steps``, ``order``, ``n_depths``, ``depth_max_m`` for the semi-discretization;
    the others ignore what they do not use).
    """
    speeds = np.asarray(speeds_rpm, float)
    diagram = METHODS[process.method_for(method)](process, tool_series(tool, speeds), speeds, **options)
    note = process.method_note(method)
    if "CAUTION" in note:
        log.warning("%s", note)
    return replace(diagram, selection=note)


@dataclass(frozen=True, eq=False)
class ChatterResult:
    """The lobe diagram, its stability pockets (deepest first) and the time-domain checks; ``tool`` the
    tool-point series the diagram used (one per diagram speed, refined speeds included, or one at every speed)."""

    diagram: LobeDiagram
    simulations: tuple[SimulationResult, ...]
    pockets: tuple[Pocket, ...] = ()
    tool: ToolSeries | None = None
    #: the spindle's thermal speed limit [rpm]: speeds above it are never recommended nor the minimum's
    speed_limit_rpm: float | None = None
    #: why the result is incomplete: the user pressed Ctrl-C after the lobes were solved (the part not done); empty
    #: when complete
    interrupted: str = ""

    @property
    def recommendation(self) -> Pocket | None:
        """The pocket to cut in (:func:`~spindlesim.chatter.pockets.best_pocket`) among those the spindle can run
        (the whole pocket at or below the speed limit), if any."""
        lim = self.speed_limit_rpm
        return best_pocket(tuple(p for p in self.pockets if lim is None or p.speed_max_rpm <= lim))

    @property
    def recommendation_text(self) -> str:
        """What the recommendation is, or why there is none (the file's ``recommendation``, the summary's line)."""
        from .pockets import MIN_GRID_SPEEDS, MIN_TOLERANCE, POCKET_LEVEL

        lim = self.speed_limit_rpm
        if not self.pockets:
            return "none: no stability pocket inside the speed range"
        if self.recommendation is None:  # every pocket runs above the spindle's thermal speed limit
            return f"none: no stability pocket at or below the thermal speed limit ({lim:,.0f} rpm)"
        below = "" if lim is None else f"; only pockets at or below the thermal speed limit ({lim:,.0f} rpm)"
        return (f"the middle of the deepest stability pocket resolved by at least {MIN_GRID_SPEEDS} grid speeds (else "
                f"the deepest); over the speed interval the limit stays at or above the depth, {POCKET_LEVEL:.0%} of "
                f"the pocket's peak or less where needed for the interval to span +-{MIN_TOLERANCE:.0%} of the "
                f"speed{below}")

    @property
    def minimum(self) -> tuple[float, float] | None:
        """(speed [rpm], depth [m]) of the smallest limit depth at the speeds the spindle can run (all without a
        speed limit); None where no limit was found there."""
        dg = self.diagram
        keep = np.ones(len(dg.speed_rpm), bool) if self.speed_limit_rpm is None else \
            np.asarray(dg.speed_rpm, float) <= self.speed_limit_rpm
        if not np.any(np.isfinite(np.asarray(dg.limit_depth_m, float)[keep])):
            return None
        return replace(dg, speed_rpm=np.asarray(dg.speed_rpm)[keep],
                       limit_depth_m=np.asarray(dg.limit_depth_m)[keep]).minimum


def run_chatter(spec: ChatterSpec, tool: ToolSource | None = None,
                simulation_tool: ToolSource | None = None,
                speed_limit_rpm: float | None = None) -> ChatterResult:
    """Lobe diagram and the requested time-domain checks of a built ``chatter:`` section.

    ``tool`` replaces ``spec.tool`` (needed when the deck says ``frf: rotor``): a tool series or what
    :func:`~spindlesim.chatter.tool.tool_series` makes one of; ``simulation_tool`` (e.g. a truncated rotor
    model) serves the time-domain simulations (the semi-discretization reduces a large model itself, checked
    on the zero-order lobes), each at the tool :meth:`~spindlesim.chatter.tool.ToolSeries.near` its speed.
    The pockets the grid does not resolve are solved at more speeds (:mod:`~spindlesim.chatter.refine`) when
    the series has the tool at any speed (one at every speed, or ``more`` to compute them); a series of one
    tool per grid speed without ``more`` is not refined.  ``speed_limit_rpm``: the spindle's thermal speed
    limit (the recommendation and the minimum stay below it).
    """
    src = tool if tool is not None else spec.tool
    if src is None:
        raise ValueError("frf: rotor needs the rotor's tool-point model (pass tool=...)")
    options = dict(spec.method_options)
    speeds = np.asarray(spec.speeds_rpm, float)
    series = tool_series(src, speeds)
    timed = series if simulation_tool is None else tool_series(simulation_tool, speeds)
    diagram = stability_lobes(spec.process, series, speeds, spec.method, **options)
    used = series
    if series.extendable:
        same_cap = dict(options) | {"stability_map": False}  # the added speeds: the map stays the grid's
        if np.isfinite(diagram.depth_cap_m) and all(options.get(k) is None for k in ("depths_m", "depth_max_m")):
            same_cap["depth_cap_m"] = diagram.depth_cap_m  # the added speeds searched as deep as the grid's

        def solve(extra: np.ndarray) -> LobeDiagram:
            nonlocal used
            added = series.at(extra)
            used = used.joined(added)
            return stability_lobes(spec.process, added, extra, spec.method, **same_cap)

        try:  # a Ctrl-C from here on keeps the lobes solved on the grid
            diagram = refine_pockets(diagram, solve)
        except KeyboardInterrupt:
            return _interrupted(diagram, (), series, speed_limit_rpm, "in the refinement of the stability pockets: "
                                "the lobes on the speed grid are written, the pockets between grid speeds not "
                                "refined and no time-domain check run")
    used = used.at(diagram.speed_rpm)
    sims: list[SimulationResult] = []
    for s, a in spec.simulation_points:
        try:
            sims.append(simulate(spec.process, timed.near(s), s, a, **dict(spec.simulation_options)))
        except KeyboardInterrupt:
            return _interrupted(diagram, tuple(sims), used, speed_limit_rpm, (
                f"in the time-domain check at {s:g} rpm, {1e3 * a:g} mm: the lobes are written with "
                f"{len(sims)} of {len(spec.simulation_points)} checks"))
    return ChatterResult(diagram, tuple(sims), stability_pockets(diagram), used, speed_limit_rpm)


def _interrupted(diagram, sims, tool, speed_limit_rpm, where: str) -> ChatterResult:
    log.warning("chatter: interrupted by the user %s", where)
    return ChatterResult(diagram, sims, stability_pockets(diagram), tool, speed_limit_rpm,
                         f"interrupted by the user {where}")
