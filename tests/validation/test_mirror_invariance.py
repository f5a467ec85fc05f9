"""A deck and its mirror image are the same machine (issue 21, item 5): every bearing family.

The mirror image numbers the shaft from the other end (tests/mirror.py). Nothing physical changes, so
the static deflection at corresponding nodes (x and y; slopes and axial motion change sign), every
bearing's reaction (Fx, Fy) and the natural frequencies at the deck's speed must agree.  A result that
depends on which end the deck numbers from is a modelling error no self-comparison can see: a
spring-preloaded ball pair used to float "the rows with the last row's thrust direction", which is the
other physical row in the mirror image (milling spindle without its tool: nose stiffness 143.9 vs
164.9 N/um at 18,000 rpm).  Which rows float is now a deck key (by thrust direction, ``outward`` by default).

Tolerances: 1e-6 relative (the nonlinear bearing equilibria converge to ~1e-10 of their loads; the
fluid-film thermal balance to its own tolerance, hence 1e-5 there).
"""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest
import yaml

from spindlesim.analysis.modal import solve_modal
from spindlesim.analysis.static import solve_static
from spindlesim.deck import parse_deck
from spindlesim.model.build import build_rotor
from tests.mirror import mirror_deck, mirrored_node

DECKS = Path(__file__).parents[2] / "decks"
ANALYSIS_SECTIONS = ("static", "modal", "campbell", "frf", "unbalance", "chatter", "rotor_transient", "analyses")


def _load(name: str) -> dict:
    d = yaml.safe_load((DECKS / name).read_text())
    for key in ANALYSIS_SECTIONS:
        d.pop(key, None)
    return d


def _milling_without_tool() -> dict:
    d = _load("milling_spindle.yaml")
    d.pop("tool")
    return d


def _roller_asymmetric() -> dict:
    d = _load("validation/roller_rotor.yaml")
    d["disks"][0]["node"] = 4  # off centre: the mirror image is another numbering, not the same deck
    d["loads"] = [{"node": 4, "fx_N": 20.0}]
    return d


def _plain_asymmetric() -> dict:
    d = _load("validation/jeffcott_plain.yaml")
    d["disks"][0]["node"] = 4
    d["bearings"][1]["clearance_mm"] = 0.06
    return d


def _ball_single_rows() -> dict:
    """Two single angular-contact rows, one at each end of the shaft, with their thrust directions
    named along z (the mirror must flip them), under an axial load and a moment."""
    d = _milling_without_tool()
    front, rear = d["bearings"][0], d["bearings"][1]
    for b, direction in ((front, "+z"), (rear, "-z")):
        b.update(arrangement="single", rows=1, axial_direction=direction)
        b.pop("row_spacing_mm")
        b.pop("preload")
    d["loads"].append({"node": 1, "fz_N": 150.0, "my_Nm": 3.0})
    return d


CASES = {
    "linear (seed 003 Table 1 coefficients)": (lambda: _load("seed003_spindle_linear.yaml"), 1e-6),
    "three-lobe fluid film, thermal (seed 003)": (lambda: _load("seed003_three_lobe.yaml"), 1e-5),
    "plain fluid film, isoviscous": (_plain_asymmetric, 1e-6),
    "cylindrical roller": (_roller_asymmetric, 1e-6),
    "ball pairs, spring-preloaded rear (milling spindle, no tool)": (_milling_without_tool, 1e-6),
    "ball pairs and tool (milling spindle)": (lambda: _load("milling_spindle.yaml"), 1e-6),
    "single ball rows, axial load and moment": (_ball_single_rows, 1e-6),
    "ball pair and DTRB (seed 001)": (lambda: _load("seed001_dtrb_rotor.yaml"), 1e-6),
}


def _rotor(d: dict):
    return build_rotor(parse_deck(yaml.safe_dump(d), "mirror.yaml").deck)


@pytest.mark.parametrize("case", list(CASES))
def test_mirror_image_gives_the_same_statics_reactions_and_frequencies(case):
    make, rtol = CASES[case]
    d = make()
    m = mirror_deck(d)
    a, b = _rotor(d), _rotor(m)
    sa, sb = solve_static(a), solve_static(b)
    nodes = np.arange(1, a.n_nodes + 1)
    to_mirror = np.array([mirrored_node(d, k) for k in nodes]) - 1
    scale = np.abs(sa.displacement_m).max()
    np.testing.assert_allclose(sb.displacement_m[to_mirror], sa.displacement_m, rtol=rtol, atol=rtol * scale)
    slope = np.abs(sa.slope_rad).max()
    np.testing.assert_allclose(sb.slope_rad[to_mirror], -sa.slope_rad, rtol=rtol, atol=rtol * slope)
    fa = dict(zip(sa.bearing_names, sa.bearing_force_N))
    fb = dict(zip(sb.bearing_names, sb.bearing_force_N))
    fscale = max(np.abs(sa.bearing_force_N).max(), 1.0)
    for name in fa:
        np.testing.assert_allclose(fb[name], fa[name], rtol=rtol, atol=rtol * fscale, err_msg=name)
    ma, mb = solve_modal(a, n_modes=8), solve_modal(b, n_modes=8)
    np.testing.assert_allclose(mb.frequency_hz, ma.frequency_hz, rtol=rtol)
    np.testing.assert_allclose(mb.damping_ratio, ma.damping_ratio, rtol=1e3 * rtol, atol=1e3 * rtol * 1e-3)


def test_spring_preload_floats_the_outward_thrust_rows_by_default_and_the_key_chooses():
    """Milling spindle without its tool at 18,000 rpm: the rear pair (z = 390 of 440 mm) floats the rows that
    carry thrust outward (+z: the inboard row of its DB pair), which the shaft's thermal growth would
    otherwise load; floating the other row is another machine (and the row the deck numbered from the other
    end used to float before the key existed: nose stiffness 143.9 N/um)."""
    d = _milling_without_tool()
    k = {}
    for side in ("outward", "+z", "inward", "-z"):
        e = copy.deepcopy(d)
        e["bearings"][1]["preload"]["floating"] = side
        k[side] = solve_static(_rotor(e)).static_stiffness_N_m
    assert k["outward"] == pytest.approx(k["+z"], rel=1e-12)
    assert k["inward"] == pytest.approx(k["-z"], rel=1e-12)
    assert k["inward"] / 1e6 == pytest.approx(143.9, abs=0.05)
    assert k["outward"] / 1e6 == pytest.approx(164.9, abs=0.05)
