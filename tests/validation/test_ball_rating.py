"""Rating lives against hand computations from ISO 281:2007 and ISO/TS 16281:2008.

ISO 281 (radial ball bearings, D_w <= 25.4 mm): C_r = b_m f_c (i cos a)^0.7 Z^(2/3) D_w^1.8 [N, mm],
b_m = 1.3 (Table 2), f_c from Table 1 (column: single-row radial and single/double-row angular
contact groove ball bearings) at D_w cos(a) / D_pw, linear interpolation; a pair as one double-row
bearing, C = 2^0.7 C_row; P = X F_r + Y F_a from Table 3 (a = 15 deg: e, Y against
i f_0 F_a / C_0r = F_a / (Z D_w^2 cos a) since C_0r = f_0 i Z D_w^2 cos a, ISO 76); L_10 = (C/P)^3.
"""

import math

import numpy as np
import pytest

from spindlesim.bearings.ball import build

from ..unit.test_ball_section import RPM, bearing, entry


def test_iso281_rating_and_life_of_the_default_pair_by_hand():
    b = bearing()
    # C of one 7014C-size bearing: Z 18, D_w 12.7 mm, D_pw 90 mm, 15 deg
    x = 12.7 * math.cos(math.radians(15.0)) / 90.0          # 0.13630
    fc = 58.2 + (x - 0.13) / 0.01 * (58.8 - 58.2)          # Table 1: 0.13 -> 58.2, 0.14 -> 58.8
    C_row = 1.3 * fc * math.cos(math.radians(15.0)) ** 0.7 * 18 ** (2 / 3) * 12.7 ** 1.8
    assert C_row == pytest.approx(49526.2, rel=1e-6)
    C_pair = 2 ** 0.7 * C_row
    # Fr = 1000 N, Fa = 500 N: Table 3, 15 deg, double row
    arg = 500.0 / (18 * 12.7 ** 2 * math.cos(math.radians(15.0)))  # 0.17827
    t = (arg - 0.178) / (0.357 - 0.178)
    e = 0.38 + t * (0.40 - 0.38)
    assert 500.0 / 1000.0 > e
    Y2 = 2.39 + t * (2.28 - 2.39)
    P = 0.72 * 1000.0 + Y2 * 500.0
    L10 = (C_pair / P) ** 3
    st = b.solve(np.array([1000.0, 0.0, 500.0, 0.0, 0.0]), 6000.0 * RPM)
    lv = st.lives
    assert lv.C_row_N == pytest.approx(C_row, rel=1e-12)
    assert lv.C_set_N == pytest.approx(C_pair, rel=1e-12)
    assert lv.equivalent_load_N == pytest.approx(P, rel=1e-12)
    assert st.life_L10_iso281_Mrev == pytest.approx(L10, rel=1e-12)


def test_iso281_catalogue_rating_override_and_pure_radial_load():
    b = bearing(dynamic_load_rating_N=48000.0)
    st = b.solve(np.array([2000.0, 0.0, 0.0, 0.0, 0.0]))
    # Fa/Fr = 0 <= e: double row P = Fr; C of the pair = 2^0.7 x catalogue C
    assert st.life_L10_iso281_Mrev == pytest.approx((2 ** 0.7 * 48000.0 / 2000.0) ** 3, rel=1e-12)


@pytest.mark.parametrize("R, a1_table", [(90.0, 1.0), (95.0, 0.64), (99.0, 0.25), (99.9, 0.093)])
def test_reliability_factor_reproduces_iso281_table(R, a1_table):
    st = bearing(reliability_percent=R).solve(np.array([1000.0, 0.0, 0.0, 0.0, 0.0]))
    assert st.lives.a1 == pytest.approx(a1_table, abs=0.005)  # the table prints two significant digits
    assert st.lives.Ln_iso281_Mrev == pytest.approx(st.lives.a1 * st.life_L10_iso281_Mrev, rel=1e-12)


