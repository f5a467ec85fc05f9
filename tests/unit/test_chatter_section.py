"""Deck section ``chatter:``: validation messages and the build to SI."""

import numpy as np
import pytest
from pydantic import ValidationError

from spindlesim.chatter import (ChatterSection, MillingProcess, ToolPointModel, TurningProcess, build_chatter,
                                write_frf_csv)
from spindlesim.chatter.frf import Mode

MILL = {"operation": "milling", "speeds_rpm": {"start": 5000.0, "stop": 25000.0, "count": 11},
        "Kt_N_mm2": 600.0, "Kn_N_mm2": 200.0, "teeth": 2, "tool_diameter_mm": 20.0, "radial_depth_mm": 1.0,
        "mode": "down"}
TURN = {"operation": "turning", "speeds_rpm": {"start": 500.0, "stop": 5000.0, "count": 11},
        "Ks_N_mm2": 2000.0, "force_angle_deg": 70.0,
        "frf": {"modes": [{"direction": "x", "frequency_hz": 180.0, "damping_ratio": 0.05, "stiffness_N_m": 2.0e7}]}}


def test_milling_section_builds_si_process():
    spec = build_chatter(ChatterSection.model_validate(MILL))
    p = spec.process
    assert isinstance(p, MillingProcess)
    assert p.Kt_N_m2 == 600e6 and p.Kr == pytest.approx(1 / 3) and p.radial_depth_m == pytest.approx(1e-3)
    assert spec.frf_source == "rotor" and spec.tool is None and spec.frf_at_each_speed is None
    assert spec.resolved_method == "semi_discretization"  # 5 % immersion, auto
    assert np.allclose(spec.speeds_rpm, np.linspace(5000, 25000, 11))


def test_turning_section_with_modes_and_options():
    d = dict(TURN, feed_direction_deg=30.0, frf_at_each_speed=False,
             simulate={"points": [{"speed_rpm": 1000.0, "depth_mm": 1.0}], "tooth_periods": 100},
             semi_discretization={"order": 0, "depth_max_mm": 5.0})
    spec = build_chatter(ChatterSection.model_validate(d))
    assert isinstance(spec.process, TurningProcess)
    assert spec.process.Ks_N_m2 == 2000e6 and spec.process.feed_direction_rad == pytest.approx(np.pi / 6)
    assert isinstance(spec.tool, ToolPointModel) and spec.frf_source == "modes"
    assert spec.resolved_method == "oriented_frf"
    assert spec.simulation_points == ((1000.0, 1e-3),)
    assert spec.method_options["order"] == 0 and spec.method_options["depth_max_m"] == pytest.approx(5e-3)


def test_frf_file_relative_to_deck_dir(tmp_path):
    model = ToolPointModel.from_modes([Mode("x", 500.0, 0.03, 2e7)])
    write_frf_csv(tmp_path / "tap_x.csv", model.frf(np.linspace(100.0, 1000.0, 101)), direction="x")
    d = dict(TURN, frf={"files": [{"path": "tap_x.csv", "direction": "x"}]})
    spec = build_chatter(ChatterSection.model_validate(d), tmp_path)
    assert spec.frf_source == "file" and spec.tool.H.shape == (101, 2, 2)


@pytest.mark.parametrize("change, fragment", [
    ({"Kr": 0.3}, "exactly one of Kn_N_mm2 and Kr"),
    ({"teeth": None}, "needs teeth"),
    ({"Ks_N_mm2": 100.0}, "Ks_N_mm2 do(es) not apply"),
    ({"radial_depth_mm": 30.0}, "radial_depth_mm exceeds"),
    ({"method": "oriented_frf"}, "for turning"),
    ({"frf": {"modes": []}}, "at least 1 item"),
    ({"frf": {"mode": []}}, "frf is 'rotor'"),
    ({"mode": "climb"}, "'up' or 'down'"),
    ({"speeds_rpm": {"start": 0.0, "stop": 100.0, "count": 3}}, "0 < start < stop"),
    ({"unknown_key": 1}, "Extra inputs"),
])
def test_section_errors(change, fragment):
    d = dict(MILL)
    for k, v in change.items():
        if v is None:
            d.pop(k)
        else:
            d[k] = v
    with pytest.raises(ValidationError) as err:
        ChatterSection.model_validate(d)
    assert fragment in str(err.value)


def test_frf_error_path_skips_union_tag():
    d = dict(TURN, frf={"modes": [{"direction": "x", "frequency_hz": 180.0, "damping_ratio": 2.0,
                                   "stiffness_N_m": 2.0e7}]})
    with pytest.raises(ValidationError) as err:
        ChatterSection.model_validate(d)
    loc = err.value.errors()[0]["loc"]
    assert loc == ("frf", "Modes", "modes", 0, "damping_ratio")  # capitalised tag: skipped by the deck loader
