"""Deck keys of the bearing at temperature (temperatures_C, fits_um, mounting, thermal_expansion_1_K): located
errors (exit 2), defaults, the standalone command's report, and a rotor deck's ball entry at temperature."""

import math
from pathlib import Path

import h5py
import numpy as np
import pytest
import yaml
from click.testing import CliRunner

from spindlesim.bearings.ball import BallSection, build, default_deck_text
from spindlesim.bearings.ball.growth import ball_bearing_growth
from spindlesim.bearings.ball.section import thermal_inputs
from spindlesim.cli import main
from spindlesim.thermal.growth_bearings import BearingTemperatures

from .test_ball_section import entry

RPM = math.pi / 30.0
HOT = {"inner_ring": 40.0, "outer_ring": 30.0, "rolling_elements": 35.0, "reference": 20.0}
MOUNT = {"bore_mm": 70.0, "outer_diameter_mm": 110.0, "shaft_bore_mm": 30.0}


def section_text(**changes) -> str:
    d = yaml.safe_load(default_deck_text())
    d["bearing"]["sweeps"] = {}
    d["bearing"].update(changes)
    return yaml.safe_dump(d, sort_keys=False)


def test_expansion_defaults_steel_rings_and_ceramic_balls():
    e = entry(temperatures_C=HOT)
    temps, ring, ball, mounting = thermal_inputs(e)
    assert ring.expansion_1_K == 11.5e-6 and ball.expansion_1_K == 11.5e-6 and mounting is None
    e = entry(temperatures_C=HOT, ball_material={"E_GPa": 310.0, "poisson": 0.26, "density_kg_m3": 3200.0})
    assert thermal_inputs(e)[2].expansion_1_K == 3.2e-6
    e = entry(temperatures_C=HOT, material={"thermal_expansion_1_K": 12.5e-6})
    assert thermal_inputs(e)[1].expansion_1_K == 12.5e-6
    assert thermal_inputs(entry()) is None and build(entry()).growth is None


def test_entry_at_temperature_builds_the_grown_bearing():
    pair = dict(arrangement="DB", rows=2, row_spacing_mm=20.0, preload={"kind": "position", "axial_um": 21.0})
    b = build(entry(temperatures_C=HOT, **pair))
    cold = build(entry(**pair))
    gr = ball_bearing_growth(cold.geometry, cold.preload, BearingTemperatures(40.0, 30.0, 35.0))
    assert b.geometry.clearance_m == pytest.approx(gr.clearance_m, rel=1e-14)
    assert b.preload.row_offsets(2).tolist() == pytest.approx((cold.preload.row_offsets(2)
                                                               + gr.row_offset_change_m).tolist(), rel=1e-14)
    assert b.solve(np.zeros(5), 0.0).row_axial_load_N[0] > 4.0 * cold.solve(np.zeros(5), 0.0).row_axial_load_N[0]
    # with a mounting the inner ring also grows with speed: more preload than without it at 15,000 rpm
    m = build(entry(temperatures_C=HOT, mounting=MOUNT, **pair))
    w = 15000 * RPM
    assert m.speed_growth is not None and m.speed_growth(w) > 1e-6 and b.speed_growth is None
    assert m.solve(np.zeros(5), w).row_axial_load_N[0] > b.solve(np.zeros(5), w).row_axial_load_N[0]


@pytest.mark.parametrize("changes, where, message", [
    (dict(temperatures_C=dict(HOT, rolling_elements=-300.0)), "bearing.temperatures_C",
     "rolling_elements = -300 C is at or below absolute zero"),
    (dict(material={"thermal_expansion_1_K": -1.1e-5}), "bearing.material", "is negative"),
    (dict(fits_um={"shaft": 3000.0}, mounting=MOUNT), "bearing.fits_um.shaft", "fits are diametral"),
    (dict(fits_um={"shaft": 3.0}), "bearing.fits_um", "fits_um needs mounting"),
    (dict(mounting=dict(MOUNT, bore_mm=80.0)), "bearing.mounting.bore_mm", "below the inner raceway"),
    (dict(temperatures_C=dict(HOT, outer_ring=900.0)), "bearing.temperatures_C", "no valid geometry"),
])
def test_bad_growth_input_is_a_located_deck_error(tmp_path, changes, where, message):
    deck = tmp_path / "bad.yaml"
    deck.write_text(section_text(**changes))
    out = tmp_path / "out"
    res = CliRunner().invoke(main, ["bearing", str(deck), "-o", str(out)])
    assert res.exit_code == 2, res.output
    assert f"{deck}:" in res.output and f"{where}: " in res.output and message in res.output
    assert not out.exists()


def test_bearing_command_reports_the_operating_clearance_and_preload(tmp_path):
    deck = tmp_path / "hot.yaml"
    deck.write_text(section_text(temperatures_C=HOT, fits_um={"shaft": 3.0, "housing": -2.0}, mounting=MOUNT))
    res = CliRunner().invoke(main, ["bearing", str(deck), "-o", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    assert "at temperature: operating clearance" in res.output and "FIT LOST: inner ring" in res.output
    sec = BallSection.model_validate(yaml.safe_load(deck.read_text())["bearing"])
    b = build(sec)
    w = sec.speed_rpm * RPM
    with h5py.File(tmp_path / "o" / "bearing.h5") as f:
        g = f["bearing"]
        assert float(g["operating_clearance_at_rest_m"][()]) == pytest.approx(b.growth.clearance_m, rel=1e-12)
        assert float(g["operating_clearance_m"][()]) == pytest.approx(b.growth.clearance_m - 2 * b.speed_growth(w),
                                                                      rel=1e-12)
        assert g["preload_offset_m"][()].tolist() == pytest.approx(b.preload.row_offsets(2).tolist(), rel=1e-12)
        assert g["preload_N"][()].tolist() == pytest.approx(b.solve(np.zeros(5), w).row_axial_load_N.tolist(),
                                                            rel=1e-8)
        assert g.attrs["temperature_inner_ring_C"] == 40.0 and int(g.attrs["inner_fit_lost"]) == 1
        assert float(g["outer_fit_interference_m"][()]) == pytest.approx(-2e-6 + 110e-3 * 10.0 * (11.5e-6 - 10.5e-6))


def test_rotor_deck_ball_entry_at_temperature(tmp_path):
    text = (Path(__file__).parents[2] / "decks" / "milling_spindle.yaml").read_text()
    d = yaml.safe_load(text)
    d.pop("spindle_thermal")  # prescribed temperatures instead of the spindle's thermal model
    front = next(b for b in d["bearings"] if b.get("type") == "ball")
    front["temperatures_C"] = HOT
    deck = tmp_path / "spindle.yaml"
    deck.write_text(yaml.safe_dump(d, sort_keys=False))
    res = CliRunner().invoke(main, ["static", str(deck), "-o", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output


def test_fit_in_millimetres_and_expansion_in_the_wrong_unit_warn(tmp_path):
    deck = tmp_path / "w.yaml"
    deck.write_text(section_text(fits_um={"shaft": 0.003}, mounting=dict(MOUNT, housing_material={
        "E_GPa": 110.0, "poisson": 0.26, "density_kg_m3": 7200.0, "thermal_expansion_1_K": 1.05e-4})))
    res = CliRunner().invoke(main, ["--strict", "bearing", str(deck), "-o", str(tmp_path / "o")])
    assert res.exit_code == 2, res.output
    assert "bearing.fits_um.shaft: " in res.output and "was it given in millimetres" in res.output
    assert "bearing.mounting.housing_material.thermal_expansion_1_K: " in res.output
