"""The bearings' and a spindle's thermal summaries read the analysis's result, not its file (issue 34, item 1):
bearing_summary.py (thermal and coefficients of the fluid-film bearings, bearing, dtrb, contact) and
thermal_summary.py (spindle_thermal).  Each summary is called on the result after the output folder is deleted and
with h5py unimportable, and must print what the command prints."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from spindlesim.cli import main

ROOT = Path(__file__).parents[2]
DECKS = ROOT / "decks"


def _small_thermal(tmp_path) -> Path:
    """decks/milling_spindle.yaml at two speeds, its warm-up sampled less."""
    text = (DECKS / "milling_spindle.yaml").read_text().replace(
        "speeds_rpm: [4000, 8000, 12000, 16000, 20000, 24000]", "speeds_rpm: [4000, 8000]").replace(
        "duration_min: 120, samples: 25}", "duration_min: 120, samples: 4}")
    assert "samples: 4}" in text
    p = tmp_path / "thermal.yaml"
    p.write_text(text)
    return p


def _handed_back(monkeypatch, cmd: str, deck: Path, out: Path, exit_code: int = 0):
    """(printed output, written, reason) of ``spindlesim cmd deck -o out``: what the run handed back caught on its
    way to the summary, the folder deleted afterwards."""
    import spindlesim.runs as runs
    from spindlesim.runs.status import IncompleteRun

    caught = []
    perform = runs.perform_analysis

    def catching(*a, **kw):
        try:
            caught.append((perform(*a, **kw), None))
        except IncompleteRun as exc:
            caught.append((exc.written, exc.noted))
            raise
        return caught[-1][0]

    monkeypatch.setattr(runs, "perform_analysis", catching)
    res = CliRunner().invoke(main, [cmd, str(deck), "-o", str(out)])
    assert res.exit_code == exit_code, res.output
    shutil.rmtree(out)
    return (res.output, *caught[-1])


def _summary_without_files(written, reason):
    """The summary of what a run handed back, its files gone and h5py unimportable meanwhile."""
    from spindlesim.output.summary import summarize_written

    assert not any(p.exists() for p in written.paths)
    loaded = sys.modules.get("h5py")
    sys.modules["h5py"] = None  # importing h5py now fails
    try:
        (found,) = summarize_written(written, reason)
    finally:
        if loaded is None:
            del sys.modules["h5py"]
        else:
            sys.modules["h5py"] = loaded
    return found


def _printed_block(name: str, lines: list[str]) -> str:
    return f"\n{name}:\n" + "\n".join(f"  {line}" for line in lines) + "\n"


@pytest.mark.parametrize("cmd, deck, analysis", [
    ("bearing", "ball_single_row.yaml", "bearing"),
    ("bearing", "dtrb_wheel_hub.yaml", "dtrb"),  # the bearing command on a dtrb deck: the dtrb analysis's result
    ("dtrb", "dtrb_wheel_hub.yaml", "dtrb"),
    ("contact", "contact_roller.yaml", "contact"),
    ("thermal", "seed003_three_lobe.yaml", "thermal"),
    ("coefficients", "seed003_three_lobe.yaml", "coefficients"),
])
def test_bearing_summaries_read_the_result_not_the_file(tmp_path, monkeypatch, cmd, deck, analysis):
    printed, written, reason = _handed_back(monkeypatch, cmd, DECKS / deck, tmp_path / "gone")
    assert written.analysis == analysis and reason is None
    name, lines, data = _summary_without_files(written, reason)
    assert name == f"{analysis}.h5" and lines and data
    assert _printed_block(name, lines) in printed


def test_isoviscous_film_summary_from_the_result(tmp_path, monkeypatch):
    """A film without the oil's density and specific heat: its temperatures are left out, and said so."""
    deck = DECKS / "validation" / "jeffcott_plain.yaml"
    printed, written, _ = _handed_back(monkeypatch, "thermal", deck, tmp_path / "gone")
    _, lines, data = _summary_without_files(written, None)
    assert any("isoviscous film, no heat balance" in ln for ln in lines)
    assert all("temperature_mean_C" not in row for row in data.values())
    assert _printed_block("thermal.h5", lines) in printed


def test_spindle_thermal_summary_reads_the_study_not_the_file(tmp_path, monkeypatch):
    deck = _small_thermal(tmp_path)
    printed, written, reason = _handed_back(monkeypatch, "thermal", deck, tmp_path / "gone")
    assert written.analysis == "spindle_thermal" and reason is None
    name, lines, data = _summary_without_files(written, reason)
    assert lines[0].startswith("thermal equilibrium at 2 speed(s), ambient 20 C") and data["speed_rpm"] == [4000.0, 8000.0]
    assert any(ln.startswith("  warm-up over") for ln in lines)
    assert _printed_block(name, lines) in printed


def test_interrupted_spindle_thermal_is_summarised_from_the_partial_study(tmp_path, monkeypatch):
    """Ctrl-C in the warm-up: the equilibria computed before it, under the INCOMPLETE line the file notes."""
    from spindlesim.analysis.spindle_thermal import SpindleThermal

    def stop(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(SpindleThermal, "warm_up", stop)
    deck = _small_thermal(tmp_path)
    printed, written, reason = _handed_back(monkeypatch, "thermal", deck, tmp_path / "gone", exit_code=130)
    assert written.result.interrupted and written.result.warm_up is None
    assert reason == "interrupted by the user in the warm-up"
    name, lines, data = _summary_without_files(written, reason)
    assert lines[0] == f"INCOMPLETE: {reason}" and data["complete"] is False and data["speed_rpm"] == [4000.0, 8000.0]
    assert _printed_block(name, lines) in printed
