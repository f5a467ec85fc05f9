"""Exit codes (spindlesim/commands/exits.py): 0 finished, 1 failed, 2 deck error, 3 ran but incomplete,
130 interrupted.  The SIGINT tests signal a real `spindlesim` process once it is integrating."""

import os
import re
import signal
import subprocess
import threading
import time
from importlib import resources
from pathlib import Path

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from tests.processes import as_in_a_terminal

SPINDLESIM = Path(__file__).parents[2] / ".venv" / "bin" / "spindlesim"
RIG_DECK = (resources.files("spindlesim.decks") / "transient.yaml").read_text()
LINEAR_DECK = (resources.files("spindlesim.decks") / "spindle_linear.yaml").read_text()
ROOT = Path(__file__).parents[2]


def _env() -> dict:
    return dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")


class _Lines:
    """Collects a pipe's lines in a thread, so the test can wait for one without blocking."""

    def __init__(self, pipe):
        self.lines: list[str] = []
        self._t = threading.Thread(target=self._read, args=(pipe,), daemon=True)
        self._t.start()

    def _read(self, pipe):
        for line in pipe:
            self.lines.append(line)

    def wait_for(self, text: str, timeout: float) -> bool:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if any(text in ln for ln in self.lines):
                return True
            time.sleep(0.05)
        return False

    def text(self) -> str:
        self._t.join(5)
        return "".join(self.lines)


def _blowing_up_deck(tmp_path) -> Path:
    """The rig deck with an RK4 step far above the flexible race's stability limit."""
    deck = tmp_path / "blow.yaml"
    deck.write_text(RIG_DECK.replace("  duration_s: 0.3 ", "  integrator: {step_us: 200.0}\n  duration_s: 0.3 "))
    return deck


@pytest.mark.slow
def test_sigint_on_a_transient_exits_130_and_marks_the_files_incomplete(tmp_path):
    out = tmp_path / "out"
    proc = subprocess.Popen([str(SPINDLESIM), "transient", "--model", "flexible_race", "--duration", "3", "-o",
                             str(out)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=_env(),
                            preexec_fn=as_in_a_terminal)
    err, out_lines = _Lines(proc.stderr), _Lines(proc.stdout)
    try:
        assert err.wait_for("transient: 100/1000", 120), err.text()  # integrating: 10 % done
        t0 = time.monotonic()
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=60)
        stopped_after = time.monotonic() - t0
        stdout = out_lines.text()
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 130, err.text()
    assert stopped_after < 30  # writing the partial files and the plots takes a few seconds
    assert "exit code 130" in err.text()
    with h5py.File(out / "transient.h5") as f:
        assert not bool(f.attrs["complete"])
        assert "interrupted" in f.attrs["incomplete_reason"]
        assert 0.3 <= f["transient/time_s"][-1] < 3.0
    assert (out / "transient_spectrum.png").stat().st_size > 0
    assert not list(out.glob("*.tmp*"))
    assert str(out / "transient.h5") in stdout


def test_integration_stopped_early_exits_3(tmp_path):
    out = tmp_path / "out"
    res = CliRunner().invoke(main, ["transient", str(_blowing_up_deck(tmp_path)), "--model", "flexible_race",
                                    "--duration", "0.05", "-o", str(out)])
    assert res.exit_code == 3, res.output
    assert "non-finite state" in res.output and "exit code 3" in res.output
    with h5py.File(out / "transient.h5") as f:
        assert not bool(f.attrs["complete"])
        assert "non-finite" in f.attrs["incomplete_reason"]
    for name in ("transient_spectrum.png", "transient_poincare.png"):
        assert (out / name).stat().st_size > 0


def test_sweep_of_incomplete_cases_exits_3_and_nothing_is_done(tmp_path):
    res = CliRunner().invoke(main, ["sweep", str(_blowing_up_deck(tmp_path)), "--analysis", "transient",
                                    "--set", "transient.duration_s=0.004,0.005", "--set", "transient.model=flexible_race",
                                    "--workers", "1", "-o", str(tmp_path / "sw")])
    assert res.exit_code == 3, res.output
    with h5py.File(tmp_path / "sw" / "sweep.h5") as f:
        assert list(f["/sweep/status"].asstr()[()]) == ["incomplete", "incomplete"]
        assert not bool(f.attrs["complete"])


