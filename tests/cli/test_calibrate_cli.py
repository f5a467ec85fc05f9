"""`spindlesim calibrate` as a user meets it (issue 30, items 3 and 6; issue 33, item 4): the example deck's
summary and files, every bad input a located one-line deck error (exit 2, nothing written), a fit that does not
converge one line (exit 1), Ctrl-C keeps the best values evaluated (exit 130, marked incomplete)."""

from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from tests.units import unit_problems

ROOT = Path(__file__).parents[2]
DECK = ROOT / "decks" / "tool_library.yaml"


def _deck(tmp_path: Path, *edits: tuple[str, str]) -> Path:
    text = DECK.read_text().replace("path: calibration/tap_", f"path: {ROOT}/decks/calibration/tap_")
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new, 1)
    p = tmp_path / "deck.yaml"
    p.write_text(text)
    return p


def _run(tmp_path, deck, *extra):
    out = tmp_path / "out"
    return CliRunner().invoke(main, ["calibrate", str(deck), "-o", str(out), *extra]), out


def test_the_example_calibration_prints_each_parameter_and_writes_its_files(tmp_path):
    res, out = _run(tmp_path, _deck(tmp_path))
    assert res.exit_code == 0, res.output
    for text in ("tool.joint.translational_N_m: 4e+08 -> 2.498e+08", "95 %:", "rms error"):
        assert text in res.output, res.output
    with h5py.File(out / "calibration.h5") as f:
        assert bool(f.attrs["complete"])
        assert [str(p) for p in f["calibration/parameter"][:].astype(str)] == [
            "tool.joint.translational_N_m", "tool.joint.rotational_Nm_rad", "tool.joint.translational_Ns_m"]
        assert f["calibration/value"].attrs["component_units"][0] == "N/m"
        assert f["calibration/measurements/0/calibrated_m_N"].dtype.kind == "c"
        corr = f["calibration/correlation"][:]
        assert np.allclose(np.diag(corr), 1.0) and np.allclose(corr, corr.T)
    text = (out / "calibrated.yaml").read_text()
    assert text.startswith("# Calibrated by spindlesim calibrate on ")
    assert not unit_problems(out / "calibration.h5")
    again, out2 = CliRunner().invoke(main, ["calibrate", str(out / "calibrated.yaml"), "-o", str(tmp_path / "o2"),
                                            "-q"]), None
    assert again.exit_code == 0, again.output  # the calibrated deck's measurement paths still resolve
    assert (out / "calibration_frf.png").exists()


BAD = [
    ("missing file", ("path: " + str(ROOT) + "/decks/calibration/tap_tip_x.csv", "path: nowhere.csv"),
     "calibration.measurements[0].file.path", "measurement file"),
    ("path not in the deck", ("path: tool.joint.translational_N_m,", "path: tool.joint.stiffness_N_m,"),
     "calibration.parameters[0].path", "no such key"),
    ("min >= max", ("min: 1.0e7, max: 1.0e10", "min: 1.0e10, max: 1.0e7"), "calibration.parameters[0].max",
     "greater than min"),
    ("start outside the bounds", ("min: 1.0e5, max: 1.0e8", "min: 3.0e6, max: 1.0e8"),
     "calibration.parameters[1].path", "outside its bounds"),
    ("a bound the key refuses", ("min: 1.0, max: 1.0e4", "min: -10.0, max: 1.0e4"),
     "calibration.parameters[2].min", "the deck refuses"),
    ("too few points in the band", ("band_hz: [200, 5000]", "band_hz: [200, 260]"),
     "calibration.measurements[0].file.path", "at least 10"),
    ("node off the rotor", ("node: 26}", "node: 99}"), "calibration.measurements[0].node", "out of range"),
]


@pytest.mark.parametrize("what,edit,key,message", BAD, ids=[b[0] for b in BAD])
def test_bad_input_is_a_located_deck_error_and_nothing_is_written(tmp_path, what, edit, key, message):
    res, out = _run(tmp_path, _deck(tmp_path, edit))
    assert res.exit_code == 2, res.output
    assert key in res.output and message in res.output, res.output
    assert "Traceback" not in res.output
    assert not out.exists() or not list(out.iterdir())


@pytest.mark.parametrize("content,message", [("frequency_hz,real_m_N,imag_m_N\n", "0 data row"),
                                             ("frequency_hz,real_m_N,imag_m_N\n20,1e-7,0\n10,1e-7,0\n",
                                              "does not increase")])
