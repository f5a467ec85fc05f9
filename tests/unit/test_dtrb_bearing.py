"""DTRB bearing: equilibrium, mirror symmetry, Jacobian vs finite differences, protocol."""

import math

import numpy as np
import pytest

from spindlesim.bearings.base import Bearing
from spindlesim.bearings.dtrb import DtrbBearing

from .test_dtrb_geometry import RPM, bearing, geometry

D_GENERAL = np.array([3e-6, -2e-6, 1.5e-5, 4e-5, -6e-5])  # a state loading both rows unevenly


def _fd_jacobian(b, d, speed, h_lin=5e-11, h_rot=5e-10):
    """Central differences; small steps because lightly loaded rib contacts (delta ~ 1e-8 m,
    Q ~ delta^1.5) curve strongly: h = 2e-9 m gives 4e-4 truncation error, 5e-11 m 6e-10."""
    J = np.empty((5, 5))
    for j in range(5):
        h = h_lin if j < 3 else h_rot
        e = np.zeros(5)
        e[j] = h
        J[:, j] = (b.reaction(d + e, speed) - b.reaction(d - e, speed)) / (2 * h)
    return J


@pytest.mark.parametrize("speed_rpm", [0.0, 3000.0])
def test_analytic_stiffness_equals_finite_differences(speed_rpm):
    b = bearing(preload_um=10.0)
    w = speed_rpm * RPM
    K = b.stiffness(D_GENERAL, w)
    J = _fd_jacobian(b, D_GENERAL, w)
    scale = np.sqrt(np.abs(np.diag(K))[:, None] * np.abs(np.diag(K))[None, :])
    assert np.all(np.abs(K + J) <= 1e-6 * scale)
    assert np.allclose(K, K.T, rtol=0, atol=1e-9 * scale.max())
    assert np.all(np.linalg.eigvalsh(K) > 0)


def test_partially_unloaded_rows_jacobian():
    # no preload, ring pushed one way: row 2 has unloaded rollers, regularisation must not leak in
    b = bearing(preload_um=0.0)
    d = np.array([8e-6, 0.0, 2.0e-5, 0.0, 1e-4])
    st = b.at(d)
    n = st.loaded_rollers()
    assert n[0] > 0 and n.sum() < 40  # some rollers carry nothing
    K = st.stiffness
    J = _fd_jacobian(b, d, 0.0)
    scale = np.sqrt(np.abs(np.diag(K))[:, None] * np.abs(np.diag(K))[None, :])
    assert np.all(np.abs(K + J) <= 1e-6 * scale)


def test_equilibrium_balances_the_applied_load_through_the_cup():
    """At zero speed every roller passes its load to the cup along the cup normal, so the
    applied load equals the summed cup forces: FX = sum Q_o cos(alpha) cos(psi),
    FY = sum Q_o cos(alpha) sin(psi), FZ = sum s_k Q_o sin(alpha)."""
    b = bearing(preload_um=20.0)
    load = np.array([6000.0, -2500.0, 4000.0, 30.0, -50.0])
    st = b.solve(load)
    assert st.converged
    assert np.allclose(st.reaction, -load, rtol=0, atol=1e-6 * np.abs(load).max())
    a = b.geometry.cup_angle_rad
    Qo, psi = st.outer_load_N, st.psi_rad
    assert np.sum(Qo * math.cos(a) * np.cos(psi)) == pytest.approx(load[0], rel=1e-8)
    assert np.sum(Qo * math.cos(a) * np.sin(psi)) == pytest.approx(load[1], rel=1e-8)
    assert (Qo[0].sum() - Qo[1].sum()) * math.sin(a) == pytest.approx(load[2], rel=1e-8)
    # moments (eqs. 39-40 in equilibrium): moment about O of the slice forces on the fixed cup
    g = b.geometry
    P = g.outer(g.point_m.T).T  # (S, 2) row-local (rho, zeta~) of the cup slice points
    q = st.outer_slice_N_m * g.slice_width_m  # (2, N, S)
    M = np.zeros(2)
    for row, s in enumerate((1.0, -1.0)):
        c, sn = np.cos(psi[row])[:, None], np.sin(psi[row])[:, None]
        X, Y, Z = P[:, 0] * c, P[:, 0] * sn, s * P[:, 1] * np.ones_like(c)
        Fx, Fy, Fz = q[row] * math.cos(a) * c, q[row] * math.cos(a) * sn, s * q[row] * math.sin(a)
        M += [np.sum(Y * Fz - Z * Fy), np.sum(Z * Fx - X * Fz)]
    assert M == pytest.approx(load[3:], abs=1e-8 * np.abs(load).max())


