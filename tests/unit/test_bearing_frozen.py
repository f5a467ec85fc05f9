"""Ball and DTRB bearings stay as built: a solve, an evaluation or the contract's calls change nothing on the
bearing object (warm starts are passed in, issue 24 item 2), so a result depends on its inputs alone."""

import pickle

import numpy as np
import pytest

from spindlesim.bearings.ball.equilibrium import Work

from .test_ball_section import RPM, bearing as ball
from .test_dtrb_geometry import bearing as dtrb


def snapshot(b) -> bytes:
    """Everything the bearing object holds, as bytes (arrays by value, NaN included)."""
    return pickle.dumps(vars(b), protocol=pickle.HIGHEST_PROTOCOL)


LOAD = np.array([1500.0, -500.0, 400.0, 10.0, 0.0])
Q = np.array([3e-6, 1e-6, 2e-6, 1e-5, 0.0])


def ball_calls(b, w):
    st = b.solve(LOAD, w)
    b.at(st.displacement, w)
    b.force_and_tangent(Q, np.zeros(5), 0.0, w, 0.3)
    b.linearized(w, LOAD)
    b.static_displacement(w, LOAD)
    b.linearized(w, LOAD, start=st.displacement)
    b.static_displacement(w, 1.1 * LOAD, start=st.displacement)


@pytest.mark.parametrize("kw", [dict(), dict(model="full", preload={"kind": "spring", "axial_N": 800.0})],
                         ids=["position preload", "spring preload"])
def test_a_ball_bearing_is_unchanged_by_its_solves(kw):
    b = ball(**kw)
    before = snapshot(b)
    ball_calls(b, 12000.0 * RPM)
    assert snapshot(b) == before


def test_the_planted_change_is_seen():
    """The snapshot sees an attribute a call would leave behind (so the tests above can fail)."""
    b = ball()
    before = snapshot(b)
    b._X = np.full((2, 3, 2), np.nan)  # what a warm start kept on the bearing looked like
    assert snapshot(b) != before


def test_a_ball_result_does_not_depend_on_the_calls_before_it():
    b = ball(model="full")
    first = b.force_and_tangent(Q, np.zeros(5), 0.0, 16000.0 * RPM, 0.2)
    b.solve(5.0 * LOAD, 3000.0 * RPM)  # a far-away history
    b.force_and_tangent(5.0 * Q, np.zeros(5), 0.0, 3000.0 * RPM, 1.0)
    again = b.force_and_tangent(Q, np.zeros(5), 0.0, 16000.0 * RPM, 0.2)
    assert all(np.array_equal(x, y) for x, y in zip(first, again))


def test_a_ball_warm_start_is_passed_in_and_finds_the_same_state():
    b = ball()
    w = 9000.0 * RPM
    cold = b.solve(LOAD, w)
    work = Work(b)
    b.solve(1.1 * LOAD, w, work=work)  # the neighbour whose ball centres start the next solve
    warm = b.solve(LOAD, w, work=work)
    assert np.isfinite(work.centres).all()  # the starts live in the work, not on the bearing
    assert np.allclose(warm.displacement, cold.displacement, rtol=1e-9, atol=1e-15)
    assert np.allclose(warm.stiffness, cold.stiffness, rtol=1e-7, atol=1e-9 * np.abs(cold.stiffness).max())


@pytest.mark.parametrize("kw", [dict(), dict(preload={"kind": "spring", "axial_N": 300.0, "floating": "-z"})],
                         ids=["position preload", "spring preload"])
