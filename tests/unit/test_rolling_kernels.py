"""The engine's explicit RK4 (compiled) against its numpy counterparts: same equations, order 4,
conservation, stability step."""

import dataclasses

import numpy as np
import pytest

from spindlesim.analysis.transient import ivp
from spindlesim.analysis.transient.engine import TransientSettings, integrate, prepare
from spindlesim.analysis.transient.fixed_step import stability_step_s
from spindlesim.bearings.roller.kinematics import CageKinematics
from spindlesim.bearings.roller.bearing import RigidRaceBearing, Waviness
from spindlesim.contact.hertz import EXPONENT_POINT
from spindlesim.model.rig import journal_rotor

KIN = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3)


def rigid_rotor(rpm=5000.0, damping=200.0, clearance=0.0, waviness=(), exponent=10 / 9, K=8.98e8, rollers=8,
                phase=0.0):
    b = RigidRaceBearing("b", 0, rollers, K, exponent, KIN, clearance, tuple(waviness), phase)
    return journal_rotor((b,), 0.6, damping, (0.0, -6.0), rpm)


def test_compiled_right_hand_side_equals_numpy():
    from spindlesim.analysis.transient import explicit
    from spindlesim.analysis.transient.explicit_kernel import rhs

    r = rigid_rotor(clearance=1e-7, waviness=[Waviness("inner", 3, 1e-7, 0.2), Waviness("outer", 5, 5e-8),
                                               Waviness("roller", 2, 3e-8, 1.0)])
    p = prepare(r, TransientSettings(1e-3, method="rk4"))
    FL, IN, hs = explicit.pack(p.system)
    sysm = p.system
    rng = np.random.default_rng(0)
    for _ in range(100):
        y = rng.normal(size=4) * np.array([1e-7, 1e-7, 1e-3, 1e-3])
        t = rng.uniform(0.0, 0.1)
        out = rhs(t, y, FL, IN, hs)
        f, _, _, _ = sysm.bearing_forces(y[:2], y[2:], t, with_tangent=False)
        F = sysm.external(t) + f - sysm.damping(sysm.profile.speed(t)) @ y[2:]
        ref = np.concatenate([y[2:], F / 0.6])
        assert np.max(np.abs(out - ref)) <= 1e-12 * np.max(np.abs(ref))


def _kicked_ball_rotor():
    # ball exponent, 8 balls placed at 22.5 + 45 k deg: no ball sits on the edge of the load zone (a contact
    # switching on or off makes the force non-smooth and RK4 would lose its order there)
    return rigid_rotor(rpm=0.0, damping=0.0, exponent=EXPONENT_POINT, K=7.055e9, phase=np.pi / 8)


def _run(r, h, T, rate=None):
    s = TransientSettings(T, method="rk4", step_s=h, sample_rate_hz=rate or 1.0 / h,
                          initial_velocity=((0, 2e-5), (1, -1e-5)), chunks=1)
    p = prepare(r, s)
    return p, integrate(p, s)


def test_rk4_converges_at_fourth_order():
    r = _kicked_ball_rotor()
    T, ends = 4e-3, []
    for h in (8e-6, 4e-6, 2e-6, 1e-6, 1.25e-7):
        _, traj = _run(r, h, T, 1.0 / 8e-6)
        ends.append(np.concatenate([traj.x[-1], traj.v[-1]]))
    err = [np.max(np.abs(e - ends[-1])) for e in ends[:-1]]
    ratios = np.array(err[:-1]) / np.array(err[1:])
    assert ratios == pytest.approx(16.0, rel=0.15), ratios  # classical RK4: error ~ h^4


def test_rk4_conserves_energy_and_drift_shrinks_with_the_step():
    r = _kicked_ball_rotor()
    b = r.bearings[0]
    ref = 0.5 * 0.6 * (2e-5 ** 2 + 1e-5 ** 2)
    drift = []
    for h in (4e-6, 1e-6):
        _, traj = _run(r, h, 0.02, 5000.0)
        e = 0.5 * 0.6 * np.sum(traj.v ** 2, axis=1) + np.array([b.potential_energy_J(x, 0.0) for x in traj.x]) \
            + 6.0 * traj.x[:, 1]
        drift.append(np.max(np.abs(e - e[0])) / ref)
    assert drift[1] < drift[0] / 50  # fourth order: 256 in theory
    assert drift[1] < 1e-6


def test_rk4_agrees_with_an_adaptive_method():
    # the compiled RK4 and scipy's DOP853 on the numpy forces: the same trajectory
    r = rigid_rotor(clearance=0.5e-6)
    s = TransientSettings(0.01, method="rk4", sample_rate_hz=20000, initial_velocity=((0, 1e-4),))
    p = prepare(r, s)
    a = integrate(p, s)
    b = ivp.integrate(p.system, p.x0, p.v0, p.plan, p.targets, method="DOP853", rtol=1e-10, chunks=1)
    # contacts open and close in the clearance, which limits both methods' order: measured 4.7e-5
    scale = np.max(np.abs(a.x))
    assert np.max(np.abs(a.x - b.x)) < 1e-4 * scale


def test_stability_step_of_an_oscillator():
    w = 2 * np.pi * 1000.0
    h = stability_step_s(np.eye(1), np.array([[w ** 2]]), np.zeros((1, 1)))
    assert h == pytest.approx(2.0 / w, rel=1e-9)


def test_rk4_run_that_diverges_stops_with_its_finite_part():
    # a step 5 times the stability limit (about 0.1 ms here): the state overflows within some hundred steps
    from spindlesim.analysis.transient.engine import simulate

    r = rigid_rotor()
    res = simulate(r, TransientSettings(0.5, method="rk4", step_s=5e-4, sample_rate_hz=1000,
                                        initial_velocity=((0, 1e-4),)))
    assert not res.complete and "non-finite" in res.reason
    assert 0 < res.time_s.size < 400 and np.all(np.isfinite(res.displacement_m))