def test_rows_swap_under_mirrored_load():
    b = bearing(preload_um=5.0, n_slices=12)
    load = np.array([5000.0, 0.0, 5000.0, 0.0, 40.0])
    mirror = load * np.array([1, 1, -1, 1, -1])  # Z -> -Z: FZ and MY change sign
    a = b.solve(load)
    m = b.solve(mirror)
    assert np.allclose(a.outer_load_N[0], m.outer_load_N[1], rtol=1e-7, atol=1e-6)
    assert np.allclose(a.outer_load_N[1], m.outer_load_N[0], rtol=1e-7, atol=1e-6)
    assert np.allclose(a.displacement * np.array([1, 1, -1, 1, -1]), m.displacement, rtol=1e-7, atol=1e-13)
    assert not np.allclose(a.outer_load_N[0], a.outer_load_N[1], rtol=0.05)  # the rows do differ


def test_preloaded_bearing_at_rest_is_symmetric():
    b = bearing(preload_um=15.0)
    st = b.at(np.zeros(5))
    assert np.abs(st.reaction[:3]).max() < 1e-6 and np.abs(st.reaction[3:]).max() < 1e-8
    assert np.allclose(st.outer_load_N, st.outer_load_N[0, 0], rtol=1e-10)
    K = st.stiffness
    assert K[0, 0] == pytest.approx(K[1, 1], rel=1e-10)
    assert K[3, 3] == pytest.approx(K[4, 4], rel=1e-10)
    off = K - np.diag(np.diag(K))
    assert np.abs(off).max() < 1e-8 * np.abs(K).max()


def test_roller_positions_follow_the_cage_eq3():
    # one roller pitch of cage rotation gives the same bearing state (eq. 3)
    b = bearing(preload_um=10.0, n_slices=10)
    w = 3000 * RPM
    g = b.geometry
    pitch = 2 * math.pi / g.rollers_per_row / g.cage_ratio  # shaft angle that moves the cage one pitch
    F0 = b.reaction(D_GENERAL, w, 0.0)
    assert np.allclose(b.reaction(D_GENERAL, w, pitch), F0, rtol=1e-9, atol=1e-6)
    assert not np.allclose(b.reaction(D_GENERAL, w, 0.3 * pitch), F0, rtol=1e-6)


def test_centrifugal_and_gyroscopic_loads_eqs_31_32():
    b = bearing()
    g = b.geometry
    w = 6000 * RPM
    f = b.inertia_load(w)
    wc = g.cage_ratio * w
    Fc = g.roller_mass_kg * g.mass_centre_radius_m * wc ** 2
    Mg = g.roller_polar_inertia_kg_m2 * wc * g.spin_ratio * w * math.sin(g.roller_axis_angle_rad)
    assert f == pytest.approx([Fc * math.cos(g.roller_axis_angle_rad), -Fc * math.sin(g.roller_axis_angle_rad), -Mg])
    assert np.all(b.inertia_load(0.0) == 0.0)
    # pure rolling: roller surface speed equals the cup speed relative to the cage at mid-length
    r_mid = g.large_end_radius_m - 0.5 * g.roller_length_m * math.tan(g.roller_half_angle_rad)
    rho_o = g.outer(g.point_m[:, 0]).mean()
    assert g.spin_ratio * r_mid == pytest.approx(g.cage_ratio * rho_o, rel=1e-12)


def test_roller_newton_converges_and_warm_start_agrees():
    b = bearing(preload_um=10.0)
    w = 3000 * RPM
    F, K, u = b.reaction_and_stiffness(D_GENERAL, w)
    st = b.at(D_GENERAL, w)
    assert st.converged and st.iterations < 30
    F2, K2, _ = b.reaction_and_stiffness(D_GENERAL, w, roller_guess=u)
    assert np.allclose(F2, F, rtol=1e-10, atol=1e-8)
    assert np.allclose(K2, K, rtol=1e-8)


def test_bearing_protocol_linearized():
    b = DtrbBearing(geometry(n_slices=10), 20e-6, name="hub", node=3, axial_load_N=2000.0)
    assert isinstance(b, Bearing)
    K, C = b.linearized(3000 * RPM, np.array([3000.0, -1000.0]))
    K5 = b.solve([3000.0, -1000.0, 2000.0, 0, 0], 3000 * RPM).stiffness
    assert np.allclose(K, K5[:2, :2]) and np.all(C == 0.0)
    assert K[0, 0] > 0 and K[1, 1] > 0
    f = b.force_and_tangent(np.array([1e-6, 0.0]), np.zeros(2))[0]
    assert f.shape == (2,) and f[0] < 0
    b5 = DtrbBearing(geometry(n_slices=10), 20e-6, axial_load_N=2000.0,
                     dof_names=("x", "y", "z", "theta_x", "theta_y"))
    K5b, C5 = b5.linearized(3000 * RPM, np.array([3000.0, -1000.0]))
    assert np.allclose(K5b, K5) and C5.shape == (5, 5)


def test_equilibrium_without_preload_from_rest():
    # no preload: K = 0 at d = 0; the damped Newton must still find the loaded state
    b = bearing(preload_um=0.0, n_slices=10)
    st = b.solve([3000.0, 0.0, 2000.0, 0.0, 0.0])
    assert st.converged
    assert np.allclose(st.reaction, [-3000.0, 0.0, -2000.0, 0.0, 0.0], atol=1e-5)
