"""Rigid-race 2-DOF bearing model (Sunnersjo 1978; Harsha and Kankar 2004)."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from spindlesim.bearings.base import NonlinearBearing
from spindlesim.bearings.rolling.hertz import palmgren_roller_stiffness, static_load_distribution
from spindlesim.bearings.rolling.kinematics import CageKinematics
from spindlesim.bearings.rolling.rigid_race import RigidRaceBearing, RigidRaceRotor, Waviness
from spindlesim.analysis.transient import TransientSettings, run_transient

KIN = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3)  # seed 000 Table 1
K_ROLLER = palmgren_roller_stiffness(6.35e-3)  # width 6.35 mm, seed 000 Table 1


def bearing(rollers=8, rpm=5000.0, clearance=0.0, waviness=()):
    return RigidRaceBearing("b", 0, rollers, K_ROLLER, 10 / 9, KIN, rpm * np.pi / 30, clearance, tuple(waviness))


def test_satisfies_bearing_protocol():
    assert isinstance(bearing(), NonlinearBearing)


def test_force_is_minus_gradient_of_contact_energy():
    b = bearing(clearance=0.1e-6)
    q = np.array([3e-8, -2e-7])
    f = b.force(q, np.zeros(2), 1.3e-3)
    h = 1e-12
    grad = [(b.potential_energy_J(q + h * e, 1.3e-3) - b.potential_energy_J(q - h * e, 1.3e-3)) / (2 * h)
            for e in np.eye(2)]
    assert f == pytest.approx(-np.array(grad), rel=1e-5)


def test_no_contact_inside_clearance():
    b = bearing(clearance=1e-6)
    assert np.all(b.force(np.array([0.5e-6, -0.5e-6]), np.zeros(2), 0.0) == 0.0)


def test_energy_conserved_at_rest_and_converges():
    # zero speed, no damping: a conservative 2-DOF oscillator on Hertz springs.
    rot = RigidRaceRotor(bearing(rpm=0.0), 0.6, 0.0, (0.0, -6.0))
    y0 = rot.initial_state()
    y0[2:4] = [2e-5, -3e-5]  # kick
    e0 = rot.energy_J(0.0, y0)
    drifts = []
    for rtol in (1e-5, 1e-7, 1e-9):
        sol = solve_ivp(rot.rhs, (0, 0.02), y0, method="DOP853", rtol=rtol, atol=rtol * rot.state_scale())
        e = np.array([rot.energy_J(t, y) for t, y in zip(sol.t, sol.y.T)])
        drifts.append(np.max(np.abs(e - e0)) / abs(0.5 * 0.6 * (2e-5**2 + 3e-5**2)))
    # relative to the oscillation energy; rtol 1e-9 measured 5.5e-5 (contacts open and close)
    assert drifts[-1] < 2e-4
    assert drifts[0] > drifts[1] > drifts[2]


def test_slowly_loaded_shaft_matches_stribeck_distribution():
    # static limit: load ramped over 50 ms at zero speed with damping, then held.
    rot = RigidRaceRotor(bearing(rollers=12, rpm=0.0), 0.6, 200.0, (0.0, -6.0), load_ramp_s=0.05)
    res = run_transient(rot, TransientSettings(0.12, chunks=4, sample_rate_hz=2000, rtol=1e-8))
    assert res.complete
    q_dyn = res.roller_force_N[-1]
    # roller j at 2 pi j/12 from +x; the load points along -y, so psi_j = theta_j + pi/2
    ref = static_load_distribution(K_ROLLER, 10 / 9, 12, 6.0, phase_rad=np.pi / 2)
    assert q_dyn == pytest.approx(ref.load_N, rel=1e-3, abs=1e-6)
    # forces balance the load, and Q_max is near Stribeck's 4.08 F_r/Z (a roller sits on the load line)
    th = rot.bearing.angles(res.time_s[-1])
    assert np.sum(q_dyn * np.sin(th)) == pytest.approx(-6.0, rel=1e-4)
    assert q_dyn.max() * 12 / 6.0 == pytest.approx(4.08, abs=0.02)


def test_eccentric_inner_race_orbits_at_shaft_speed():
    # one-wave inner race waviness = an eccentric inner race of eccentricity A turning with the shaft:
    # the shaft centre must orbit at the shaft frequency (83.33 Hz) with radius ~A.
    A = 0.2e-6
    rot = RigidRaceRotor(bearing(rollers=12, waviness=[Waviness("inner", 1, A)]), 0.6, 200.0, (0.0, -6.0))
    res = run_transient(rot, TransientSettings(0.15, settle_s=0.03, rtol=1e-7))
    f = res.spectrum.frequency_hz
    amp = res.spectrum.amplitude
    i = int(np.argmin(np.abs(f - 5000 / 60)))
    assert res.spectrum.dominant_frequency_hz(0, 10.0) == pytest.approx(5000 / 60, abs=res.spectrum.resolution_hz)
    # Hann-window scalloping: the line sits within half a bin of 83.33 Hz, amplitude within ~15% of A
    assert amp[i - 1:i + 2, 0].max() == pytest.approx(A, rel=0.2)
    assert amp[i - 1:i + 2, 1].max() == pytest.approx(A, rel=0.2)


def test_waviness_validation():
    with pytest.raises(ValueError):
        Waviness("cage", 3, 1e-6)
