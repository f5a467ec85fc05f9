"""DTRB against closed forms and the trends of seed 001 (Figs. 8 and 10).

References:
- Stribeck / Harris & Kotzalas (Rolling Bearing Analysis, 5th ed., 2007, ch. 7): under a pure
  axial load on a tapered row every roller carries Q = Fa / (Z sin alpha) on the cup.
- Harris & Kotzalas, tapered roller force balance: Q_i = Q_o sin(alpha_o + alpha_f) / sin(alpha_i + alpha_f),
  Q_f = Q_o sin(alpha_o - alpha_i) / sin(alpha_i + alpha_f), rib angle alpha_f = 90 deg - theta
  for seed 001's rib normal (-sin theta, cos theta).
- Preloaded pair at rest: each roller's force on the ring lies along the cup normal, so
  KXX = sum_rows (Z/2) k_n cos^2 alpha and KZZ = sum_rows Z k_n sin^2 alpha, k_n = dQ_o/d(normal approach).
"""

import math

import numpy as np
import pytest

from ..unit.test_dtrb_geometry import RPM, bearing


@pytest.mark.parametrize("Fa", [2000.0, 20000.0])
@pytest.mark.parametrize("crown_m", [2.68, math.inf])
def test_pure_axial_load_stribeck(Fa, crown_m):
    b = bearing(preload_um=0.0, crown_radius_m=crown_m, n_slices=20)
    g = b.geometry
    st = b.solve([0.0, 0.0, Fa, 0.0, 0.0])
    Z, a = g.rollers_per_row, g.cup_angle_rad
    assert np.allclose(st.outer_load_N[0], Fa / (Z * math.sin(a)), rtol=1e-9)
    assert np.all(st.outer_load_N[1] == 0.0)  # row 2 lifts off without preload
    # force triangle (Harris & Kotzalas) with alpha_f = 90 deg - theta
    af = 0.5 * math.pi - g.rib_angle_rad
    Qo = st.outer_load_N[0]
    assert np.allclose(st.inner_load_N[0], Qo * math.sin(a + af) / math.sin(g.cone_angle_rad + af), rtol=1e-9)
    assert np.allclose(st.rib_load_N[0], Qo * math.sin(a - g.cone_angle_rad) / math.sin(g.cone_angle_rad + af),
                       rtol=1e-8)
    # and the mirrored load goes to row 2 alone
    st2 = b.solve([0.0, 0.0, -Fa, 0.0, 0.0])
    assert np.allclose(st2.outer_load_N[1], Fa / (Z * math.sin(a)), rtol=1e-9)


@pytest.mark.parametrize("preload_um", [5.0, 40.0])
def test_preloaded_pair_stiffness_closed_form(preload_um):
    """k_n from the roller loads alone (finite difference of Q_o over the preload: a_z = delta0
    moves the cone along Z, whose component on the cup normal is sin(alpha))."""
    b = bearing(preload_um=preload_um)
    g = b.geometry
    Z, a = g.rollers_per_row, g.cup_angle_rad
    h = 1e-3 * preload_um * 1e-6
    Qp = b.with_preload(preload_um * 1e-6 + h).at(np.zeros(5)).outer_load_N[0, 0]
    Qm = b.with_preload(preload_um * 1e-6 - h).at(np.zeros(5)).outer_load_N[0, 0]
    k_n = (Qp - Qm) / (2 * h) / math.sin(a)
    K = b.at(np.zeros(5)).stiffness
    assert K[0, 0] == pytest.approx(2 * (Z / 2) * k_n * math.cos(a) ** 2, rel=1e-5)
    assert K[1, 1] == pytest.approx(2 * (Z / 2) * k_n * math.cos(a) ** 2, rel=1e-5)
    assert K[2, 2] == pytest.approx(2 * Z * k_n * math.sin(a) ** 2, rel=1e-5)
    assert K[2, 2] / K[0, 0] == pytest.approx(2 * math.tan(a) ** 2, rel=1e-7)  # 1e-10 regularisation


