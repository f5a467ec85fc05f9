"""Reynolds solver: complementarity, verified perturbations, symmetries.

Independent checks: the discrete LCP conditions (Cryer 1971), central finite differences
of the full nonlinear (re-solved LCP) force for stiffness and damping, the symmetry of
the damping matrix of a plain bearing (Lund's cross damping terms are equal for any
bearing without tilting pads), and the 3-fold symmetry of a centred 3-lobe bearing.
"""

import math

import numpy as np
import pytest

from spindlesim.bearings.fluidfilm import coefficients as coef
from spindlesim.bearings.fluidfilm.geometry import multilobe_geometry, plain_geometry
from spindlesim.bearings.fluidfilm.reynolds import ReynoldsError, ReynoldsSolver

GRID = (96, 8)  # small grid: these are properties of the discrete problem, any grid


@pytest.fixture(scope="module")
def lobe_solver():
    return ReynoldsSolver(multilobe_geometry(0.07, 0.035, 12e-6, 0.5, 3), *GRID)


def test_complementarity_conditions(lobe_solver):
    X, Y = 0.2, -0.35
    sol = lobe_solver.solve(X, Y)
    A, b = lobe_solver.assemble(X, Y)
    w = A @ sol.pressure - b
    scale = np.abs(b).max()
    assert sol.pressure.min() >= 0.0
    assert w.min() > -1e-9 * scale
    assert np.abs(sol.pressure * w).max() < 1e-9 * scale * sol.pressure.max()
    # both regimes are present: a real cavitation zone and a real full-film zone
    assert 0.2 < sol.full_film.mean() < 0.9
    # clipping the unconstrained (half-Sommerfeld-like) solution is a different answer
    import scipy.sparse.linalg as spla

    clipped = np.maximum(spla.spsolve(A.tocsc(), b), 0.0)
    assert np.abs(clipped - sol.pressure).max() > 0.01 * sol.pressure.max()


@pytest.mark.parametrize("position", [(0.2, -0.35), (-0.1, 0.05)])
def test_stiffness_matches_finite_difference(lobe_solver, position):
    X, Y = position
    sol = lobe_solver.solve(X, Y)
    h = 1e-6
    fd = np.zeros((2, 2))
    for j, d in enumerate(((h, 0.0), (0.0, h))):
        fp = lobe_solver.solve(X + d[0], Y + d[1]).force
        fm = lobe_solver.solve(X - d[0], Y - d[1]).force
        fd[:, j] = (fp - fm) / (2 * h)
    np.testing.assert_allclose(sol.jac_position, fd, atol=1e-4 * np.abs(fd).max())


def test_damping_matches_finite_difference(lobe_solver):
    X, Y = 0.2, -0.35
    sol = lobe_solver.solve(X, Y)
    h = 1e-6
    fd = np.zeros((2, 2))
    for j, d in enumerate(((h, 0.0), (0.0, h))):
        fp = lobe_solver.solve(X, Y, Xdot=d[0], Ydot=d[1]).force
        fm = lobe_solver.solve(X, Y, Xdot=-d[0], Ydot=-d[1]).force
        fd[:, j] = (fp - fm) / (2 * h)
    np.testing.assert_allclose(sol.jac_velocity, fd, atol=1e-4 * np.abs(fd).max())


def test_plain_bearing_damping_is_symmetric():
    sol = ReynoldsSolver(plain_geometry(0.1, 0.05, 1e-4), *GRID).solve(0.55, 0.1)
    B = sol.jac_velocity
    assert B[0, 1] == pytest.approx(B[1, 0], rel=1e-10)
    assert B[0, 1] != pytest.approx(0.0, abs=1e-3 * np.abs(B).max())


def test_centred_three_lobe_is_invariant_under_120_deg():
    geo = multilobe_geometry(0.07, 0.07, 12e-6, 0.5, 3, first_lobe_centre_deg=10.0)
    sol = ReynoldsSolver(geo, *GRID).solve(0.0, 0.0)
    assert np.abs(sol.force).max() < 1e-9 * np.abs(sol.jac_position).max()
    c, s = math.cos(2 * math.pi / 3), math.sin(2 * math.pi / 3)
    R = np.array([[c, -s], [s, c]])
    for J in (sol.jac_position, sol.jac_velocity):
        np.testing.assert_allclose(R @ J @ R.T, J, atol=1e-9 * np.abs(J).max())
        # 3-fold symmetry makes the 2x2 matrices isotropic: [[a, b], [-b, a]]
        assert J[0, 0] == pytest.approx(J[1, 1], rel=1e-8)
        assert J[0, 1] == pytest.approx(-J[1, 0], rel=1e-8, abs=1e-10 * np.abs(J).max())


