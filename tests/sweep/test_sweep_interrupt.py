"""Interrupted sweeps: Ctrl-C stops a real sweep within seconds (exit code 130), an interrupted case is
never "done", nothing queued starts, and the resumed study equals a clean run; the same rules on the
process pool and on Dask; case files respect the umask; sweep scalars carry their source's units."""

import json
import os
import signal
import stat
import subprocess
import time
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.commands.exits import exit_code_of
from spindlesim.deck import default_deck
from spindlesim.runs import run_info_for
from spindlesim.sweep import SweepInterrupted, build_cases, run_sweep
from spindlesim.sweep.report import write_summary
from spindlesim.sweep.runner import DONE, is_finished, load_record
from tests.processes import as_in_a_terminal

ROOT = Path(__file__).parents[2]
SPINDLESIM = ROOT / ".venv" / "bin" / "spindlesim"
ROLLERS = [5, 8, 12, 10]
#: scalars that measure the computer, not the rotor
_TIMING = ("wall_time", "elapsed")


def _tiny_study(tmp_path) -> Path:
    """decks/studies/seed000_rollers.yaml on the flexible race, 0.05 s simulated: each case takes about a
    second, so a Ctrl-C finds one running and others queued."""
    text = (ROOT / "decks" / "studies" / "seed000_rollers.yaml").read_text()
    for old, new in (("  model: rigid_race ", "  model: flexible_race "), ("  duration_s: 0.3 ", "  duration_s: 0.05 "),
                     ("transient.rollers: [5, 8, 12]", f"transient.rollers: {ROLLERS}")):
        assert old in text
        text = text.replace(old, new)
    deck = tmp_path / "study.yaml"
    deck.write_text(text)
    return deck


def _records(out: Path) -> dict[str, dict]:
    return {p.parent.name: json.loads(p.read_text()) for p in out.glob("cases/*/case.json")}


