"""Result summaries on the terminal (issue 16, item 8): text by default, --quiet, --json."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.analysis.resonance import required_separation_margin

DECKS = Path(__file__).parents[2] / "decks"


@pytest.mark.parametrize("af,below,expect", [
    (2.0, True, 0.0),  # AF < 2.5: critically damped, no margin (API 684)
    (5.0, True, 0.17 * (1 - 1 / 3.5)),  # 12.1 %
    (5.0, False, 0.10 + 0.17 * (1 - 1 / 3.5)),  # 22.1 %
    (100.0, True, 0.16),  # capped at 16 % below the operating speed
    (100.0, False, 0.26),  # capped at 26 % above
])
def test_api684_separation_margin(af, below, expect):
    assert required_separation_margin(af, below) == pytest.approx(expect, rel=1e-12)


def _run(tmp_path, *args):
    res = CliRunner().invoke(main, [*args, "-o", str(tmp_path)])
    assert res.exit_code == 0, res.output
    return res.output


def test_modal_prints_a_table_after_the_paths(tmp_path):
    out = _run(tmp_path, "modal", "--modes", "4")
    lines = out.splitlines()
    assert lines[0].endswith("modal.h5")
    assert any("frequency Hz" in ln and "whirl" in ln for ln in lines)
    rows = [ln for ln in lines if ln.strip()[:2].strip().isdigit() and "Hz" not in ln]
    assert len(rows) == 4


def test_static_names_the_stiffness_and_bearing_reactions(tmp_path):
    out = _run(tmp_path, "static")
    assert "static stiffness at node 1 x" in out and "N/um" in out
    assert "bearing front" in out and "bearing rear" in out


def test_quiet_prints_only_paths(tmp_path):
    out = _run(tmp_path, "static", "--quiet")
    assert all(ln.endswith((".h5", ".png")) for ln in out.splitlines() if ln.strip())


def test_json_summary_is_machine_readable(tmp_path):
    out = _run(tmp_path, "campbell", "--speeds", "500:12000:12", "--json")
    doc = json.loads(out.splitlines()[-1])
    assert any(p.endswith("campbell.h5") for p in doc["paths"])
    s = doc["summary"]["campbell.h5"]
    assert "critical_speeds" in s and "stability_threshold" in s


def _campbell_study(tmp_path, monkeypatch):
    """The CampbellStudy the campbell command summarises (its result, caught on the way)."""
    from tests.rotor_helpers import cli_with_result

    _, written = cli_with_result(monkeypatch, ["campbell", "--speeds", "1000:6000:3", "--modes", "4", "--quiet",
                                               "-o", tmp_path])
    return written.result


def test_campbell_summary_reads_the_result_not_the_deck(tmp_path, monkeypatch):
    """The operating speed is the study's (campbell.h5's attribute too): the summary parses no YAML (issue 24,
    item 3) and reads no file (issue 34, item 1)."""
    import shutil
    import sys

    from spindlesim.deck import default_deck
    from spindlesim.output.summary import summary_of

    study = _campbell_study(tmp_path / "o", monkeypatch)
    shutil.rmtree(tmp_path / "o")
    monkeypatch.setitem(sys.modules, "yaml", None)  # importing yaml now fails
    lines, data = summary_of("campbell")(study)
    assert data["operating_speed_rpm"] == default_deck("spindle").deck.operating.speed_rpm > 0


def test_campbell_summary_prints_the_analysis_stability_threshold(tmp_path, monkeypatch):
    """The threshold is the result's ``first_unstable`` (speed, mode indices): the lowest speed with a negatively
    damped tracked mode, as the analysis defines it."""
    import dataclasses

    from spindlesim.output.summary import summary_of

    study = _campbell_study(tmp_path, monkeypatch)
    hot = study.hot
    assert hot.first_unstable is None and (hot.damping_ratio > 0).all()
    z = hot.damping_ratio.copy()
    z[1, 2] = -0.01
    study = dataclasses.replace(study, hot=dataclasses.replace(hot, damping_ratio=z))
    assert study.hot.first_unstable == (1, 2)
    sp, fr = hot.speed_rpm[1], hot.frequency_hz[1, 2]
    lines, data = summary_of("campbell")(study)
    assert data["stability_threshold"]["speed_rpm"] == sp and data["stability_threshold"]["mode"] == 3
    assert data["stability_threshold"]["frequency_hz"] == fr
    assert any(ln.strip().startswith(f"UNSTABLE from {sp:g} rpm: mode 3") for ln in lines)


def test_first_unstable_is_the_lowest_speed_with_negative_damping():
    from spindlesim.analysis.results import CampbellResult

    z = np.array([[0.1, 0.2, np.nan], [0.1, -0.01, 0.3], [-0.2, -0.1, 0.3]])
    res = CampbellResult(speed_rpm=np.array([0.0, 1000.0, 2000.0]), frequency_hz=np.ones((3, 3)), log_dec=z,
                         damping_ratio=z, whirl=np.full((3, 3), "forward"), critical_speeds_rpm=np.zeros(0),
                         critical_modes=np.zeros(0, int))
    assert res.first_unstable == (1, 1)
    stable = CampbellResult(**{**res.__dict__, "damping_ratio": np.abs(np.nan_to_num(z))})
    assert stable.first_unstable is None


# Numbers rounded to what they mean (issue 23, section 4)

def test_numbers_below_the_noise_print_as_zero_and_never_minus_zero():
    from spindlesim.output.numbers import clean, g

    assert clean([-1.529, 2.784e-14, 0.5294, -3.024e-14]).tolist() == [-1.529, 0.0, 0.5294, 0.0]
    assert clean([4.4e-20, 2.0e-6], reference=2.0e-6)[0] == 0.0
    assert clean([1e-3, 2.0]).tolist() == [1e-3, 2.0]  # a small value above the noise stays
    assert g(-0.0) == "0" and g(clean([-1e-20, 1.0])[0]) == "0" and g(-2.5) == "-2.5"


@pytest.mark.parametrize("value,half,expect", [
    (266.68, 2.78, "267 +/- 3 Hz"),  # 5.56 Hz bin
    (266.68, 5.5, "267 +/- 6 Hz"),  # 11 Hz bin
    (84.43, 0.14, "84.43 +/- 0.14 Hz"),  # a leading 1 keeps two digits
    (1234.567, 0.025, "1234.57 +/- 0.03 Hz"),
    (3333.3, 14.0, "3333 +/- 14 Hz"),
])
def test_a_spectral_line_is_printed_to_its_resolution(value, half, expect):
    from spindlesim.output.numbers import with_resolution

    assert with_resolution(value, half, "Hz") == expect


def test_static_summary_prints_no_round_off(tmp_path):
    out = _run(tmp_path, "static", str(DECKS / "seed001_dtrb_rotor.yaml"))  # old: x 4.442e-14 um, reaction 3.229e-12, -0
    rows = [ln for ln in out.splitlines() if ("reaction" in ln or "deflection" in ln) and not ln.endswith(".png")]
    assert len(rows) == 3  # the deflection and the two bearings (the damping-only `linear` entries are gone)
    for ln in rows:
        assert "e-1" not in ln and "-0," not in ln and not ln.rstrip(" N").endswith("-0"), ln
    assert "deflection there x 0 um, y 2.768 um" in out
    assert "bearing acbb         reaction          0,     -588.5 N" in out


def test_frf_summary_says_which_dof_responds_and_which_is_forced(tmp_path):
    out = _run(tmp_path, "frf", str(DECKS / "seed001_dtrb_rotor.yaml"))
    assert "response at node 5 x / force at node 9 x, 3000 rpm" in out


def _undamped_ball_sets(tmp_path) -> Path:
    """decks/milling_spindle.yaml with its ball sets' damping off (C = 0, as before issue 30)."""
    import yaml

    d = yaml.safe_load((DECKS / "milling_spindle.yaml").read_text())
    for b in d["bearings"]:
        b["damping"] = {"stiffness_proportional_s": 0.0}
    path = tmp_path / "undamped.yaml"
    path.write_text(yaml.safe_dump(d))
    return path


