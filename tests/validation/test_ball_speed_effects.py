"""Speed effects of the default deck's 7014C-size DB pair against a hand calculation of one ball.

Hand calculation (written out below, independent of the model's code): Jones' high-speed ball in
the four unknowns of Harris and Kotzalas (2007, Advanced Concepts, ch. 3), X1, X2 (ball centre from
the outer groove centre, axial and radial), delta_i, delta_o, with

    (A1 - X1)^2 + (A2 - X2)^2 = ((f_i - 1/2) D + delta_i)^2,   X1^2 + X2^2 = ((f_o - 1/2) D + delta_o)^2
    Q_i sin a_i - Q_o sin a_o + (M_g / D)(l_i cos a_i - l_o cos a_o) = 0
    Q_i cos a_i - Q_o cos a_o - (M_g / D)(l_i sin a_i - l_o sin a_o) + F_c = 0

(l_i, l_o) = (0, 2) for outer-race control, (2, 0) for inner-race control, (1, 1) for the full model;
F_c = m (d_m/2) w_c^2, M_g = J w_R w_c sin(beta); beta from tan(beta) = sin a_o / (cos a_o + D/d_m)
(outer-race control), tan(beta) = sin a_i / (cos a_i - D/d_m) (inner-race control) or
beta = (a_i + a_o)/2 (full); w_c and w_R from pure rolling at both contacts in Harris' form
(see ``kinematics`` below).  The friction couple acts in the sense of T = w_c e_z x H (the torque the
races must apply so that the ball's spin axis precesses with the cage; checked in 3D below).  Here M_g
is the size J |w_R| w_c sin(beta); Harris and Kotzalas print the two friction terms with the opposite
signs and a signed w_R < 0, which is the same force (tests/validation/test_ball_published.py).

Position preload of the pair at zero external load: the shaft stays at q = 0 by symmetry, so every
ball of a row sees A1 = B D sin(a0) + axial/2, A2 = B D cos(a0).  Spring preload: A1 is a fifth
unknown with the inner-ring thrust per ball Q_i sin a_i + (l_i M_g / D) cos a_i = F_s / Z.
"""

import math

import numpy as np
import pytest
from scipy.optimize import root

from ..unit.test_ball_section import RPM, bearing
from .test_ball_closed_forms import E_STAR_STEEL, curvature_sums
from spindlesim.contact.hertz import point_contact_constant

D, DM, FI, FO, Z, A0 = 12.7e-3, 90e-3, 0.52, 0.53, 18, math.radians(15.0)
BD = (FI + FO - 1.0) * D
GI, GO = (FI - 0.5) * D, (FO - 0.5) * D
KI = point_contact_constant(*curvature_sums(D, DM, FI, A0, True), E_STAR_STEEL)
KO = point_contact_constant(*curvature_sums(D, DM, FO, A0, False), E_STAR_STEEL)
MASS = 7850.0 * math.pi * D ** 3 / 6.0
J = MASS * D * D / 10.0
G = D / DM


#: (l_i, l_o) of Harris and Kotzalas' ball balance for each race control
LAMBDAS = {"outer": (0.0, 2.0), "full": (1.0, 1.0), "inner": (2.0, 0.0)}


def _race(full) -> str:
    """The race control of a ``full`` argument: True / False (full / outer) or a name of LAMBDAS."""
    return full if isinstance(full, str) else ("full" if full else "outer")


def kinematics(ai, ao, w, full):
    """(F_c, M_g, w_c, w_R, beta) of Harris and Kotzalas (2007, ch. 3), outer ring fixed; ``full``: True,
    False (outer-race control) or "outer", "inner", "full"."""
    race = _race(full)
    if race == "full":
        beta = 0.5 * (ai + ao)
    elif race == "inner":
        beta = math.atan2(math.sin(ai), math.cos(ai) - G)
    else:
        beta = math.atan2(math.sin(ao), math.cos(ao) + G)
    tb = math.tan(beta)
    po = (math.cos(ao) + tb * math.sin(ao)) / (1.0 + G * math.cos(ao))
    pi_ = (math.cos(ai) + tb * math.sin(ai)) / (1.0 - G * math.cos(ai))
    wR = w / ((po + pi_) * G * math.cos(beta))
    wc = w * (1.0 - G * math.cos(ai)) * (math.cos(ao) + tb * math.sin(ao)) / (
        (1.0 + G * math.cos(ao)) * (math.cos(ai) + tb * math.sin(ai))
        + (1.0 - G * math.cos(ai)) * (math.cos(ao) + tb * math.sin(ao)))
    return MASS * 0.5 * DM * wc * wc, J * wR * wc * math.sin(beta), wc, wR, beta


