"""The floating outer rings of a spring-preloaded ball set (bearings/ball/floating.py): the shift carries the
spring force to 1e-11 of it, from a call's first solve (one ball's share at the speed) in a few evaluations of
the floating rows and from the call's last solution, moved to first order with q, in one or two."""

import numpy as np
import pytest

from spindlesim.bearings.ball import floating
from spindlesim.bearings.ball.equilibrium import Work

from .test_ball_section import RPM, bearing


@pytest.fixture
def counted(monkeypatch):
    """The spring-preloaded DB pair (row 1 floats) and a counter of its floating-row evaluations."""
    b = bearing(preload={"kind": "spring", "axial_N": 300.0, "floating": "-z"})
    calls = []
    real = type(b)._rows

    def rows(self, q, om, phi, w, idx, work=None):
        calls.append(tuple(idx))
        return real(self, q, om, phi, w, idx, work)

    monkeypatch.setattr(type(b), "_rows", rows)
    return b, calls


@pytest.mark.parametrize("rpm", [0.0, 6000.0, 12000.0, 24000.0])
def test_the_shift_carries_the_spring_force_in_few_evaluations(counted, rpm):
    b, calls = counted
    fl = np.flatnonzero(b._floating)
    q = b.solve(np.array([300.0, -200.0, 0.0, 0.0, 0.0]), rpm * RPM).displacement
    work = Work(b)
    calls.clear()
    w, ev = floating.shift(b, q, rpm * RPM, 0.0, fl, work)
    assert len(calls) <= 4  # 5-7 from the spring force shared at the mounted angle
    thrust = -b._s_float * ev.f_rows[:, 2].sum()
    assert thrust == pytest.approx(300.0, rel=3e-11)
    # the call's next solve, the inner ring moved by 1 nm and 0.1 urad (a late Newton step of the set): from the
    # last one moved to first order (without that term 3 evaluations at 0-12,000 rpm)
    calls.clear()
    q2 = q + np.array([1e-9, -1e-9, 1e-9, 1e-7, -1e-7])
    w2, ev2 = floating.shift(b, q2, rpm * RPM, 0.0, fl, work)
    assert len(calls) <= 2
    assert -b._s_float * ev2.f_rows[:, 2].sum() == pytest.approx(300.0, rel=3e-11)
    # the same shift as from a fresh start
    w3, _ = floating.shift(b, q2, rpm * RPM, 0.0, fl, Work(b))
    assert w2 == pytest.approx(w3, rel=1e-9, abs=1e-15)
