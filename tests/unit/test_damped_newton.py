"""The one damped Newton of the bearing statics (bearings/statics.py): a step is taken only when it does not
raise the merit, on a made-up problem where the full Newton step overshoots.

atan(x) = 0 from x0 = 2: Newton's step -atan(x)(1 + x^2) lands at -3.5 and the iterates grow without bound
(for |x0| above about 1.39); the damped Newton refuses those steps, damps, and converges to 0.
"""

import numpy as np
import pytest

from spindlesim.bearings.statics import damped_newton


def atan_problem():
    seen = []  # (x, merit) of every evaluation, trial steps included

    def evaluate(x):
        R = -np.arctan(x)
        seen.append((float(x[0]), float(abs(R[0]))))
        return R, np.array([[1.0 / (1.0 + x[0] ** 2)]]), None

    return evaluate, seen


SETTINGS = dict(converged=lambda r, _: abs(r[0]) <= 1e-12, merit=lambda r: float(np.linalg.norm(r)), cap=1e3,
                damping=np.ones(1), lam0=1e-12, max_iter=200)


def test_the_full_newton_step_overshoots_here():
    x = 2.0
    for _ in range(4):
        x_next = x - np.arctan(x) * (1.0 + x * x)
        assert abs(np.arctan(x_next)) > abs(np.arctan(x))  # each full step raises the residual
        x = x_next
    assert abs(x) > 1e4


def test_only_steps_that_lower_the_residual_are_taken_and_the_root_is_found():
    evaluate, seen = atan_problem()
    out = damped_newton(evaluate, np.array([2.0]), **SETTINGS)
    assert out.converged and abs(out.x[0]) < 1e-12
    merits = [m for _, m in seen]
    refused = [i for i in range(1, len(merits)) if merits[i] > merits[i - 1] and abs(seen[i][0]) > 2.0]
    assert refused, "the first full step (to -3.5) must have been tried and refused"
    assert seen[1][0] == pytest.approx(2.0 - np.arctan(2.0) * 5.0, rel=1e-9)
    # the path taken: from each accepted point the next accepted one has a merit no larger
    taken, path = out.x[0], [2.0]
    current = abs(np.arctan(2.0))
    for x, m in seen[1:]:
        if m <= current * (1.0 + 1e-12):
            path.append(x)
            current = m
    assert path[-1] == taken
    assert all(abs(np.arctan(b)) <= abs(np.arctan(a)) * (1.0 + 1e-12) for a, b in zip(path, path[1:]))


def test_a_singular_tangent_is_damped_not_fatal():
    """Zero stiffness at the start (a contact at first touch): the damping carries the step."""
    def evaluate(x):  # f = x^3 - 1: J = 0 at x = 0
        return np.array([1.0 - x[0] ** 3]), np.array([[3.0 * x[0] ** 2]]), None

    out = damped_newton(evaluate, np.array([0.0]), converged=lambda r, _: abs(r[0]) <= 1e-12,
                        merit=lambda r: float(abs(r[0])), cap=0.5)
    assert out.converged and out.x[0] == pytest.approx(1.0, abs=1e-12)


def test_a_residual_at_its_noise_floor_ends_the_solve():
    """An inner solve leaves noise in the residual: below the caller's floor a refused step ends the solve
    (converged), without the floor the solve runs out of damping and reports no convergence."""
    def noisy():
        rng = np.random.default_rng(1)

        def evaluate(x):
            return np.array([1.0 - x[0] + 1e-9 * rng.standard_normal()]), np.eye(1), None

        return evaluate

    kw = dict(converged=lambda r, _: abs(r[0]) <= 1e-15, merit=lambda r: float(abs(r[0])), cap=10.0)
    assert not damped_newton(noisy(), np.array([0.0]), **kw).converged
    out = damped_newton(noisy(), np.array([0.0]), floor=lambda r, _: abs(r[0]) <= 1e-8, **kw)
    assert out.converged and out.x[0] == pytest.approx(1.0, abs=1e-8)


def test_an_undamped_start_takes_newtons_step_and_halves_a_refused_one_before_damping():
    """The rotor statics' options: lam0 = 0 takes Newton's own step; a step that raises the merit is halved
    (``backtrack``) before the damping grows; an exception of ``refuse`` at a trial point refuses the step."""
    evaluate, seen = atan_problem()
    out = damped_newton(evaluate, np.array([2.0]), converged=lambda r, _: abs(r[0]) <= 1e-12,
                        merit=lambda r: float(np.linalg.norm(r)), cap=np.inf, damping=np.ones(1), lam0=0.0,
                        lam_min=0.0, backtrack=10, max_iter=50)
    assert out.converged and abs(out.x[0]) < 1e-12
    newton = 2.0 - np.arctan(2.0) * 5.0
    assert seen[1][0] == pytest.approx(newton, rel=1e-15)  # undamped
    assert seen[2][0] == pytest.approx(2.0 + 0.5 * (newton - 2.0), rel=1e-15)  # the same step halved

    def refusing(x):  # no position beyond 1.5 from the root
        if abs(x[0]) > 1.5:
            raise ArithmeticError("out of reach")
        return -np.arctan(x), np.array([[1.0 / (1.0 + x[0] ** 2)]]), None

    kw = dict(converged=lambda r, _: abs(r[0]) <= 1e-12, merit=lambda r: float(abs(r[0])), cap=np.inf,
              damping=np.ones(1), lam0=0.0, lam_min=0.0, max_iter=50)
    out = damped_newton(refusing, np.array([1.45]), backtrack=10, refuse=(ArithmeticError,), **kw)
    assert out.converged and abs(out.x[0]) < 1e-12
    with pytest.raises(ArithmeticError):  # not refused: the caller's error
        damped_newton(refusing, np.array([1.45]), backtrack=10, **kw)
