"""The tool point as the chatter analyses see it: one protocol, and one series of it over the speeds.

The protocol (:class:`ToolPoint`), stated once.  A tool point is the 2 x 2 receptance of the tool tip
(directions and layout: :mod:`spindlesim.chatter.frf`); an object is one when it has

* ``receptance(omega) -> H[len(omega), 2, 2]`` [m/N] at angular frequencies [rad/s];
* ``frf(frequency_hz=None) -> ToolPointFrf``: its receptance sampled on ``frequency_hz``, by default on its
  own grid (a model: the grid clustered on its modes; a measured FRF: its samples);
* ``state_space``: its state-space model (A, B, C) where it has one, else None (a measured FRF: the
  methods that need one fit it, :func:`as_state_space`);
* ``source``: where it came from, in words.

:class:`~spindlesim.chatter.state_space.ToolPointModel` (state space) and
:class:`~spindlesim.chatter.frf.ToolPointFrf` (sampled receptance) implement it.

The series (:class:`ToolSeries`): the tool point at each speed of a lobe diagram.  Either one tool at every
speed (:meth:`ToolSeries.constant`), or one per speed (``speeds_rpm``, ``tools``), looked up by the speed
itself, and optionally a way to compute the tool at more speeds (``more``: the rotor's model at the speeds
a refinement adds; a callable ``tool(speed_rpm)`` becomes a series with it).  The lobe methods, the
driver, the time-domain checks, the writer and the figures take a series; :func:`tool_series` makes one
of whatever a caller hands the driver (a tool, a sequence with one per speed, a callable, a series): the
only place that asks which kind of tool source it has.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Callable, Protocol, Sequence, Union

import numpy as np

from .frf import ToolPointFrf
from .state_space import ToolPointModel

__all__ = ["ToolPoint", "ToolSeries", "ToolSource", "tool_series", "as_state_space", "for_simulation"]

log = logging.getLogger(__name__)


class ToolPoint(Protocol):
    """The module note's protocol: what the chatter analyses use of a tool point."""

    source: str

    def receptance(self, omega: np.ndarray) -> np.ndarray: ...

    def frf(self, frequency_hz: np.ndarray | None = None) -> ToolPointFrf: ...

    @property
    def state_space(self) -> ToolPointModel | None: ...


