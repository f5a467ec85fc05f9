"""Campbell modes solved while the static states are still being found (analysis/prefetch.py):
the same numbers as the serial path, the serial path whenever the guessed basis fails its check,
and no thread left behind by a failing diagram."""

import threading

import numpy as np
import pytest

import spindlesim.analysis.campbell as campbell
import spindlesim.analysis.reduced as reduced
from spindlesim.deck import default_deck
from spindlesim.model.build import build_rotor
from tests.rotor_helpers import speed_tabled

FIELDS = ("speed_rpm", "frequency_hz", "damping_ratio", "log_dec", "whirl", "critical_speeds_rpm")


def _solve(deck, speeds, cores, monkeypatch):
    monkeypatch.setattr(campbell, "usable_cores", lambda: cores)
    return campbell.solve_campbell(build_rotor(default_deck(deck).deck), speeds, n_modes=6)


def _same(a, b):
    for f in FIELDS:
        x, y = getattr(a, f), getattr(b, f)
        assert np.array_equal(x, y), f
    assert a.model == b.model


@pytest.mark.parametrize("deck,speeds", [("milling_spindle", np.linspace(0, 24000, 12)),
                                         ("spindle_linear", np.linspace(0, 12000, 9))])
def test_prefetched_modes_equal_the_serial_ones(monkeypatch, deck, speeds):
    monkeypatch.setattr(campbell._Guess, "MIN_STATE_S", 0.0)  # prefetch however cheap the states are
    calls = []
    real = campbell.ModalPrefetch.finish
    monkeypatch.setattr(campbell.ModalPrefetch, "finish", lambda self: calls.append(1) or real(self))
    on = _solve(deck, speeds, 2, monkeypatch)
    assert calls, "the prefetched modes were not used"
    off = _solve(deck, speeds, 1, monkeypatch)
    _same(on, off)


def test_a_guess_that_fails_its_check_gives_the_serial_result(monkeypatch):
    monkeypatch.setattr(campbell._Guess, "MIN_STATE_S", 0.0)
    speeds = np.linspace(0, 12000, 9)
    monkeypatch.setattr(reduced, "FREQ_RTOL", 1e-9)  # the first cut-off fails; a larger basis (or the full model)
    used = []
    real = campbell.ModalPrefetch.finish
    monkeypatch.setattr(campbell.ModalPrefetch, "finish", lambda self: used.append(1) or real(self))
    on = _solve("spindle_linear", speeds, 2, monkeypatch)
    assert used  # modes were prefetched on the guessed basis ... and dropped when it failed its check
    off = _solve("spindle_linear", speeds, 1, monkeypatch)
    _same(on, off)
    assert "reduced: 30 of" not in on.model  # not the guessed basis


def test_states_as_cheap_as_a_linear_rotor_s_are_not_prefetched(monkeypatch):
    """0.4 ms a state: nothing to hide the modes behind (the speeds go to the cores in runs instead).  The clock
    the rule reads advances 0.4 ms a reading, as on an idle machine (a loaded one can stretch a real state past
    the threshold, and this test is about the rule, not about the machine)."""
    ticks = iter(np.arange(1000) * 0.4e-3)
    monkeypatch.setattr(campbell, "time", type("Clock", (), {"perf_counter": staticmethod(lambda: next(ticks))}))
    started = []
    real = campbell.ModalPrefetch.__init__
    monkeypatch.setattr(campbell.ModalPrefetch, "__init__", lambda self, solve: started.append(1) or real(self, solve))
    _solve("spindle_linear", np.linspace(0, 12000, 9), 2, monkeypatch)
    assert not started


def test_no_prefetch_thread_outlives_a_failing_diagram(monkeypatch):
    """Ctrl-C during the static states: the diagram of the speeds solved before it comes back marked
    interrupted (issue 23: the work done is kept), and no prefetch thread is left running."""
    import spindlesim.analysis.points as points

    monkeypatch.setattr(campbell._Guess, "MIN_STATE_S", 0.0)
    rotor = speed_tabled(build_rotor(default_deck("spindle_linear").deck))  # a state solved at every speed
    monkeypatch.setattr(campbell, "usable_cores", lambda: 2)
    real = points.operating_state

    def failing(rotor_, speed, shaft, **kw):
        if speed > 5000:
            raise KeyboardInterrupt  # Ctrl-C during the static states
        return real(rotor_, speed, shaft, **kw)

    monkeypatch.setattr(points, "operating_state", failing)
    res = campbell.solve_campbell(rotor, np.linspace(0, 12000, 9), n_modes=6)
    assert res.interrupted and "interrupted by the user at 6000 rpm" in res.incomplete_reason
    np.testing.assert_allclose(res.speed_rpm, [0.0, 1500.0, 3000.0, 4500.0])
    assert np.all(np.isfinite(res.frequency_hz))
    assert not [t for t in threading.enumerate() if t.name == "campbell-modal-prefetch"]
