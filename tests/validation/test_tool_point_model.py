"""The tool and holder on the spindle nose: bending the right way (issue 21, item 1).

The holder and tool of a ``tool:`` section extend outwards from the nose; on the usual deck (nose at
node 1) that is towards -z.  Two checks that do not compare the model with itself:

1. Closed form: whatever the spindle and its bearings do, the tool-tip deflection under a tip force P,
   less the rigid-body motion of the nose (its displacement plus its slope times the distance to the
   tip), is the deflection of the holder-tool chain as a cantilever clamped at the nose: for each beam
   segment (from the nose outwards) with the shear P and the moment P a at its far end (a = distance to
   the tip),

       deflection  P L^3/(3 E I) + P a L^2/(2 E I) + P L/(kappa G A),  rotation  P L^2/(2 E I) + P a L/(E I),

   carried to the tip by the rotation, and each joint adds P/k_t and a rotation P a/k_r
   (Timoshenko's cantilever, e.g. Gere and Timoshenko, Mechanics of Materials, sec. 9.4 and 9.9;
   Cowper's shear coefficient for a hollow circle).  Nelson's element is exact for end loads, so the
   model must match to round-off.
2. Mirror image: the milling spindle numbered from the other end (element k -> 19 - k, node k ->
   20 - k, the tool on node 19 pointing along +z) is the same machine: the tool-tip deflection under a
   tip load and the natural frequencies (at rest and at the deck speed) must agree to 1e-6.  (Both
   pairs position-preloaded here: which row of a spring-preloaded pair floats is item 5.)
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
from tests.mirror import mirror_deck

MILLING = Path(__file__).parents[2] / "decks" / "milling_spindle.yaml"


def _cowper(nu: float, do: float, di: float) -> float:
    m2 = (di / do) ** 2
    return 6 * (1 + nu) * (1 + m2) ** 2 / ((7 + 6 * nu) * (1 + m2) ** 2 + (20 + 12 * nu) * m2)


def _beam(row):
    do, di, L, _rho, E, G, nu, _fa = row
    do, di, L, E, G = do * 1e-3, di * 1e-3, L * 1e-3, E * 1e9, G * 1e9
    return ("beam", L, E * np.pi / 64 * (do**4 - di**4), _cowper(nu, do, di) * G * np.pi / 4 * (do**2 - di**2))


def _chain(tool_section) -> list:
    """Parts of the tool section from the nose outwards."""
    parts = []
    if tool_section.get("interface"):
        j = tool_section["interface"]
        parts.append(("joint", float(j["translational_N_m"]), float(j["rotational_Nm_rad"])))
    parts += [_beam(r) for r in tool_section["holder"]["elements"]]
    j = tool_section["joint"]
    parts.append(("joint", float(j["translational_N_m"]), float(j["rotational_Nm_rad"])))
    parts += [_beam(r) for r in tool_section["tool"]["elements"]]
    return parts


def cantilever_tip_deflection(parts, P: float) -> float:
    """Tip deflection of the chain clamped at its base under the tip force P (module note)."""
    length = sum(p[1] for p in parts if p[0] == "beam")
    w = theta = 0.0
    x = 0.0  # distance from the base
    for p in parts:
        if p[0] == "joint":
            a = length - x
            w += P / p[1]
            theta += P * a / p[2]
            continue
        _, L, EI, kGA = p
        a = length - x - L  # lever of the tip force about the segment's far end
        w += theta * L + P * L**3 / (3 * EI) + P * a * L**2 / (2 * EI) + P * L / kGA
        theta += P * L**2 / (2 * EI) + P * a * L / EI
        x += L
    return w


def _deck_dict() -> dict:
    d = yaml.safe_load(MILLING.read_text())
    for key in ("static", "modal", "campbell", "frf", "unbalance", "chatter"):
        d.pop(key, None)
    for b in d["bearings"]:
        if b.get("preload", {}).get("kind") == "spring":
            b["preload"] = {"kind": "position", "axial_um": 10.0}
    return d


def _rotor(d: dict, tip_load_N: float = 0.0, speed_rpm: float | None = None):
    d = copy.deepcopy(d)
    d["loads"] = [] if tip_load_N == 0 else [{"node": 26, "fx_N": tip_load_N}]
    if speed_rpm is not None:
        d["operating"]["speed_rpm"] = speed_rpm
    return build_rotor(parse_deck(yaml.safe_dump(d), "mill.yaml").deck)


@pytest.mark.parametrize("mirrored", [False, True])
def test_tool_tip_deflection_beyond_the_nose_tangent_is_the_cantilever_closed_form(mirrored):
    d = _deck_dict()
    d["operating"]["gravity"] = False
    if mirrored:
        d = mirror_deck(d)
    P = 200.0
    rotor = _rotor(d, P, speed_rpm=0.0)
    r = solve_static(rotor)
    nose = d["tool"].get("holder_node", 1) - 1
    tip = rotor.tool_tip
    z = rotor.node_z_m
    assert (z[tip] < z[nose]) != mirrored  # outwards from the nose
    x, slope_y = r.displacement_m[:, 0], r.slope_rad[:, 1]  # theta_y = dx/dz
    relative = x[tip] - (x[nose] + slope_y[nose] * (z[tip] - z[nose]))
    expected = cantilever_tip_deflection(_chain(d["tool"]), P)
    assert expected > 0
    assert relative == pytest.approx(expected, rel=1e-7)
    # the tool continues the nose's slope outwards: the tip moves more than the nose
    assert x[tip] > x[nose] > 0


def test_mirror_image_of_the_milling_spindle_gives_the_same_tool_tip_and_frequencies():
    d = _deck_dict()
    m = mirror_deck(d)
    tips = []
    for deck in (d, m):
        rotor = _rotor(deck, 200.0, speed_rpm=0.0)
        r = solve_static(rotor, stiffness_node=rotor.tool_tip)
        tips.append((r.displacement_m[rotor.tool_tip], r.static_stiffness_N_m))
    (u0, k0), (u1, k1) = tips
    np.testing.assert_allclose(u1, u0, rtol=1e-6, atol=1e-6 * np.abs(u0).max())
    assert k1 == pytest.approx(k0, rel=1e-6)
    for speed in (0.0, 18000.0):
        f = [solve_modal(_rotor(deck, speed_rpm=speed), n_modes=10).frequency_hz for deck in (d, m)]
        np.testing.assert_allclose(f[1], f[0], rtol=1e-6)
