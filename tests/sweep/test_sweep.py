"""Parameter sweeps: overrides by path, process pool vs Dask, resume after a kill, failures recorded."""

import json
import os
import signal
import subprocess
import sys
import time
from importlib import resources

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.deck import default_deck, parse_deck
from spindlesim.sweep import build_cases, parse_set_option, run_sweep
from spindlesim.sweep.cases import parse_values

DECK = default_deck("spindle_linear").text
LINEAR_DECK = str(resources.files("spindlesim.decks") / "spindle_linear.yaml")


def test_values_and_ranges():
    assert parse_values("5,8,12") == [5, 8, 12]
    assert parse_values("1000:6000:11")[:3] == [1000, 1500, 2000]
    assert parse_values("0:1:3") == [0, 0.5, 1.0]
    assert parse_values("0.0:1.0:2") == [0.0, 1.0]
    assert parse_values("[[1,0],[0,1]],[[2,0],[0,2]]") == [[[1, 0], [0, 1]], [[2, 0], [0, 2]]]
    assert parse_set_option("bearings.front.K_N_m.0.0=1e8,2e8") == ("bearings.front.K_N_m.0.0", [1e8, 2e8])
    with pytest.raises(ValueError):
        parse_set_option("operating.speed_rpm")


def test_grid_list_and_named_items():
    cases = build_cases(DECK, {"operating.speed_rpm": [1000, 2000, 3000], "bearings.rear.K_N_m.1.1": [1e8, 2e8]},
                        "modal")
    assert len(cases) == 6 and len({c.key for c in cases}) == 6
    d = parse_deck(cases[5].deck_text).deck
    assert d.operating.speed_rpm == 3000 and d.bearings[1].K_N_m[1][1] == 2e8
    assert d.bearings[0].K_N_m[1][1] == 467.71e6  # the other bearing untouched
    lst = build_cases(DECK, {"operating.speed_rpm": [1, 2], "modal.modes": [3, 4]}, "modal", mode="list")
    assert [(c.parameters["operating.speed_rpm"], c.parameters["modal.modes"]) for c in lst] == [(1, 3), (2, 4)]
    with pytest.raises(KeyError, match="bearings.middle: no item named 'middle'"):
        build_cases(DECK, {"bearings.middle.K_N_m.0.0": [1.0]}, "modal")
    with pytest.raises(ValueError, match="equally many"):
        build_cases(DECK, {"operating.speed_rpm": [1, 2], "modal.modes": [3]}, "modal", mode="list")


def _freqs(res):
    return np.array([r["scalars"]["modal/f3_hz"] for r in res.records])


@pytest.mark.slow
def test_process_pool_and_dask_give_identical_results(tmp_path):
    pytest.importorskip("distributed")
    cases = build_cases(DECK, {"operating.speed_rpm": [0, 6000, 12000]}, "modal", options={"plots": False})
    a = run_sweep(cases, tmp_path / "pool", workers=2)
    b = run_sweep(cases, tmp_path / "dask", workers=2, scheduler="local")
    assert all(r["status"] == "done" for r in a.records + b.records)
    np.testing.assert_array_equal(_freqs(a), _freqs(b))
    assert _freqs(a)[2] < _freqs(a)[0]  # backward mode falls with speed: the cases really differ


def test_resume_runs_only_missing_cases(tmp_path):
    cases = build_cases(DECK, {"operating.speed_rpm": [0, 3000, 6000, 9000]}, "static", options={"plots": False})
    first = run_sweep(cases, tmp_path, workers=1)
    assert len(first.ran) == 4
    for c in cases[1:3]:
        (tmp_path / "cases" / c.key / "case.json").unlink()
    again = run_sweep(cases, tmp_path, workers=1)
    assert set(again.ran) == {cases[1].key, cases[2].key}
    assert len(again.skipped) == 2


@pytest.mark.slow
def test_killed_sweep_completes_only_missing_cases_on_rerun(tmp_path):
    out = tmp_path / "sw"
    cmd = [sys.executable, "-m", "spindlesim", "sweep", LINEAR_DECK, "--analysis", "modal", "--workers", "1",
           "--set", "operating.speed_rpm=0:10000:6", "--case-plots", "-o", str(out)]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.time() + 120
    while time.time() < deadline:
        done = list(out.glob("cases/*/case.json"))
        if len(done) >= 2:
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    finished = {p.parent.name for p in out.glob("cases/*/case.json")}
    assert 2 <= len(finished) < 6, "the sweep should have been killed part-way"
    res = CliRunner().invoke(main, cmd[3:])
    assert res.exit_code == 0, res.output
    with h5py.File(out / "sweep.h5") as f:
        assert f["/sweep"].attrs["skipped"] == len(finished)
        assert f["/sweep"].attrs["ran"] == 6 - len(finished)
        assert list(f["/sweep/status"].asstr()[()]) == ["done"] * 6