def hand_ball(w, full, A1=None, thrust=None, start=None):
    """One ball: (a_i, a_o, Q_i, Q_o, F_c, M_g[, A1]) at shaft speed w; A1 given (position) or solved
    for the inner-ring thrust per ball (spring); ``full`` as for ``kinematics``."""
    li, lo = LAMBDAS[_race(full)]
    A2 = BD * math.cos(A0)

    def parts(x):
        X1, X2, di, do = x[:4]
        a1 = A1 if thrust is None else x[4]
        Li, Lo = GI + di, GO + do
        si, ci = (a1 - X1) / Li, (A2 - X2) / Li
        so, co = X1 / Lo, X2 / Lo
        ai, ao = math.atan2(si, ci), math.atan2(so, co)
        Qi, Qo = KI * max(di, 0.0) ** 1.5, KO * max(do, 0.0) ** 1.5
        Fc, Mg = kinematics(ai, ao, w, full)[:2] if w else (0.0, 0.0)
        eq = [(a1 - X1) ** 2 + (A2 - X2) ** 2 - Li ** 2, X1 ** 2 + X2 ** 2 - Lo ** 2,
              Qi * si - Qo * so + Mg / D * (li * ci - lo * co),
              Qi * ci - Qo * co - Mg / D * (li * si - lo * so) + Fc]
        if thrust is not None:
            eq.append(Qi * si + li * Mg / D * ci - thrust)
        return eq, (ai, ao, Qi, Qo, Fc, Mg, a1)

    scale = np.array([1e-8, 1e-8, 1e2, 1e2, 1e2])
    x0 = np.array(start if start is not None else
                  [GO * math.sin(A0), GO * math.cos(A0), 1e-6, 1e-6, BD * math.sin(A0) + 2e-6])
    n = 4 if thrust is None else 5
    sol = root(lambda x: np.array(parts(x)[0]) / scale[:n], x0[:n], method="hybr", tol=1e-15)
    assert np.max(np.abs(np.array(parts(sol.x)[0]) / scale[:n])) < 1e-9, sol.message
    return parts(sol.x)[1], sol.x


@pytest.mark.parametrize("full", [False, True], ids=["outer_race_control", "full"])
def test_position_preloaded_ball_against_hand_calculation(full):
    b = bearing(model="full" if full else "outer_race_control")
    A1 = BD * math.sin(A0) + 0.5 * 21e-6
    start = None
    for rpm in (10000.0, 20000.0):  # one ball at two speeds
        (ai, ao, Qi, Qo, Fc, Mg, _), start = hand_ball(rpm * RPM, full, A1=A1, start=start)
        st = b.solve(np.zeros(5), rpm * RPM)
        assert np.max(np.abs(st.displacement)) < 1e-15
        assert math.radians(st.contact_angle_inner_deg[0, 0]) == pytest.approx(ai, rel=1e-8)
        assert math.radians(st.contact_angle_outer_deg[0, 0]) == pytest.approx(ao, rel=1e-8)
        assert st.element_load_inner_N[0, 0] == pytest.approx(Qi, rel=1e-7)
        assert st.element_load_outer_N[0, 0] == pytest.approx(Qo, rel=1e-7)
        assert st.centrifugal_force_N[0, 0] == pytest.approx(Fc, rel=1e-8)
        assert st.gyroscopic_moment_Nm[0, 0] == pytest.approx(Mg, rel=1e-7)
        assert st.row_axial_load_N[0] == pytest.approx(Z * (Qi * math.sin(ai) + (Mg / D if full else 0.0)
                                                            * math.cos(ai)), rel=1e-7)


def test_spring_preloaded_ball_against_hand_calculation():
    b = bearing(preload={"kind": "spring", "axial_N": 250.0})
    start = None
    for rpm in (5000.0, 15000.0):
        (ai, ao, Qi, Qo, Fc, Mg, _), start = hand_ball(rpm * RPM, False, thrust=250.0 / Z, start=start)
        st = b.solve(np.zeros(5), rpm * RPM)
        for row in (0, 1):
            assert math.radians(st.contact_angle_inner_deg[row, 0]) == pytest.approx(ai, rel=1e-8)
            assert math.radians(st.contact_angle_outer_deg[row, 0]) == pytest.approx(ao, rel=1e-8)
            assert st.element_load_inner_N[row, 0] == pytest.approx(Qi, rel=1e-7)
            assert st.element_load_outer_N[row, 0] == pytest.approx(Qo, rel=1e-7)