def test_modal_damping_has_significant_digits(tmp_path):
    out = _run(tmp_path / "a", "modal", str(DECKS / "milling_spindle.yaml"), "--modes", "2")
    rows = [ln.split() for ln in out.splitlines() if ln.strip()[:2].strip().isdigit() and "Hz" not in ln]
    assert [r[2] for r in rows] == ["0.0106", "0.0108"]  # the axial mode: beta omega / 2 (1e-5 s, 339.5 Hz)
    out = _run(tmp_path / "b", "modal", str(_undamped_ball_sets(tmp_path)), "--modes", "1")
    rows = [ln.split() for ln in out.splitlines() if ln.strip()[:2].strip().isdigit() and "Hz" not in ln]
    assert [r[2] for r in rows] == ["1.69e-06"]  # old: 0.0000; with the radial dampers of before, 1.49e-05


def _unloaded_lathe(tmp_path) -> Path:
    """decks/lathe_headstock.yaml without its thermal section, loads and gravity, and with its bearings' damping
    replaced by radial dampers (`linear`, K = 0: the deck before issue 30): a DTRB rotor whose axial mode has no
    damping at all."""
    import yaml

    d = yaml.safe_load((DECKS / "lathe_headstock.yaml").read_text())
    for b in d["bearings"]:
        b["damping"] = {"stiffness_proportional_s": 0.0}
    d["bearings"] += [{"name": f"{b['name']}_damper", "node": b["node"], "type": "linear",
                       "K_N_m": [[0.0, 0.0], [0.0, 0.0]], "C_Ns_m": [[c, 0.0], [0.0, c]]}
                      for b, c in zip(list(d["bearings"]), (2000.0, 1000.0))]
    d.pop("spindle_thermal")
    d.pop("loads")
    d["operating"]["gravity"] = False
    path = tmp_path / "lathe.yaml"
    path.write_text(yaml.safe_dump(d))
    return path


