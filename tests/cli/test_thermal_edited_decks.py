"""Issue 35, item 1: `thermal` on ordinary edits of the milling deck (front preload 30 or 5 um, the rear pair
moved from node 16 to 14) crashed with "SVD did not converge" and wrote nothing, although the thermal
equilibria and the speed limit were solved: the tool-point receptance was evaluated exactly at an undamped
pole.  Now the receptance is taken off such a pole, and a part of the analysis that fails anyway is written
as missing with its reason (exit 3, the rest of the file kept)."""

from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.chatter import ToolPointModel
from spindlesim.chatter.frf import Mode
from spindlesim.chatter.state_space import POLE_GAP
from spindlesim.cli import main

DECK = Path(__file__).parents[2] / "decks" / "milling_spindle.yaml"

EDITS = {
    "preload_30um": ("axial_um: 15.0", "axial_um: 30.0"),
    "preload_5um": ("axial_um: 15.0", "axial_um: 5.0"),
    "rear_at_node_14": ("    node: 16\n", "    node: 14\n"),
}


def _edited(tmp_path: Path, name: str) -> Path:
    old, new = EDITS[name]
    text = DECK.read_text()
    assert text.count(old) >= 1
    text = text.replace(old, new).replace("node: 16, type: linear", "node: 14, type: linear")
    p = tmp_path / f"{name}.yaml"
    p.write_text(text)
    return p


def _undamped(k=2.0e7, f=500.0) -> ToolPointModel:
    w = 2 * np.pi * f
    A = np.array([[0.0, 1.0], [-w * w, 0.0]])
    B = np.array([[0.0, 0.0], [w * w / k, 0.0]])
    C = np.array([[1.0, 0.0], [0.0, 0.0]])
    return ToolPointModel(A, B, C, "undamped")


def test_receptance_at_an_undamped_pole_is_finite_and_that_of_the_gap():
    """An undamped mode H = 1/(k (1 - r^2)) is infinite at r = 1; it is evaluated POLE_GAP off the pole: the
    peak of the same mode with damping ratio POLE_GAP, 1/(2 k POLE_GAP), to the first order."""
    k, f = 2.0e7, 500.0
    m = _undamped(k, f)
    H = m.receptance(np.array([2 * np.pi * f]))
    assert np.all(np.isfinite(H))
    assert abs(H[0, 0, 0]) == pytest.approx(1.0 / (2 * k * POLE_GAP), rel=1e-3)
    modes = m.modes()
    assert len(modes) == 1 and np.isfinite(modes[0].peak_compliance_m_N)
    grid = m.frequency_grid()  # holds the mode's own frequency
    assert np.all(np.isfinite(m.receptance(2 * np.pi * grid)))


def test_a_damped_mode_is_not_touched_by_the_pole_gap():
    """Damping ratio 1e-5 (above POLE_GAP): the receptance at resonance is the closed form to round-off."""
    md = Mode("x", 500.0, 1e-5, 2.0e7)
    m = ToolPointModel.from_modes([md])
    f = np.array([499.0, 500.0, 500.0 * (1 + 1e-7), 501.0])
    assert np.allclose(m.receptance(2 * np.pi * f)[:, 0, 0], md.receptance(f), rtol=1e-9, atol=0)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(EDITS))
def test_thermal_runs_to_the_end_on_an_edited_milling_deck(tmp_path, name):
    deck = _edited(tmp_path, name)
    out = tmp_path / "o"
    res = CliRunner().invoke(main, ["thermal", str(deck), "-o", str(out)])
    assert res.exit_code == 0, res.output
    assert "SVD did not converge" not in res.output
    assert "stable depth of cut at the running speed" in res.output
    with h5py.File(out / "thermal.h5") as f:
        assert bool(f.attrs["complete"])
        c = f["spindle_thermal/warm_up/chatter"]
        depth, rpm = c["limit_depth_m"][:], c["speed_rpm"][:]
        cutting = (rpm > 0) & (c["capped"][:] == 0)
        assert cutting.sum() >= 10 and np.all(np.isfinite(depth[cutting])) and np.all(depth[cutting] > 0)
        assert "speed_limit_rpm" in f["spindle_thermal"].attrs or name != "preload_30um"
    assert (out / "thermal_warm_up.png").exists()


def test_a_failed_part_is_written_as_missing_and_the_rest_kept(tmp_path, monkeypatch):
    """The lobes of one warm-up instant fail: that instant's depth is NaN and named, the equilibria, the
    warm-up and the other depths are written, the file is marked incomplete, the command exits 3 and says
    what failed and where in one line."""
    import spindlesim.analysis.warm_up_chatter as wuc

    real, calls = wuc.stability_lobes, []

    def flaky(*a, **k):
        calls.append(1)
        if len(calls) == 2:
            raise np.linalg.LinAlgError("SVD did not converge")
        return real(*a, **k)

    monkeypatch.setattr(wuc, "stability_lobes", flaky)
    text = DECK.read_text().replace("speeds_rpm: [4000, 8000, 12000, 16000, 20000, 24000]", "speeds_rpm: [12000]")
    text = text.replace("warm_up: {steps: [[0, 4000], [30, 8000], [60, 12000], [90, 0]], duration_min: 120, "
                        "samples: 25}", "warm_up: {steps: [[0, 4000], [30, 8000]], duration_min: 60, samples: 4}")
    text = text.replace("count: 200}", "count: 20}")
    deck = tmp_path / "d.yaml"
    deck.write_text(text)
    out = tmp_path / "o"
    res = CliRunner().invoke(main, ["thermal", str(deck), "-o", str(out)])
    assert res.exit_code == 3, res.output
    assert "SVD did not converge" in res.output and "min (" in res.output
    with h5py.File(out / "thermal.h5") as f:
        assert not f.attrs["complete"]
        assert "stable depth of cut" in f.attrs["incomplete_reason"]
        depth = f["spindle_thermal/warm_up/chatter/limit_depth_m"][:]
        assert np.isnan(depth).sum() >= 1 and np.isfinite(depth).sum() >= 1
        assert "SVD did not converge" in f["spindle_thermal/warm_up/chatter"].attrs["not_computed"]
        assert len(f["spindle_thermal/speed_rpm"][:]) == 1
