"""A DTRB at prescribed temperatures (issue 22, item 3: "likewise the axial preload of a DTRB"): the deck key
`temperatures_C` of the `dtrb:` section and of a rotor's `type: dtrb` entry gives the bearing the preload
delta0 its growth gives (bearings/dtrb/thermal.dtrb_preload_change, checked there).

* A uniform temperature changes nothing (every part grows about the same centre by the same strain).
* Cones 10 K warmer than the cup (rollers between) press into the rollers: delta0 rises by the growth
  function's change, and the bearing's radial and axial stiffness under the same load rise with it; cones
  colder than the cup lower both (the change is odd in the ring temperature difference, to first order).
* The rotor entry and the section take the same path; the material's expansion coefficient scales the
  change (half the coefficient, half the change).
"""

import numpy as np
import pytest

from spindlesim.bearings.dtrb.bearing import DtrbBearing
from spindlesim.bearings.dtrb.section import DtrbMaterial, at_deck_temperatures, geometry_from, material_body
from spindlesim.bearings.dtrb.thermal import dtrb_preload_change
from spindlesim.bearings.temperatures import PartTemperatures as DtrbTemperatures
from spindlesim.deck import default_deck
from spindlesim.thermal.growth import BEARING_STEEL
from spindlesim.thermal.growth_bearings import BearingTemperatures

LOAD = np.array([5000.0, 0.0, 5000.0, 0.0, 0.0])


@pytest.fixture(scope="module")
def section():
    return default_deck("dtrb").deck.dtrb


def _at(section, inner, outer, rollers, material=None):
    b = DtrbBearing(geometry_from(section.bearing), 30e-6, body=material_body(material or section.bearing.material))
    t = DtrbTemperatures(inner_ring=inner, outer_ring=outer, rolling_elements=rollers)
    return b, at_deck_temperatures(b, t)


def test_uniform_temperature_keeps_the_preload(section):
    b, hot = _at(section, 60.0, 60.0, 60.0)
    assert hot.preload_m == pytest.approx(b.preload_m, abs=1e-15)


def test_warm_cones_raise_the_preload_and_the_stiffness(section):
    b, warm = _at(section, 40.0, 30.0, 35.0)
    _, cold = _at(section, 30.0, 40.0, 35.0)
    ref = dtrb_preload_change(b.geometry, BearingTemperatures(40.0, 30.0, 35.0), BEARING_STEEL).preload_change_m
    assert ref > 5e-6  # about 17 um on the default deck's bearing
    assert warm.preload_m == pytest.approx(b.preload_m + ref, rel=1e-12)
    assert cold.preload_m == pytest.approx(b.preload_m - ref, rel=1e-9)
    k = {}
    for name, brg in (("base", b), ("warm", warm), ("cold", cold)):
        st = brg.solve(LOAD, 0.0)
        K = brg.stiffness(st.displacement)
        k[name] = (K[0, 0], K[2, 2])
    assert k["warm"][0] > k["base"][0] > k["cold"][0] and k["warm"][1] > k["base"][1] > k["cold"][1]


def test_expansion_coefficient_scales_the_change(section):
    b, steel = _at(section, 40.0, 30.0, 35.0)
    half = DtrbMaterial(thermal_expansion_1_K=0.5 * BEARING_STEEL.expansion_1_K)
    _, low = _at(section, 40.0, 30.0, 35.0, half)
    assert low.preload_m - b.preload_m == pytest.approx(0.5 * (steel.preload_m - b.preload_m), rel=1e-9)


def test_rotor_entry_takes_the_temperatures():
    import yaml

    from spindlesim.deck import parse_deck
    from spindlesim.model.build import build_rotor
    from pathlib import Path

    path = Path(__file__).parents[2] / "decks" / "seed001_dtrb_rotor.yaml"
    d = yaml.safe_load(path.read_text())
    entry = next(e for e in d["bearings"] if e["type"] == "dtrb")
    cold = [b for b in build_rotor(parse_deck(yaml.safe_dump(d), "a.yaml").deck).bearings if b.name == entry["name"]][0]
    entry["temperatures_C"] = {"inner_ring": 40.0, "outer_ring": 30.0, "rolling_elements": 35.0}
    warm = [b for b in build_rotor(parse_deck(yaml.safe_dump(d), "b.yaml").deck).bearings if b.name == entry["name"]][0]
    ref = dtrb_preload_change(cold.geometry, BearingTemperatures(40.0, 30.0, 35.0), BEARING_STEEL).preload_change_m
    assert warm.preload_m == pytest.approx(cold.preload_m + ref, rel=1e-12)


def test_cylindrical_roller_entry_takes_its_clearance_from_the_temperatures():
    """A `type: roller` entry with `temperatures_C` gets the radial clearance of its grown parts: by hand,
    P_d' = P_d + d_o a (T_o - T0) - d_i a (T_i - T0) - 2 D_w a (T_w - T0) (free rings), the entry's radial
    clearance being half the diametral one: inner ring 50 C, rollers 40 C, outer ring 30 C take the seed
    000 bearing's 10 um radial clearance to 7.30 um."""
    from spindlesim.bearings.roller.section import RollerEntry, build, operating_clearance_mm

    base = dict(type="roller", name="r", node=1, radial_clearance_mm=0.010)
    e = RollerEntry.model_validate(base | {"temperatures_C": {"inner_ring": 50.0, "outer_ring": 30.0,
                                                             "rolling_elements": 40.0}})
    a, di, do, dw = 11.5e-6, e.inner_raceway_diameter_mm, e.outer_raceway_diameter_mm, e.roller_diameter_mm
    by_hand = 0.010 + 0.5 * (do * a * 10.0 - di * a * 30.0 - 2 * dw * a * 20.0)
    assert operating_clearance_mm(e) == pytest.approx(by_hand, rel=1e-12)
    assert operating_clearance_mm(RollerEntry.model_validate(base)) == 0.010
    uniform = RollerEntry.model_validate(base | {"temperatures_C": {"inner_ring": 60.0, "outer_ring": 60.0,
                                                                   "rolling_elements": 60.0}})
    grown_gap = 0.5 * (do - di - 2 * dw) * a * 40.0  # a uniform growth scales the raceway gap as well
    assert operating_clearance_mm(uniform) == pytest.approx(0.010 + grown_gap, rel=1e-9)
    assert build(e).radial_clearance_m == pytest.approx(by_hand * 1e-3, rel=1e-12)


def test_temperatures_apply_to_the_assembled_preload_not_the_last_one(section):
    """A thermal loop calls ``at_temperatures`` on the bearing of each pass: the change is from the cold
    assembly's delta0 every time, never added twice; freezing at an operating point keeps it."""
    b, warm = _at(section, 40.0, 30.0, 35.0)
    t = BearingTemperatures(40.0, 30.0, 35.0)
    assert warm.at_temperatures(t).preload_m == pytest.approx(warm.preload_m, rel=1e-12)
    assert warm.at_temperatures(BearingTemperatures.uniform(20.0)).preload_m == pytest.approx(b.preload_m, abs=1e-15)
    frozen = warm.at_operating_point(0.0, np.zeros(5))
    assert frozen.made_preload_m == b.preload_m and frozen.body is warm.body