def test_the_contracts_start_is_an_argument_that_saves_set_iterations_not_a_result(kw, monkeypatch):
    """``static_displacement`` from a neighbouring operating point's displacement (a Campbell diagram's previous
    speed: ``start``) and ``linearized`` from the displacement that carries the load find the same displacement
    and coefficients as from the unloaded ring, in fewer set iterations (the first cage position none); a start
    from which the set Newton fails is dropped."""
    from spindlesim.bearings.ball import equilibrium

    b = ball(**kw)
    w, near = 12000.0 * RPM, b.solve(1.05 * LOAD, 11500.0 * RPM).displacement
    iterations = []
    real = equilibrium.solve

    def counted(*args, **kwargs):
        out = real(*args, **kwargs)
        iterations.append(out[2])
        return out

    monkeypatch.setattr(equilibrium, "solve", counted)
    cold = b.static_displacement(w, LOAD), b.linearized(w, LOAD)[0]
    n_cold, iterations[:] = sum(iterations), []
    d = b.static_displacement(w, LOAD, start=near)  # as the rotor's operating points: from the neighbour,
    warm = d, b.linearized(w, LOAD, start=d)[0]  # the coefficients from the displacement that carries the load
    assert iterations[1] == 0 and sum(iterations) < n_cold - 3
    assert np.allclose(warm[0], cold[0], rtol=1e-9, atol=1e-15)
    assert np.allclose(warm[1], cold[1], rtol=1e-7, atol=1e-9 * np.abs(cold[1]).max())
    far = np.array([1.0, -1.0, 1.0, 0.1, 0.1])  # the rings far past each other: no ball fits
    assert np.allclose(b.static_displacement(w, LOAD, start=far), cold[0], rtol=1e-9, atol=1e-15)


def test_a_dtrb_is_unchanged_by_its_solves_and_its_operating_point_is_a_new_bearing():
    b = dtrb(preload_um=10.0)
    before = snapshot(b)
    w = 3000.0 * RPM
    st = b.solve(np.array([3000.0, -1000.0, 2000.0, 0.0, 0.0]), w)
    b.at(st.displacement, w)
    b.force_and_tangent(np.array([2e-6, -1e-6]), np.zeros(2), 0.0, w, 0.4)
    b.linearized(w, np.array([3000.0, -1000.0]))
    held = b.at_operating_point(w, np.array([3000.0, -1000.0]))
    assert snapshot(b) == before
    assert held is not b and np.any(held._held != 0.0) and not np.any(b._held)
    first = held.force_and_tangent(np.array([2e-6, -1e-6]), np.zeros(2), 0.0, w, 0.4)
    held.force_and_tangent(np.array([9e-6, 5e-6]), np.zeros(2), 0.0, w, 1.4)
    again = held.force_and_tangent(np.array([2e-6, -1e-6]), np.zeros(2), 0.0, w, 0.4)
    assert all(np.array_equal(x, y) for x, y in zip(first, again))


def test_a_dtrb_time_integration_gets_its_own_bearing_with_a_roller_start():
    """The transient's copy (at_operating_point(..., transient=True)) starts each call's roller Newton from
    the previous call's solution (halving a DTRB rotor transient's cost); it is a new object, the deck's
    bearing stays as built, and its forces and tangents along a path of small steps equal cold evaluations
    to the roller solver's tolerance."""
    from spindlesim.bearings.dtrb.bearing import TimeSteppedDtrb

    b = dtrb(preload_um=10.0)
    before = snapshot(b)
    w = 3000.0 * RPM
    stepped = b.at_operating_point(w, np.array([3000.0, -1000.0]), transient=True)
    cold = b.at_operating_point(w, np.array([3000.0, -1000.0]))
    assert isinstance(stepped, TimeSteppedDtrb) and stepped is not b and not isinstance(cold, TimeSteppedDtrb)
    for k in range(6):
        q, t = np.array([2e-6 + 1e-8 * k, -1e-6 + 2e-8 * k]), 1e-4 * k
        F, K, _ = stepped.force_and_tangent(q, np.zeros(2), t, w)
        F0, K0, _ = cold.force_and_tangent(q, np.zeros(2), t, w)
        np.testing.assert_allclose(F, F0, rtol=0, atol=2e-5 * np.abs(F0).max())  # the roller solver stops near 1e-5
        np.testing.assert_allclose(K, K0, rtol=0, atol=2e-4 * np.abs(K0).max())
    assert stepped._start is not None and snapshot(b) == before
