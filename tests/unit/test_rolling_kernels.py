"""Compiled kernels (numba) against the numpy models, and the RK4 integrator's order and conservation.

The numpy right-hand sides are the reference: they are the ones checked against
the physics in test_rolling_rigid_race.py and test_rolling_flexible_race.py.
"""

import dataclasses

import numpy as np
import pytest

from spindlesim.analysis.fixed_step import python_rk4, stability_step_s
from spindlesim.bearings.rolling import flexible_race_kernel, rigid_race_kernel
from spindlesim.bearings.rolling.flexible_race import HousingSupport
from spindlesim.bearings.rolling.hertz import EXPONENT_BALL
from spindlesim.bearings.rolling.kinematics import CageKinematics
from spindlesim.bearings.rolling.rigid_race import RigidRaceBearing, RigidRaceRotor, Waviness

from .test_rolling_flexible_race import model as flexible_model

KIN = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3)


def rigid(rpm=5000.0, damping=200.0, clearance=0.0, waviness=(), ramp=0.0, exponent=10 / 9, K=8.98e8,
          rollers=8, phase=0.0):
    brg = RigidRaceBearing("b", 0, rollers, K, exponent, KIN, rpm * np.pi / 30, clearance, tuple(waviness), phase)
    return RigidRaceRotor(brg, 0.6, damping, (0.0, -6.0), load_ramp_s=ramp)


def surface_flexible(**kw):
    m = flexible_model(**kw)
    return dataclasses.replace(m, housing=dataclasses.replace(m.housing, rocking_arc_m=2 * np.pi * 16e-3 / 12))


@pytest.mark.parametrize("rotor", [
    rigid(),
    rigid(clearance=1e-7, ramp=0.01, waviness=[Waviness("inner", 3, 1e-7, 0.2), Waviness("outer", 5, 5e-8),
                                               Waviness("roller", 2, 3e-8, 1.0)]),
])
def test_rigid_kernel_equals_numpy_rhs(rotor):
    params = rigid_race_kernel.pack(rotor)
    rng = np.random.default_rng(0)
    out = np.empty(4)
    for _ in range(200):
        y = rng.normal(size=4) * np.array([1e-7, 1e-7, 1e-3, 1e-3])
        t = rng.uniform(0.0, 0.1)
        rigid_race_kernel.rhs(t, y, *params, out)
        ref = rotor.rhs(t, y)
        assert np.max(np.abs(out - ref)) <= 1e-12 * np.max(np.abs(ref))


@pytest.mark.parametrize("m", [
    surface_flexible(rollers=12, rpm=5000.0, damped=True, mu=0.05),
    surface_flexible(rollers=5, rpm=3000.0, damped=True, mu=0.1),
    dataclasses.replace(flexible_model(rollers=8, rpm=5000.0, damped=True, mu=0.1),
                        housing=HousingSupport(flexible_model(damped=True, mu=0.1).housing.contact, 1e-8, 1e7, False),
                        load_ramp_s=0.01),
])
def test_flexible_kernel_equals_numpy_force(m):
    params = flexible_race_kernel.pack(m)
    y0 = m.initial_state()
    n = m.n_pos
    rng = np.random.default_rng(1)
    F, q_out = np.empty(n), np.empty(m.rollers)
    for _ in range(50):
        y = y0 + rng.normal(size=y0.size) * m.state_scale() * 0.3
        t = rng.uniform(0.0, 0.05)
        flexible_race_kernel.generalized_force(t, y[:n], y[n:], *params[:6], F, q_out)
        ref = m.generalized_force(t, y[:n], y[n:])
        # round-off: the race forces are differences of ~100 N beam and housing forces
        assert np.max(np.abs(F - ref)) <= 1e-9 * np.max(np.abs(ref))
        q_ref = m.contact_state(t, y[:n], y[n:])["Q_out"]
        assert np.max(np.abs(q_out - q_ref)) <= 1e-8 * np.max(q_ref)  # penetration is r + R - R_o - u: cancels


@pytest.mark.parametrize("system, h, steps", [(rigid(), 1e-6, 400), (surface_flexible(rollers=5, rpm=5000.0,
                                                                                      damped=True), 1e-6, 60)])
