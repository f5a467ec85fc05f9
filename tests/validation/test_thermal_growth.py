"""Thermal, fit and centrifugal growth (spindlesim.thermal.growth, growth_bearings; the families' bearings/*/growth, thermal) against hand calculations.

- Free rings: the textbook change of a radial bearing's diametral clearance, d_o e_o - d_i e_i - 2 D e_b
  (Harris and Kotzalas 2007, Essential Concepts, "Interference fitting and clearance"), and the exact
  groove-centre form 2 (dA0 cos a0 - dA_r) for an angular-contact bearing.
- A position-preloaded DB pair with the inner ring 10 K warmer than the outer: the preload of each row by hand
  (every ball a series Hertz spring along the grown groove-centre vector: Q = K_n (|A| - A0)^1.5, thrust
  Z Q A_a / |A|), against the full ball model built with the grown geometry; and the first-order estimate
  through dA_a = dA_r / tan(a).
- Lame's thick cylinders and the rotating disc (Timoshenko and Goodier) in closed form; the fit-loss speed.
- Trends: Si3N4 balls grow less, the preload rises less; DF is more sensitive than DB; O vs X across a spindle.
"""

import math

import numpy as np
import pytest

from spindlesim.bearings.ball.bearing import BallBearing, Preload
from spindlesim.bearings.ball.geometry import ball_geometry
from spindlesim.bearings.ball.growth import SpeedGrowth, at_temperature, axial_equivalent_of_radial, ball_bearing_growth
from spindlesim.bearings.dtrb.thermal import dtrb_preload_change
from spindlesim.bearings.roller.thermal import roller_operating_clearance
from spindlesim.contact.hertz import point_contact_constant
from spindlesim.thermal.growth import (BEARING_STEEL, SI3N4, ThermoElastic, fit_pressure, free_growth,
                                       inner_fit_loss_speed_rad_s, inner_ring_fit, outer_ring_fit,
                                       rotating_disc_radial_displacement, shaft_housing_axial_growth, thermal_strain)
from spindlesim.thermal.growth_bearings import BearingTemperatures, Mounting

from ..unit.test_ball_section import bearing

RPM = math.pi / 30.0
A = 11.5e-6
HOT = BearingTemperatures(inner_ring_C=40.0, outer_ring_C=30.0, rolling_elements_C=35.0, reference_C=20.0)


def test_free_growth_and_strain():
    assert free_growth(0.1, A, 70.0) == pytest.approx(0.1 * A * 50.0, rel=1e-14)
    assert thermal_strain(A, 20.0) == 0.0
    with pytest.raises(ValueError, match="absolute zero"):
        thermal_strain(A, -300.0)
    with pytest.raises(ValueError, match="negative"):
        thermal_strain(-1e-6, 30.0)
    with pytest.raises(ValueError, match="thermal expansion"):
        ThermoElastic(208e9, 0.3, 7850.0, -1e-6)


def test_deep_groove_clearance_of_free_rings_by_hand():
    """Deep groove (a0 = 0), 20 um clearance: P_d' = P_d + d_o e_o - d_i e_i - 2 D e_b exactly."""
    g = ball_geometry(balls=9, ball_diameter_m=12.7e-3, pitch_diameter_m=70e-3, contact_angle_deg=0.0,
                      inner_conformity=0.52, outer_conformity=0.53, clearance_m=20e-6)
    gr = ball_bearing_growth(g, Preload(), HOT)
    D, dm = 12.7e-3, 70e-3
    # raceway (groove bottom) diameters of the model's reference state
    R_oi = g.inner_centre_radius_m
    d_i = 2.0 * (R_oi - 0.52 * D)
    d_o = 2.0 * (R_oi - g.reference_radial_m + 0.53 * D)
    assert d_o - d_i - 2 * D == pytest.approx(20e-6, rel=1e-9)
    hand = 20e-6 + d_o * A * 10.0 - d_i * A * 20.0 - 2 * D * A * 15.0
    assert gr.clearance_m == pytest.approx(hand, rel=1e-12)
    assert gr.clearance_m * 1e6 == pytest.approx(11.95, abs=0.01)   # 20 um -> 11.95 um


