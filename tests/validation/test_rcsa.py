"""Receptance coupling (issue 30, item 5): a tool coupled onto the spindle by RCSA equals the assembled rotor
whose `tool:` is that tool, at rest and at speed, for several tools, holders and joints (the only difference is
the two static solves' tolerance); a slender tool on a rigid spindle is a cantilever (Euler-Bernoulli static
compliance and first frequency, Timoshenko's shear correction); the tool's weight on the nose is its weight."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from spindlesim.analysis.rcsa import condensed_load
from spindlesim.analysis.tool_library import couple_tools
from spindlesim.analysis.tool_point import tool_point_model
from spindlesim.deck import load_deck, parse_deck
from spindlesim.deck.document import ElementRows, ToolEntry, ToolJoint, library_tools
from spindlesim.fe.assembly import assemble_shaft
from spindlesim.model.rotor import Rotor
from spindlesim.model.tool_library import build_tool_library, with_tool

ROOT = Path(__file__).parents[2]
CARBIDE = [14500.0, 580.0, 240.0, 0.22, 0.0]
STEEL = [7850.0, 210.0, 80.8, 0.3, 0.0]

ENTRIES = [
    ToolEntry(name="deck tool"),
    ToolEntry(name="long stick-out", tool=ElementRows(elements=[[16, 0, 25] + CARBIDE, [12.8, 0, 35] + CARBIDE,
                                                                [12.8, 0, 35] + CARBIDE])),
    ToolEntry(name="soft joint", joint=ToolJoint(translational_N_m=8e7, rotational_Nm_rad=4e5,
                                                  translational_Ns_m=60.0, rotational_Nms_rad=0.5)),
    ToolEntry(name="8 mm in its own chuck",
              holder=ElementRows(elements=[[63, 8, 20] + STEEL, [24, 8, 60] + STEEL]),
              joint=ToolJoint(translational_N_m=1e8, rotational_Nm_rad=5e5, translational_Ns_m=100.0),
              tool=ElementRows(elements=[[8, 0, 12] + CARBIDE, [6.4, 0, 20] + CARBIDE])),
    ToolEntry(name="collet chuck, stiff interface",
              interface=ToolJoint(translational_N_m=5e9, rotational_Nm_rad=5e7, translational_Ns_m=2e4),
              holder=ElementRows(elements=[[63, 20, 20] + STEEL, [50, 20, 50] + STEEL]),
              tool=ElementRows(elements=[[20, 0, 25] + CARBIDE, [16, 0, 45] + CARBIDE])),
]


def _relative_error(deck, rpm: float, f: np.ndarray) -> dict[str, float]:
    tools = library_tools(deck)
    lib = couple_tools(build_tool_library(deck, tools), rpm, f)
    out = {}
    for (name, section), coupled in zip(tools, lib.tools):
        H = tool_point_model(with_tool(deck, section), rpm).receptance(2 * np.pi * f)
        out[name] = float(np.max(np.abs(coupled.receptance_m_N - H)) / np.max(np.abs(H)))
    return out


@pytest.mark.parametrize("rpm", [0.0, 18000.0])
def test_coupled_tools_equal_the_assembled_rotor_on_the_milling_spindle(rpm):
    """Ball-bearing pairs (5 DOF per node, the axial DOF coupled to the tilts), gravity on, the HSK interface
    joint with damping: every tool's coupled receptance equals the assembled model's within 1e-8 of its
    largest value (measured 1e-10 .. 4e-10: the two static solves' tolerance)."""
    d = load_deck(ROOT / "decks" / "milling_spindle.yaml").deck.model_copy(update={"tools": ENTRIES})
    f = np.linspace(20.0, 5000.0, 400)
    err = _relative_error(d, rpm, f)
    assert max(err.values()) < 1e-8, err


def test_rigid_mounting_and_radial_bearings_equal_the_assembled_rotor():
    """Seed 003's spindle on its printed linear coefficients (4 DOF per node, cross-coupled bearings) with a
    tool mounted rigidly (no interface joint) at 6000 rpm."""
    text = (ROOT / "decks" / "seed003_spindle_linear.yaml").read_text() + """
tool:
  holder: {elements: [[50.0, 16.0, 30.0, 7850.0, 210.0, 80.8, 0.3, 0.0], [34.0, 16.0, 50.0, 7850.0, 210.0, 80.8, 0.3, 0.0]]}
  joint: {translational_N_m: 3.0e8, rotational_Nm_rad: 1.5e6, translational_Ns_m: 200.0}
  tool: {elements: [[16.0, 0.0, 30.0, 14500.0, 580.0, 240.0, 0.22, 0.0], [12.8, 0.0, 40.0, 14500.0, 580.0, 240.0, 0.22, 0.0]]}
tools:
  - {name: as in tool}
  - name: shorter
    tool: {elements: [[16.0, 0.0, 20.0, 14500.0, 580.0, 240.0, 0.22, 0.0], [12.8, 0.0, 20.0, 14500.0, 580.0, 240.0, 0.22, 0.0]]}
"""
    d = parse_deck(text, "<seed003 + tools>").deck
    assert d.tool.interface is None
    err = _relative_error(d, 6000.0, np.linspace(20.0, 4000.0, 300))
    assert max(err.values()) < 1e-8, err


def _cantilever_deck(length_mm: float, dia_mm: float) -> str:
    """A short, thick shaft on two very stiff linear bearings (a rigid spindle) and a steel cylinder mounted
    rigidly at node 1 as the tool, in 20 elements."""
    n = 20
    rows = "\n".join(f"      - [{dia_mm}, 0.0, {length_mm / n}, 7850.0, 210.0, 80.0, 0.3, 0.0]" for _ in range(n))
    return f"""title: cantilever on a rigid spindle
shaft:
  elements:
    - [300.0, 0.0, 50.0, 7850.0, 210.0, 80.0, 0.3, 0.0]
    - [300.0, 0.0, 50.0, 7850.0, 210.0, 80.0, 0.3, 0.0]
bearings:
  - {{name: a, node: 1, type: linear, K_N_m: [[1.0e13, 0.0], [0.0, 1.0e13]], C_Ns_m: [[0.0, 0.0], [0.0, 0.0]]}}
  - {{name: b, node: 3, type: linear, K_N_m: [[1.0e13, 0.0], [0.0, 1.0e13]], C_Ns_m: [[0.0, 0.0], [0.0, 0.0]]}}
operating: {{speed_rpm: 0}}
tool:
  holder: {{elements: [[{dia_mm}, 0.0, 1.0e-2, 7850.0, 210.0, 80.0, 0.3, 0.0]]}}
  joint: {{translational_N_m: 1.0e13, rotational_Nm_rad: 1.0e12}}
  tool:
    elements:
{rows}
tools:
  - {{name: cylinder}}
"""


def test_a_slender_tool_on_a_rigid_spindle_is_a_cantilever():
    """Steel cylinder, d = 10 mm, L = 200 mm, clamped: static tip compliance L^3/(3 E I) + L/(k G A) (Timoshenko,
    k of a solid circle 6(1+nu)/(7+6nu)), first frequency 1.8751^2 sqrt(E I/(rho A L^4))/(2 pi) = 180.9 Hz
    (Euler-Bernoulli; shear and rotary inertia lower it by about (d/L)^2: < 0.3 % here)."""
    L, d = 0.200, 0.010
    deck = parse_deck(_cantilever_deck(L * 1e3, d * 1e3), "<cantilever>").deck
    E, G, rho, nu = 210e9, 80e9, 7850.0, 0.3
    A, I = np.pi * d**2 / 4, np.pi * d**4 / 64
    k = 6 * (1 + nu) / (7 + 6 * nu)
    static = L**3 / (3 * E * I) + L / (k * G * A)
    f1 = 1.8751**2 * np.sqrt(E * I / (rho * A * L**4)) / (2 * np.pi)
    assert f1 == pytest.approx(180.9, abs=0.1)
    f = np.concatenate([[0.5], np.linspace(0.99 * f1, 1.01 * f1, 2001)])
    lib = couple_tools(build_tool_library(deck, library_tools(deck)), 0.0, f)
    H = lib.tools[0].receptance_m_N[:, 0, 0]
    assert H[0].real == pytest.approx(static, rel=2e-3)  # 0.5 Hz: static (1e-5 of the first mode's r^2)
    peak = f[1:][np.argmax(np.abs(H[1:]))]
    assert peak == pytest.approx(f1, rel=3e-3)
    assert peak < f1  # Timoshenko below Euler-Bernoulli


def test_the_tools_weight_on_the_nose_is_its_weight_and_moment():
    """The static load condensed to the coupling node: the force is the part's weight m g (down), the moment m g
    times the distance of its centre of mass from the nose (an overhung part tilts the nose down)."""
    deck = parse_deck(_cantilever_deck(200.0, 10.0).replace("speed_rpm: 0}", "speed_rpm: 0, gravity: true}"),
                      "<cantilever>").deck
    part = build_tool_library(deck, library_tools(deck)).tools[0]
    r: Rotor = part.rotor
    shaft = assemble_shaft(r)
    load = condensed_load(shaft, 0.0, r.gravity_m_s2 * shaft.gravity_unit, r.dofs.at(0, r.dofs.names))
    f = dict(zip(r.dofs.names, load))
    m = part.mass_kg
    assert m == pytest.approx(7850 * np.pi * 0.01**2 / 4 * 0.20001, rel=1e-12)
    assert f["y"] == pytest.approx(-m * 9.80665, rel=1e-11)
    assert f["x"] == pytest.approx(0.0, abs=1e-12)
    z = r.node_z_m
    el = r.elements
    zc = np.sum((z[el.node_a] + z[el.node_b]) / 2 * el.density_kg_m3 * el.area_m2 * el.length_m) / m
    arm = abs(zc - z[0])
    assert abs(f["theta_x"]) == pytest.approx(m * 9.80665 * arm, rel=1e-9)
