"""Issue 35, item 2: Ctrl-C keeps what was computed.  A KeyboardInterrupt raised part-way through `thermal` and
`campbell` (at a chosen point, in process: no timing) ends with exit code 130 and their files written, marked
incomplete, with what was finished before it."""

from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np
from click.testing import CliRunner

from spindlesim.cli import main

ROOT = Path(__file__).parents[2]
MILLING = ROOT / "decks" / "milling_spindle.yaml"


def _small_thermal(tmp_path) -> Path:
    text = MILLING.read_text().replace("speeds_rpm: [4000, 8000, 12000, 16000, 20000, 24000]",
                                       "speeds_rpm: [4000, 8000]")
    p = tmp_path / "d.yaml"
    p.write_text(text)
    return p


def test_ctrl_c_in_the_warm_up_keeps_the_equilibria(tmp_path, monkeypatch):
    from spindlesim.analysis.spindle_thermal import SpindleThermal

    def stop(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(SpindleThermal, "warm_up", stop)
    out = tmp_path / "o"
    res = CliRunner().invoke(main, ["thermal", str(_small_thermal(tmp_path)), "-o", str(out)])
    assert res.exit_code == 130, res.output
    assert "interrupted by the user in the warm-up" in res.output
    with h5py.File(out / "thermal.h5") as f:
        assert not f.attrs["complete"]
        assert "interrupted by the user in the warm-up" in f.attrs["incomplete_reason"]
        assert list(f["spindle_thermal/speed_rpm"][:]) == [4000.0, 8000.0]
        assert "warm_up" not in f["spindle_thermal"]
    assert (out / "thermal_speeds.png").exists()


def test_ctrl_c_between_two_speeds_keeps_the_first(tmp_path, monkeypatch):
    from spindlesim.analysis.points import OperatingPoints

    real = OperatingPoints.thermal_state

    def second_stops(self, rpm):
        if rpm > 5000:
            raise KeyboardInterrupt
        return real(self, rpm)

    monkeypatch.setattr(OperatingPoints, "thermal_state", second_stops)
    out = tmp_path / "o"
    res = CliRunner().invoke(main, ["thermal", str(_small_thermal(tmp_path)), "-o", str(out)])
    assert res.exit_code == 130, res.output
    with h5py.File(out / "thermal.h5") as f:
        assert not f.attrs["complete"]
        assert "8000 rpm" in f.attrs["incomplete_reason"]
        assert list(f["spindle_thermal/speed_rpm"][:]) == [4000.0]


def test_ctrl_c_in_campbells_comparison_keeps_the_diagram(tmp_path, monkeypatch):
    import spindlesim.analysis.campbell_study as campbell

    calls = []

    original = campbell.solve_campbell

    def second_stops(*a, **k):
        calls.append(1)
        if len(calls) == 2:  # the frozen comparison
            raise KeyboardInterrupt
        return original(*a, **k)

    monkeypatch.setattr(campbell, "solve_campbell", second_stops)
    out = tmp_path / "o"
    res = CliRunner().invoke(main, ["campbell", str(MILLING), "--speeds", "0:12000:5", "-o", str(out)])
    assert res.exit_code == 130, res.output
    with h5py.File(out / "campbell.h5") as f:
        assert not f.attrs["complete"]
        assert "comparison" in f.attrs["incomplete_reason"]
        assert np.allclose(f["campbell/speed_rpm"][:], np.linspace(0, 12000, 5))
        assert np.all(np.isfinite(f["campbell/frequency_hz"][:, 0]))
    assert (out / "campbell.png").exists()
