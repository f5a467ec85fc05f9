"""Race control of the balls: inner-race control against a hand calculation, the gyroscopic couple from the
3-D rolling kinematics, and Jones' race-control criterion computed here from the hand-calculated ball.

References written here, independent of the model's code:

- Jones' high-speed ball with Harris and Kotzalas' printed balance (2007, Advanced Concepts, ch. 3) and
  l_i = 2, l_o = 0, beta from tan(beta) = sin a_i / (cos a_i - D/d_m) (no spin on the inner race), w_c and
  w_R from Harris' rolling kinematics (test_ball_speed_effects.hand_ball with race "inner").
- The couple: with no spin at the inner contact and no slip at both contact centres the ball's angular
  velocity W follows from three linear equations; the torque the races must apply is w_c e_z x (J W), and
  the model's friction force at the inner contact, (2 M_g / D) t_i, must have that moment about the ball
  centre.  Its size is the closed form M_g = J w_R w_c sin(beta).
- Jones' criterion: the spin moments (3/8) Q a E(k) of both contacts from Hertz (point_contact, exact
  elliptic integrals, the curvature sums of test_ball_closed_forms) at the hand-calculated loads; outer-race
  control where M_so > M_si cos(a_i - a_o).  Harris and Kotzalas (AC ch. 2): outer-race control is the
  usual state of an oil-lubricated angular-contact bearing at high speed.
"""

import math

import numpy as np
import pytest
from scipy.special import ellipe

from spindlesim.bearings.ball.sweeps import Solver
from spindlesim.contact.hertz import point_contact

from ..unit.test_ball_section import RPM, bearing
from .test_ball_closed_forms import E_STAR_STEEL, curvature_sums
from .test_ball_speed_effects import A0, BD, D, DM, FI, FO, J, Z, hand_ball, kinematics

A1_21UM = BD * math.sin(A0) + 0.5 * 21e-6  # position preload 21 um, no external load: every ball alike


@pytest.mark.parametrize("rpm", [10000.0, 20000.0])
def test_inner_race_control_against_hand_calculation(rpm):
    (ai, ao, Qi, Qo, Fc, Mg, _), _ = hand_ball(rpm * RPM, "inner", A1=A1_21UM)
    st = bearing(model="inner_race_control").solve(np.zeros(5), rpm * RPM)
    assert st.model == "inner_race_control"
    assert math.radians(st.contact_angle_inner_deg[0, 0]) == pytest.approx(ai, rel=1e-8)
    assert math.radians(st.contact_angle_outer_deg[0, 0]) == pytest.approx(ao, rel=1e-8)
    assert st.element_load_inner_N[0, 0] == pytest.approx(Qi, rel=1e-7)
    assert st.element_load_outer_N[0, 0] == pytest.approx(Qo, rel=1e-7)
    assert st.centrifugal_force_N[0, 0] == pytest.approx(Fc, rel=1e-8)
    assert st.gyroscopic_moment_Nm[0, 0] == pytest.approx(Mg, rel=1e-7)
    # the inner contact carries the couple: the row's thrust includes its friction force (l_i = 2)
    assert st.row_axial_load_N[0] == pytest.approx(Z * (Qi * math.sin(ai) + 2.0 * Mg / D * math.cos(ai)), rel=1e-7)
    # no spin on the controlling race, spin on the other
    assert st.spin_roll_inner[0, 0] < 1e-12 and st.spin_roll_outer[0, 0] > 0.1


def test_race_controls_differ_as_jones_predicts():
    """At 20,000 rpm the three hypotheses give three different balls: under inner-race control the ball's axis
    tilts further (beta 25.5 against 7.6 deg) and M_g triples, the inner contact angle rises less and the outer
    contact carries more of the load; each state has no spin at its controlling race."""
    w = 20000.0 * RPM
    out = {race: hand_ball(w, race, A1=A1_21UM)[0] for race in ("outer", "inner", "full")}
    betas = {race: math.degrees(kinematics(v[0], v[1], w, race)[4]) for race, v in out.items()}
    assert betas["inner"] > betas["full"] > betas["outer"]
    assert out["inner"][5] > 2.5 * out["outer"][5]            # M_g
    assert out["inner"][0] < out["full"][0] < out["outer"][0]  # a_i
    assert out["inner"][1] > out["full"][1] > out["outer"][1]  # a_o
    for race, model in (("outer", "outer_race_control"), ("inner", "inner_race_control"), ("full", "full")):
        st = bearing(model=model).solve(np.zeros(5), w)
        assert st.contact_angle_inner_deg[0, 0] == pytest.approx(math.degrees(out[race][0]), rel=1e-8)
        assert st.gyroscopic_moment_Nm[0, 0] == pytest.approx(out[race][5], rel=1e-7)
        if race == "outer":
            assert st.spin_roll_outer[0, 0] < 1e-12 < st.spin_roll_inner[0, 0]
        elif race == "inner":
            assert st.spin_roll_inner[0, 0] < 1e-12 < st.spin_roll_outer[0, 0]
        else:  # equal and opposite spins about the bisector
            assert st.spin_roll_inner[0, 0] == pytest.approx(st.spin_roll_outer[0, 0], rel=1e-9)


