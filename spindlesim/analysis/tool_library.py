"""A tool library on one spindle: every tool's tip receptance by receptance coupling (``rcsa``), at a speed and
with the bearings at a temperature state.

The spindle's receptances at the nose are computed once per static state: the state carries the tool's weight
(``rcsa.condensed_load``), so tools that load the nose alike (gravity off: all of them) share one; each tool is
then a small solve per frequency.  Each tool's coupled receptance equals that of the rotor whose ``tool:`` is the
entry (``model.tool_library.with_tool``), to the static solver's tolerance (docs/validation.md).
"""

from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np

from ..fe.assembly import assemble_shaft
from ..model.rotor import NodalLoad, Rotor
from ..model.tool_library import ToolLibraryModel, ToolPart
from .operating import RPM, OperatingState, operating_state, system_matrices
from .rcsa import condensed_load, joint_compliance, port_receptance, tool_tip_receptance

log = logging.getLogger(__name__)

__all__ = ["CoupledTool", "ToolLibrary", "couple_tools", "ToolLobes", "tool_lobes", "ToolLibraryStudy",
           "tool_library_study"]


@dataclass(frozen=True)
class CoupledTool:
    """One tool on the spindle: its tip receptance [f, 2, 2] (response x, y per force x, y), the static load it
    puts on the nose (the nose's DOFs), its mass and nose-to-tip length."""

    name: str
    receptance_m_N: np.ndarray
    nose_load: np.ndarray
    mass_kg: float
    nose_to_tip_m: float


@dataclass(frozen=True)
class ToolLibrary:
    """Every tool's tip receptance at ``speed_rpm`` on ``frequency_hz``; ``spindle_receptance`` [state, f, m, m]
    the spindle's at the nose (DOFs ``dof_names``) for each static state solved, ``state_of`` each tool's."""

    speed_rpm: float
    frequency_hz: np.ndarray
    nose_node: int  # 1-based
    dof_names: tuple[str, ...]
    tools: tuple[CoupledTool, ...]
    spindle_receptance: np.ndarray
    state_of: tuple[int, ...]

    def tool(self, name: str) -> CoupledTool:
        for t in self.tools:
            if t.name == name:
                return t
        raise KeyError(name)


def _nose_load(part: ToolPart, speed_rad_s: float) -> np.ndarray:
    r = part.rotor
    shaft = assemble_shaft(r)
    g = r.gravity_m_s2 * shaft.gravity_unit
    return condensed_load(shaft, speed_rad_s, g, r.dofs.at(0, r.dofs.names))


def _loaded(spindle: Rotor, nose: int, load: np.ndarray) -> Rotor:
    """The spindle with a tool's static load on its nose (the node's DOFs in the rotor's order)."""
    names = spindle.dofs.names
    f = dict(zip(names, load))
    extra = NodalLoad(nose, (f.get("x", 0.0), f.get("y", 0.0), f.get("theta_x", 0.0), f.get("theta_y", 0.0)),
                      f.get("z", 0.0))
    return dataclasses.replace(spindle, loads=spindle.loads + (extra,))


def couple_tools(model: ToolLibraryModel, speed_rpm: float, frequency_hz, bearings: Sequence | None = None,
                 progress: Callable[[int, int], None] | None = None) -> ToolLibrary:
    """Every tool of ``model`` coupled onto its spindle at ``speed_rpm`` (module note); ``bearings``: the
    spindle's bearings at a temperature state (e.g. its thermal equilibrium), default as built."""
    f = np.asarray(frequency_hz, float)
    if f.size == 0 or np.any(f <= 0):
        raise ValueError("the tool library's frequencies must be positive")
    w = 2 * np.pi * f
    om = float(speed_rpm) * RPM
    spindle = model.spindle if bearings is None else dataclasses.replace(model.spindle, bearings=tuple(bearings))
    names = spindle.dofs.names
    nose_idx = spindle.dofs.at(model.nose, names)
    shaft = assemble_shaft(spindle)
    loads = [_nose_load(p, om) for p in model.tools]
    states: list[tuple[np.ndarray, OperatingState, np.ndarray]] = []
    state_of, out = [], []
    total = len(model.tools)
    for k, (part, load) in enumerate(zip(model.tools, loads)):
        s = next((i for i, (ld, _, _) in enumerate(states) if np.array_equal(ld, load)), None)
        if s is None:
            rotor = _loaded(spindle, model.nose, load)
            start = states[-1][1] if states else None
            st = operating_state(rotor, float(speed_rpm), shaft, start=start)
            H_aa = port_receptance(system_matrices(rotor, state=st), nose_idx, w)
            states.append((load, st, H_aa))
            s = len(states) - 1
        state_of.append(s)
        r = part.rotor
        G = tool_tip_receptance(assemble_shaft(r), om, r.dofs.at(0, names), r.dofs.at(part.tip, ("x", "y")),
                                states[s][2], joint_compliance(part.interface, names, w), w)
        out.append(CoupledTool(part.name, G, load, part.mass_kg, part.nose_to_tip_m))
        if progress is not None:
            progress(k + 1, total)
    log.info("tool library: %d tools, %d spindle state(s) at %g rpm", total, len(states), speed_rpm)
    return ToolLibrary(float(speed_rpm), f, model.nose + 1, tuple(names), tuple(out),
                       np.array([h for _, _, h in states]), tuple(state_of))


