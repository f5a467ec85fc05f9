"""A single row under a combined load with its tilt held (as on a shaft) or free, against a brute-force
equilibrium written here (issue 23, item 7: 33.5 um with the tilt free, about 6.3 um with it held).

Reference (at rest, independent of the model's code): the rigid inner ring moves by (x, y, z) and turns by
(theta_x, theta_y); the inner groove curvature centre of ball j, at p_j = (R_i cos psi_j, R_i sin psi_j, z_c)
with R_i = d_m/2 + (f_i - 1/2) D cos a0 and z_c = (f_i - 1/2) D sin a0 (Harris and Kotzalas 2007, Advanced
Concepts, ch. 1 and 3: the groove-centre loci), moves by u_j = (x, y, z) + theta x p_j.  The groove-centre
vector of the ball becomes A_j = (A0 sin a0 + u_z, A0 cos a0 + u_r) (axial, radial; A0 = (f_i + f_o - 1) D),
the ball two Hertz contacts in series along it, Q_j = K_n <|A_j| - A0>^1.5 (K_n from the exact Hertz
constants of both contacts), pushing the inner ring back along -A_j/|A_j| at p_j.  Equilibrium: the ball
forces and their moments about the bearing centre balance the load on the free DOFs; on a held DOF the
bearing's moment is what the shaft must supply (the holding load).  Solved with scipy's root.
"""

import math

import numpy as np
import pytest
from scipy.optimize import root

from spindlesim.bearings.ball.equilibrium import Held

from ..unit.test_ball_section import RPM, bearing
from .test_ball_closed_forms import series_constant

Z, D, DM, FI, FO, A0 = 18, 12.7e-3, 90e-3, 0.52, 0.53, math.radians(15.0)
BD = (FI + FO - 1.0) * D
KN = series_constant(D, DM, FI, FO, A0)
PSI = 2.0 * math.pi * np.arange(Z) / Z
R_I = 0.5 * DM + (FI - 0.5) * D * math.cos(A0)
Z_C = (FI - 0.5) * D * math.sin(A0)
LOAD = np.array([2000.0, 0.0, 1000.0, 0.0, 0.0])


def single_row(**changes):
    """The default deck's 7014C row alone: no preload unless ``changes`` give one."""
    return bearing(**{**dict(arrangement="single", rows=None, row_spacing_mm=None, preload=None), **changes})


def ball_forces(q):
    """(force [3], moment about the centre [3]) of the balls on the inner ring at q = (x, y, z, tx, ty)."""
    x, y, z, tx, ty = q
    er = np.stack([np.cos(PSI), np.sin(PSI), np.zeros(Z)], axis=1)
    p = R_I * er + np.array([0.0, 0.0, Z_C])
    u = np.array([x, y, z]) + np.cross(np.array([tx, ty, 0.0]), p)
    A = np.stack([BD * math.sin(A0) + u[:, 2], BD * math.cos(A0) + np.sum(u * er, axis=1)], axis=1)
    L = np.linalg.norm(A, axis=1)
    Q = KN * np.maximum(L - BD, 0.0) ** 1.5
    n = A / L[:, None]
    F = -(Q * n[:, 0])[:, None] * np.array([0.0, 0.0, 1.0]) - (Q * n[:, 1])[:, None] * er
    return F.sum(axis=0), np.cross(p, F).sum(axis=0)


def brute_force(load, tilt_held: bool):
    """q and the holding moment (Mx, My) with the tilt held at 0, or with it free."""
    n = 3 if tilt_held else 5

    def residual(v):
        q = np.concatenate([v[:3] * 1e-6, np.zeros(2) if tilt_held else v[3:] * 1e-3])
        F, M = ball_forces(q)
        r = list(F + load[:3])
        if not tilt_held:
            r += list(M[:2] / R_I + load[3:] / R_I)
        return np.array(r)

    v0 = np.array([5.0, 0.0, 20.0, 0.0, 1.0])[:n]
    sol = root(residual, v0, method="hybr", tol=1e-14)
    assert sol.success and np.max(np.abs(residual(sol.x))) < 1e-8, sol.message
    q = np.concatenate([sol.x[:3] * 1e-6, np.zeros(2) if tilt_held else sol.x[3:] * 1e-3])
    _, M = ball_forces(q)
    return q, -M[:2]


