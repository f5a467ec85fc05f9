"""BallBearing: the bearing contract, the exact tangent against central differences, balances.

Tangent check: K_t = -df/dq from the implicit-function Jacobian (module kernel) against central
differences of f, Richardson-extrapolated (steps 2e-9 m / 4e-8 rad and half of them), relative to
sqrt(K_ii K_jj); the issue asks for 1e-6.  Balances: every ball's equilibrium rebuilt here from the
reported loads, angles, centrifugal force and gyroscopic moment (Jones 1960; Harris and Kotzalas
2007, Advanced Concepts, ch. 3), and the set reaction against the applied load, to 1e-9.
"""

import math

import numpy as np
import pytest

from spindlesim.bearings.ball import build
from spindlesim.bearings.ball.bearing import BallBearing, BallEquilibriumError
from spindlesim.bearings.base import Bearing

from .test_ball_section import RPM, bearing, entry


def fd_tangent(b, q, speed, angle=0.0):
    def f(qq):
        return b.force_and_tangent(qq, np.zeros(5), 0.0, speed, angle)[0]

    def central(h):
        J = np.empty((5, 5))
        for j in range(5):
            e = np.zeros(5)
            e[j] = h * (1.0 if j < 3 else 20.0)
            J[:, j] = -(f(q + e) - f(q - e)) / (2 * e[j])
        return J

    return (4.0 * central(1e-9) - central(2e-9)) / 3.0


def rel_error(K, J):
    d = np.sqrt(np.abs(np.diag(K)))
    scale = np.outer(d, d)
    return float(np.max(np.abs(K - J) / scale))


CASES = [
    # (deck changes, displacement q [m, rad], speed rpm)
    (dict(), [4e-6, -3e-6, 2e-6, 1.5e-5, -2e-5], 0.0),
    (dict(), [4e-6, -3e-6, 2e-6, 1.5e-5, -2e-5], 15000.0),
    (dict(model="full"), [4e-6, -3e-6, 2e-6, 1.5e-5, -2e-5], 15000.0),
    (dict(model="inner_race_control"), [4e-6, -3e-6, 2e-6, 1.5e-5, -2e-5], 15000.0),
    (dict(model="inner_race_control", preload={"kind": "spring", "axial_N": 800.0}), [3e-6, 2e-6, -1e-6, -1e-5, 1e-5],
     12000.0),
    (dict(preload={"kind": "spring", "axial_N": 800.0}), [3e-6, 2e-6, -1e-6, -1e-5, 1e-5], 0.0),
    (dict(preload={"kind": "spring", "axial_N": 800.0}), [3e-6, 2e-6, -1e-6, -1e-5, 1e-5], 12000.0),
    (dict(arrangement="DF"), [2e-6, 1e-6, 3e-6, 1e-5, 1e-5], 8000.0),
    (dict(rows=3, axial_direction="-z"), [2e-6, 1e-6, -3e-6, 1e-5, 5e-6], 8000.0),
    (dict(ball_material={"E_GPa": 310.0, "poisson": 0.26, "density_kg_m3": 3200.0}, model="full"),
     [3e-6, -1e-6, 2e-6, 2e-5, 1e-5], 20000.0),
]


@pytest.mark.parametrize("changes, q, rpm", CASES)
def test_tangent_equals_central_differences(changes, q, rpm):
    b = bearing(**changes)
    q = np.array(q)
    f, K, C = b.force_and_tangent(q, np.zeros(5), 0.0, rpm * RPM, 0.3)
    assert np.all(C == 0.0)
    assert rel_error(K, fd_tangent(b, q, rpm * RPM, 0.3)) < 1e-6
    if rpm == 0.0 and changes.get("model") != "full":
        # at rest the ball problem has a potential: the tangent is symmetric
        d = np.sqrt(np.abs(np.diag(K)))
        assert np.max(np.abs(K - K.T) / np.outer(d, d)) < 1e-12