def test_run_prints_a_results_summary_and_a_failure_exits_1(tmp_path):
    deck = tmp_path / "d.yaml"
    deck.write_text(LINEAR_DECK + "\nanalyses: [static, modal]\n")
    res = CliRunner().invoke(main, ["run", str(deck), "-o", str(tmp_path / "ok")])
    assert res.exit_code == 0, res.output
    assert str(tmp_path / "ok" / "modal.h5") in res.output
    assert "modal.h5:" in res.output and "frequency Hz" in res.output  # the summary, not only the paths
    quiet = CliRunner().invoke(main, ["run", str(deck), "-q", "-o", str(tmp_path / "ok")])
    assert quiet.exit_code == 0 and "modal.h5:" not in quiet.output
    # no bearing stiffness: a singular problem, reported without a traceback, exit code 1
    deck.write_text(re.sub(r"K_N_m: \[\[.*\]\]", "K_N_m: [[0.0, 0.0], [0.0, 0.0]]", LINEAR_DECK)
                    + "\nanalyses: [static, modal]\n")
    bad = CliRunner().invoke(main, ["run", str(deck), "-o", str(tmp_path / "bad")])
    assert bad.exit_code == 1, bad.output
    assert "static failed" in bad.output and "exit code 1" in bad.output


@pytest.mark.parametrize("command", [["campbell", "--speeds", "0:6000:4"], ["run"], ["sweep", "--analysis", "modal",
                                                                               "--set", "operating.speed_rpm=0:2000:2"]])
def test_an_output_folder_that_cannot_be_written_is_exit_2_before_computing(tmp_path, command):
    """-o below a regular file: no folder can be made there (as root too, where permissions do not stop a
    write); one line, exit code 2, and nothing computed (the progress of the analysis never starts)."""
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    deck = tmp_path / "linear.yaml"
    deck.write_text(LINEAR_DECK)
    res = CliRunner().invoke(main, [command[0], str(deck), *command[1:], "-o", str(blocker / "out")])
    assert res.exit_code == 2, res.output
    assert "cannot write to the output folder" in res.output and "Traceback" not in res.output
    assert "campbell: " not in res.output and "sweep: " not in res.output  # no progress: nothing was computed


def test_input_errors_exit_2_with_one_clear_line(tmp_path):
    """Issue 23: a fluid film asked to run at rest, and shaft dimensions in metres under _mm keys, are input
    errors (exit 2), not solver failures; the fluid film's message names the bearing once; the metres case
    points at the plausibility warnings instead of blaming the bearings alone; --json prints the error."""
    at_rest = CliRunner().invoke(main, ["modal", "--speed", "0", "-o", str(tmp_path / "a")])
    assert at_rest.exit_code == 2, at_rest.output
    assert at_rest.output.count("bearing 'front'") == 1 and "needs a positive speed" in at_rest.output
    thermal = CliRunner().invoke(main, ["thermal", "--speed", "0", "-o", str(tmp_path / "b")])
    assert thermal.exit_code == 2 and "positive speed" in thermal.output
    negative = CliRunner().invoke(main, ["static", "--speed", "-6000", "-o", str(tmp_path / "c")])
    assert negative.exit_code == 2 and "--speed" in negative.output

    import yaml

    d = yaml.safe_load(LINEAR_DECK)
    for row in d["shaft"]["elements"]:
        row[0], row[1], row[2] = row[0] / 1000, row[1] / 1000, row[2] / 1000  # metres under _mm keys
    deck = tmp_path / "metres.yaml"
    deck.write_text(yaml.safe_dump(d))
    res = CliRunner().invoke(main, ["static", str(deck), "-o", str(tmp_path / "d")])
    assert res.exit_code == 2, res.output
    # a shaft whose every row is under 1 mm is a located deck error (it used to surface as a singular stiffness
    # matrix with a pointer to the plausibility warnings; the static solver now equilibrates badly scaled systems)
    assert "were they given in metres" in res.output and "shaft.elements[0][0]" in res.output
    js = _separate_streams().invoke(main, ["static", str(deck), "--json", "-o", str(tmp_path / "e")])
    import json

    assert json.loads(js.stdout)["exit_code"] == 2