def test_tilt_held_against_brute_force():
    q_ref, hold_ref = brute_force(LOAD, tilt_held=True)
    st = single_row().solve(LOAD, 0.0, held=Held.of(theta_x=0.0, theta_y=0.0))
    assert st.held == (False, False, False, True, True)
    assert st.displacement[:3] == pytest.approx(q_ref[:3], rel=1e-7, abs=1e-13)
    assert np.all(st.displacement[3:] == 0.0)
    assert st.holding_load[3:] == pytest.approx(hold_ref, rel=1e-7, abs=1e-9)
    assert np.all(st.holding_load[:3] == 0.0)
    assert st.displacement[0] * 1e6 == pytest.approx(6.28, abs=0.01)   # issue 23: "about 6.3 um"
    assert st.holding_load[4] == pytest.approx(-27.06, abs=0.01)       # the moment the shaft supplies [N m]
    assert st.applied_load() == pytest.approx(LOAD)
    assert st.load == pytest.approx(LOAD + st.holding_load)


def test_tilt_free_against_brute_force():
    q_ref, hold_ref = brute_force(LOAD, tilt_held=False)
    st = single_row().solve(LOAD, 0.0)
    assert st.displacement == pytest.approx(q_ref, rel=1e-7, abs=1e-13)
    assert st.displacement[0] * 1e6 == pytest.approx(33.52, abs=0.01)   # issue 23: 33.5 um
    assert st.displacement[4] * 1e3 == pytest.approx(2.245, abs=0.001)  # 2.2 mrad
    assert np.all(st.holding_load == 0.0) and np.all(hold_ref == pytest.approx(0.0, abs=1e-9))
    assert st.reaction[3:] == pytest.approx([0.0, 0.0], abs=1e-9)       # no moment on the free ring


def test_held_displacement_carries_the_holding_load():
    """Displacement control: z held at 20 um with Fx 2 kN; the holding force is the bearing's own axial reaction
    there (state_at the same q), and holding every DOF needs no iteration."""
    b = single_row()
    load = np.array([2000.0, 0.0, 0.0, 0.0, 0.0])
    st = b.solve(load, 5000.0 * RPM, held=Held.of(z=20e-6, theta_x=0.0, theta_y=0.0))
    assert st.displacement[2] == 20e-6
    at = b.at(st.displacement, 5000.0 * RPM)
    assert st.holding_load[2] == pytest.approx(-at.reaction[2], rel=1e-12)
    assert st.holding_load[3:] == pytest.approx(-at.reaction[3:], rel=1e-12)
    assert at.reaction[:2] == pytest.approx(-load[:2], rel=1e-9, abs=1e-6)
    q = np.array([5e-6, -2e-6, 15e-6, 1e-4, -2e-4])
    allheld = b.solve(np.zeros(5), 0.0, held=Held.of(**dict(zip(("x", "y", "z", "theta_x", "theta_y"), q))))
    assert allheld.iterations == 0 and allheld.displacement == pytest.approx(q, rel=1e-15)
    assert allheld.holding_load == pytest.approx(-b.at(q).reaction, rel=1e-12)


def test_a_load_on_a_held_dof_is_refused():
    with pytest.raises(ValueError, match="theta_y is held"):
        single_row().solve(np.array([2000.0, 0.0, 1000.0, 0.0, 5.0]), held=Held.of(theta_x=0.0, theta_y=0.0))
    spring = single_row(preload={"kind": "spring", "axial_N": 200.0})
    with pytest.raises(ValueError, match="z cannot be held"):
        spring.solve(np.array([0.0, 0.0, 200.0, 0.0, 0.0]), held=Held.of(z=0.0))
