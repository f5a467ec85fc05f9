"""Issue 35, item 2, for `chatter`: Ctrl-C keeps what was computed.  A KeyboardInterrupt raised at a chosen point
(in process: no timing) ends with exit code 130 and chatter.h5 written, marked incomplete, with what was finished
before it: the tool-point FRF when the lobes were interrupted, the lobes when a later part was."""

from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np
from click.testing import CliRunner

from spindlesim.cli import main

ROOT = Path(__file__).parents[2]
MILLING = ROOT / "decks" / "milling_spindle.yaml"


def _small(tmp_path) -> Path:
    """The milling deck on 12 speeds without its thermal section (the speed limit is not what is tested)."""
    text = MILLING.read_text().replace("speeds_rpm: {start: 6000, stop: 24000, count: 200}",
                                       "speeds_rpm: {start: 8000, stop: 20000, count: 12}")
    assert "count: 12" in text
    text = text[:text.index("\nspindle_thermal:")] + "\n"
    p = tmp_path / "d.yaml"
    p.write_text(text)
    return p


def _interrupt_on(monkeypatch, module, name: str, call: int = 1):
    original = getattr(module, name)
    calls = []

    def wrapped(*a, **k):
        calls.append(1)
        if len(calls) == call:
            raise KeyboardInterrupt
        return original(*a, **k)

    monkeypatch.setattr(module, name, wrapped)


def _run(tmp_path, *extra):
    out = tmp_path / "o"
    res = CliRunner().invoke(main, ["chatter", str(_small(tmp_path)), "-o", str(out), *extra])
    return out, res


def test_ctrl_c_in_the_lobes_keeps_the_tool_point_frf(tmp_path, monkeypatch):
    import spindlesim.analysis.chatter_study as study

    _interrupt_on(monkeypatch, study, "run_chatter")
    out, res = _run(tmp_path)
    assert res.exit_code == 130, res.output
    assert "interrupted by the user in the lobes" in res.output
    with h5py.File(out / "chatter.h5") as f:
        assert not f.attrs["complete"]
        assert "no lobes" in f.attrs["incomplete_reason"]
        assert "limit_depth_m" not in f["chatter"]
        H = f["chatter/frf/receptance_m_N"][:]
        assert H.shape[1:] == (2, 2) and np.all(np.isfinite(H)) and np.abs(H).max() > 0
        # the modes of the FRF at each of the 12 speeds were solved before the lobes
        assert f["chatter/frf_per_speed/frequency_hz"].shape[0] == 12
    assert "lobes: not computed (interrupted); the tool-point FRF is written (node 26)" in res.output
    assert (out / "chatter_frf.png").exists() and not (out / "chatter_lobes.png").exists()


def test_ctrl_c_in_a_time_domain_check_keeps_the_lobes_and_the_checks_done(tmp_path, monkeypatch):
    import spindlesim.chatter.stability as stability

    _interrupt_on(monkeypatch, stability, "simulate", call=2)
    out, res = _run(tmp_path, "--simulate", "12000", "0.5", "--simulate", "15000", "0.5")
    assert res.exit_code == 130, res.output
    with h5py.File(out / "chatter.h5") as f:
        assert not f.attrs["complete"]
        assert "1 of 2 checks" in f.attrs["incomplete_reason"]
        depth = f["chatter/limit_depth_m"][:]
        assert depth.shape[0] >= 12 and np.any(np.isfinite(depth))
        assert list(f["chatter/simulation"]) == ["1"]
    assert (out / "chatter_lobes.png").exists() and (out / "chatter_simulation_1.png").exists()


def test_ctrl_c_in_the_refinement_keeps_the_grid_lobes(tmp_path, monkeypatch):
    import spindlesim.chatter.stability as stability

    _interrupt_on(monkeypatch, stability, "refine_pockets")
    out, res = _run(tmp_path)
    assert res.exit_code == 130, res.output
    with h5py.File(out / "chatter.h5") as f:
        assert not f.attrs["complete"]
        assert "refinement of the stability pockets" in f.attrs["incomplete_reason"]
        assert f["chatter/speed_rpm"].shape == (12,)  # the grid, nothing added
        assert np.any(np.isfinite(f["chatter/limit_depth_m"][:]))


def test_ctrl_c_before_anything_is_computed_leaves_no_folder(tmp_path, monkeypatch):
    import spindlesim.analysis.chatter_study as study

    _interrupt_on(monkeypatch, study, "tool_point_series")
    out, res = _run(tmp_path)
    assert res.exit_code == 130, res.output
    assert not out.exists()


class _Pressed:
    """A pending result (the comparison's, the speed limit's) whose wait the user interrupts."""

    cancelled = 0

    def __init__(self, *a, **k):
        pass

    def result(self):
        raise KeyboardInterrupt

    def cancel(self):
        _Pressed.cancelled += 1


def test_ctrl_c_while_the_comparison_is_awaited_keeps_the_lobes(tmp_path, monkeypatch):
    """The lobes of the deck speed's FRF are computed aside (spindlesim/analysis/aside.py) while the lobes at every
    speed are; a Ctrl-C while they are awaited keeps the lobes and stops the child."""
    import spindlesim.analysis.chatter_study as study

    monkeypatch.setattr(study, "Aside", _Pressed)
    _Pressed.cancelled = 0
    out, res = _run(tmp_path)
    assert res.exit_code == 130, res.output
    assert _Pressed.cancelled >= 1
    with h5py.File(out / "chatter.h5") as f:
        assert not f.attrs["complete"]
        assert "the comparison not" in f.attrs["incomplete_reason"]
        assert np.any(np.isfinite(f["chatter/limit_depth_m"][:])) and "at_deck_speed" not in f["chatter"]


def test_ctrl_c_while_the_speed_limit_is_awaited_keeps_the_lobes(tmp_path, monkeypatch):
    """The thermal speed limit is solved aside too; interrupted while it is awaited, the lobes are written without it."""
    import spindlesim.runs.common as common

    monkeypatch.setattr(common, "thermal_speed_limit_aside", lambda loaded: _Pressed())
    out, res = _run(tmp_path)
    assert res.exit_code == 130, res.output
    with h5py.File(out / "chatter.h5") as f:
        assert not f.attrs["complete"]
        assert "thermal speed limit" in f.attrs["incomplete_reason"]
        assert np.any(np.isfinite(f["chatter/limit_depth_m"][:]))