def test_compiled_rk4_equals_python_rk4(system, h, steps):
    y0 = system.initial_state()
    y0[y0.size // 2] += 1e-4  # kick
    a, b = y0.copy(), y0.copy()
    sa, sb = np.empty((steps // 10, y0.size)), np.empty((steps // 10, y0.size))
    assert system.compiled_stepper()(a, 0.0, h, steps, 10, sa) == (steps // 10, 0)
    assert python_rk4(system.rhs)(b, 0.0, h, steps, 10, sb) == (steps // 10, 0)
    # same arithmetic up to the force round-off (1e-9 of the largest force, test above), which the stiff
    # 200 kHz race modes carry into the race velocities: 4e-6 of their size after 60 steps (measured)
    scale = np.max(np.abs(sb), axis=0) + 1e-30
    assert np.max(np.abs(sa - sb) / scale) < 1e-4


def _kicked_ball_rotor():
    # ball exponent, 8 balls placed at 22.5 + 45 k deg: no ball sits on the edge of the load zone (a contact
    # switching on or off makes the force non-smooth and RK4 would lose its order there)
    rot = rigid(rpm=0.0, damping=0.0, exponent=EXPONENT_BALL, K=7.055e9, phase=np.pi / 8)
    y0 = rot.initial_state()
    y0[2:4] = [2e-5, -1e-5]
    return rot, y0


def test_rk4_converges_at_fourth_order():
    rot, y0 = _kicked_ball_rotor()
    stepper = rot.compiled_stepper()
    T, ends = 4e-3, []
    for h in (8e-6, 4e-6, 2e-6, 1e-6, 1.25e-7):
        y, out = y0.copy(), np.empty((1, 4))
        stepper(y, 0.0, h, round(T / h), round(T / h), out)
        ends.append(y.copy())
    err = [np.max(np.abs(e - ends[-1])) for e in ends[:-1]]
    ratios = np.array(err[:-1]) / np.array(err[1:])
    # classical RK4: error ~ h^4, ratio 16 per halving
    assert ratios == pytest.approx(16.0, rel=0.15), ratios


def test_rk4_conserves_energy_and_drift_shrinks_with_the_step():
    rot, y0 = _kicked_ball_rotor()
    stepper = rot.compiled_stepper()
    ref = 0.5 * rot.mass_kg * (2e-5**2 + 1e-5**2)
    e0 = rot.energy_J(0.0, y0)
    drift = []
    for h in (4e-6, 1e-6):
        y = y0.copy()
        n = round(0.02 / h)
        out = np.empty((100, 4))
        stepper(y, 0.0, h, n, n // 100, out)
        t = np.arange(1, 101) * (n // 100) * h
        drift.append(max(abs(rot.energy_J(ti, yi) - e0) for ti, yi in zip(t, out)) / ref)
    assert drift[1] < drift[0] / 50  # fourth order: 256 in theory
    assert drift[1] < 1e-6


def test_flexible_energy_conserved_with_compiled_rk4():
    # measured drift over 2 ms / kick energy at h0 (stability step, 1.41 us), h0/2, h0/4, h0/8:
    # 9.7e-3, 2.3e-3, 1.6e-4, 1.0e-5. At h0 RK4 damps the 200 kHz segment modes (|R| = 0.75 per step at
    # h |lambda| = 2); the drift then falls at fourth order (ratio 16 per halving).
    m = surface_flexible(rollers=5)
    y0 = m.initial_state()
    n = m.n_pos
    y0[n:n + 2] = [1e-4, -2e-4]
    e0 = m.energy_J(0.0, y0)
    ref = 0.5 * 0.6 * (1e-4**2 + 2e-4**2)
    h = m.default_step_s(y0)
    assert 5e-7 < h <= 2e-6
    stepper = m.compiled_stepper()
    drift = []
    for hh in (h / 4, h / 8):
        y = y0.copy()
        steps = round(2e-3 / hh)
        out = np.empty((20, y0.size))
        stepper(y, 0.0, hh, steps, steps // 20, out)
        t = np.arange(1, 21) * (steps // 20) * hh
        drift.append(max(abs(m.energy_J(ti, yi) - e0) for ti, yi in zip(t, out)) / ref)
    assert drift[0] / drift[1] > 10
    assert drift[1] < 3e-5


def test_stability_step_of_an_oscillator():
    w = 2 * np.pi * 1000.0
    h = stability_step_s(lambda t, y: np.array([y[1], -w**2 * y[0]]), np.zeros(2), np.ones(2))
    assert h == pytest.approx(2.0 / w, rel=1e-6)