def _scalars(path: Path) -> dict[str, np.ndarray]:
    found = {}
    with h5py.File(path) as f:
        f["sweep/scalars"].visititems(lambda n, o: found.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return found


def _h5_complete(path: Path) -> bool:
    with h5py.File(path) as f:
        return bool(f.attrs["complete"])


@pytest.mark.slow
def test_ctrl_c_stops_a_sweep_and_the_resumed_study_equals_a_clean_run(tmp_path):
    deck, out = _tiny_study(tmp_path), tmp_path / "resumed"
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")
    cmd = ["sweep", str(deck), "--workers", "1", "-o"]
    proc = subprocess.Popen([str(SPINDLESIM), *cmd, str(out)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env=env, start_new_session=True, preexec_fn=as_in_a_terminal)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:  # one case done and the next one running
            recs = _records(out)
            done = [k for k, r in recs.items() if r["status"] == DONE]
            running = [p.parent.name for p in out.glob("cases/*/deck.yaml") if p.parent.name not in recs]
            if done and running:
                break
            assert proc.poll() is None, proc.stderr.read().decode()
            time.sleep(0.02)
        else:
            pytest.fail("the sweep did not get going")
        t0 = time.monotonic()
        os.killpg(proc.pid, signal.SIGINT)  # what a terminal's Ctrl-C does: the whole process group
        proc.wait(timeout=60)
        stopped_after = time.monotonic() - t0
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    err = proc.stderr.read().decode()
    assert proc.returncode == 130, err
    assert stopped_after < 20, f"the sweep took {stopped_after:.1f} s to stop"

    recs = _records(out)
    assert set(running) <= set(recs) and all(recs[k]["status"] == "interrupted" for k in running)
    n_done = sum(r["status"] == DONE for r in recs.values())
    assert 1 <= n_done < len(ROLLERS)
    for key, r in recs.items():  # "done" only with every file complete, and never for a stopped case
        assert (r["status"] == DONE) == is_finished(r, out / "cases" / key)
    started = {p.parent.name for p in out.glob("cases/*/deck.yaml")}
    assert len(started) < len(ROLLERS), "queued cases must not start after Ctrl-C"
    assert not list(out.rglob("*.tmp*"))
    with h5py.File(out / "sweep.h5") as f:
        assert not bool(f.attrs["complete"])
        assert "interrupted" in f.attrs["incomplete_reason"]
        status = list(f["/sweep/status"].asstr()[()])
    assert status.count("done") == n_done and "not run" in status

    resumed = CliRunner().invoke(main, [*cmd, str(out)])
    assert resumed.exit_code == 0, resumed.output
    assert f"{len(ROLLERS) - n_done} run, {n_done} already finished" in resumed.output
    assert "status" in resumed.output and resumed.output.count(" done ") >= len(ROLLERS)  # the per-case table
    clean = CliRunner().invoke(main, [*cmd[:2], "--workers", "2", "-o", str(tmp_path / "clean")])
    assert clean.exit_code == 0, clean.output

    assert _h5_complete(out / "sweep.h5") and _h5_complete(tmp_path / "clean" / "sweep.h5")
    a, b = _scalars(out / "sweep.h5"), _scalars(tmp_path / "clean" / "sweep.h5")
    assert set(a) == set(b) and "transient/dominant_amplitude_m" in a
    assert not [n for n in a if "poincare" in n and "[" in n], "Poincare samples are not scalars"
    for name in a:  # the resumed cases run in this process, the clean ones in workers: BLAS threading may
        if not any(w in name for w in _TIMING):  # differ between them and move the last bits (seen: 5e-11)
            np.testing.assert_allclose(a[name], b[name], rtol=1e-9, atol=0, err_msg=name)


def _modal_cases():
    return build_cases(default_deck("spindle_linear").text, {"operating.speed_rpm": [0, 2000, 4000, 6000, 8000, 10000]},
                       "modal", options={"plots": False})


def _frequencies(res) -> np.ndarray:
    return np.array([r["scalars"]["modal/f3_hz"] for r in res.records])


@pytest.mark.slow
@pytest.mark.parametrize("scheduler", [None, "local"], ids=["process_pool", "dask"])
def test_interrupt_while_waiting_records_no_unfinished_case_as_done(tmp_path, scheduler):
    if scheduler is not None:
        pytest.importorskip("distributed")
    cases = _modal_cases()

    def ctrl_c(done, total, eta):  # Ctrl-C arrives in the loop that waits for the cases
        raise KeyboardInterrupt

    with pytest.raises(SweepInterrupted) as info:
        run_sweep(cases, tmp_path / "s", workers=1, scheduler=scheduler, progress=ctrl_c)
    res = info.value.result
    assert res.interrupted and not res.complete and exit_code_of(info.value) == 130
    assert 1 <= res.count(DONE) < len(cases)
    assert res.count("interrupted") + res.count("not run") == len(cases) - res.count(DONE)
    for c, r in zip(cases, res.records):
        case_dir = tmp_path / "s" / "cases" / c.key
        assert (r["status"] == DONE) == is_finished(load_record(case_dir), case_dir)
    assert not list((tmp_path / "s").rglob("*.tmp*"))

    again = run_sweep(cases, tmp_path / "s", workers=1, scheduler=scheduler)
    assert again.complete and len(again.skipped) == res.count(DONE)
    assert len(again.ran) == len(cases) - res.count(DONE)
    clean = run_sweep(cases, tmp_path / "clean", workers=2)
    np.testing.assert_array_equal(_frequencies(again), _frequencies(clean))


def test_a_case_recorded_done_with_an_incomplete_file_runs_again(tmp_path):
    """Records of older versions said "done" for interrupted runs; their files say complete = False."""
    cases = _modal_cases()[:2]
    run_sweep(cases, tmp_path, workers=1)
    with h5py.File(tmp_path / "cases" / cases[0].key / "modal.h5", "a") as f:
        f.attrs["complete"] = False
    again = run_sweep(cases, tmp_path, workers=1)
    assert again.ran == (cases[0].key,) and again.skipped == (cases[1].key,)
    assert again.complete


@pytest.mark.parametrize("umask, mode", [(0o022, 0o644), (0o027, 0o640)], ids=["umask022", "umask027"])
def test_case_files_respect_the_umask_and_scalars_carry_their_units(tmp_path, umask, mode):
    loaded = default_deck("spindle_linear")
    cases = build_cases(loaded.text, {"operating.speed_rpm": [0, 3000]}, "static", options={"plots": False})
    old = os.umask(umask)
    try:
        res = run_sweep(cases, tmp_path, workers=1)
        summary = write_summary(res, run_info_for(loaded), "static")
    finally:
        os.umask(old)
    for p in [summary, *tmp_path.glob("cases/*/*")]:
        assert stat.S_IMODE(p.stat().st_mode) == mode, p.name

    source = tmp_path / "cases" / cases[0].key / "static.h5"
    with h5py.File(summary) as s, h5py.File(source) as f:
        names = []
        s["sweep/scalars"].visit(lambda n: names.append(n) if isinstance(s["sweep/scalars"][n], h5py.Dataset)
                                 else None)
        assert "static/static_stiffness_N_m" in names and "static.attr.stiffness_node" in names
        for n in names:
            unit = s["sweep/scalars"][n].attrs["units"]
            dataset = n.split("[")[0]
            if dataset in f:  # a dataset's scalar: the dataset's own units
                assert unit == f[dataset].attrs["units"], n
            else:  # a derived scalar or a group attribute: stated, never "see the case file"
                assert unit and unit != "see the case file", n
        assert s["sweep/scalars/static.attr.stiffness_node"].attrs["units"] == "1"  # a node number
        assert s["sweep/scalars/static.attr.speed_rpm"].attrs["units"] == "rpm"


def test_ctrl_c_after_every_case_finished_still_writes_the_summary_and_exits_130(tmp_path, monkeypatch):
    """A Ctrl-C while the summary of finished cases is written waits for it: sweep.h5 (complete: every
    case is done) and the summary plots are written, then the command stops with 130."""
    import spindlesim.sweep.report as report

    deck = tmp_path / "linear.yaml"
    deck.write_text(default_deck("spindle_linear").text)
    real = report.write_summary

    def interrupted_summary(*args, **kwargs):
        os.kill(os.getpid(), signal.SIGINT)  # the terminal's Ctrl-C, while the summary is being written
        return real(*args, **kwargs)

    monkeypatch.setattr(report, "write_summary", interrupted_summary)
    out = tmp_path / "sweep"
    res = CliRunner().invoke(main, ["sweep", str(deck), "--analysis", "modal", "--workers", "1",
                                    "--set", "operating.speed_rpm=0:4000:3", "-o", str(out)])
    assert res.exit_code == 130, res.output
    assert "interrupted after the cases finished" in res.output
    with h5py.File(out / "sweep.h5") as f:
        assert bool(f.attrs["complete"])
    assert (out / "sweep_scalars.png").exists()
