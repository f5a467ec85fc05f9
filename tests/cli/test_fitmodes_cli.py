"""`spindlesim fitmodes` and `spindlesim impact` as a user meets them (issue 30, items 1 and 2): the packaged simulated
tap test run without FILE (summary, files, HDF5 units, the FRF file the chatter readers take), every bad input one
located line (exit 2, nothing written), Ctrl-C exit 130, --json; the commands listed by `spindlesim --help`."""

from __future__ import annotations

import json
import re
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.chatter.readers import read_frf
from spindlesim.cli import main
from tests.units import unit_problems

ROOT = Path(__file__).parents[2]
TAPTEST = ROOT / "decks" / "taptest"

def _run(*args):
    return CliRunner().invoke(main, list(map(str, args)))


def test_help_lists_both_commands():
    res = _run("--help")
    assert res.exit_code == 0
    assert re.search(r"^\s+fitmodes\s+Modes of a measured FRF", res.output, re.M)
    assert re.search(r"^\s+impact\s+Tap test FRF from hammer", res.output, re.M)


def test_fitmodes_without_file_runs_the_packaged_tap_test(tmp_path):
    """The packaged simulated tap test of the milling spindle at rest: five modes with their fit error, the files,
    units on every dataset, and modes.yaml that loads as a list of modes."""
    out = tmp_path / "fm"
    res = _run("fitmodes", "-o", out)
    assert res.exit_code == 0, res.output
    for text in ("5 mode(s)", "fit error", "f [Hz]", "1091.", "2617.", "taken as x", "band 430-4000 Hz"):
        assert text in res.output, res.output
    assert sorted(p.name for p in out.iterdir()) == ["fitmodes.h5", "fitmodes_overlay.png",
                                                      "fitmodes_stabilisation.png", "modes.yaml"]
    assert not unit_problems(out / "fitmodes.h5"), unit_problems(out / "fitmodes.h5")
    import yaml

    modes = yaml.safe_load((out / "modes.yaml").read_text())
    assert [m["direction"] for m in modes] == ["x"] * 5
    assert {"frequency_hz", "damping_ratio", "stiffness_N_m"} <= set(modes[0])
    with h5py.File(out / "fitmodes.h5") as f:
        assert f["fitmodes/modes/frequency_hz"].shape == (5,) and f["fitmodes/x/measured_m_N"].dtype.kind == "c"
        assert f.attrs["deck_source"].endswith("tap_tip_x.csv") and "SIMULATED tap test" in f.attrs["deck_text"]
        assert 0 < f["fitmodes/x"].attrs["fit_error"] < 0.05


def test_fitmodes_json_band_and_direction(tmp_path):
    res = _run("fitmodes", TAPTEST / "tap_tip_x.csv", "--direction", "x", "--band", "1800:2800", "-o", tmp_path,
               "--json")
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)["summary"]["fitmodes"]
    assert [round(m["frequency_hz"]) for m in data["modes"]] == [2036, 2618]


def _bad(tmp_path, text):
    p = tmp_path / "bad.csv"
    p.write_text(text)
    return p


@pytest.mark.parametrize("name, text, line, message", [
    ("missing", None, None, "no such file"),
    ("a directory", "", None, "a directory, not a file"),
    ("too few points", "frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n", 2, "1 data row(s); at least two are needed"),
    ("header, no rows", "# tap\nfrequency_hz,real_m_N,imag_m_N\n", 2, "0 data row(s); at least two are needed"),
    ("out of order", "frequency_hz,real_m_N,imag_m_N\n100,1e-7,-1e-6\n120,1e-7,-1e-6\n110,1e-7,-1e-6\n", 4,
     "frequency 110 Hz does not increase (previous 120 Hz)"),
])
def test_fitmodes_bad_file_is_one_located_line_exit_2_nothing_written(tmp_path, name, text, line, message):
    path = tmp_path / "none.csv" if text is None else tmp_path if text == "" else _bad(tmp_path, text)
    out = tmp_path / "out"
    res = _run("fitmodes", path, "-o", out)
    assert res.exit_code == 2, res.output
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in res.output
    assert lines[0].startswith(f"{path}:{line}: " if line else f"{path}: ") and message in lines[0], lines
    assert not out.exists()


