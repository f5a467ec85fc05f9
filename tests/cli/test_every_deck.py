"""Every command on every example deck and on a minimal deck of each bearing family, through the CLI
(issue 21): exit 0, every promised dataset present (../shared/DESIGN.md section 5 and
docs/output-format.md), finite results (the writer refuses NaN/Inf unless a dataset declares NaN as
its fill value: checked here on the files), units on every dataset.

Speeds and durations are cut down where a command takes an option for it; nothing else is changed."""

from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from tests.units import unit_problems

ROOT = Path(__file__).parents[2]
DECKS = ROOT / "decks"

PROMISED = {
    "static": ["/static/node_z_m", "/static/displacement_m", "/static/slope_rad", "/static/bearing_force_N"],
    "modal": ["/modal/frequency_hz", "/modal/damping_ratio", "/modal/log_dec", "/modal/whirl", "/modal/mode_shape"],
    "campbell": ["/campbell/speed_rpm", "/campbell/frequency_hz", "/campbell/log_dec", "/campbell/whirl"],
    "frf": ["/frf/frequency_hz", "/frf/receptance_m_N"],
    "unbalance": ["/unbalance/speed_rpm", "/unbalance/response_m"],
    "thermal": ["temperature_mean_C", "temperature_out_C", "viscosity_Pa_s", "sommerfeld", "eccentricity_ratio",
                "attitude_angle_deg", "min_film_m", "friction_torque_Nm", "oil_flow_m3_s", "reynolds_number"],
    "coefficients": ["K_N_m", "C_Ns_m", "k", "c", "sommerfeld", "eccentricity_ratio", "attitude_angle_deg"],
    "transient": ["/transient/time_s", "/transient/displacement_m"],
    "dtrb": ["/dtrb/stiffness", "/dtrb/reaction", "/dtrb/roller_load_N"],
    "contact": ["/contact/x_m", "/contact/y_m", "/contact/pressure_Pa"],
    "bearing": ["/bearing/displacement", "/bearing/stiffness", "/bearing/element_load_N",
                "/bearing/contact_angle_inner_deg", "/bearing/contact_angle_outer_deg", "/bearing/max_pressure_Pa",
                "/bearing/life_L10_Mrev"],
    "chatter": ["/chatter/speed_rpm", "/chatter/limit_depth_m", "/chatter/chatter_frequency_hz"],
    "tools": ["/tools/spindle/receptance", "/tools/em16_shrink_60/receptance_m_N", "/tools/em16_shrink_60/frequency_hz"],
}
#: thermal.h5 of a spindle's thermal model (deck section spindle_thermal)
SPINDLE_THERMAL = ["/spindle_thermal/speed_rpm", "/spindle_thermal/temperature_C", "/spindle_thermal/heat_W",
                   "/spindle_thermal/row_thrust_N", "/spindle_thermal/tool_tip_axial_drift_m",
                   "/spindle_thermal/tool_tip_radial_drift_m",
                   "/spindle_thermal/warm_up/time_s", "/spindle_thermal/warm_up/natural_frequency_hz"]
#: quantities an isoviscous film without density and specific heat does not have (no heat balance)
NO_HEAT_BALANCE = {"temperature_mean_C", "temperature_out_C", "oil_flow_m3_s", "reynolds_number"}

ROW = "[50.0, 0.0, 50.0, 7850.0, 208.0, 80.0, 0.3, 0.0]"
SHAFT = "shaft:\n  elements: [" + ", ".join([ROW] * 6) + "]\n"
TAIL = ("operating: {speed_rpm: 3000, gravity: true}\nloads:\n  - {node: 7, fx_N: 100.0}\n"
        "unbalance: {node: 7, amount_g_mm: 10.0, output: {node: 7, dof: x}, speeds_rpm: {start: 500, stop: 6000, count: 12}}\n")
