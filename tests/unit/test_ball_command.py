"""`spindlesim bearing` with held DOFs, race control and the truncation check: deck keys and their located
errors, the kinematics behind M_g, bearing.h5 (state and sweep groups) and the summary."""

import h5py
import numpy as np
import pytest
import yaml
from click.testing import CliRunner
from pydantic import ValidationError

from spindlesim.bearings.ball.kinematics import ball_motion
from spindlesim.cli import main
from spindlesim.deck import DeckError, parse_deck

from .test_ball_section import RPM, bearing, default_section_dict, entry

SINGLE = dict(arrangement="single", rows=None, row_spacing_mm=None, preload=None,
              load={"fx_N": 2000.0, "fz_N": 1000.0})


def deck_text(**changes) -> str:
    d = default_section_dict()
    for key in ("rows", "row_spacing_mm", "preload"):
        if changes.get(key, 0) is None:
            d.pop(key, None)
            changes.pop(key)
    d.update(changes)
    return yaml.safe_dump({"title": "ball command test", "bearing": d}, sort_keys=False)


@pytest.mark.parametrize("model", ["outer_race_control", "inner_race_control", "full"])
def test_gyroscopic_moment_is_the_turning_of_the_ball_axis(model):
    """M_g of the kernel = J w_c |W_x| from the rolling kinematics (kinematics.py) of every ball of a loaded
    pair, for each race control; the controlling race has no spin."""
    b = bearing(model=model)
    w = 15000.0 * RPM
    st = b.solve(np.array([1500.0, -500.0, 400.0, 10.0, 0.0]), w)
    g = b.geometry
    m = ball_motion(np.radians(st.contact_angle_inner_deg), np.radians(st.contact_angle_outer_deg), w,
                    g.pitch_diameter_m, g.ball_diameter_m, model)
    J = g.ball_inertia_kg_m2
    assert st.gyroscopic_moment_Nm == pytest.approx(J * m.cage_rad_s * np.abs(m.ball_radial_rad_s), rel=1e-10)
    if model == "outer_race_control":
        assert np.max(np.abs(m.spin_outer_rad_s)) < 1e-9 * w
    elif model == "inner_race_control":
        assert np.max(np.abs(m.spin_inner_rad_s)) < 1e-9 * w


def test_rotor_entries_take_the_three_race_controls_but_not_auto():
    assert entry(model="inner_race_control").model == "inner_race_control"
    with pytest.raises(ValidationError, match="inner_race_control"):
        entry(model="auto")


@pytest.mark.parametrize("changes, where, words", [
    (dict(held={"theta_y_mrad": 0.0}, load={"fx_N": 1000.0, "my_Nm": 5.0}), "bearing.held.theta_y_mrad",
     "load.my_Nm"),
    (dict(held={"x_um": 2.0}), "bearing.held.x_um", "load.fx_N (1000)"),
    (dict(held={"z_um": 0.0}, load={"fx_N": 0.0}, sweeps={"load": {"component": "fz_N", "start": 0.0, "stop": 10.0,
                                                                   "count": 2}}),
     "bearing.sweeps.load.component", "fz_N is the load of the held DOF z"),
    (dict(SINGLE, preload={"kind": "spring", "axial_N": 200.0}, load={"fz_N": 0.0}, held={"z_um": 0.0}, sweeps={}),
     "bearing.held.z_um", "floats on the spring"),
    (dict(shoulders={"inner_height_mm": 7.0}), "bearing.shoulders.inner_height_mm", "not below the groove radius"),
    (dict(shoulders={"outer_height_mm": 3.0, "outer_angle_deg": 60.0}), "bearing.shoulders", "not both"),
    (dict(held={"theta_x_mrad": 150.0}), "bearing.held.theta_x_mrad", "must be <= 100"),
    (dict(held={"x_um": 700.0}, load={}), "bearing.held.x_um", "beyond the groove-centre distance"),
    (dict(held={"theta_y_mrad": 15.0}), "bearing.held.theta_y_mrad", "the rings would pass through the balls"),
])
def test_bad_held_dofs_and_shoulders_are_located_deck_errors(changes, where, words):
    with pytest.raises(DeckError) as exc:
        parse_deck(deck_text(**changes), "b.yaml")
    text = str(exc.value)
    assert where in text and words in text, text


def test_a_displacement_past_the_grooves_is_a_reported_error():
    from spindlesim.bearings.ball.bearing import BallEquilibriumError

    b = bearing(**{k: v for k, v in SINGLE.items() if k != "load"})
    with pytest.raises(BallEquilibriumError, match="past the outer one at a ball"):
        b.at(np.array([1e-3, 0.0, 0.0, 0.0, 0.0]), 4000.0 * RPM)