def test_fitmodes_band_outside_the_data_is_an_input_error(tmp_path):
    res = _run("fitmodes", TAPTEST / "tap_tip_x.csv", "--band", "5000:6000", "-o", tmp_path / "out")
    assert res.exit_code == 2 and "is outside the measured 2-4000 Hz" in res.stderr and not (tmp_path / "out").exists()
    res = _run("fitmodes", "--band", "300", "-o", tmp_path / "out")
    assert res.exit_code == 2 and "give LO:HI" in res.output


def test_fitmodes_interrupted_exits_130_and_writes_nothing(tmp_path, monkeypatch):
    import spindlesim.measured.identification as identification

    def stop(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(identification, "identify_modes", stop)
    monkeypatch.setattr("spindlesim.measured.identify_modes", stop, raising=False)
    out = tmp_path / "out"
    res = _run("fitmodes", "-o", out)
    assert res.exit_code == 130 and "interrupted" in res.stderr and not out.exists()


def test_impact_without_records_runs_the_packaged_impacts(tmp_path):
    """The four packaged simulated impacts: the double hit is left out and said why, the coherence at the peaks is
    near 1, and frf_x.csv reads with the chatter readers (receptance and coherence)."""
    out = tmp_path / "imp"
    res = _run("impact", "-o", out)
    assert res.exit_code == 0, res.output
    assert "3 of 4 impact(s) averaged" in res.output
    assert re.search(r"left out \S+tap_impact_x_3\.csv:\d+: double hit", res.output), res.output
    assert "peaks:" in res.output and "coherence 1.000" in res.output
    frf = read_frf(out / "frf_x.csv", "csv", "x")
    assert frf.coherence is not None and np.all(frf.coherence[:, 0, 0] <= 1.0)
    assert np.array_equal(frf.H, read_frf(TAPTEST / "tap_tip_x.csv", "csv", "x").H)  # the packaged FRF is this one
    assert not unit_problems(out / "impact.h5"), unit_problems(out / "impact.h5")
    with h5py.File(out / "impact.h5") as f:
        assert f["impact/records/used"][:].tolist() == [1, 1, 0, 1]


@pytest.mark.parametrize("name, text, line, message", [
    ("missing", None, None, "no such file"),
    ("header, no rows", "time_s,force_N,acceleration_m_s2\n", 1, "a header but no rows"),
])
def test_impact_bad_record_is_one_located_line_exit_2(tmp_path, name, text, line, message):
    path = tmp_path / "none.csv" if text is None else _bad(tmp_path, text)
    out = tmp_path / "out"
    res = _run("impact", TAPTEST / "tap_impact_x_1.csv", path, "-o", out)
    assert res.exit_code == 2, res.output
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"{path}:{line}: " if line else f"{path}: ") and message in lines[0]
    assert not out.exists()


def test_impact_records_that_do_not_match_exit_2(tmp_path):
    """A record of another length than the first: one line naming it, exit 2, nothing written."""
    text = (TAPTEST / "tap_impact_x_2.csv").read_text().splitlines()
    short = tmp_path / "short.csv"
    short.write_text("\n".join(text[:-100]) + "\n")
    out = tmp_path / "out"
    res = _run("impact", TAPTEST / "tap_impact_x_1.csv", short, "-o", out)
    assert res.exit_code == 2 and "3900 samples, the first record has 4000" in res.stderr and not out.exists()


def test_the_packaged_tap_test_is_the_repository_s_and_says_it_is_simulated():
    """decks/taptest/ and its package copy (what the commands run without FILE) are the same files, each under
    200 kB, each opening with the note that it is simulated and from what."""
    from importlib import resources

    packaged = Path(str(resources.files("spindlesim.decks"))) / "taptest"
    names = sorted(p.name for p in TAPTEST.glob("*.csv"))
    assert names == sorted(p.name for p in packaged.glob("*.csv")) and len(names) == 5
    for name in names:
        text = (TAPTEST / name).read_bytes()
        assert text == (packaged / name).read_bytes() and len(text) < 200_000, name
        assert text.startswith(b"# SIMULATED tap test, not a measurement: decks/milling_spindle.yaml at rest"), name
