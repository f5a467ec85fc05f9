"""Rigid-race bearing (Sunnersjo 1978; Harsha and Kankar 2004) through the contract and the engine."""

import numpy as np
import pytest

from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate
from spindlesim.analysis.transient.system import Excitation, TimeLoad
from spindlesim.bearings.base import Bearing
from spindlesim.bearings.roller.kinematics import CageKinematics
from spindlesim.bearings.roller.load_distribution import static_load_distribution
from spindlesim.bearings.roller.bearing import RigidRaceBearing, Waviness
from spindlesim.contact.hertz import palmgren_stiffness
from spindlesim.model.rig import journal_rotor

KIN = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3)  # seed 000 Table 1
K_ROLLER = palmgren_stiffness(6.35e-3)  # width 6.35 mm, seed 000 Table 1
RPM = np.pi / 30


def bearing(rollers=8, clearance=0.0, waviness=()):
    return RigidRaceBearing("b", 0, rollers, K_ROLLER, 10 / 9, KIN, clearance, tuple(waviness))


def test_satisfies_the_contract():
    b = bearing()
    assert isinstance(b, Bearing)
    f = b.frequencies_hz(5000 * RPM)
    assert f["roller_pass"] == pytest.approx(8 * 0.39868 * 5000 / 60, rel=1e-4)  # REFERENCES.md: 265.8 Hz


def test_force_is_minus_gradient_of_contact_energy():
    b = bearing(clearance=0.1e-6)
    q, a = np.array([3e-8, -2e-7]), 0.7
    f, K, C = b.force_and_tangent(q, np.zeros(2), 0.0, 0.0, a)
    h = 1e-12
    grad = [(b.potential_energy_J(q + h * e, a) - b.potential_energy_J(q - h * e, a)) / (2 * h) for e in np.eye(2)]
    assert f == pytest.approx(-np.array(grad), rel=1e-5)
    # the tangent is minus the derivative of the force (central differences)
    Kd = np.column_stack([-(b.force_and_tangent(q + h * e, np.zeros(2), 0, 0, a)[0]
                            - b.force_and_tangent(q - h * e, np.zeros(2), 0, 0, a)[0]) / (2 * h) for e in np.eye(2)])
    assert np.allclose(K, Kd, rtol=1e-5) and np.all(C == 0)


def test_no_contact_inside_clearance():
    b = bearing(clearance=1e-6)
    assert np.all(b.force_and_tangent(np.array([0.5e-6, -0.5e-6]), np.zeros(2), 0.0, 0.0)[0] == 0.0)


def test_compiled_force_equals_numpy():
    from spindlesim.bearings.roller import rigid_race_kernel

    b = bearing(waviness=[Waviness("outer", 8, 0.3e-6), Waviness("inner", 3, 0.2e-6, 0.4),
                          Waviness("roller", 2, 0.1e-6)])
    c = b.compiled()
    out = np.zeros(2)
    for q, t in ((np.array([1e-6, -2e-6]), 1.3e-3), (np.array([-3e-7, 1e-7]), 4.1e-2)):
        rigid_race_kernel.force(c.floats, 0, c.ints, 0, q, np.zeros(2), t, 523.6, 523.6 * t, out)
        ref = b.force_and_tangent(q, np.zeros(2), t, 523.6)[0]
        assert out == pytest.approx(ref, rel=1e-13, abs=1e-12)


@pytest.mark.slow
def test_energy_conserved_at_rest_and_converges():
    # zero speed, no damping: a conservative 2-DOF oscillator on Hertz springs, released from a push
    b = bearing()
    rot = journal_rotor((b,), 0.6, 0.0, (0.0, -6.0))
    drifts = []
    for rtol in (1e-5, 1e-7, 1e-9):
        res = simulate(rot, TransientSettings(0.02, method="DOP853", rtol=rtol, sample_rate_hz=20000,
                                              perturbation=Perturbation(0, 20.0), chunks=2))
        x = res.rotor_displacement
        v = res.velocity_m_s
        e = (0.5 * 0.6 * np.sum(v ** 2, axis=1) + np.array([b.potential_energy_J(xi, 0.0) for xi in x])
             + 6.0 * x[:, 1])
        drifts.append(np.max(np.abs(e - e[0])) / np.ptp(0.5 * 0.6 * np.sum(v ** 2, axis=1)))
    # relative to the oscillation energy; contacts open and close, so the convergence is slow
    assert drifts[-1] < 2e-4
    assert drifts[0] > drifts[1] > drifts[2]