def run_cli(tmp_path, name, **changes):
    deck = tmp_path / f"{name}.yaml"
    deck.write_text(deck_text(**changes))
    res = CliRunner().invoke(main, ["bearing", str(deck), "-o", str(tmp_path / name)])
    assert res.exit_code == 0, res.output
    return res.output, h5py.File(tmp_path / name / "bearing.h5", "r")


def test_held_tilt_through_the_cli(tmp_path):
    sweeps = {"speed_rpm": {"start": 0.0, "stop": 20000.0, "count": 3},
              "load": {"component": "fx_N", "start": 0.0, "stop": 2000.0, "count": 2}}
    out, f = run_cli(tmp_path, "held", **SINGLE, held={"theta_x_mrad": 0.0, "theta_y_mrad": 0.0}, model="auto",
                     speed_rpm=0.0, sweeps=sweeps)
    with f:
        g = f["bearing"]
        assert g["displacement"][0] == pytest.approx(6.277e-6, rel=1e-3)
        assert g["holding_load"][4] == pytest.approx(-27.06, rel=1e-3)
        assert g.attrs["held"] == "held theta_x 0 mrad, theta_y 0 mrad" and g.attrs["model_setting"] == "auto"
        assert "tilt_warning" not in g.attrs
        for key in ("speed", "load"):
            s = g[f"sweeps/{key}"]
            for name in ("element_load_inner_N", "element_load_outer_N", "centrifugal_force_N", "gyroscopic_moment_Nm",
                         "contact_angle_inner_deg", "contact_angle_outer_deg", "race_control_criterion",
                         "edge_angle_inner_deg", "truncated_inner", "holding_load", "race_control_model"):
                assert name in s, (key, name)
            assert "inner-race" in s["element_load_inner_N"].attrs["description"]
            assert "outer-race" in s["element_load_N"].attrs["description"]
            assert np.array_equal(s["element_load_N"][()], s["element_load_outer_N"][()])
        sp = g["sweeps/speed"]
        Fc = sp["centrifugal_force_N"][()]
        assert np.all(Fc[0] == 0.0) and np.all(Fc[-1] > 100.0)
        assert np.all(sp["holding_load"][:, 4] < 0.0) and np.all(sp["displacement"][:, 3:] == 0.0)
        # Q_o - Q_i is about the centrifugal force (the gyroscopic couple takes a little)
        gap = sp["element_load_outer_N"][-1] - sp["element_load_inner_N"][-1]
        assert np.all(np.abs(gap - Fc[-1]) < 0.3 * Fc[-1])
        models = [m.decode() if isinstance(m, bytes) else m for m in sp["race_control_model"][()]]
        assert models[-1] == "outer_race_control"
    assert "displacement x 6.277 um, y 0 um, z 21.67 um, theta_x 0 mrad (held), theta_y 0 mrad (held)" in out
    assert "holding load Mx 0 N m, My -27.06 N m" in out
    assert "Jones' criterion" in out and "shoulders at 65 / 64.3 deg" in out


def test_free_single_row_warns_of_its_tilt(tmp_path):
    out, f = run_cli(tmp_path, "free", **SINGLE, speed_rpm=0.0, sweeps={})
    with f:
        g = f["bearing"]
        assert float(g.attrs["free_tilt_rad"]) == pytest.approx(2.2445e-3, rel=1e-3)
        assert g["tilt_held/displacement"][0] == pytest.approx(6.277e-6, rel=1e-3)
        assert g["holding_load"][()] == pytest.approx(np.zeros(5))
    assert "displacement x 33.52 um" in out
    assert "WARNING: bearing '7014C_DB': the free inner ring tilts 2.24 mrad" in out
    assert "it deflects 6.277 um radially" in out


def test_truncation_reaches_the_file_and_the_summary(tmp_path):
    out, f = run_cli(tmp_path, "cut", **SINGLE, speed_rpm=20000.0, shoulders={"inner_angle_deg": 45.0},
                     sweeps={"speed_rpm": {"start": 10000.0, "stop": 20000.0, "count": 3}})
    with f:
        g = f["bearing"]
        n = int(g.attrs["truncated_contacts"])
        assert n > 0 and int(np.sum(g["truncated_inner"][()])) == n
        assert g.attrs["shoulder_angle_inner_deg"] == pytest.approx(45.0)
        assert "speed sweep" in g.attrs["truncation_warning"]
        assert g["sweeps/speed/truncated_inner"][()].shape == (3, 1, 18)
    assert f"TRUNCATED at {n} contact(s)" in out and "WARNING: bearing '7014C_DB', Fx 2000 N, Fz 1000 N" in out
    assert (tmp_path / "cut" / "ball_contact_ellipses.png").exists()