def test_a_rotor_the_solver_finds_singular_is_a_located_deck_error(tmp_path):
    """Issue 33 (found by the deck fuzzer at 20,000 examples): one shaft row 5e7 mm in diameter (inside the
    physical range of a _mm key) makes the stiffness matrix singular; the error names the deck, the line of the
    bearings and what to check, exit 2, nothing written (it was one unlocated line)."""
    import json

    deck = tmp_path / "wide.yaml"
    deck.write_text((ROOT / "decks" / "validation" / "jeffcott_plain.yaml").read_text()
                    .replace("- [50.0,", "- [50000000.0,", 1))
    assert "50000000.0" in deck.read_text()
    res = CliRunner().invoke(main, ["static", str(deck), "-o", str(tmp_path / "o")])
    assert res.exit_code == 2, res.output
    line = next(ln for ln in res.output.splitlines() if ln.startswith(str(deck)))
    at = next(i for i, ln in enumerate(deck.read_text().splitlines(), 1) if ln.startswith("bearings:"))
    assert line.startswith(f"{deck}:{at}:1: bearings: static: the stiffness matrix"), line
    assert "nothing was written" in res.output and not (tmp_path / "o").exists()
    js = _separate_streams().invoke(main, ["static", str(deck), "--json", "-o", str(tmp_path / "e")])
    err = json.loads(js.stdout)["errors"][0]
    assert err["line"] == at and err["key"] == "bearings"


def test_json_on_a_deck_error_prints_the_errors_as_json(tmp_path):
    import json

    deck = tmp_path / "bad.yaml"
    deck.write_text(LINEAR_DECK.replace("speed_rpm:", "speed_rpmm:", 1))
    res = _separate_streams().invoke(main, ["modal", str(deck), "--json", "-o", str(tmp_path / "o")])
    assert res.exit_code == 2
    out = json.loads(res.stdout)
    assert out["exit_code"] == 2 and out["errors"] and out["errors"][0]["line"] > 0
    assert any("speed_rpm" in e["key"] + e["message"] for e in out["errors"])


def _separate_streams() -> CliRunner:
    """A runner whose ``stdout`` holds stdout alone (click 8.2+ always; 8.1 with mix_stderr=False)."""
    try:
        return CliRunner(mix_stderr=False)
    except TypeError:
        return CliRunner()


@pytest.mark.slow
def test_ctrl_c_in_a_campbell_diagram_keeps_the_speeds_done(tmp_path):
    """Issue 23: Ctrl-C in `campbell` said "interrupted" and wrote nothing. Now the speeds whose static
    states were found are written, marked incomplete with the reason, and the exit code is 130."""
    out = tmp_path / "out"
    proc = subprocess.Popen([str(SPINDLESIM), "campbell", "--speeds", "1000:12000:40", "-o", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=_env(),
                            preexec_fn=as_in_a_terminal)
    err = _Lines(proc.stderr)
    try:
        assert err.wait_for("campbell: 8/40", 120), err.text()  # the fluid-film states are being found
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 130, err.text()
    with h5py.File(out / "campbell.h5") as f:
        assert not bool(f.attrs["complete"])
        assert "interrupted by the user" in f.attrs["incomplete_reason"]
        speeds = f["campbell/speed_rpm"][()]
        assert 8 <= len(speeds) < 40 and speeds[0] == 1000.0
        assert np.isfinite(f["campbell/frequency_hz"][()]).any()
    assert (out / "campbell.png").exists()
