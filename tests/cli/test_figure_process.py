"""The figure process of the `spindlesim` program (spindlesim/output/drawing.py).

Figures drawn in the forked figure process are the figures drawn in the main process, byte for
byte; a figure that cannot be written is an exit-1 message, not a traceback; neither Ctrl-C nor a
killed parent leaves a process or a temporary file behind; and the main process never imports
matplotlib for the everyday commands (that is the time the figure process saves)."""

import os
import signal
import subprocess
import sys
import time
from importlib import resources
from pathlib import Path

import pytest

from tests.processes import as_in_a_terminal

SPINDLESIM = Path(__file__).parents[2] / ".venv" / "bin" / "spindlesim"
LINEAR_DECK = (resources.files("spindlesim.decks") / "spindle_linear.yaml").read_text()
LINUX = sys.platform.startswith("linux")


def _env(**kw) -> dict:
    return dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg", **kw)


def _run(args, **env):
    return subprocess.run([str(SPINDLESIM), *map(str, args)], env=_env(**env), capture_output=True, text=True,
                          timeout=120)


def _children(pid: int) -> list[int]:
    with open(f"/proc/{pid}/task/{pid}/children") as f:
        return [int(p) for p in f.read().split()]


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(") ")[1][0] != "Z"
    except FileNotFoundError:
        return False


@pytest.mark.slow
@pytest.mark.parametrize("command", [["modal"], ["frf"], ["campbell", "--speeds", "0:12000:6"]])
def test_figures_from_the_figure_process_equal_those_drawn_in_the_main_process(tmp_path, command):
    deck = tmp_path / "linear.yaml"
    deck.write_text(LINEAR_DECK)
    a = _run([*command, deck, "-o", tmp_path / "a", "-q"])
    b = _run([*command, deck, "-o", tmp_path / "b", "-q"], SPINDLESIM_FIGURE_PROCESS="0")
    assert a.returncode == b.returncode == 0, a.stderr + b.stderr
    assert a.stdout.replace(str(tmp_path / "a"), "") == b.stdout.replace(str(tmp_path / "b"), "")
    pngs = sorted(p.name for p in (tmp_path / "a").glob("*.png"))
    assert pngs and pngs == sorted(p.name for p in (tmp_path / "b").glob("*.png"))
    for name in pngs:
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name


@pytest.mark.slow
@pytest.mark.parametrize("figure_process", ["1", "0"])
def test_a_figure_that_cannot_be_written_is_a_message_and_exit_1(tmp_path, figure_process):
    deck = tmp_path / "linear.yaml"
    deck.write_text(LINEAR_DECK)
    out = tmp_path / "out"
    (out / "modal_shapes.png").mkdir(parents=True)  # a directory where the figure goes
    r = _run(["modal", deck, "-o", out], SPINDLESIM_FIGURE_PROCESS=figure_process)
    assert r.returncode == 1, r.stderr
    assert "cannot write the results" in r.stderr and "modal_shapes.png" in r.stderr
    assert "Traceback" not in r.stderr
    assert not list(out.glob("*.tmp*"))  # the figure's temporary file is gone


def test_the_everyday_plotting_modules_do_not_import_matplotlib():
    code = ("import sys\n"
            "import spindlesim.runs.rotor, spindlesim.output.rotor_plots, spindlesim.chatter.plots\n"
            "import spindlesim.output.drawing, spindlesim.output.figures\n"
            "print(sorted(m for m in sys.modules if m.startswith('matplotlib')))\n")
    r = subprocess.run([sys.executable, "-c", code], env=_env(), capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def _start(tmp_path, args):
    return subprocess.Popen([str(SPINDLESIM), *map(str, args)], env=_env(), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True,
                            preexec_fn=as_in_a_terminal)


def _figure_process_of(proc, timeout=20.0) -> int:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        kids = _children(proc.pid) if _alive(proc.pid) else []
        if kids:
            return kids[0]
        time.sleep(0.01)
    raise AssertionError("no figure process appeared")


@pytest.mark.skipif(not LINUX, reason="reads /proc")
def test_a_killed_run_leaves_no_figure_process(tmp_path):
    # the default deck's fluid-film Campbell diagram takes seconds: killed while it computes
    proc = _start(tmp_path, ["campbell", "--speeds", "1000:12000:40", "-o", tmp_path / "out"])
    child = _figure_process_of(proc)
    time.sleep(1.0)
    proc.kill()
    proc.wait(10)
    deadline = time.monotonic() + 5.0
    while _alive(child) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _alive(child), "the figure process outlived its parent"


@pytest.mark.slow
@pytest.mark.skipif(not LINUX, reason="reads /proc")
@pytest.mark.parametrize("delay_s", [0.0, 1.0])  # at once: while the command still imports and reads the deck
def test_ctrl_c_exits_130_with_no_process_or_temporary_file_left(tmp_path, delay_s):
    out = tmp_path / "out"
    proc = _start(tmp_path, ["campbell", "--speeds", "1000:12000:40", "-o", out])
    child = _figure_process_of(proc)
    time.sleep(delay_s)
    os.killpg(proc.pid, signal.SIGINT)  # the terminal's Ctrl-C: the whole foreground group
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 130, err
    assert "interrupted" in err and "Traceback" not in err and "Aborted" not in err
    deadline = time.monotonic() + 5.0
    while _alive(child) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _alive(child)
    assert not list(out.glob("*.tmp*")) if out.exists() else True