def test_angular_contact_clearance_by_hand_and_uniform_growth_scales_everything():
    b = bearing()  # 7014C-size DB pair, 21 um position preload
    g = b.geometry
    D, fi, fo, a0 = g.ball_diameter_m, 0.52, 0.53, math.radians(15.0)
    R_oi = g.inner_centre_radius_m
    R_oo = R_oi - g.reference_radial_m
    ei, eo, eb = A * 20.0, A * 10.0, A * 15.0
    dA0 = fi * D * ei + fo * D * eo - D * eb
    dAr = R_oi * ei - R_oo * eo
    gr = ball_bearing_growth(g, b.preload, HOT)
    assert gr.clearance_m == pytest.approx(2.0 * (dA0 * math.cos(a0) - dAr), rel=1e-10)
    assert gr.clearance_m * 1e6 == pytest.approx(-10.35, abs=0.01)
    # uniform temperature, one material: every length scales by (1 + e), the preload offset too
    uni = ball_bearing_growth(g, b.preload, BearingTemperatures.uniform(70.0))
    e = A * 50.0
    assert uni.clearance_m == pytest.approx(0.0, abs=1e-15)
    assert uni.ball_diameter_m == pytest.approx(D * (1 + e), rel=1e-14)
    assert uni.pitch_diameter_m == pytest.approx(g.pitch_diameter_m * (1 + e), rel=1e-12)
    assert uni.inner_conformity == pytest.approx(fi, rel=1e-13)
    assert uni.row_offset_change_m == pytest.approx([10.5e-6 * e] * 2, rel=1e-8)


def _hand_row_thrust(g2, c_row, E_star):
    """Each ball a series Hertz spring along the groove-centre vector at rest (Jones; docs/theory.md)."""
    D, dm = g2.ball_diameter_m, g2.pitch_diameter_m
    A0 = (g2.inner_conformity + g2.outer_conformity - 1.0) * D
    Aa = A0 * math.sin(g2.contact_angle_rad) + c_row
    Ar = A0 * math.cos(g2.contact_angle_rad) - 0.5 * g2.clearance_m
    L = math.hypot(Aa, Ar)
    af = g2.mounted_angle_rad
    gam = D * math.cos(af) / dm
    ki = point_contact_constant((2 / D) / (1 - gam), (2 - 1 / g2.inner_conformity) / D, E_star)
    ko = point_contact_constant((2 / D) / (1 + gam), (2 - 1 / g2.outer_conformity) / D, E_star)
    Kn = (ki ** (-2 / 3) + ko ** (-2 / 3)) ** -1.5
    return g2.balls * Kn * (L - A0) ** 1.5 * Aa / L


@pytest.mark.parametrize("ball", [BEARING_STEEL, SI3N4], ids=["steel", "Si3N4"])
def test_db_pair_preload_from_an_inner_outer_temperature_difference(ball):
    b = bearing() if ball is BEARING_STEEL else bearing(
        ball_material={"E_GPa": 310.0, "poisson": 0.26, "density_kg_m3": 3200.0})
    g2, pre2, gr = at_temperature(b.geometry, b.preload, HOT, BEARING_STEEL, ball)
    model = BallBearing(g2, pre2).solve(np.zeros(5), 0.0).row_axial_load_N
    hand = _hand_row_thrust(g2, pre2.row_offsets(2)[0], g2.E_star_Pa)
    assert model.tolist() == pytest.approx([hand, hand], rel=1e-9)
    # the engineering estimate: the radial change acts as an axial one (same |A|, dA_r / tan(a) to first
    # order) on the bearing as made; it ignores that the contact angle falls, and overestimates the thrust
    # by 9 % (steel) and 5 % (Si3N4) here
    g = b.geometry
    dAa = gr.row_offset_change_m[0] + axial_equivalent_of_radial(gr.radial_change_m - gr.groove_distance_change_m,
                                                                 g.reference_axial_m + 10.5e-6,
                                                                 g.reference_radial_m)
    est = _hand_row_thrust(g, 10.5e-6 + dAa, g.E_star_Pa)
    assert 1.03 < est / hand < 1.12
    rest = b.solve(np.zeros(5), 0.0).row_axial_load_N[0]
    rise = hand / rest
    if ball is BEARING_STEEL:
        assert rise == pytest.approx(1092.2 / 254.18, rel=1e-3)     # 254 N -> 1092 N for 10 K
    else:
        assert rise < 0.75 * 1092.2 / 254.18 and hand == pytest.approx(905.0, rel=1e-3)  # hybrid: 301 -> 905 N