def test_deep_groove_with_clearance_tangent_and_symmetry():
    """Single deep-groove row with 15 um clearance under combined displacement (some balls unloaded)."""
    b = build(entry(contact_angle_deg=0.0, radial_clearance_um=15.0, inner_conformity=0.515, outer_conformity=0.525))
    q = np.array([12e-6, 4e-6, 30e-6, 5e-5, 0.0])
    for rpm in (0.0, 10000.0):
        f, K, _ = b.force_and_tangent(q, np.zeros(5), 0.0, rpm * RPM, 0.05)
        assert rel_error(K, fd_tangent(b, q, rpm * RPM, 0.05)) < 1e-6
    f, K, _ = b.force_and_tangent(q, np.zeros(5), 0.0, 0.0, 0.05)
    d = np.sqrt(np.abs(np.diag(K)))
    assert np.max(np.abs(K - K.T) / np.outer(d, d)) < 1e-12


def test_contract():
    b = bearing()
    assert isinstance(b, Bearing)
    assert b.dof_names == ("x", "y", "z", "theta_x", "theta_y")
    assert b.internal_mass.size == 0
    assert b.at_operating_point(1000.0, np.zeros(5)) is b
    with pytest.raises(NotImplementedError):
        b.compiled()
    f, K, C = b.force_and_tangent(np.zeros(5), np.zeros(5), 0.0, 0.0)
    assert f.shape == (5,) and K.shape == (5, 5) and C.shape == (5, 5)
    # the speed * t default of the contract: same ball positions as the explicit angle
    f1 = b.force_and_tangent(np.array([5e-6, 0, 0, 0, 0]), np.zeros(5), 1e-3, 1000.0)[0]
    f2 = b.force_and_tangent(np.array([5e-6, 0, 0, 0, 0]), np.zeros(5), 0.0, 1000.0, angle=1.0)[0]
    assert np.allclose(f1, f2, rtol=1e-12, atol=1e-9)


def test_frequencies_are_the_kinematic_ones():
    """Cage f (1 - D cos(a)/d_m)/2, BPFO Z f_c, BPFI Z (f - f_c) (Harris and Kotzalas, Essential Concepts, ch. 8)."""
    b = bearing()
    fr = b.frequencies_hz(12000.0 * RPM)
    g = 12.7 * math.cos(math.radians(15.0)) / 90.0
    assert fr["cage"] == pytest.approx(200.0 * (1 - g) / 2, rel=1e-12)
    assert fr["ball_pass_outer"] == pytest.approx(18 * 100.0 * (1 - g), rel=1e-12)
    assert fr["ball_pass_inner"] == pytest.approx(18 * 100.0 * (1 + g), rel=1e-12)
    assert fr["ball_spin"] == pytest.approx(90.0 / (2 * 12.7) * 200.0 * (1 - g * g), rel=1e-12)


@pytest.mark.parametrize("changes, rpm", [(dict(), 0.0), (dict(), 18000.0), (dict(model="full"), 18000.0),
                                          (dict(model="inner_race_control"), 18000.0),
                                          (dict(preload={"kind": "spring", "axial_N": 300.0}), 10000.0)])
def test_set_and_ball_balances(changes, rpm):
    b = bearing(**changes)
    load = np.array([2500.0, -1200.0, 900.0, 35.0, -20.0])
    st = b.solve(load, rpm * RPM, cage_angle=0.1)
    assert np.max(np.abs(st.reaction + load)) <= 1e-9 * np.max(np.abs(load))
    # every ball: Q_i n_i - Q_o n_o + F_c e_r + friction couple = 0 in (axial, radial)
    D = b.geometry.ball_diameter_m
    ai, ao = np.radians(st.contact_angle_inner_deg), np.radians(st.contact_angle_outer_deg)
    Qi, Qo, Fc, Mg = st.element_load_inner_N, st.element_load_outer_N, st.centrifugal_force_N, st.gyroscopic_moment_Nm
    li, lo = {"outer_race_control": (0.0, 2.0), "inner_race_control": (2.0, 0.0), "full": (1.0, 1.0)}[b.model]
    ci, co = li * Mg / D, -lo * Mg / D
    Ra = Qi * np.sin(ai) - Qo * np.sin(ao) + ci * np.cos(ai) + co * np.cos(ao)
    Rr = Qi * np.cos(ai) - Qo * np.cos(ao) + Fc - ci * np.sin(ai) - co * np.sin(ao)
    assert np.max(np.abs(Ra)) <= 1e-9 * Qo.max() and np.max(np.abs(Rr)) <= 1e-9 * Qo.max()
    if rpm == 0.0:
        assert np.allclose(Qi, Qo, rtol=1e-12) and np.allclose(ai, ao, rtol=1e-12)


