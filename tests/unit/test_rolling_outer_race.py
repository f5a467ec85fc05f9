"""Segmented outer race: beam element (seed 000 eqs. 5-17) and free-ring frequencies."""

import numpy as np
import pytest

from spindlesim.bearings.roller.outer_race import SegmentedRing, deflection_eq17, frame_stiffness

# seed 000 Table 1: outer raceway 28.262 mm, housing radius 16 mm, width 6.35 mm -> thickness 1.869 mm
RING = SegmentedRing(12, 0.5 * (14.131e-3 + 16e-3), 1.869e-3, 6.35e-3, 208e9, 7850.0)


def test_frame_stiffness_symmetric_with_three_rigid_modes():
    K = frame_stiffness(208e9, 1e-5, 3e-12, 8e-3)
    assert np.allclose(K, K.T)
    w = np.linalg.eigvalsh(K)
    assert np.sum(np.abs(w) < 1e-9 * w.max()) == 3
    # rigid rotation of the beam by a small angle a: v = a x, phi = a -> no force
    a, l = 1e-3, 8e-3
    assert np.allclose(K @ np.array([0, 0, a, 0, a * l, a]), 0, atol=1e-9 * w.max() * a)


def test_reference_ring_is_stress_free_and_rigid_motion_is_force_free():
    # round-off only: EA/l ~ 3e8 N/m times ~1e-17 m of chord-length rounding
    assert np.allclose(RING.internal_force(np.zeros(36)), 0.0, atol=1e-6)
    # large rigid rotation (1 rad) plus translation: co-rotational beams carry no force (eqs. 12-13)
    rot = 1.0
    c, s = np.cos(rot), np.sin(rot)
    P = RING.ref_positions @ np.array([[c, s], [-s, c]]) + np.array([1e-3, -2e-3])
    q = np.column_stack([P - RING.ref_positions, np.full(12, rot)]).ravel()
    f = RING.internal_force(q)
    assert np.max(np.abs(f)) < 1e-6  # N; stiffness EA/l ~ 3e8 N/m, so this is < 1e-14 m of strain


def test_beam_forces_are_minus_gradient_of_strain_energy():
    rng = np.random.default_rng(1)
    q = rng.normal(size=36) * np.tile([1e-6, 1e-6, 1e-4], 12)
    f = RING.internal_force(q)
    h = np.tile([1e-9, 1e-9, 1e-7], 12)
    for k in (0, 4, 8, 20, 35):
        dq = np.zeros(36); dq[k] = h[k]
        g = (RING.strain_energy_J(q + dq) - RING.strain_energy_J(q - dq)) / (2 * h[k])
        assert f[k] == pytest.approx(-g, rel=1e-5, abs=1e-7 * np.max(np.abs(f)))
    # free body: beam forces sum to zero (Newton's third law)
    F = f.reshape(12, 3)
    assert np.allclose(F[:, 0:2].sum(axis=0), 0, atol=1e-9 * np.abs(F).max())


def test_eq17_is_the_hermite_deflection_of_the_end_rotations():
    EI, L = 0.7, 8e-3
    phi1, phi2 = 2e-4, -5e-4
    RN = EI / L * (4 * phi1 + 2 * phi2)  # end moments from eq. 11
    QN = EI / L * (2 * phi1 + 4 * phi2)
    x = np.linspace(0, 1, 11)
    v = deflection_eq17(RN, QN, L, x * L, EI)
    hermite = L * (phi1 * (x - 2 * x**2 + x**3) + phi2 * (x**3 - x**2))
    assert np.allclose(v, hermite, rtol=1e-12, atol=1e-20)
    assert v[0] == 0 and abs(v[-1]) < 1e-18
    # slope at the ends equals the end rotations
    assert np.gradient(v, x * L)[0] == pytest.approx(phi1, rel=0.05)


