"""The tool library of a deck (``tools:``) as substructures: the spindle without a tool, and each tool (holder,
holder-tool joint, tool) as a free-free beam model of its own, with the joint that mounts it on the nose.

Receptance coupling (``analysis.rcsa``) joins them again; the parts here are the same elements, joints and node
positions ``model.build`` gives the rotor whose ``tool:`` is that entry, so the coupled receptance equals that
rotor's.  SI units (deck units are converted by ``build.element_rows`` and ``build.tool_parts``).

A tool part's own nodes are numbered from 0: node 0 is its coupling node (the holder's first node: a node of its
own held by the interface joint, or, mounted rigidly, the nose itself), the last node the tool tip.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from .build import build_rotor, tool_parts
from .dofs import DofMap
from .rotor import Joint, Rotor


@dataclass(frozen=True)
class ToolPart:
    """One library tool, free-free (module note): ``rotor`` holds its elements and the holder-tool joint (no
    bearings, no loads but gravity), ``interface`` the joint to the nose (None: mounted rigidly)."""

    name: str
    rotor: Rotor
    interface: Joint | None
    tip: int  # its own node of the tool tip
    nose_to_tip_m: float  # from the nose to the tip

    @property
    def mass_kg(self) -> float:
        el = self.rotor.elements
        return float(np.sum(el.density_kg_m3 * el.area_m2 * el.length_m))


@dataclass(frozen=True)
class ToolLibraryModel:
    """The spindle without a tool (shaft, disks, bearings, the deck's loads on shaft nodes) and the tools."""

    spindle: Rotor
    nose: int  # 0-based node of the spindle the tools are mounted on
    tools: tuple[ToolPart, ...]
    shaft_nodes: int  # nodes of the shaft; a deck node number above it is on the deck's own holder or tool


def tool_part(name: str, section: Any, spindle: Rotor) -> ToolPart:
    """The ``tool:``-shaped ``section`` as a free-free part (module note) on the shaft nodes of ``spindle``."""
    z = spindle.node_z_m
    n, nose = len(z), section.holder_node - 1
    el, tz, joints, tip = tool_parts(section, z)
    interface = joints[0] if section.interface is not None else None
    own = list(range(n, n + len(tz)))  # the part's nodes in the rotor's numbering
    zs = list(tz)
    if interface is None:  # the holder's first node is the nose itself
        own, zs = [nose] + own, [float(z[nose])] + zs
    local = {g: k for k, g in enumerate(own)}
    el = dataclasses.replace(el, node_a=np.array([local[int(a)] for a in el.node_a]),
                             node_b=np.array([local[int(b)] for b in el.node_b]),
                             viscous_damping_s=spindle.elements.viscous_damping_s,
                             hysteretic_loss_factor=spindle.elements.hysteretic_loss_factor)
    inner = tuple(dataclasses.replace(j, node_a=local[j.node_a], node_b=local[j.node_b])
                  for j in joints if j is not interface)
    rotor = Rotor(node_z_m=np.array(zs), elements=el, gravity_m_s2=spindle.gravity_m_s2, joints=inner,
                  dofs=DofMap(len(zs), spindle.dofs.names), tool_tip=local[tip], speed_rpm=spindle.speed_rpm)
    return ToolPart(name, rotor, interface, local[tip], float(abs(zs[local[tip]] - z[nose])))


def build_tool_library(deck: Any, tools: list[tuple[str, Any]]) -> ToolLibraryModel:
    """The spindle of ``deck`` without its tool, and each of ``tools`` ((name, ``tool:``-shaped section), e.g.
    ``deck.document.library_tools(deck)``) as a :class:`ToolPart`."""
    spindle = build_rotor(deck.model_copy(update={"tool": None}))
    if not tools:
        raise ValueError("the tool library is empty")
    nose = tools[0][1].holder_node - 1
    parts = tuple(tool_part(name, section, spindle) for name, section in tools)
    return ToolLibraryModel(spindle, nose, parts, len(spindle.node_z_m))


def with_tool(deck: Any, section: Any) -> Rotor:
    """The rotor of ``deck`` with ``section`` as its ``tool:`` (the assembled model a coupled receptance equals)."""
    return build_rotor(deck.model_copy(update={"tool": section}))


__all__ = ["ToolPart", "ToolLibraryModel", "tool_part", "build_tool_library", "with_tool"]