def test_reaction_at_rest_is_the_sum_of_the_inner_contact_forces():
    """f = sum over balls of -Q_i along the contact normal, mapped to x, y, z and moments about the
    inner groove-centre locus (radius R_i, row position z_k + s (r_i - D/2) sin a_f)."""
    b = bearing()
    q = np.array([6e-6, -2e-6, 3e-6, 2e-5, 1e-5])
    st = b.at(q, 0.0, 0.2)
    g = b.geometry
    f = np.zeros(5)
    Ri = g.inner_centre_radius_m
    for k in range(2):
        s = g.row_sign[k]
        zc = g.row_z_m[k] + s * (g.inner_groove_radius_m - g.ball_diameter_m / 2) * math.sin(g.mounted_angle_rad)
        a = np.radians(st.contact_angle_inner_deg[k])
        psi = st.psi_rad[k]
        Fr, Fa = -st.element_load_inner_N[k] * np.cos(a), -st.element_load_inner_N[k] * np.sin(a) * s
        Fx, Fy = Fr * np.cos(psi), Fr * np.sin(psi)
        X, Y = Ri * np.cos(psi), Ri * np.sin(psi)
        f += [Fx.sum(), Fy.sum(), Fa.sum(), np.sum(Y * Fa - zc * Fy), np.sum(zc * Fx - X * Fa)]
    assert np.allclose(st.reaction, f, rtol=1e-12, atol=1e-9)


def test_linearized_is_the_tangent_at_the_loaded_equilibrium():
    b = bearing()
    load = np.array([1500.0, 0.0, 400.0, 0.0, 10.0])
    one = BallBearing(b.geometry, b.preload, pitch_samples=1)
    K1, C1 = one.linearized(9000.0 * RPM, load)
    q = one.solve(load, 9000.0 * RPM).displacement
    f, K, _ = one.force_and_tangent(q, np.zeros(5), 0.0, 9000.0 * RPM, 0.0)
    assert np.allclose(f, -load, rtol=0, atol=1e-9 * 1500.0)
    assert np.allclose(K1, K, rtol=1e-10, atol=1e-12 * np.abs(K).max()) and np.all(C1 == 0)
    K4, _ = b.linearized(9000.0 * RPM, load)  # averaged over a ball pitch: close to one position
    assert np.allclose(K4[:3, :3], K1[:3, :3], rtol=5e-3, atol=1e-6 * np.abs(K1).max())


def test_results_do_not_depend_on_the_warm_start():
    b = bearing(model="full")
    q = np.array([3e-6, 1e-6, 2e-6, 1e-5, 0.0])
    cold = b.force_and_tangent(q, np.zeros(5), 0.0, 16000.0 * RPM, 0.2)
    b.force_and_tangent(q * 5.0, np.zeros(5), 0.0, 3000.0 * RPM, 1.0)  # a far-away history
    warm = b.force_and_tangent(q, np.zeros(5), 0.0, 16000.0 * RPM, 0.2)
    assert np.allclose(cold[0], warm[0], rtol=1e-11, atol=1e-8)
    assert np.allclose(cold[1], warm[1], rtol=1e-8, atol=1e-6 * np.abs(cold[1]).max())