def test_failing_case_is_recorded_and_others_finish(tmp_path):
    res = CliRunner().invoke(main, ["sweep", LINEAR_DECK, "--analysis", "static", "--workers", "1", "--mode", "list",
                                    "--set", "bearings.front.K_N_m=[[0,0],[0,0]],[[1.0e8,0],[0,1.0e8]]",
                                    "--set", "bearings.rear.K_N_m=[[0,0],[0,0]],[[1.0e8,0],[0,1.0e8]]",
                                    "-o", str(tmp_path)])
    assert res.exit_code == 1
    with h5py.File(tmp_path / "sweep.h5") as f:
        status = list(f["/sweep/status"].asstr()[()])
        err = list(f["/sweep/error"].asstr()[()])
    assert status == ["failed", "done"]
    assert "singular" in err[0]
    rec = json.loads(next(p for p in tmp_path.glob("cases/*/case.json") if "failed" in p.read_text()).read_text())
    assert rec["parameters"]["bearings.front.K_N_m"] == [[0, 0], [0, 0]]
    # matrices as text, in the unit their key names (issue 33, item 2)
    from tests.units import unit_problems

    assert not unit_problems(tmp_path / "sweep.h5")


def test_bad_override_is_a_deck_error(tmp_path):
    res = CliRunner().invoke(main, ["sweep", "--analysis", "modal", "--set", "operating.speed_rpm=-5,10",
                                    "-o", str(tmp_path)])
    assert res.exit_code == 2
    assert "case 0" in res.output and "operating.speed_rpm" in res.output
    assert not (tmp_path / "sweep.h5").exists()


@pytest.mark.slow
def test_a_dask_sweep_is_quiet_by_default_and_logs_with_verbose(tmp_path):
    """`--scheduler local` printed 34 INFO lines of the scheduler and a connection traceback on the
    terminal: without -v none of Dask's lines, with -v its INFO lines."""
    pytest.importorskip("distributed")
    from pathlib import Path

    exe = Path(__file__).parents[2] / ".venv" / "bin" / "spindlesim"
    deck = tmp_path / "linear.yaml"
    deck.write_text(default_deck("spindle_linear").text)
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")
    runs = {}
    for flag, out in (([], "quiet"), (["-v"], "verbose")):
        runs[out] = subprocess.run([str(exe), *flag, "sweep", str(deck), "--analysis", "modal", "--set",
                                    "operating.speed_rpm=0:2000:2", "--scheduler", "local", "--workers", "1",
                                    "-o", str(tmp_path / out), "-q"], env=env, capture_output=True, text=True,
                                   timeout=300)
    quiet, verbose = runs["quiet"], runs["verbose"]
    assert quiet.returncode == 0 and verbose.returncode == 0, quiet.stderr + verbose.stderr
    assert "distributed" not in quiet.stderr and "Traceback" not in quiet.stderr, quiet.stderr
    dask_lines = [ln for ln in verbose.stderr.splitlines() if ln.startswith("info: ") and "cheduler" in ln]
    assert dask_lines, verbose.stderr  # Dask's own INFO lines (scheduler start and close) with -v


def test_a_scalar_constant_to_round_off_is_drawn_flat(tmp_path):
    """A key result that varies by 0.003 % between the cases used to fill its panel's height (issue 23)."""
    from spindlesim.sweep.cases import Case
    from spindlesim.sweep.report import scalars_figure
    from spindlesim.sweep.runner import DONE, SweepResult

    rpm = [1000.0, 2000.0, 3000.0]
    cases = tuple(Case(i, {"operating.speed_rpm": s}, "", "modal") for i, s in enumerate(rpm))
    freq = [1116.72, 1116.75, 1116.70]  # 0.0045 % apart
    damp = [0.01, 0.02, 0.03]
    records = tuple({"status": DONE, "scalars": {"modal/frequency_hz[0]": f, "modal/damping_ratio[0]": d},
                     "units": {"modal/frequency_hz[0]": "Hz", "modal/damping_ratio[0]": "1"}}
                    for f, d in zip(freq, damp))
    fig = scalars_figure(SweepResult(cases, records, (), (), tmp_path))
    panels = {ax.get_ylabel().split(" [")[0]: ax for ax in fig.axes}
    flat = next(ax for name, ax in panels.items() if "frequency" in name)
    lo, hi = flat.get_ylim()
    assert hi - lo >= 0.02 * 1116.7 * 0.99  # +- 1 %: the three points on one level (old: 0.05 Hz tall)
    assert [t.get_text() for t in flat.texts if t.get_gid() == "flat"] == ["constant to 0.0045 % (drawn flat)"]
    varying = next(ax for name, ax in panels.items() if "damping" in name)
    assert not [t for t in varying.texts if t.get_gid() == "flat"] and varying.get_ylim()[1] < 0.04