def test_awkward_measurement_files(tmp_path, content, message):
    bad = tmp_path / "bad.csv"
    bad.write_text(content)
    res, out = _run(tmp_path, _deck(tmp_path, ("path: " + str(ROOT) + "/decks/calibration/tap_tip_x.csv",
                                               f"path: {bad}")))
    assert res.exit_code == 2, res.output
    assert "calibration.measurements[0].file.path" in res.output and message in res.output.lower(), res.output


def test_a_fit_that_does_not_converge_is_one_line_and_exit_1(tmp_path):
    res, out = _run(tmp_path, _deck(tmp_path, ("  band_hz: [200, 5000]", "  band_hz: [200, 5000]\n  max_evaluations: 10")))
    assert res.exit_code == 1, res.output
    lines = [ln for ln in res.output.splitlines() if ln.startswith("spindlesim calibrate:")]
    assert len(lines) == 1 and "did not converge within" in lines[0]
    assert not (out / "calibration.h5").exists()


def test_ctrl_c_keeps_the_best_values_evaluated(tmp_path, monkeypatch):
    import spindlesim.sweep.calibration as cal

    real = cal._Model.residual

    def interrupted(self, x):
        if self.evaluations >= 6:
            raise KeyboardInterrupt
        return real(self, x)

    monkeypatch.setattr(cal._Model, "residual", interrupted)
    res, out = _run(tmp_path, _deck(tmp_path))
    assert res.exit_code == 130, res.output
    assert "interrupted" in res.output
    with h5py.File(out / "calibration.h5") as f:
        assert not f.attrs["complete"]
        assert np.all(np.isnan(f["calibration/lower_95"][:]))
    assert "INCOMPLETE" in (out / "calibrated.yaml").read_text()


def test_the_run_report_shows_the_calibration_written_beside_it(tmp_path):
    """Issue 33, item 4: `spindlesim calibrate -o OUT`, then `spindlesim run -o OUT` on the same deck: report.html
    has the calibration's summary and figure; `run` does not fit again (calibration.h5 untouched)."""
    import yaml

    data = yaml.safe_load(_deck(tmp_path).read_text())
    for key in ("modal", "campbell", "frf", "unbalance", "chatter", "spindle_thermal", "tools"):
        data.pop(key, None)
    deck = tmp_path / "small.yaml"
    deck.write_text(yaml.safe_dump(data, sort_keys=False))
    res, out = _run(tmp_path, deck, "-q")
    assert res.exit_code == 0, res.output
    stamp = (out / "calibration.h5").stat().st_mtime_ns
    res = CliRunner().invoke(main, ["run", str(deck), "-o", str(out), "-q"])
    assert res.exit_code == 0, res.output
    page = (out / "report.html").read_text()
    for text in ("tool.joint.translational_N_m", "rms error", "calibration_frf.png",
                 "Calibration: measured FRFs"):
        assert text in page, text
    assert (out / "calibration.h5").stat().st_mtime_ns == stamp


def test_a_parameter_at_its_bound_from_the_start_is_said_and_its_interval_ends_there(tmp_path):
    """Issue 33, item 4: the joint's lower bound raised to the deck's own value (4e8 N/m), below the truth of the
    simulated taps (2.5e8): the fit stays on the bound, the summary says AT A BOUND and that the interval is not a
    95 % one there, and the interval does not reach below the bound (it reached 3.75e8 before)."""
    deck = _deck(tmp_path, ("{path: tool.joint.translational_N_m, min: 1.0e7, max: 1.0e10}",
                            "{path: tool.joint.translational_N_m, min: 4.0e8, max: 1.0e10}"))
    res, out = _run(tmp_path, deck)
    assert res.exit_code == 0, res.output
    assert "AT A BOUND" in res.output and "is not a 95 % interval there" in res.output
    with h5py.File(out / "calibration.h5") as f:
        names = [str(n) for n in f["calibration/parameter"][:].astype(str)]
        k = names.index("tool.joint.translational_N_m")
        assert bool(f["calibration/at_bound"][k])
        assert f["calibration/value"][k] == pytest.approx(4.0e8, rel=1e-6)
        assert f["calibration/lower_95"][k] >= 4.0e8 * (1 - 1e-9)
        assert f["calibration/upper_95"][k] > 4.0e8