def test_gyroscopic_couple_direction_in_3d():
    """Ball at psi = 0 of row 0 (thrust +z): x radial, z axial.  From the 3-D kinematics (no spin at
    the outer contact, no slip at both contact centres) the rate of the ball's angular momentum is
    dH/dt = w_c e_z x (J w_ball); the model's friction force at the outer contact must supply it."""
    b = bearing()
    w = 18000.0 * RPM
    st = b.solve(np.zeros(5), w)
    ai, ao = math.radians(st.contact_angle_inner_deg[0, 0]), math.radians(st.contact_angle_outer_deg[0, 0])
    no = np.array([math.cos(ao), 0.0, math.sin(ao)])  # ball centre -> outer contact
    ni = np.array([math.cos(ai), 0.0, math.sin(ai)])  # inner contact -> ball centre
    rc = 0.5 * DM  # ball centre radius (pitch circle)
    ez = np.array([0.0, 0.0, 1.0])
    # unknowns: w_x, w_z (ball, absolute) and w_c; pure rolling at both contact centres along y
    ro, ri = 0.5 * D * no, -0.5 * D * ni
    M = np.array([
        [no[0], no[2], 0.0],                           # (w_ball - w_outer) . n_o = 0, outer ring fixed
        [-ro[2], ro[0], rc],                           # v_y(centre) + (w x r_o)_y = 0, (w x r)_y = w_z r_x - w_x r_z
        [-ri[2], ri[0], rc],                           # ... = w (rc + r_i,x) at the inner contact
    ])
    rhs = np.array([0.0, 0.0, w * (rc + ri[0])])
    wx, wz, wc = np.linalg.solve(M, rhs)
    torque = wc * np.cross(ez, J * np.array([wx, 0.0, wz]))
    Mg = st.gyroscopic_moment_Nm[0, 0]
    assert abs(torque[1]) == pytest.approx(Mg, rel=1e-9)  # the model's M_g = J w_R w_c sin(beta)
    # model: friction on the ball at the outer contact, (axial, radial) = -(2 M_g / D)(cos a_o, -sin a_o)
    F = -(2.0 * Mg / D) * np.array([-math.sin(ao), 0.0, math.cos(ao)])  # (x = radial, z = axial)
    assert np.cross(ro, F) == pytest.approx(torque, rel=1e-9, abs=1e-12 * abs(Mg))


SPEEDS = np.array([0.0, 2500.0, 5000.0, 10000.0, 20000.0])


@pytest.mark.parametrize("preload", [{"kind": "position", "axial_um": 21.0}, {"kind": "spring", "axial_N": 250.0}],
                         ids=["position", "spring"])
def test_speed_trends_of_the_pair(preload):
    """Outer contact angle falls and inner rises with speed; the outer contact carries the inner load
    plus about the centrifugal force; axial stiffness falls from rest to 5000 rpm; a spring preload
    keeps the axial load, a position preload gains thrust from the centrifugal force."""
    b = bearing(preload=preload)
    states = [b.solve(np.zeros(5), n * RPM) for n in SPEEDS]
    ai = np.array([s.contact_angle_inner_deg[0, 0] for s in states])
    ao = np.array([s.contact_angle_outer_deg[0, 0] for s in states])
    assert np.all(np.diff(ao) < 0) and np.all(np.diff(ai) > 0)
    for s in states[1:]:
        gap = s.element_load_outer_N[0, 0] - s.element_load_inner_N[0, 0]
        assert 0.85 * s.centrifugal_force_N[0, 0] < gap < 1.15 * s.centrifugal_force_N[0, 0]
    kzz = np.array([s.stiffness[2, 2] for s in states])
    assert kzz[1] < kzz[0] and kzz[2] < kzz[1]
    thrust = np.array([s.row_axial_load_N for s in states])
    if preload["kind"] == "spring":
        assert np.allclose(thrust, 250.0, rtol=1e-10)
    else:
        assert np.all(np.diff(thrust[:, 0]) > 0)