def test_slowly_loaded_shaft_matches_stribeck_distribution():
    # static limit: 6 N ramped over 50 ms at zero speed with damping, then held (Harris ch. 7)
    rot = journal_rotor((bearing(rollers=12),), 0.6, 200.0)
    res = simulate(rot, TransientSettings(0.12, method="rk4", sample_rate_hz=2000,
                                          excitation=Excitation(loads=(TimeLoad(1, -6.0, "ramp", t_on_s=0.05),))))
    assert res.complete
    q_dyn = res.bearing_outputs[0]["roller_load_N"][0][-1]
    # roller j at 2 pi j/12 from +x; the load points along -y, so psi_j = theta_j + pi/2
    ref = static_load_distribution(K_ROLLER, 10 / 9, 12, 6.0, phase_rad=np.pi / 2)
    assert q_dyn == pytest.approx(ref.load_N, rel=1e-3, abs=1e-6)
    assert q_dyn.max() * 12 / 6.0 == pytest.approx(4.08, abs=0.02)  # Stribeck, line contact


def test_static_equilibrium_matches_stribeck_distribution():
    # the engine's start (the one static solver) under 6 N downward at zero speed
    rot = journal_rotor((bearing(rollers=12),), 0.6, 200.0, (0.0, -6.0))
    res = simulate(rot, TransientSettings(1e-3, method="rk4", sample_rate_hz=10000))
    q0 = res.bearing_outputs[0]["roller_load_N"][0][0]
    ref = static_load_distribution(K_ROLLER, 10 / 9, 12, 6.0, phase_rad=np.pi / 2)
    assert q0 == pytest.approx(ref.load_N, rel=1e-8, abs=1e-9)
    # it is an equilibrium of the dynamic model: after 1 ms at rest nothing has moved
    assert np.max(np.abs(res.displacement_m - res.displacement_m[0])) < 1e-9 * np.max(np.abs(res.displacement_m[0]))


def test_eccentric_inner_race_orbits_at_shaft_speed():
    # one-wave inner race waviness = an eccentric inner race of eccentricity A turning with the shaft:
    # the shaft centre must orbit at the shaft frequency (83.33 Hz) with radius ~A.
    A = 0.2e-6
    rot = journal_rotor((bearing(rollers=12, waviness=[Waviness("inner", 1, A)]),), 0.6, 200.0, (0.0, -6.0), 5000)
    res = simulate(rot, TransientSettings(0.15, method="rk4", settle_s=0.03))
    f, amp = res.spectrum.frequency_hz, res.spectrum.amplitude
    i = int(np.argmin(np.abs(f - 5000 / 60)))
    assert res.spectrum.dominant_frequency_hz(0, 10.0) == pytest.approx(5000 / 60, abs=res.spectrum.resolution_hz)
    # Hann-window scalloping: the line sits within half a bin of 83.33 Hz, amplitude within ~20% of A
    assert amp[i - 1:i + 2, 0].max() == pytest.approx(A, rel=0.2)
    assert amp[i - 1:i + 2, 1].max() == pytest.approx(A, rel=0.2)


def test_linearized_is_the_pitch_averaged_tangent():
    # contract: linearized() is the tangent at the static state averaged over one roller pitch
    b = bearing(rollers=8)
    # 6 N from 1 deg off the vertical: no roller of the 24 pitch positions sits at first touch
    # (delta = 0, where Q = K delta^(10/9) has no second derivative and differences are meaningless)
    W = 6.0 * np.array([np.cos(np.radians(-91.0)), np.sin(np.radians(-91.0))])
    K, C = b.linearized(5000 * RPM, W)
    q = b.static_displacement(5000 * RPM, W)
    f, _ = b.pitch_average(q)
    assert f == pytest.approx(-W, abs=1e-9 * 6.0)
    h = 1e-11
    Kd = np.column_stack([-(b.pitch_average(q + h * e)[0] - b.pitch_average(q - h * e)[0]) / (2 * h) for e in np.eye(2)])
    assert np.max(np.abs(K - Kd)) < 1e-5 * np.max(np.abs(K))


def test_waviness_validation():
    with pytest.raises(ValueError):
        Waviness("cage", 3, 1e-6)