def test_back_to_back_pair_mirrors_under_reversed_thrust():
    b = bearing()
    a = b.solve(np.array([800.0, 0.0, 1500.0, 0.0, 0.0]), 6000.0 * RPM)
    m = b.solve(np.array([800.0, 0.0, -1500.0, 0.0, 0.0]), 6000.0 * RPM)
    assert m.row_axial_load_N == pytest.approx(a.row_axial_load_N[::-1], rel=1e-9)
    assert m.displacement[2] == pytest.approx(-a.displacement[2], rel=1e-9)
    assert a.row_axial_load_N[0] - a.row_axial_load_N[1] == pytest.approx(1500.0, rel=1e-9)


def test_rest_is_the_limit_of_low_speed():
    b = bearing()
    load = np.array([1000.0, 0.0, 300.0, 0.0, 0.0])
    rest, slow = b.solve(load, 0.0), b.solve(load, 1e-3)
    assert np.allclose(slow.element_load_inner_N, rest.element_load_inner_N, rtol=1e-6, atol=1e-6)
    assert np.allclose(slow.stiffness, rest.stiffness, rtol=1e-6, atol=1e-6 * rest.stiffness.max())


def test_spring_preloaded_rows_keep_their_force_and_add_no_axial_stiffness():
    # the rows carrying -z thrust float: row 1 of the DB pair (at its +z end)
    b = bearing(preload={"kind": "spring", "axial_N": 400.0, "floating": "-z"})
    for rpm in (0.0, 15000.0):
        st = b.solve(np.array([1200.0, 0.0, 500.0, 0.0, 0.0]), rpm * RPM)
        assert st.row_axial_load_N[1] == pytest.approx(400.0, rel=1e-10)  # floating row (the last)
        assert st.row_axial_load_N[0] == pytest.approx(900.0, rel=1e-9)
        # the axial stiffness is that of the fixed row alone (row 1 evaluated at the same state)
        fixed = b._rows(st.displacement, rpm * RPM, 0.0, np.zeros(2), np.array([0]))
        assert st.stiffness[2, 2] == pytest.approx(fixed.K_rows[0, 2, 2], rel=1e-9)


def test_fully_floating_set_carries_exactly_its_spring_force():
    b = build(entry(preload={"kind": "spring", "axial_N": 300.0}))
    st = b.solve(np.array([500.0, 0.0, 300.0, 0.0, 0.0]), 5000.0 * RPM)
    assert st.row_axial_load_N[0] == pytest.approx(300.0, rel=1e-10)
    assert np.all(st.stiffness[2, :] == 0.0) and np.all(st.stiffness[:, 2] == 0.0)
    with pytest.raises(ValueError, match="exactly the spring force"):
        b.solve(np.array([500.0, 0.0, 100.0, 0.0, 0.0]), 0.0)


def test_failed_set_equilibrium_says_what_and_where():
    b = bearing()
    with pytest.raises(BallEquilibriumError, match=r"no set equilibrium under the load .* at 5000 rpm"):
        b._equilibrium(np.array([3000.0, 0.0, 0.0, 0.0, 0.0]), 5000.0 * RPM, 0.0, max_iter=1)


def test_traction_needed_by_the_gyroscopic_couple_is_reported(caplog):
    """Outer-race control at moderate speed needs little traction; the full model with a light spring
    preload at 20000 rpm needs more friction at the inner contact than it could have: warned."""
    st = bearing().solve(np.zeros(5), 10000.0 * RPM)
    D = 12.7e-3
    assert st.traction_ratio == pytest.approx(2 * st.gyroscopic_moment_Nm / D / st.element_load_outer_N, rel=1e-12)
    assert st.traction_ratio.max() < 0.05
    with caplog.at_level("WARNING", logger="spindlesim.bearings.ball.bearing"):
        st = bearing(model="full", preload={"kind": "spring", "axial_N": 250.0}).solve(np.zeros(5), 20000.0 * RPM)
    assert st.traction_ratio.max() > 0.1
    assert "gyroscopic slip" in caplog.text
