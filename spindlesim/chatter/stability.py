"""Driver: one entry point for every process and method.

The process resolves the method (``auto`` included: oriented FRF for turning, boring and
grinding; zero-order for milling, semi-discretization below 30 % radial immersion) and the
method is looked up in a table, so the driver never asks which method or process it has.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from .results import LobeDiagram, SimulationResult
from .sd_lobes import semi_discretization_lobes
from .section import ChatterSpec
from .simulation import simulate
from .state_space import Tool, ToolSource
from .turning import turning_lobes
from .zero_order import zero_order_lobes

__all__ = ["METHODS", "stability_lobes", "ChatterResult", "run_chatter"]

METHODS: dict[str, Callable[..., LobeDiagram]] = {
    "oriented_frf": turning_lobes,
    "zero_order": zero_order_lobes,
    "semi_discretization": semi_discretization_lobes,
}


def stability_lobes(process, tool: ToolSource, speeds_rpm, method: str = "auto", **options) -> LobeDiagram:
    """Lobe diagram of ``process`` for the tool-point ``tool`` at ``speeds_rpm``.

    ``tool``: a :class:`ToolPointModel` or :class:`ToolPointFrf` (same at every speed), a
    sequence with one per speed, or a callable ``tool(speed_rpm)``.  ``options`` go to the
    method (e.g. ``steps``, ``order``, ``n_depths``, ``depth_max_m`` for the semi-discretization;
    the others ignore what they do not use).
    """
    return METHODS[process.method_for(method)](process, tool, np.asarray(speeds_rpm, float), **options)


@dataclass(frozen=True, eq=False)
class ChatterResult:
    diagram: LobeDiagram
    simulations: tuple[SimulationResult, ...]


def _tool_at(tool: ToolSource, speeds: np.ndarray, speed: float) -> Tool:
    if callable(tool):
        return tool(float(speed))
    if isinstance(tool, (list, tuple)):
        return tool[int(np.argmin(np.abs(speeds - speed)))]
    return tool


def run_chatter(spec: ChatterSpec, tool: ToolSource | None = None,
                simulation_tool: ToolSource | None = None) -> ChatterResult:
    """Lobe diagram and the requested time-domain checks of a built ``chatter:`` section.

    ``tool`` replaces ``spec.tool`` (needed when the deck says ``frf: rotor``);
    ``simulation_tool`` (e.g. a truncated rotor model) serves the time-domain methods: the
    semi-discretization and the simulations.
    """
    src = tool if tool is not None else spec.tool
    if src is None:
        raise ValueError("frf: rotor needs the rotor's tool-point model (pass tool=...)")
    timed = simulation_tool if simulation_tool is not None else src
    lobes_tool = timed if spec.resolved_method == "semi_discretization" else src
    diagram = stability_lobes(spec.process, lobes_tool, spec.speeds_rpm, spec.method, **dict(spec.method_options))
    sims = tuple(simulate(spec.process, _tool_at(timed, spec.speeds_rpm, s), s, a, **dict(spec.simulation_options))
                 for s, a in spec.simulation_points)
    return ChatterResult(diagram, sims)