PLAIN = "{type: plain, diameter_mm: 50.0, width_mm: 25.0, clearance_mm: 0.05, oil: %s}"
FAMILIES = {
    "plain_isoviscous": PLAIN % "{viscosity_Pa_s: 0.01}",
    "plain_thermal": PLAIN % "{grade: ISO VG 32, density_kg_m3: 870, specific_heat_J_kgK: 1900, inlet_C: 40}",
    "three_lobe": ("{type: three_lobe, diameter_mm: 50.0, width_mm: 25.0, clearance_mm: 0.03, preload: 0.5, "
                   "oil: {grade: ISO VG 32, density_kg_m3: 870, specific_heat_J_kgK: 1900, inlet_C: 40}}"),
    "linear": "{type: linear, K_N_m: [[2.0e8, 1.0e7], [-1.0e7, 2.5e8]], C_Ns_m: [[2000.0, 0.0], [0.0, 2500.0]]}",
    "ball_row": ("{type: ball, balls: 16, ball_diameter_mm: 11.1125, pitch_diameter_mm: 70.0, contact_angle_deg: 15.0, "
                 "inner_conformity: 0.52, outer_conformity: 0.53, axial_direction: '%s'}"),
    "ball_pair": ("{type: ball, balls: 16, ball_diameter_mm: 11.1125, pitch_diameter_mm: 70.0, contact_angle_deg: 15.0, "
                  "inner_conformity: 0.52, outer_conformity: 0.53, arrangement: DB, rows: 2, row_spacing_mm: 20.0, "
                  "preload: {kind: position, axial_um: 10.0}}"),
    "dtrb": ("{type: dtrb, preload_um: 40.0, geometry: {rollers_per_row: 20, cup_angle_deg: 15.64, "
             "pitch_diameter_mm: 70.0, large_end_diameter_mm: 10.0, roller_length_mm: 14.0, "
             "large_end_offset_mm: 18.0, crown_radius_mm: 2680.0, slices: 20}}"),
    "roller": "{type: roller, rollers: 12, model: rigid_race}",
}


def _family_deck(family: str) -> str:
    entry = FAMILIES[family]
    bearings = []
    for name, node, direction in (("front", 2, "+z"), ("rear", 6, "-z")):
        e = entry % direction if family == "ball_row" else entry
        bearings.append("  - " + e[:-1] + f", name: {name}, node: {node}}}")
    if family == "roller":  # the seed 000 bearing's 15 mm journals
        return (SHAFT.replace("[50.0,", "[15.0,") + "bearings:\n" + "\n".join(bearings) + "\n"
                + TAIL.replace("fx_N: 100.0", "fx_N: 20.0").replace("gravity: true", "gravity: false"))
    return f"title: {family}\n{SHAFT}bearings:\n" + "\n".join(bearings) + "\n" + TAIL


ROTOR = ["static", "modal", "campbell", "frf", "unbalance"]
FLUID = ["thermal", "coefficients"]
#: example decks -> commands that apply to them (a deck without the section a command needs is a deck error)
EXAMPLES = {
    "milling_spindle.yaml": ROTOR + ["chatter", "thermal"],  # thermal: the spindle's thermal model
    "seed001_dtrb_rotor.yaml": ROTOR + ["transient"],
    "seed003_spindle_linear.yaml": ROTOR,
    "seed003_three_lobe.yaml": ROTOR + FLUID + ["chatter"],
    "validation/jeffcott_plain.yaml": ROTOR + FLUID + ["transient"],
    "validation/roller_rotor.yaml": ["static", "modal", "campbell", "frf", "transient"],  # no unbalance section
    "validation/spindle_runup.yaml": ROTOR + ["transient"],
    "seed000_roller_bearing.yaml": ["transient"],
    "dtrb_wheel_hub.yaml": ["dtrb"],
    "ball_single_row.yaml": ["bearing"],
    "contact_roller.yaml": ["contact"],
    "tool_library.yaml": ["tools"],
}
EMBEDDED = {"bearing": "bearing", "dtrb": "dtrb", "contact": "contact", "transient": "transient",
            "chatter": "milling_spindle", "thermal": "spindle", "coefficients": "spindle", "tools": "tool_library"}