def test_centred_three_lobe_coefficients_independent_of_orientation():
    """Rotating the lobe pattern rotates nothing for a centred journal (isotropy)."""
    a = ReynoldsSolver(multilobe_geometry(0.07, 0.07, 12e-6, 0.5, 3, orientation="on_lobe"),
                       *GRID).solve(0.0, 0.0)
    b = ReynoldsSolver(multilobe_geometry(0.07, 0.07, 12e-6, 0.5, 3,
                                          orientation="between_lobes"), *GRID).solve(0.0, 0.0)
    np.testing.assert_allclose(a.jac_position, b.jac_position, rtol=1e-8)


def test_journal_touching_the_bore_is_refused():
    solver = ReynoldsSolver(plain_geometry(0.1, 0.05, 1e-4), *GRID)
    with pytest.raises(ReynoldsError):
        solver.solve(0.7, 0.75)


def test_rotating_the_load_rotates_plain_bearing_coefficients():
    """A 360 deg plain bore is axisymmetric: K(load rotated by a) = R(a) K R(a)^T."""
    from spindlesim.bearings.fluidfilm.performance import operating_point

    solver = ReynoldsSolver(plain_geometry(0.05, 0.025, 40e-6), *GRID)
    a = math.radians(35.0)
    R = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    w = np.array([0.0, -2000.0])
    r0 = operating_point(solver, 0.01, 300.0, w)
    r1 = operating_point(solver, 0.01, 300.0, R @ w)
    np.testing.assert_allclose(r1.K_N_m, R @ r0.K_N_m @ R.T, rtol=1e-6, atol=1e-6 * np.abs(r0.K_N_m).max())
    np.testing.assert_allclose(r1.position_m, R @ r0.position_m, rtol=1e-6)
    np.testing.assert_allclose(coef.to_load_frame(r1.K_N_m, R @ w),
                               coef.to_load_frame(r0.K_N_m, w), rtol=1e-6, atol=1.0)


def test_film_heights_from_the_precomputed_part_equal_the_film_formula():
    """The solver splits H = a - (a - 1) cos(theta - centre) - X cos(theta) - Y sin(theta) into a part
    computed once and the journal's part; at any position both give the formula's values exactly."""
    from spindlesim.bearings.fluidfilm.reynolds import _film_at

    geo = multilobe_geometry(0.07, 0.035, 12e-6, 0.5, 3)
    s = ReynoldsSolver(geo, *GRID)
    g = s.grid
    rng = np.random.default_rng(3)
    for _ in range(20):
        r, a = 0.8 * rng.random(), 2 * np.pi * rng.random()
        X, Y = r * np.cos(a), r * np.sin(a)
        Hc, Ha, Hmid = s.film_heights(X, Y)
        assert np.array_equal(Hc, _film_at(geo, g.cf_land, g.cf_theta, X, Y))
        assert np.array_equal(Ha, _film_at(geo, g.af_land, g.af_theta, X, Y))
        assert np.array_equal(Hmid, _film_at(geo, s._mid_land, s._mid_theta, X, Y))


def test_a_journal_touching_at_an_axial_face_only_is_reported_as_touching():
    """A 3-lobe bore (seed 003: preload 0.5) at e/Cb 1.205 towards 80 deg: the film at the axial faces of a lobe's
    minimum is negative (-2.6e-4 Cb) while the circumferential faces and the cell middles still have 4.5e-4 Cb.
    The solver says the journal touches the bore (ReynoldsError, which the equilibrium's line search steps back
    from).  It had solved on with a conductance H^3 < 0 there: here a film of no physical meaning, returned as if
    solved; under an impossible load (2.4 MN on the 70 mm bearing) LAPACK's "leading minor not positive definite",
    a bare LinAlgError out of the thermal equilibrium, where now the search reports that no equilibrium exists."""
    import math

    from spindlesim.bearings.fluidfilm.geometry import multilobe_geometry
    from spindlesim.bearings.fluidfilm.reynolds import ReynoldsError, ReynoldsSolver

    s = ReynoldsSolver(multilobe_geometry(0.069965, 0.069965, 12e-6, 0.5, 3), 96, 8)
    X, Y = 1.205 * math.cos(math.radians(80.0)), 1.205 * math.sin(math.radians(80.0))
    Hc = s._base_cf - X * s._cos_cf - Y * s._sin_cf
    Ha = s._base_af - X * s._cos_af - Y * s._sin_af
    Hm = s._base_mid - X * s._cos_mid - Y * s._sin_mid
    assert Ha.min() < 0 < min(Hc.min(), Hm.min())  # the case: an axial face alone
    with pytest.raises(ReynoldsError, match="touches the bore"):
        s.solve(X, Y)
