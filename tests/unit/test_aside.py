"""A computation set aside (spindlesim/analysis/aside.py): computed in a forked child while this process goes on,
its result the call's own; the child's exception raised here as the call raises it; Ctrl-C stops the child; where
no child can be forked (SPINDLESIM_SD_PROCESSES=0) the call is made here when its result is asked for."""

import os
import time

import numpy as np
import pytest

from spindlesim.analysis import aside
from spindlesim.analysis.aside import Aside, Known


def _pid_and_sum(x):
    return os.getpid(), float(np.sum(x))


class Odd(Exception):
    """An exception that does not survive pickling (two arguments, one taken)."""

    def __init__(self, a, b):
        super().__init__(f"{a}/{b}")


def _raises():
    raise Odd(1, 2)


def _sleeps():
    time.sleep(600)


@pytest.mark.skipif(not aside.available(), reason="no fork here")
def test_the_result_is_computed_in_a_child_and_is_the_calls():
    x = np.linspace(0.0, 1.0, 1001)
    pid, got = Aside(_pid_and_sum, x).result()
    assert pid != os.getpid()
    assert got == float(np.sum(x))


@pytest.mark.skipif(not aside.available(), reason="no fork here")
def test_the_childs_exception_is_raised_here_whole():
    with pytest.raises(Odd, match="1/2"):
        Aside(_raises).result()


@pytest.mark.skipif(not aside.available(), reason="no fork here")
def test_cancel_stops_the_child():
    a = Aside(_sleeps)
    procs = list(a._pool._processes.values())
    assert procs and procs[0].is_alive()
    a.cancel()
    # a child left running would fail here instead of hanging the suite.  Polled, not one join: the pool's own
    # thread reaps the child too, and whichever thread's waitpid comes second sees no child and leaves the
    # exit status unset for a moment (seen once in the suite: the join returned, the child still reported alive)
    deadline = time.monotonic() + 30.0
    while procs[0].is_alive() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not procs[0].is_alive()


def test_without_worker_processes_the_call_is_made_here(monkeypatch):
    monkeypatch.setenv("SPINDLESIM_SD_PROCESSES", "0")
    assert not aside.available()
    pid, got = Aside(_pid_and_sum, np.ones(3)).result()
    assert pid == os.getpid() and got == 3.0
    assert Known(5).result() == 5


@pytest.mark.skipif(not aside.available(), reason="no fork here")
def test_chatter_computed_aside_is_the_serial_chatter(tmp_path, monkeypatch):
    """`chatter` on the milling deck (12 speeds, its thermal section kept) with the comparison's lobes and the
    thermal speed limit computed aside, and with everything in this process: the same numbers, bit for bit
    (issue "Lobes in seconds": the two were computed one after the other before)."""
    from pathlib import Path

    from spindlesim.deck import load_deck
    from spindlesim.runs import perform_analysis

    text = (Path(__file__).parents[2] / "decks" / "milling_spindle.yaml").read_text().replace(
        "speeds_rpm: {start: 6000, stop: 24000, count: 200}", "speeds_rpm: {start: 14000, stop: 20000, count: 12}")
    deck = tmp_path / "d.yaml"
    deck.write_text(text)
    runs = {}
    for where in ("1", "0"):
        monkeypatch.setenv("SPINDLESIM_SD_PROCESSES", where)
        runs[where] = perform_analysis("chatter", load_deck(str(deck)), tmp_path / where).result
    a, b = runs["1"], runs["0"]
    assert a.result.speed_limit_rpm == b.result.speed_limit_rpm is not None  # 18,000 rpm: within the speeds
    assert a.result.speed_limit_rpm < 20000
    for x, y in ((a.result.diagram, b.result.diagram), (a.at_deck, b.at_deck)):
        assert np.array_equal(x.limit_depth_m, y.limit_depth_m, equal_nan=True)
        assert np.array_equal(x.chatter_frequency_hz, y.chatter_frequency_hz, equal_nan=True)
    assert a.result.recommendation == b.result.recommendation


KILLED_PARENT = """
import os, sys, time
from spindlesim.analysis.aside import Aside

def pid_then_sleep():
    print(os.getpid(), flush=True)
    time.sleep(600)

pending = Aside(pid_then_sleep)
time.sleep(600)
"""


@pytest.mark.skipif(not aside.available() or not os.path.isdir("/proc"), reason="no fork here, or no /proc")
def test_a_child_exits_when_its_parent_is_killed():
    """A killed command (SIGKILL: nothing of it runs) leaves no child set aside waiting for ever: the child's
    watchdog sees its parent gone within its period (0.5 s)."""
    import signal
    import subprocess
    import sys

    import select

    proc = subprocess.Popen([sys.executable, "-c", KILLED_PARENT], stdout=subprocess.PIPE, text=True)
    ready, _, _ = select.select([proc.stdout], [], [], 120.0)  # never wait for ever
    if not ready:
        proc.kill()
        pytest.fail("the child set aside did not start within 120 s")
    child = int(proc.stdout.readline())  # the child prints its pid from inside the computation
    assert os.path.isdir(f"/proc/{child}")
    proc.send_signal(signal.SIGKILL)
    proc.wait(10)
    deadline = time.monotonic() + 10.0
    while os.path.isdir(f"/proc/{child}") and time.monotonic() < deadline:
        try:  # a zombie until its new parent reaps it: gone as far as work is concerned
            with open(f"/proc/{child}/stat") as f:
                if f.read().split(") ")[-1].startswith("Z"):
                    break
        except OSError:
            break
        time.sleep(0.05)
    alive = os.path.isdir(f"/proc/{child}")
    if alive:
        with open(f"/proc/{child}/stat") as f:
            alive = not f.read().split(") ")[-1].startswith("Z")
    assert not alive, "the child outlived its parent"
