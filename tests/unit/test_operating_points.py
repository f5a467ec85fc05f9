"""The spindle at its operating points, solved once (issue 24): every analysis of a run reads one
:class:`~spindlesim.analysis.points.OperatingPoints`, so the shaft is assembled once and each static state
(speed, bearing set) is solved once.  The work is counted at its source: the shaft assembly of
``fe.assembly`` and the static solver of ``analysis.operating``, whoever calls them."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import spindlesim.analysis.operating as operating
import spindlesim.analysis.points as points_module
from spindlesim.analysis.points import OperatingPoints
from spindlesim.deck import parse_deck, default_deck, load_deck
from spindlesim.model.build import build_rotor
from spindlesim.runs import run_analysis
from tests.rotor_helpers import speed_tabled

DECKS = Path(__file__).parents[2] / "decks"


@pytest.fixture
def counted(monkeypatch):
    """Counts of shaft assemblies and static-state solves, wherever they are asked for (in this process: a sweep's
    states are not shared with a child here, whose solves these counts would not see; tests/unit/
    test_shared_sweep.py counts a shared one)."""
    counts = {"assemblies": 0, "solves": [], "speeds": []}
    monkeypatch.setattr(points_module, "SHARE_MIN", 10**9)
    real_assemble, real_state = operating.assemble_shaft, points_module.operating_state

    def assemble(rotor):
        counts["assemblies"] += 1
        return real_assemble(rotor)

    def state(rotor, speed_rpm=None, *args, **kwargs):
        counts["speeds"].append(float(speed_rpm if speed_rpm is not None else rotor.speed_rpm))
        return real_state(rotor, speed_rpm, *args, **kwargs)

    def state_elsewhere(*args, **kwargs):  # a static state solved outside the operating points
        counts["solves"].append("outside")
        return real_state(*args, **kwargs)

    for module in (operating, points_module):
        monkeypatch.setattr(module, "assemble_shaft", assemble)
    monkeypatch.setattr(points_module, "operating_state", state)
    monkeypatch.setattr(operating, "operating_state", state_elsewhere)
    return counts


def test_campbell_with_the_frozen_comparison_assembles_once_and_solves_each_speed_once(counted, tmp_path):
    """Milling spindle: 50 speeds 0-24,000 rpm and the comparison with the bearings frozen at 0 rpm (a speed
    of the diagram): one assembly, 50 static states, nothing solved twice.  (Its thermal section is left out:
    with it the figure shades the speeds above the thermal speed limit, whose equilibria are other work.)"""
    text = (DECKS / "milling_spindle.yaml").read_text()
    loaded = parse_deck(text[:text.index("\nspindle_thermal:")] + "\n", "milling without its thermal section")
    assert loaded.deck.spindle_thermal is None
    run_analysis("campbell", loaded, tmp_path, {})
    assert counted["assemblies"] == 1
    assert len(counted["speeds"]) == 50 and len(set(counted["speeds"])) == 50
    assert not counted["solves"]


def test_frf_with_its_tool_point_solves_its_state_once(counted, tmp_path):
    loaded = load_deck(DECKS / "milling_spindle.yaml")
    run_analysis("frf", loaded, tmp_path, {"plots": False})
    assert counted["assemblies"] == 1
    assert counted["speeds"] == [18000.0]
    assert not counted["solves"]


def test_the_analyses_of_one_run_share_the_assembly_and_the_deck_speed_state(counted, tmp_path):
    """The analyses of one run context (what `spindlesim run` makes) share the assembly and the states; without
    one, each call solves what it needs (nothing is cached by object identity)."""
    from spindlesim.runs.common import RunContext

    loaded = load_deck(DECKS / "milling_spindle.yaml")
    shared = RunContext(loaded)
    for name in ("static", "modal", "frf"):
        run_analysis(name, shared, tmp_path, {"plots": False})
    assert counted["assemblies"] == 1
    assert counted["speeds"] == [18000.0]


def test_a_state_is_kept_and_a_sweep_starts_each_speed_from_its_neighbour():
    pts = OperatingPoints(speed_tabled(build_rotor(default_deck("spindle_linear").deck)))
    a = pts.state(3000.0)
    assert pts.state(3000.0) is a and pts.solves == 1
    sweep = pts.along(np.array([0.0, 1500.0, 3000.0]))
    assert pts.solves == 3 and sweep.states[2] is a  # 3000 rpm was known
    assert not sweep.stopped and sweep.first == 0


def test_a_rotor_on_speed_independent_bearings_is_solved_once(counted):
    """The seed spindle on its linear bearings (one row of coefficients each, no internal damping): its static state
    is the same at every speed, so a 50-speed sweep solves it once, and each speed's state equals the one solved at
    that speed to the bit (the same equations; speed enters only as the state's speed).  With a speed table (the
    same numbers at two speeds) the rotor is solved at every speed."""
    rotor = build_rotor(load_deck(DECKS / "seed003_spindle_linear.yaml").deck)
    assert all(b.speed_independent for b in rotor.bearings)
    speeds = np.linspace(0.0, 12000.0, 50)
    sweep = OperatingPoints(rotor).along(speeds)
    assert counted["speeds"] == [0.0] and len(sweep) == 50
    for k in (1, 37):
        own = OperatingPoints(rotor).state(speeds[k])
        got = sweep.states[k]
        assert got.speed_rad_s == own.speed_rad_s == speeds[k] * np.pi / 30
        assert np.array_equal(got.q, own.q)
        for (ka, ca), (kb, cb) in zip(got.coefficients, own.coefficients):
            assert np.array_equal(ka, kb) and np.array_equal(ca, cb)
    counted["speeds"].clear()
    tabled = speed_tabled(rotor)
    assert not any(b.speed_independent for b in tabled.bearings)
    OperatingPoints(tabled).along(speeds[:5])
    assert counted["speeds"] == list(speeds[:5])


def test_the_rotor_statics_is_the_damped_newton_of_the_statics_and_names_what_failed(monkeypatch):
    """The rotor's equilibrium goes through ``bearings.statics.damped_newton``; when it fails the message
    says at which speed, with which bearings and after how many iterations."""
    rotor = build_rotor(default_deck("milling_spindle").deck)
    calls = []
    real = operating.damped_newton

    def counted(*args, **kwargs):
        calls.append(kwargs.get("lam0"))
        return real(*args, **kwargs)

    monkeypatch.setattr(operating, "damped_newton", counted)
    st = operating.operating_state(rotor, 12000.0)
    assert calls and st.newton_iterations > 0
    with pytest.raises(operating.EquilibriumError, match=r"at 12000 rpm .*damped Newton.*\(front, rear.*1 of 1 "
                                                         r"iterations, residual"):
        operating.operating_state(rotor, 12000.0, max_iter=1)


def test_a_sweep_starts_each_ball_set_from_the_previous_state_passed_in(monkeypatch):
    """The bearings stay as built: the previous speed's displacement of each ball set is passed to
    ``static_displacement`` (``start``), and ``linearized`` starts from the state's own displacement; the
    coefficients are those of a state solved cold."""
    from spindlesim.bearings.ball.bearing import BallBearing

    rotor = build_rotor(default_deck("milling_spindle").deck)
    seen = []
    for verb in ("static_displacement", "linearized"):
        real = getattr(BallBearing, verb)

        def spy(self, speed, static_load=None, start=None, _real=real, _verb=verb):
            seen.append((_verb, self.name, None if start is None else np.array(start)))
            return _real(self, speed, static_load, start=start)

        monkeypatch.setattr(BallBearing, verb, spy)
    pts = OperatingPoints(rotor)
    first, second = pts.along(np.array([6000.0, 7000.0])).states
    seen = seen[-4:]  # the second speed: a static displacement and the coefficients of each set
    for k, b in enumerate(rotor.bearings[:2]):
        d_first, d_second = (st.q[st.bearing_index[k]] for st in (first, second))
        assert [s[0] for s in seen if s[1] == b.name] == ["static_displacement", "linearized"]
        start_d, start_k = (s[2] for s in seen if s[1] == b.name)
        np.testing.assert_array_equal(start_d, d_first)
        np.testing.assert_allclose(start_k, d_second, rtol=1e-6, atol=1e-12)
    cold = operating.operating_state(rotor, 7000.0)
    for (k1, _), (k2, _) in zip(second.coefficients, cold.coefficients):
        np.testing.assert_allclose(k1, k2, rtol=1e-6, atol=1e-6 * np.abs(k2).max())