def test_axial_equivalent_of_radial_first_order():
    Aa, Ar = 1e-4, 4e-4
    assert axial_equivalent_of_radial(1e-8, Aa, Ar) == pytest.approx(1e-8 * Ar / Aa, rel=1e-3)
    # exact: |A| kept
    d = axial_equivalent_of_radial(3e-6, Aa, Ar)
    assert math.hypot(Aa + d, Ar) == pytest.approx(math.hypot(Aa, Ar + 3e-6), rel=1e-15)


def test_df_is_more_sensitive_than_db_to_a_warm_inner_ring():
    """In DB the inner rings' axial growth moves their grooves towards the outer ones' (less preload); in
    DF away from them (more): the classic reason back-to-back spindle sets tolerate warm shafts better."""
    out = {}
    for arr in ("DB", "DF"):
        b = bearing(arrangement=arr)
        g2, pre2, gr = at_temperature(b.geometry, b.preload, HOT)
        out[arr] = (gr.row_offset_change_m[0], BallBearing(g2, pre2).solve(np.zeros(5), 0.0).row_axial_load_N[0])
    assert out["DB"][0] < 0.0 < out["DF"][0]
    assert out["DF"][1] > out["DB"][1]


def test_lame_fit_closed_forms():
    steel = BEARING_STEEL
    d, c, I = 70e-3, 78e-3, 10e-6
    # solid shaft of the ring's material: the raceway grows by I d / c (Harris and Kotzalas' rule)
    fit = inner_ring_fit(I, d, c, steel, 0.0, steel)
    assert fit.raceway_change_m == pytest.approx(I * d / c, rel=1e-12)
    # hollow shaft, other material: p by hand
    shaft = ThermoElastic(200e9, 0.29, 7800.0, 12e-6)
    a = 30e-3
    p_hand = I / (d * (((c ** 2 + d ** 2) / (c ** 2 - d ** 2) + 0.3) / 208e9
                       + ((d ** 2 + a ** 2) / (d ** 2 - a ** 2) - 0.29) / 200e9))
    assert fit_pressure(I, d, a, shaft, c, steel) == pytest.approx(p_hand, rel=1e-14)
    assert inner_ring_fit(I, d, c, steel, a, shaft).pressure_Pa == pytest.approx(p_hand, rel=1e-14)
    # outer ring in a thick housing contracts; a warmer housing than ring loosens the fit
    D, b_ = 110e-3, 103e-3
    o = outer_ring_fit(8e-6, D, b_, steel, math.inf, BEARING_STEEL)
    p_o = 8e-6 / (D * ((1 + 0.3) / 208e9 + ((D ** 2 + b_ ** 2) / (D ** 2 - b_ ** 2) - 0.3) / 208e9))
    assert o.pressure_Pa == pytest.approx(p_o, rel=1e-14)
    assert o.raceway_change_m == pytest.approx(-2 * p_o * D ** 2 * b_ / (208e9 * (D ** 2 - b_ ** 2)), rel=1e-14)
    loose = outer_ring_fit(8e-6, D, b_, steel, math.inf, BEARING_STEEL, ring_strain=0.0, housing_strain=1e-4)
    assert loose.interference_m == pytest.approx(8e-6 - D * 1e-4, rel=1e-12) and loose.lost and loose.pressure_Pa == 0.0