@dataclass(frozen=True, eq=False)
class ToolSeries:
    """The tool point at each of ``speeds_rpm`` (None: ``tools[0]`` at every speed); ``more(speeds)`` gives the
    tools at speeds off the series (None: it cannot)."""

    speeds_rpm: np.ndarray | None
    tools: tuple[ToolPoint, ...]
    more: Callable[[np.ndarray], Sequence[ToolPoint]] | None = None

    def __post_init__(self) -> None:
        tools = tuple(self.tools)
        object.__setattr__(self, "tools", tools)
        if self.speeds_rpm is None:
            if len(tools) != 1:
                raise ValueError(f"a constant tool series holds one tool, not {len(tools)}")
            return
        speeds = np.asarray(self.speeds_rpm, float)
        if len(tools) != len(speeds):
            raise ValueError(f"{len(tools)} tool models for {len(speeds)} speeds")
        object.__setattr__(self, "speeds_rpm", speeds)

    @classmethod
    def constant(cls, tool: ToolPoint) -> "ToolSeries":
        """``tool`` at every speed."""
        return cls(None, (tool,))

    @classmethod
    def computed(cls, tool_at: Callable[[float], ToolPoint], speeds_rpm) -> "ToolSeries":
        """``tool_at(speed_rpm)`` at each of ``speeds_rpm``, and at any speed added later."""
        def more(speeds):
            return [tool_at(float(s)) for s in np.asarray(speeds, float)]

        return cls(speeds_rpm, tuple(more(speeds_rpm)), more)

    @property
    def speed_dependent(self) -> bool:
        """Whether the tool changes with the speed (one per speed) rather than being the same at every speed."""
        return self.speeds_rpm is not None

    @property
    def first(self) -> ToolPoint:
        """The tool at the series' first speed (the constant tool)."""
        return self.tools[0]

    @property
    def extendable(self) -> bool:
        """Whether the series has, or can compute, the tool at any speed."""
        return not self.speed_dependent or self.more is not None

    def along(self, speeds_rpm) -> list[ToolPoint]:
        """The tool at each of ``speeds_rpm``: the constant tool, the series' own at its speeds (by the speed
        itself), the ones ``more`` computes at the others; ValueError for a speed it has no tool for."""
        speeds = np.asarray(speeds_rpm, float)
        if not self.speed_dependent:
            return [self.tools[0]] * len(speeds)
        index = {}
        for i, s in enumerate(self.speeds_rpm.tolist()):
            index.setdefault(s, i)
        missing = [s for s in speeds.tolist() if s not in index]
        extra = {}
        if missing:
            if self.more is None:
                raise ValueError(f"no tool at {', '.join(f'{s:g}' for s in missing)} rpm")
            extra = dict(zip(missing, self.more(np.array(missing))))
        return [self.tools[index[s]] if s in index else extra[s] for s in speeds.tolist()]

    def tool_at(self, speed_rpm: float) -> ToolPoint:
        """The tool at one speed (:meth:`along`)."""
        return self.along([speed_rpm])[0]

    def near(self, speed_rpm: float) -> ToolPoint:
        """The tool at ``speed_rpm`` when the series has or can compute it, else the one at the series' speed
        nearest to it (a time-domain check at a speed off a rotor's series: its model is not recomputed)."""
        if self.extendable:
            return self.tool_at(speed_rpm)
        return self.tools[int(np.argmin(np.abs(self.speeds_rpm - float(speed_rpm))))]

    def at(self, speeds_rpm) -> "ToolSeries":
        """This series at ``speeds_rpm`` (:meth:`along`; a constant series is itself)."""
        if not self.speed_dependent:
            return self
        speeds = np.asarray(speeds_rpm, float)
        return ToolSeries(speeds, tuple(self.along(speeds)), self.more)

    def joined(self, other: "ToolSeries") -> "ToolSeries":
        """The speeds and tools of both (a constant series: itself)."""
        if not self.speed_dependent:
            return self
        return ToolSeries(np.concatenate([self.speeds_rpm, other.speeds_rpm]), self.tools + other.tools, self.more)

    def mapped(self, fn: Callable[[ToolPoint], ToolPoint]) -> "ToolSeries":
        """``fn`` of every tool, at the same speeds (the result computes no more tools)."""
        return ToolSeries(self.speeds_rpm, tuple(fn(t) for t in self.tools))


ToolSource = Union[ToolPoint, Sequence[ToolPoint], Callable[[float], ToolPoint], ToolSeries]


def tool_series(source: ToolSource, speeds_rpm) -> ToolSeries:
    """A :class:`ToolSeries` of ``source`` at ``speeds_rpm``: a series as it is, one tool (model or FRF) at every
    speed, a sequence with one tool per speed, or a callable ``tool(speed_rpm)`` computed at each speed."""
    if isinstance(source, ToolSeries):
        return source
    if isinstance(source, (ToolPointModel, ToolPointFrf)):
        return ToolSeries.constant(source)
    if callable(source):
        return ToolSeries.computed(source, speeds_rpm)
    return ToolSeries(np.asarray(speeds_rpm, float), tuple(source))


def as_state_space(tool: ToolPoint, **fit_options) -> ToolPointModel:
    """The tool's state-space model; a sampled FRF is modal-fitted first."""
    model = tool.state_space
    if model is not None:
        return model
    from .modal_fit import fit_tool_point_model  # measured FRFs only

    log.info("fitting a modal model to the sampled FRF (%s)", tool.source or "unnamed")
    return fit_tool_point_model(tool.frf(), **fit_options).model


#: a state-space model with more states than this is cut for the time-domain simulation
SIMULATION_STATES = 16


def for_simulation(tool: ToolPoint) -> ToolPoint:
    """A rotor model for the time-domain simulation: its modes up to three times the highest mode with a tenth
    of the largest peak compliance (the stiff, lightly damped modes far above would only shrink the time step);
    a small model or a sampled FRF as it is."""
    m = tool.state_space
    if m is None or m.A.shape[0] <= SIMULATION_STATES:
        return tool
    top = max(s.frequency_hz for s in m.significant_modes(rel=0.1))
    return m.truncated(3.0 * top)
