"""The semi-discretization shares its monodromy batches among threads or worker processes: the limit depths do
not depend on how many threads there are nor on where the batches run, and a worker that asks for more parallel
work runs it itself (a worker waiting on its own pool would wait forever)."""

import threading

import numpy as np

import spindlesim.chatter.sd_lobes as sd_lobes
import spindlesim.chatter.semi_discretization as sd
from spindlesim.chatter import MillingProcess, Mode, ToolPointModel, stability_lobes

FN, ZETA, MT = 922.0, 0.011, 0.03993
TOOL = ToolPointModel.from_modes([Mode("x", FN, ZETA, MT * (2 * np.pi * FN) ** 2),
                                  Mode("y", 1.1 * FN, ZETA, MT * (2 * np.pi * 1.1 * FN) ** 2)])
PROCESS = MillingProcess(2, 20e-3, 5e-3, "down", 6e8, 1 / 3)


def _with_workers(monkeypatch, n):
    monkeypatch.setattr(sd, "workers", lambda: n)
    monkeypatch.setattr(sd_lobes, "workers", lambda: n)


def test_limits_do_not_depend_on_the_thread_count(monkeypatch):
    speeds = np.linspace(9000.0, 24000.0, 12)
    runs = {}
    for n in (1, 3):
        _with_workers(monkeypatch, n)
        runs[n] = stability_lobes(PROCESS, TOOL, speeds, "semi_discretization").limit_depth_m
    assert np.all(np.isfinite(runs[1]))
    np.testing.assert_allclose(runs[3], runs[1], rtol=1e-8)


def test_nested_parallel_work_runs_in_the_worker(monkeypatch):
    _with_workers(monkeypatch, 2)
    out = []
    caller = threading.Thread(target=lambda: out.append(
        sd.parallel_map(lambda k: sd.parallel_map(lambda j: (k, j), range(3)), range(4))), daemon=True)
    caller.start()
    caller.join(timeout=60.0)  # a deadlock fails the test instead of hanging the suite
    assert not caller.is_alive(), "nested parallel_map deadlocked"
    assert out == [[[(k, j) for j in range(3)] for k in range(4)]]


def test_batches_on_worker_processes_give_the_same_limits_as_threads(monkeypatch):
    """Every batch above PROCESS_WORK (here: all) goes to the worker processes; each is evaluated whole in one
    place, so the limits are equal to the last bit, and the pool is really used (its workers ran)."""
    speeds = np.linspace(9000.0, 24000.0, 12)
    monkeypatch.setenv("SPINDLESIM_SD_PROCESSES", "0")
    threads = stability_lobes(PROCESS, TOOL, speeds, "semi_discretization").limit_depth_m
    monkeypatch.setenv("SPINDLESIM_SD_PROCESSES", "1")
    monkeypatch.setattr(sd, "PROCESS_WORK", 0.0)
    _with_workers(monkeypatch, 2)
    sent = []
    submit = sd.ProcessPoolExecutor.submit
    monkeypatch.setattr(sd.ProcessPoolExecutor, "submit", lambda self, *a, **k: sent.append(1) or submit(self, *a, **k))
    procs = stability_lobes(PROCESS, TOOL, speeds, "semi_discretization").limit_depth_m
    assert len(sent) > 10
    assert np.all(np.isfinite(threads))
    np.testing.assert_array_equal(procs, threads)


def test_critical_multipliers_in_one_batch_are_those_of_one_point_at_a_time(monkeypatch):
    """The boundary's kind, chatter frequency and lobe number at every limit are computed in batches on the
    workers (issue "Lobes in seconds"): each is bit for bit what the one-point evaluation (the code before it)
    gives, on threads and on the worker processes alike."""
    prob = sd_lobes._Grouped(PROCESS, [TOOL], np.linspace(9000.0, 24000.0, 7), np.array([60, 60, 60, 80, 80, 80, 80]), 1)
    s_idx, depth = np.arange(7), np.linspace(0.4e-3, 1.6e-3, 7)
    one = [prob.problems[prob.group[s]].critical(int(prob.local[s]), float(a)) for s, a in zip(s_idx, depth)]
    for where in (1e300, 0.0):  # threads; then every batch on the worker processes
        monkeypatch.setattr(sd, "PROCESS_WORK", where)
        _with_workers(monkeypatch, 2)
        assert prob.criticals(s_idx, depth) == one
    assert {cm.kind for cm in one} <= {"hopf", "flip"} and all(cm.chatter_frequency_hz > 0 for cm in one)