def test_rotating_disc_closed_forms_and_fit_loss_speed():
    m = BEARING_STEEL
    w = 20000 * RPM
    b = 0.04
    # solid disc edge: rho w^2 b^3 (1 - nu) / (4 E)
    assert rotating_disc_radial_displacement(b, 0.0, 2 * b, m, w) == pytest.approx(
        7850 * w * w * b ** 3 * 0.7 / (4 * 208e9), rel=1e-13)
    # thin ring: hoop stress rho w^2 r^2, u = rho w^2 r^3 / E
    r = 0.04
    thin = rotating_disc_radial_displacement(r, 2 * (r - 1e-5), 2 * (r + 1e-5), m, w)
    assert thin == pytest.approx(7850 * w * w * r ** 3 / 208e9, rel=1e-3)
    # a 70 mm bore ring on a hollow shaft: the fit is exactly lost at the closed-form speed
    I, d, c, a = 3e-6, 70e-3, 77.3e-3, 30e-3
    wl = inner_fit_loss_speed_rad_s(I, d, c, m, a, m)
    assert inner_ring_fit(I, d, c, m, a, m, speed_rad_s=wl).interference_m == pytest.approx(0.0, abs=1e-15)
    assert wl / RPM == pytest.approx(9941, rel=1e-3)
    assert not inner_ring_fit(I, d, c, m, a, m, speed_rad_s=0.9 * wl).lost
    assert inner_ring_fit(I, d, c, m, a, m, speed_rad_s=1.1 * wl).lost


def test_speed_growth_of_a_free_inner_ring_is_the_disc_formula():
    """Above the fit-loss speed the ring is free: its groove centre moves with the raceway by u(c) of the
    disc, the A_r the ball model adds at that speed."""
    b = bearing()
    mount = Mounting(bore_m=70e-3, outer_diameter_m=110e-3, shaft_bore_m=30e-3)
    sg = SpeedGrowth(b.geometry, BearingTemperatures.uniform(20.0), BEARING_STEEL, mount)
    g = b.geometry
    c = 2.0 * (g.inner_centre_radius_m - 0.52 * g.ball_diameter_m)
    w = 18000 * RPM
    assert sg(w) == pytest.approx(rotating_disc_radial_displacement(0.5 * c, 70e-3, c, BEARING_STEEL, w), rel=1e-12)
    assert sg.fit(w).interference_m < 0.0 and sg(0.0) == 0.0


def test_shaft_against_housing_across_the_spindle():
    L = 0.4
    o = shaft_housing_axial_growth(L, 11.5e-6, 45.0, 10.5e-6, 30.0, "O")
    rel = L * (11.5e-6 * 25.0 - 10.5e-6 * 10.0)
    assert o.relative_m == pytest.approx(rel, rel=1e-14)          # 73 um
    assert o.preload_offset_change_m == pytest.approx(-rel, rel=1e-14)
    assert shaft_housing_axial_growth(L, 11.5e-6, 45.0, 10.5e-6, 30.0, "X").preload_offset_change_m == pytest.approx(rel)
    fl = shaft_housing_axial_growth(L, 11.5e-6, 45.0, 10.5e-6, 30.0, "locating_floating")
    assert fl.preload_offset_change_m == 0.0 and fl.float_m == pytest.approx(rel)


def test_dtrb_preload_change():
    from spindlesim.bearings.dtrb.geometry import dtrb_geometry

    g = dtrb_geometry(rollers_per_row=20, cup_angle_deg=15.64, pitch_diameter_m=70e-3, large_end_diameter_m=10e-3,
                      roller_length_m=14e-3, large_end_offset_m=18e-3, crown_radius_m=2.68)
    uni = dtrb_preload_change(g, BearingTemperatures.uniform(80.0))
    assert abs(uni.preload_change_m) < 1e-15
    warm = dtrb_preload_change(g, HOT)
    assert warm.preload_change_m > 0.0
    # first order in the strain difference
    hotter = dtrb_preload_change(g, BearingTemperatures(60.0, 30.0, 45.0))
    assert hotter.preload_change_m == pytest.approx(3.0 * warm.preload_change_m, rel=1e-9)


def test_cylindrical_roller_clearance_by_hand():
    di, do, Dw = 18.738e-3, 28.262e-3, 4.762e-3
    rc = roller_operating_clearance(di, do, Dw, HOT)
    P0 = do - di - 2 * Dw
    assert rc.diametral_clearance_m == pytest.approx(P0 + do * A * 10 - di * A * 20 - 2 * Dw * A * 15, rel=1e-12)
    assert rc.radial_clearance_m == pytest.approx(0.5 * rc.diametral_clearance_m)