@dataclass(frozen=True)
class ToolLobes:
    """One tool's lobe diagram (the deck's ``chatter:`` process and method, the tool-point model of the rotor
    with that tool at the library's speed and temperatures): its minimum and the recommended pocket."""

    name: str
    speed_rpm: np.ndarray
    limit_depth_m: np.ndarray
    min_speed_rpm: float
    min_depth_m: float
    recommended_speed_rpm: float  # NaN: no pocket
    recommended_depth_m: float
    method: str


def tool_lobes(name: str, points, spec, speed_rpm: float, speed_limit_rpm: float | None = None) -> ToolLobes:
    """The lobes of ``spec`` (a built ``chatter:`` section, its time-domain checks left out) for the tool-point
    model of the operating points ``points`` (the rotor with that tool) at ``speed_rpm``, the same at every
    speed of the diagram; the minimum and the recommendation at or below ``speed_limit_rpm`` (the spindle's
    thermal speed limit)."""
    from ..chatter import run_chatter
    from .tool_point import tool_point_model

    model = tool_point_model(points, speed_rpm)
    spec = dataclasses.replace(spec, simulation_points=())
    res = run_chatter(spec, model, speed_limit_rpm=speed_limit_rpm)
    dg = res.diagram
    s_min, d_min = res.minimum if res.minimum is not None else (float("nan"), float("nan"))
    rec = res.recommendation
    return ToolLobes(name, np.asarray(dg.speed_rpm, float), np.asarray(dg.limit_depth_m, float), s_min, d_min,
                     rec.speed_rpm if rec is not None else float("nan"),
                     rec.depth_m if rec is not None else float("nan"), spec.resolved_method)


@dataclass(frozen=True)
class ToolLibraryStudy:
    """What ``spindlesim tools`` computes: the coupled receptances and, with a ``chatter:`` section, each tool's
    lobes (``lobes`` empty without)."""

    library: ToolLibrary
    lobes: tuple[ToolLobes, ...] = ()
    #: where a Ctrl-C stopped the lobes ("": it did not): the receptances and the tools' lobes before it are kept
    interrupted: str = ""

    @property
    def lobes_frf(self) -> str:
        """Which FRF the tools' lobes use (file and summary)."""
        return f"the rotor with each tool at {self.library.speed_rpm:g} rpm, the same at every speed of the diagram"


def tool_library_study(model: ToolLibraryModel, speed_rpm: float, frequency_hz, bearings: Sequence | None = None,
                       lobes_of: Sequence[tuple[str, object]] = (), spec=None, speed_limit_rpm: float | None = None,
                       progress: Callable[[int, int], None] | None = None) -> ToolLibraryStudy:
    """What ``spindlesim tools`` computes: every tool coupled onto the spindle (:func:`couple_tools`), and with a
    chatter ``spec`` the lobes of each (name, operating points of the rotor with that tool) of ``lobes_of``."""
    steps = len(model.tools) + len(lobes_of)

    def tick(done: int, _total: int) -> None:
        if progress is not None:
            progress(done, steps)

    library = couple_tools(model, speed_rpm, frequency_hz, bearings, progress=tick)
    lobes: list[ToolLobes] = []
    for k, (name, points) in enumerate(lobes_of):
        try:
            lobes.append(tool_lobes(name, points, spec, speed_rpm, speed_limit_rpm))
        except KeyboardInterrupt:
            why = (f"interrupted by the user in the lobes of tool {name!r}: the receptances of every tool and the "
                   f"lobes of {k} of {len(lobes_of)} tools are written")
            log.warning("tools: %s", why)
            return ToolLibraryStudy(library, tuple(lobes), why)
        tick(len(model.tools) + k + 1, steps)
    return ToolLibraryStudy(library, tuple(lobes))
