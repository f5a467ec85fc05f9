"""The study ``spindlesim sweep`` runs (spindlesim/sweep/study.py), without the command: the swept values,
every case's deck checked before any runs, the run with its summary handed over, the outcome lines."""

from pathlib import Path
from types import SimpleNamespace

import h5py
import pytest

from spindlesim.deck import default_deck
from spindlesim.sweep import build_cases
from spindlesim.sweep.runner import SweepResult
from spindlesim.sweep.study import case_deck_issues, outcome_lines, run_study, study_parameters


def test_set_replaces_the_deck_values_of_its_path_and_keeps_the_others():
    section = SimpleNamespace(parameters={"operating.speed_rpm": SimpleNamespace(start=1000, stop=3000, count=3),
                                          "bearings.rear.K_N_m.1.1": [1e8, 2e8]})
    assert study_parameters(section, ["bearings.rear.K_N_m.1.1=3e8"]) == {
        "operating.speed_rpm": [1000, 2000, 3000], "bearings.rear.K_N_m.1.1": [3e8]}
    assert study_parameters(None, ["operating.speed_rpm=0,10"]) == {"operating.speed_rpm": [0, 10]}
    with pytest.raises(ValueError, match="PATH=VALUES"):
        study_parameters(section, ["operating.speed_rpm"])


def test_every_case_deck_is_checked_and_the_bad_case_named():
    loaded = default_deck("spindle_linear")
    cases = build_cases(loaded.text, {"operating.speed_rpm": [1000, "fast"]}, "modal")
    issues = case_deck_issues(loaded, cases)
    assert issues and all("[case 1: {'operating.speed_rpm': 'fast'}]" in str(i) for i in issues)
    assert case_deck_issues(loaded, cases[:1]) == []


def test_outcome_lines_count_the_cases_and_name_each_failure():
    records = ({"status": "done"}, {"status": "failed", "index": 1, "parameters": {"x": 1}, "error": "boom\nat line"},
               {"status": "incomplete", "index": 2, "parameters": {"x": 2}, "error": "stopped early"},
               {"status": "interrupted", "index": 3, "parameters": {"x": 3}})
    res = SweepResult(cases=(), records=records, ran=("a", "b", "c"), skipped=("d",), outdir=Path("."))
    assert outcome_lines(res) == ["sweep: 3 run, 1 already finished, not done: 1 failed, 1 incomplete, 1 interrupted",
                                  "  case 1 {'x': 1}: boom", "  case 2 {'x': 2}: stopped early"]
    done = SweepResult(cases=(), records=({"status": "done"},), ran=(), skipped=("a",), outdir=Path("."))
    assert outcome_lines(done) == ["sweep: 0 run, 1 already finished, 0 failed"]


def test_a_study_writes_its_summary_and_hands_it_over(tmp_path):
    loaded = default_deck("spindle_linear")
    cases = build_cases(loaded.text, {"operating.speed_rpm": [0, 3000]}, "modal")
    shown = []
    res, late = run_study(loaded, cases, "modal", tmp_path, workers=1, command_line="test",
                          show=lambda paths, lines, data: shown.append((paths, lines, data)))
    assert [r["status"] for r in res.records] == ["done", "done"] and not late.interrupted
    (paths, lines, data), = shown
    assert paths[0] == tmp_path / "sweep.h5" and all(p.exists() for p in paths)
    assert len(lines) == 3 and "f1 [Hz]" in lines[0]  # the header and a row a case
    with h5py.File(tmp_path / "sweep.h5") as f:
        assert bool(f.attrs["complete"]) and f.attrs["command_line"] == "test"
        assert f["sweep"].attrs["analysis"] == "modal" and int(f["sweep"].attrs["done"]) == 2