def test_free_ring_frequencies_converge_to_analytic():
    # thin free ring, mode n: w_n = sqrt(EI/(rho A R^4)) n (n^2-1)/sqrt(n^2+1) (REFERENCES.md)
    f2 = RING.analytic_ring_frequency_hz(2)
    f3 = RING.analytic_ring_frequency_hz(3)
    assert f2 == pytest.approx(5225.6, rel=1e-3)  # seed 000 race, E 208 GPa, 7850 kg/m3
    errs = []
    for n in (6, 8, 12, 24):
        ring = SegmentedRing(n, RING.mean_radius_m, RING.thickness_m, RING.width_m, 208e9, 7850.0)
        f = ring.free_frequencies_hz()
        assert np.all(f[:3] < 1e-3 * f2)  # three rigid-body modes
        assert f[3] == pytest.approx(f[4], rel=1e-6)  # each ring mode is a pair
        errs.append((abs(f[3] / f2 - 1), abs(f[5] / f3 - 1)))
    errs = np.array(errs)
    # measured: n=2 mode 4.2%, 3.4%, 1.7%, 0.25%; n=3 mode 22.7%, 9.4%, 3.8%, 1.3%
    assert np.all(np.diff(errs[:, 0]) < 0) and np.all(np.diff(errs[:, 1]) < 0)
    assert errs[2, 0] < 0.05 and errs[2, 1] < 0.05  # 12 segments within 5%
    assert errs[3, 0] < 0.01


def _u(q, psi):
    i, j, G = RING.surface_operator(np.atleast_1d(psi))
    Q = q.reshape(12, 3)
    return np.sum(G[:, 0:3] * Q[i], 1) + np.sum(G[:, 3:6] * Q[j], 1)


def test_surface_operator_rigid_ring_motions():
    psi = np.linspace(0, 2 * np.pi, 97)[:-1]
    # uniform expansion a: the race surface moves out by a everywhere
    a = 3e-9
    q = np.column_stack([a * np.cos(RING.phi), a * np.sin(RING.phi), np.zeros(12)]).ravel()
    assert _u(q, psi) == pytest.approx(np.full(psi.size, a), rel=1e-12)
    # small rigid rotation: no radial motion of the surface
    al = 1e-6
    q = np.column_stack([-al * RING.ref_positions[:, 1], al * RING.ref_positions[:, 0], np.full(12, al)]).ravel()
    assert np.max(np.abs(_u(q, psi))) < 1e-12 * RING.mean_radius_m
    # rigid translation d: u = f . d to within the interpolation error of cos over one segment, 1 - cos(pi/12)
    d = np.array([2e-9, -1e-9])
    q = np.column_stack([np.tile(d, (12, 1)), np.zeros(12)]).ravel()
    exact = np.cos(psi) * d[0] + np.sin(psi) * d[1]
    assert np.max(np.abs(_u(q, psi) - exact)) < (1 - np.cos(np.pi / 12)) * np.hypot(*d)


def test_surface_continuous_across_segments_and_bending_follows_eq17():
    rng = np.random.default_rng(3)
    q = rng.normal(size=36) * np.tile([2e-8, 2e-8, 2e-6], 12)
    eps = 1e-12
    for k in range(12):
        assert _u(q, RING.phi[k] - eps) == pytest.approx(_u(q, RING.phi[k] + eps), rel=1e-6, abs=1e-18)
    # only end rotations of segment 0 (beam 0 bends, segments fixed): u = v(eq. 17) (eta . f)
    q = np.zeros(36)
    q[2] = 1e-5
    b = RING.beam_state(q)
    EI = RING.youngs_modulus_Pa * RING.inertia_m4
    for x in (0.2, 0.5, 0.8):
        alpha = np.arctan((2 * x - 1) * np.tan(np.pi / 12)) + np.pi / 12  # ray through chord fraction x
        v = deflection_eq17(b["S"][0, 2], b["S"][0, 5], RING.chord_m, x * RING.chord_m, EI)
        gam = RING.ref_chord_angle[0]
        proj = -np.sin(gam) * np.cos(alpha) + np.cos(gam) * np.sin(alpha)
        assert _u(q, alpha)[0] == pytest.approx(v * proj, rel=1e-6)