def test_stiffness_independent_of_preload_while_row2_is_unloaded():
    """Seed 001 Fig. 8, left part: below the preload that brings row 2 into contact the
    ring simply shifts by delta0 and the stiffness cannot change (exact at zero speed)."""
    b = bearing(n_slices=15)
    load = [0.0, 0.0, 5000.0, 0.0, 0.0]
    s1 = b.with_preload(1e-6).solve(load)
    s2 = b.with_preload(4e-6).solve(load)
    assert s1.loaded_rollers()[1] == 0 and s2.loaded_rollers()[1] == 0
    assert np.allclose(s1.stiffness, s2.stiffness, rtol=1e-7, atol=1e-6 * np.abs(s1.stiffness).max())
    assert s2.displacement[2] == pytest.approx(s1.displacement[2] - 3e-6, abs=1e-12)


def test_seed001_fig8_trend_flat_then_rising():
    """FX = FZ = 5 kN at 3000 rpm, preload 0.1-70 um (seed 001 Fig. 8): KXX and KZZ change
    little while row 2 has unloaded rollers and rise once it is fully loaded."""
    b = bearing(n_slices=15)
    sw = b.preload_sweep(np.array([0.1, 5, 10, 15, 35, 50, 70]) * 1e-6, [5000.0, 0, 5000.0, 0, 0], 3000 * RPM)
    n2 = sw.loaded_rollers[:, 1]
    kxx, kzz = sw.stiffness[:, 0, 0], sw.stiffness[:, 2, 2]
    partial = n2 < 20
    assert partial[:4].all() and not partial[4:].any()
    assert np.ptp(kxx[partial]) < 0.05 * kxx[0] and np.ptp(kzz[partial]) < 0.1 * kzz[0]
    assert np.all(np.diff(kxx[~partial]) > 0) and np.all(np.diff(kzz[~partial]) > 0)
    assert kxx[-1] > 1.5 * kxx[0] and kzz[-1] > 1.5 * kzz[0]


def test_seed001_fig10_trend_soft_stiff_transition():
    """FX 2-20 kN at FZ = 5 kN, delta0 = 30 um, 3000 rpm (seed 001 Fig. 10): KXX first falls as
    rollers unload, then rises as the Hertz stiffening of the loaded rollers wins."""
    b = bearing(preload_um=30.0, n_slices=15)
    fx = np.linspace(2000.0, 20000.0, 10)
    sw = b.load_sweep(0, fx, [0.0, 0, 5000.0, 0, 0], 3000 * RPM)
    kxx = sw.stiffness[:, 0, 0]
    i = int(np.argmin(kxx))
    assert 0 < i < len(fx) - 1
    assert kxx[0] > 1.02 * kxx[i] and kxx[-1] > 1.02 * kxx[i]
    assert sw.loaded_rollers[-1].sum() < sw.loaded_rollers[0].sum()  # unloaded rollers appear


def test_seed001_crowning_trend():
    """Seed 001 section 3-2-2 (Figs. 17-19): a larger crown radius (R = 1300, 2600, 3900 mm,
    straight) gives a stiffer bearing at the same preload (60 um) and load."""
    load = [5000.0, 0.0, 5000.0, 0.0, 0.0]
    kxx = [bearing(preload_um=60.0, crown_radius_m=R, n_slices=20).solve(load).stiffness[0, 0]
           for R in (1.3, 2.6, 3.9, math.inf)]
    assert np.all(np.diff(kxx) > 0)


def test_radial_direction_does_not_matter():
    # 20 rollers: a quarter turn maps the rollers onto each other, so FY gives KYY = KXX under FX
    b = bearing(preload_um=20.0, n_slices=10)
    sx = b.solve([6000.0, 0.0, 3000.0, 0.0, 0.0])
    sy = b.solve([0.0, 6000.0, 3000.0, 0.0, 0.0])
    assert sy.stiffness[1, 1] == pytest.approx(sx.stiffness[0, 0], rel=1e-8)
    assert sy.stiffness[0, 0] == pytest.approx(sx.stiffness[1, 1], rel=1e-8)
    assert sy.displacement[1] == pytest.approx(sx.displacement[0], rel=1e-8)
    assert np.allclose(np.roll(sy.outer_load_N, -5, axis=1), sx.outer_load_N, rtol=1e-7)