def test_deep_groove_equivalent_load_by_hand():
    """Single-row deep-groove bearing, Fa = 600 N, Fr = 1000 N: f_0 Fa / C_0r = Fa / (Z D_w^2) = 0.2067
    (Table 3: 0.172 -> e 0.19, Y 2.30; 0.345 -> e 0.22, Y 1.99); Fa/Fr > e: P = 0.56 Fr + Y Fa."""
    b = build(entry(contact_angle_deg=0.0, inner_conformity=0.52, outer_conformity=0.52))
    arg = 600.0 / (18 * 12.7 ** 2)
    t = (arg - 0.172) / (0.345 - 0.172)
    P = 0.56 * 1000.0 + (2.30 + t * (1.99 - 2.30)) * 600.0
    st = b.solve(np.array([1000.0, 0.0, 600.0, 0.0, 0.0]))
    assert st.lives.equivalent_load_N == pytest.approx(P, rel=1e-12)


@pytest.mark.parametrize("Z, Dw, Dpw", [(9, 12.7, 65.0), (18, 12.7, 90.0), (12, 15.875, 100.0)])
def test_reference_life_matches_iso281_for_a_radially_loaded_zero_clearance_bearing(Z, Dw, Dpw):
    """ISO/TS 16281 is built on the same Lundberg-Palmgren theory as ISO 281: for a rigid zero-clearance
    deep-groove bearing under pure radial load (half the raceway loaded, the case C_r is defined for)
    the reference rating life from the load distribution must come back to ISO 281's (C/F_r)^3.
    Averaged over two cage positions (ball on / between the load line)."""
    b = build(entry(balls=Z, ball_diameter_mm=Dw, pitch_diameter_mm=Dpw, contact_angle_deg=0.0,
                    inner_conformity=0.52, outer_conformity=0.53))
    Fr = 3000.0
    ratios = []
    for phi in (0.0, math.pi / Z):
        st = b.solve(np.array([Fr, 0.0, 0.0, 0.0, 0.0]), 0.0, phi)
        ratios.append(st.life_L10r_iso16281_Mrev / st.life_L10_iso281_Mrev)
    assert np.mean(ratios) == pytest.approx(1.0, abs=0.01)


def test_reference_life_by_hand_from_the_load_distribution():
    b = bearing()
    st = b.solve(np.array([3000.0, 0.0, 800.0, 0.0, 20.0]), 12000.0 * RPM)
    lv = st.lives
    g = 12.7 * math.cos(math.radians(15.0)) / 90.0
    ratio = 1.044 * ((1 - g) / (1 + g)) ** 1.72 * (0.52 * (2 * 0.53 - 1) / (0.53 * (2 * 0.52 - 1))) ** 0.41
    base = lv.C_row_N / (18 * math.cos(math.radians(15.0)))
    Qci = base / 0.407 * (1 + ratio ** (10 / 3)) ** 0.3
    Qce = base / 0.389 * (1 + ratio ** (-10 / 3)) ** 0.3
    Qei = np.cbrt(np.mean(st.element_load_inner_N ** 3, axis=1))  # inner ring rotates: cubic mean
    Qee = np.mean(st.element_load_outer_N ** (10 / 3), axis=1) ** 0.3  # outer ring stationary
    L = np.sum((Qei / Qci) ** (10 / 3) + (Qee / Qce) ** (10 / 3)) ** -0.9
    assert lv.Q_ci_N == pytest.approx(Qci, rel=1e-12) and lv.Q_ce_N == pytest.approx(Qce, rel=1e-12)
    assert st.life_L10r_iso16281_Mrev == pytest.approx(L, rel=1e-12)


def test_preload_and_speed_shorten_the_reference_life_only():
    """ISO 281 sees only Fr, Fa; the reference life sees the preload and the centrifugal loads."""
    load = np.array([2000.0, 0.0, 0.0, 0.0, 0.0])
    light, heavy = bearing().solve(load), bearing(preload={"kind": "position", "axial_um": 40.0}).solve(load)
    assert light.life_L10_iso281_Mrev == pytest.approx(heavy.life_L10_iso281_Mrev, rel=1e-12)
    assert heavy.life_L10r_iso16281_Mrev < light.life_L10r_iso16281_Mrev
    fast = bearing().solve(load, 15000.0 * RPM)
    assert fast.life_L10r_iso16281_Mrev < light.life_L10r_iso16281_Mrev
