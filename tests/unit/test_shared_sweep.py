"""A sweep's static states shared with a forked child (``OperatingPoints.along``): the same states as one process
solves them, to the solvers' tolerances (the child's first speed starts from the states known at the fork, not
from its neighbour), each speed solved once in all, and the failure policy of one process: where the child stops
short, this process goes on from there; a bearing that fails fails at the same speed with the same message."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

import spindlesim.analysis.points as points_module
from spindlesim.analysis.aside import available
from spindlesim.analysis.points import OperatingPoints
from spindlesim.deck import load_deck, parse_deck
from spindlesim.model.build import build_rotor
from tests.rotor_helpers import speed_tabled

DECKS = Path(__file__).parents[2] / "decks"
SPEEDS = np.linspace(3000.0, 21000.0, 40)

needs_child = pytest.mark.skipif(not available(), reason="no process can be forked here (one core or no fork)")


def _milling():
    """The milling spindle on its two ball bearing sets (solved by iteration), without its thermal section."""
    text = (DECKS / "milling_spindle.yaml").read_text()
    return parse_deck(text[:text.index("\nspindle_thermal:")] + "\n", "milling without its thermal section").deck


@pytest.fixture
def calls(monkeypatch):
    """The speeds whose static state this process solves."""
    seen = []
    real = points_module.operating_state

    def counted(rotor, speed_rpm=None, *args, **kwargs):
        seen.append(float(speed_rpm))
        return real(rotor, speed_rpm, *args, **kwargs)

    monkeypatch.setattr(points_module, "operating_state", counted)
    return seen


def _serial(deck, speeds, monkeypatch):
    with monkeypatch.context() as m:
        m.setattr(points_module, "SHARE_MIN", 10**9)
        return OperatingPoints(build_rotor(deck)).along(speeds)


@needs_child
def test_a_shared_sweep_gives_the_states_of_one_process(calls, monkeypatch):
    """40 speeds of the milling spindle: this process solves the first 20 (the child the rest); every state
    equals the serial one: bearing stiffness within 1e-9 of its largest term and displacements within 1e-9 of
    the largest (measured 5e-13 and 5e-12: the ball sets' Newton tolerance), each speed counted once."""
    deck = _milling()
    serial = _serial(deck, SPEEDS, monkeypatch)
    calls.clear()
    pts = OperatingPoints(build_rotor(deck))
    shared = pts.along(SPEEDS)
    assert calls == list(SPEEDS[:20])  # the other half came from the child
    assert pts.solves == 40 and not shared.stopped and np.array_equal(shared.speeds_rpm, SPEEDS)
    for a, b in zip(serial.states, shared.states):
        assert b.shaft is pts.shaft
        assert a.speed_rad_s == b.speed_rad_s
        assert np.max(np.abs(a.q - b.q)) <= 1e-9 * np.max(np.abs(a.q))
        for (Ka, Ca), (Kb, Cb) in zip(a.coefficients, b.coefficients):
            assert np.max(np.abs(Ka - Kb)) <= 1e-9 * np.max(np.abs(Ka))
            assert np.max(np.abs(Ca - Cb)) <= 1e-9 * np.max(np.abs(Ca)) + 1e-300
    assert pts.state(SPEEDS[30]) is shared.states[30]  # kept here as if solved here
    # the first half is this process's own work, bit for bit
    for a, b in zip(serial.states[:20], shared.states[:20]):
        assert np.array_equal(a.q, b.q)


@needs_child
def test_where_the_child_stops_this_process_goes_on(calls, monkeypatch):
    """A child that cannot solve from 15,000 rpm up (a failure there only, planted): this process solves those
    speeds itself from the child's last state, and the sweep is whole."""
    parent = os.getpid()
    real = points_module.operating_state

    def fails_in_the_child(rotor, speed_rpm=None, *args, **kwargs):
        if os.getpid() != parent and speed_rpm >= 15000.0:
            raise ArithmeticError("planted")
        return real(rotor, speed_rpm, *args, **kwargs)

    deck = _milling()
    calls.clear()
    monkeypatch.setattr(points_module, "operating_state", fails_in_the_child)
    pts = OperatingPoints(build_rotor(deck))
    sweep = pts.along(SPEEDS)
    assert not sweep.stopped and len(sweep) == 40 and pts.solves == 40
    assert calls == list(SPEEDS[:20]) + list(SPEEDS[SPEEDS >= 15000.0])  # the child gave those below
    monkeypatch.undo()
    serial = _serial(deck, SPEEDS, monkeypatch)
    for a, b in zip(serial.states, sweep.states):
        assert np.max(np.abs(a.q - b.q)) <= 1e-9 * np.max(np.abs(a.q))


@needs_child
def test_a_failure_in_the_childs_half_stops_the_sweep_there_as_in_one_process(monkeypatch):
    """A speed that fails wherever it is solved (17,000 rpm and above, planted): the sweep stops there with the
    one-process message, the states below it kept."""
    real = points_module.operating_state

    def fails(rotor, speed_rpm=None, *args, **kwargs):
        if speed_rpm >= 17000.0:
            raise ArithmeticError("planted")
        return real(rotor, speed_rpm, *args, **kwargs)

    monkeypatch.setattr(points_module, "operating_state", fails)
    deck = _milling()
    shared = OperatingPoints(build_rotor(deck)).along(SPEEDS, what="test")
    serial = _serial(deck, SPEEDS, monkeypatch)
    first_bad = float(SPEEDS[SPEEDS >= 17000.0][0])
    assert shared.stopped == serial.stopped and f"stopped at {first_bad:g} rpm" in shared.stopped
    assert np.array_equal(shared.speeds_rpm, serial.speeds_rpm) and not shared.interrupted


@needs_child
def test_a_ctrl_c_while_the_childs_states_are_taken_keeps_what_was_solved():
    """A Ctrl-C in the caller's callback at the first of the child's states: the states up to it are kept, the
    sweep marked interrupted."""
    pts = OperatingPoints(build_rotor(_milling()))
    seen = []

    def on_state(st, rpm):
        seen.append(rpm)
        if rpm == SPEEDS[20]:
            raise KeyboardInterrupt

    sweep = pts.along(SPEEDS, on_state=on_state)
    assert sweep.interrupted and len(sweep) == 21 and "interrupted by the user after" in sweep.stopped


def test_linear_bearings_are_not_shared(calls):
    """Bearings with a linear reaction (nothing solved by iteration): one process solves every speed, the
    fork would cost more than it saves (60 speeds of the seed 003 spindle: 36 ms in all; with a speed table, as
    here, each speed is solved; without one the state is solved once)."""
    pts = OperatingPoints(speed_tabled(build_rotor(load_deck(DECKS / "seed003_spindle_linear.yaml").deck)))
    sweep = pts.along(np.linspace(200.0, 12000.0, 40))
    assert len(sweep) == 40 and len(calls) == 40


@needs_child
def test_a_shared_sweep_of_thermal_states_keeps_them_here(monkeypatch):
    """decks/lathe_headstock.yaml with its spindle thermal model (each state the spindle's thermal equilibrium at
    its speed): the child's thermal states are kept here with the static states they set, and equal the
    one-process ones to the thermal loop's tolerance (0.01 K on every node; measured 2e-5 of the largest bearing
    stiffness on 40 speeds: the loop's own dependence on where it starts, as with the extrapolated starts of one
    process)."""
    from spindlesim.runs.common import RunContext

    loaded = load_deck(DECKS / "lathe_headstock.yaml")
    speeds = np.linspace(200.0, 1800.0, 20)
    with monkeypatch.context() as m:
        m.setattr(points_module, "SHARE_MIN", 10**9)
        serial = RunContext(loaded).points.along(speeds)
    pts = RunContext(loaded).points
    assert pts.thermal is not None
    shared = pts.along(speeds)
    assert len(shared) == 20 and pts.solves == 20 and not shared.stopped
    for s, st in zip(speeds, shared.states):
        assert pts.thermal_state(s).operating is st and pts.state(s) is st and st.shaft is pts.shaft
    for a, b in zip(serial.states, shared.states):
        for (Ka, _), (Kb, _) in zip(a.coefficients, b.coefficients):
            assert np.max(np.abs(Ka - Kb)) <= 1e-4 * np.max(np.abs(Ka))