def test_inner_race_couple_direction_in_3d():
    """Ball at psi = 0 of row 1 (thrust +z): x radial, z axial.  No spin at the inner contact, no slip at
    both contact centres; the rate of the ball's angular momentum w_c e_z x (J W) must be the moment of the
    model's friction force at the inner contact, and its size M_g = J w_R w_c sin(beta)."""
    w = 18000.0 * RPM
    st = bearing(model="inner_race_control").solve(np.zeros(5), w)
    ai, ao = math.radians(st.contact_angle_inner_deg[0, 0]), math.radians(st.contact_angle_outer_deg[0, 0])
    no = np.array([math.cos(ao), 0.0, math.sin(ao)])  # ball centre -> outer contact
    ni = np.array([math.cos(ai), 0.0, math.sin(ai)])  # inner contact -> ball centre
    rc, ez = 0.5 * DM, np.array([0.0, 0.0, 1.0])
    ro, ri = 0.5 * D * no, -0.5 * D * ni
    M = np.array([
        [ni[0], ni[2], 0.0],          # (W - w e_z) . n_i = 0: no spin relative to the inner ring
        [-ro[2], ro[0], rc],          # v_y at the outer contact = 0 (outer ring fixed)
        [-ri[2], ri[0], rc],          # v_y at the inner contact = w (rc + r_i,x)
    ])
    rhs = np.array([w * ni[2], 0.0, w * (rc + ri[0])])
    wx, wz, wc = np.linalg.solve(M, rhs)
    torque = wc * np.cross(ez, J * np.array([wx, 0.0, wz]))
    Mg = st.gyroscopic_moment_Nm[0, 0]
    assert abs(torque[1]) == pytest.approx(Mg, rel=1e-9)
    # closed form J w_R w_c sin(beta), Harris' kinematics at the model's angles
    _, Mg_closed, wc_h, _, _ = kinematics(ai, ao, w, "inner")
    assert Mg == pytest.approx(Mg_closed, rel=1e-10) and wc == pytest.approx(wc_h, rel=1e-10)
    # model: friction on the ball at the inner contact c_i t_i, c_i = 2 M_g / D, t_i = (cos a_i, -sin a_i) in (a, r)
    F = (2.0 * Mg / D) * np.array([-math.sin(ai), 0.0, math.cos(ai)])
    assert np.cross(ri, F) == pytest.approx(torque, rel=1e-9, abs=1e-12 * abs(Mg))


def hertz_spin_moment(Q, f, inner):
    """(3/8) Q a E(k) of one contact, Hertz at the free contact angle (the model's curvature sums)."""
    a, b, _, _ = point_contact(Q, *curvature_sums(D, DM, f, A0, inner), E_STAR_STEEL)
    return 0.375 * Q * a * ellipe(1.0 - (b / a) ** 2)


@pytest.mark.parametrize("rpm, expected", [(1000.0, -1), (10000.0, 1), (20000.0, 1)])
def test_jones_criterion_against_hand_calculation(rpm, expected):
    """Outer-race control at high speed (Harris and Kotzalas: the usual case of an oil-lubricated
    angular-contact bearing); at 1000 rpm the inner contact, whose ellipse is longer (f_i 0.52 < f_o 0.53),
    resists spin more and the criterion admits only inner-race control (where the couple hardly matters)."""
    (ai, ao, Qi, Qo, *_), _ = hand_ball(rpm * RPM, "outer", A1=A1_21UM)
    Msi, Mso = hertz_spin_moment(Qi, FI, True), hertz_spin_moment(Qo, FO, False)
    c = math.cos(ai - ao)
    hand = 1 if (Mso >= Msi * c and not Msi >= Mso * c) else (-1 if Msi >= Mso * c and not Mso >= Msi * c else 0)
    assert hand == expected
    st = bearing().solve(np.zeros(5), rpm * RPM)
    assert st.spin_moment_inner_Nm[0, 0] == pytest.approx(Msi, rel=1e-7)
    assert st.spin_moment_outer_Nm[0, 0] == pytest.approx(Mso, rel=1e-7)
    assert np.all(st.race_control == expected)


def test_auto_picks_the_race_the_criterion_admits():
    """model auto, the preloaded pair without external load (every ball alike): inner-race control at 1000 rpm,
    outer at 12,000 rpm, and the shared couple (full) at 3000 rpm, where the criterion admits only the inner race
    at the outer-controlled state and only the outer race at the inner-controlled one."""
    b = bearing()
    solver = Solver.of(b, auto=True)
    assert solver.solve(np.zeros(5), 1000.0 * RPM).model == "inner_race_control"
    assert solver.solve(np.zeros(5), 12000.0 * RPM).model == "outer_race_control"
    assert np.all(b.solve(np.zeros(5), 3000.0 * RPM).race_control == -1)
    assert np.all(b.with_model("inner_race_control").solve(np.zeros(5), 3000.0 * RPM).race_control == 1)
    st = solver.solve(np.zeros(5), 3000.0 * RPM)
    assert st.model == "full" and np.all(st.race_used == 0)


def test_auto_decides_per_ball():
    """A single row under Fx 2 kN + Fz 1 kN with its tilt held, 4000 rpm: the loaded balls favour the inner race,
    the nearly unloaded ones opposite the load the outer race; each ball gets the race its own state admits."""
    from spindlesim.bearings.ball.equilibrium import Held

    b = bearing(arrangement="single", rows=None, row_spacing_mm=None, preload=None)
    solver = Solver.of(b, Held.of(theta_x=0.0, theta_y=0.0), auto=True)
    st = solver.solve(np.array([2000.0, 0.0, 1000.0, 0.0, 0.0]), 4000.0 * RPM)
    assert st.model == "auto"
    used, admitted = st.race_used, st.race_control
    assert np.any(used == 1) and np.any(used == -1)
    assert np.all((used == admitted) | (admitted == 0) | (used == 0))
    assert used[0, 0] == -1 and used[0, 9] == 1  # psi 0 (most loaded) and 180 deg