def test_an_undamped_mode_is_not_unstable(tmp_path):
    """Its computed damping ratio is round-off of either sign (it was -4.2e-15 and reported UNSTABLE): zero."""
    from spindlesim.analysis.modal import solve_modal
    from spindlesim.deck import load_deck
    from spindlesim.model.build import build_rotor

    rotor = build_rotor(load_deck(_unloaded_lathe(tmp_path)).deck)
    m = solve_modal(rotor, 1200.0, 6)
    axial = [k for k, w in enumerate(m.whirl) if w == "axial"]
    assert axial, m.whirl
    for k in axial:
        assert m.damping_ratio[k] == 0.0 and math.copysign(1.0, m.log_dec[k]) == 1.0
        assert not m.unstable[k]
    assert np.all(m.damping_ratio[[k for k in range(len(m.whirl)) if k not in axial]] > 1e-4)
    out = _run(tmp_path / "out", "modal", str(_unloaded_lathe(tmp_path)), "--modes", "6")
    assert "UNSTABLE" not in out and " -0 " not in out


def test_static_summary_says_whether_gravity_is_on(tmp_path):
    out = _run(tmp_path / "a", "static", str(_unloaded_lathe(tmp_path)))
    assert "under the applied loads, no gravity: Fx 0 N, Fy 0 N" in out
    assert "deflection there x 0 um, y 0 um" in out  # nothing loads the rotor: noise prints 0
    out = _run(tmp_path / "b", "static", str(DECKS / "lathe_headstock.yaml"))
    assert "gravity 9.80665 m/s2 included" in out