SHORT = {"campbell": ["--speeds", "0:6000:4"], "transient": ["--duration", "0.02"], "tools": ["--no-lobes"]}


def _cases():
    for deck, commands in EXAMPLES.items():
        for c in commands:
            yield pytest.param(DECKS / deck, c, id=f"{deck}-{c}")
    for family in FAMILIES:
        for c in ROTOR + (FLUID if family in ("plain_isoviscous", "plain_thermal", "three_lobe") else []):
            yield pytest.param(family, c, id=f"{family}-{c}")
    for c, name in EMBEDDED.items():
        yield pytest.param(None, c, id=f"default-{c}")


def _check_file(path: Path, command: str) -> None:
    with h5py.File(path) as f:
        assert bool(f.attrs["complete"]), f.attrs.get("incomplete_reason")
        names: list[str] = []
        f.visititems(lambda n, o: names.append("/" + n) if isinstance(o, h5py.Dataset) else None)
        promised = SPINDLE_THERMAL if command == "thermal" and "spindle_thermal" in f else PROMISED[command]
        for key in promised:
            if key.startswith("/"):
                assert key in f, f"{path.name}: {key} missing"
            else:  # per bearing: /<command>/<bearing>/<key>
                for g in f[command].values():
                    absent = str(g.attrs.get("not_computed", ""))
                    if key in NO_HEAT_BALANCE and key in absent:
                        continue
                    assert key in g, f"{path.name}: {g.name}/{key} missing"
        for n in names:
            ds = f[n]
            assert "units" in ds.attrs, n
            if ds.dtype.kind in "fc":
                v = ds[()]
                fill = "_FillValue" in ds.attrs
                ok = np.isfinite(v) | (np.isnan(v) if fill else False)
                assert np.all(ok), f"{path.name}: {n} has non-finite values"


@pytest.mark.slow
@pytest.mark.parametrize("deck,command", list(_cases()))
def test_every_command_on_every_deck_finishes_with_every_promised_dataset(deck, command, tmp_path):
    if isinstance(deck, str):
        path = tmp_path / f"{deck}.yaml"
        path.write_text(_family_deck(deck))
        deck = path
    args = [command] + ([str(deck)] if deck is not None else []) + ["-o", str(tmp_path / "out"), "-q"]
    res = CliRunner().invoke(main, args + SHORT.get(command, []))
    assert res.exit_code == 0, res.output
    _check_file(tmp_path / "out" / f"{command}.h5", command)
    for h5 in (tmp_path / "out").glob("*.h5"):  # every dataset has a unit, the one its name says (issue 33)
        assert not unit_problems(h5), unit_problems(h5)
    assert list((tmp_path / "out").glob("*.png")), "no figure"
    assert not list((tmp_path / "out").glob("*.tmp*"))


@pytest.mark.parametrize("command,deck", [("chatter", "seed003_spindle_linear.yaml"),
                                          ("unbalance", "validation/roller_rotor.yaml"),
                                          ("dtrb", "seed003_spindle_linear.yaml"),
                                          ("contact", "seed003_spindle_linear.yaml"),
                                          ("bearing", "seed003_spindle_linear.yaml"),
                                          ("tools", "seed003_spindle_linear.yaml")])
def test_a_command_whose_deck_section_is_missing_is_a_deck_error(command, deck, tmp_path):
    res = CliRunner().invoke(main, [command, str(DECKS / deck), "-o", str(tmp_path / "out")])
    assert res.exit_code == 2, res.output
    assert f"needs a '{command}' section" in res.output and "Traceback" not in res.output
    assert not (tmp_path / "out").exists() or not list((tmp_path / "out").iterdir())
