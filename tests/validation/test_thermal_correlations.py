"""Heat-transfer correlations against published values and their limits (issue 22;
docs/validation.md "Spindle thermal network")."""

from __future__ import annotations

import math

import numpy as np
import pytest

from spindlesim.bearings.conductance import (ball_bearing_conductances, contact_ellipse_unit,
                                             ellipse_constriction_resistance, race_radii)
from spindlesim.thermal import convection as cv
from spindlesim.thermal.conduction import contact_conductance_cmy, cylindrical_shell_conductance
from spindlesim.thermal.motor import MotorRating, motor_losses, windage_torque_coefficient
from spindlesim.thermal.properties import air, fluid, water


def test_water_against_iapws():
    """IAPWS-95 / IAPWS 2008 / IAPWS 2011 at 25 degC and 0.1 MPa (values of the formulations):
    rho 997.05 kg/m3, mu 0.8900 mPa s, k 0.6065 W/(m K), c_p 4181.3 J/(kg K); 35 degC: 994.03,
    0.7191 mPa s, 0.6217, 4179.3.  25 and 35 degC are mid-points of the table (worst case)."""
    for t, ref in ((25.0, (997.048, 8.90022e-4, 0.606516, 4181.31)), (35.0, (994.033, 7.19126e-4, 0.6217, 4179.26))):
        p = water(t)
        got = (p.density_kg_m3, p.viscosity_Pa_s, p.conductivity_W_mK, p.specific_heat_J_kgK)
        for g, r, tol in zip(got, ref, (2e-4, 3e-3, 1.5e-3, 3e-4)):
            assert g == pytest.approx(r, rel=tol)


def test_air_against_lemmon():
    """Lemmon et al. 2000 / Lemmon and Jacobsen 2004 at 26.85 degC (300 K), 1 atm: rho 1.1770,
    mu 1.8537e-5 Pa s, k 0.026385 W/(m K), c_p 1006.4; Pr 0.7071 (Incropera Table A.4: 0.707)."""
    p = air(26.85)
    assert p.density_kg_m3 == pytest.approx(1.17700, rel=2e-3)
    assert p.viscosity_Pa_s == pytest.approx(1.85373e-5, rel=1e-3)
    assert p.conductivity_W_mK == pytest.approx(0.0263845, rel=1e-3)
    assert p.prandtl == pytest.approx(0.707, abs=1e-3)
    with pytest.raises(ValueError, match="tabulated"):
        air(250.0)
    assert fluid("water_glycol_30", 20.0).specific_heat_J_kgK == pytest.approx(3718.25)


def test_churchill_chu_steam_pipe_example():
    """Incropera et al., Fundamentals of Heat and Mass Transfer (6th ed.), Example 9.3: horizontal
    steam pipe D = 0.1 m at 165 degC in air at 23 degC: h = 7.29 W/(m2 K), q' (convection) = 325
    W/m (Ra 5.08e6, Nu 23.3 with the book's air table; the numbers are as we recall the example).
    With our air properties at the film temperature: h = 7.28, q' = 325.0."""
    h = cv.free_cylinder_h(0.1, 165.0, 23.0)
    assert h == pytest.approx(7.29, rel=5e-3)
    assert h * math.pi * 0.1 * (165.0 - 23.0) == pytest.approx(325.0, rel=5e-3)


def test_churchill_chu_against_morgan():
    """Morgan's power laws (Incropera Table 9.1, Nu = C Ra^n: 0.850/0.188 for 1e2-1e4, 0.480/0.250
    for 1e4-1e7, 0.125/0.333 for 1e7-1e12) against Churchill-Chu in air (Pr 0.71): Churchill-Chu is
    up to 17.6 % lower at Ra 1e2-1e3, within 9.6 % over 1e4-1e9 (where spindle housings are: Ra of
    a 0.2 m housing 10 K above the room ~ 1e7), 13.5 % lower at 1e12."""
    for ra in np.geomspace(1e2, 1e12, 41):
        c, n = (0.850, 0.188) if ra < 1e4 else (0.480, 0.250) if ra < 1e7 else (0.125, 0.333)
        tol = 0.10 if 1e4 <= ra <= 1e9 else 0.18
        assert cv.churchill_chu_cylinder_nusselt(ra, 0.71) == pytest.approx(c * ra ** n, rel=tol)


def test_gnielinski_and_its_blend():
    """Gnielinski (1976) at Re 1e4, Pr 0.7: f = (0.790 ln 1e4 - 1.64)^-2 = 0.03148, Nu = 29.82 (by
    hand); Dittus-Boelter 0.023 Re^0.8 Pr^0.4 = 31.61 (6 % apart, the usual spread).  Laminar 4.36
    below Re 2300; Gnielinski's 2013 linear blend is continuous at 2300 and 4000."""
    assert cv.gnielinski_nusselt(1e4, 0.7) == pytest.approx(29.82, abs=0.01)
    assert cv.dittus_boelter_nusselt(1e4, 0.7) == pytest.approx(31.61, abs=0.01)
    for pr in (0.7, 5.0, 50.0):
        for wall, lam in (("flux", 4.36), ("temperature", 3.66)):
            nu = lambda re: cv.channel_nusselt(re, pr, wall)  # noqa: E731
            assert nu(2000.0) == lam and nu(2300.0) == lam
            assert nu(2300.0 + 1e-6) == pytest.approx(lam, rel=1e-8)
            assert nu(4000.0 - 1e-6) == pytest.approx(cv.gnielinski_nusselt(4000.0, pr), rel=1e-8)
            res = np.linspace(2000, 2e4, 500)
            vals = np.array([nu(r) for r in res])
            assert np.all(np.diff(vals) > 0) or np.all(np.diff(vals[res > 2300]) > 0)
    # Gnielinski vs Dittus-Boelter, Re 1e4-1e5, Pr 0.7-7: within 20 % (worst 19.6 % at Re 1e5, Pr 7;
    # 0.1-1 % at Re 1e4, Pr 3-7)
    for re in (1e4, 3e4, 1e5):
        for pr in (0.7, 3.0, 7.0):
            assert cv.gnielinski_nusselt(re, pr) == pytest.approx(cv.dittus_boelter_nusselt(re, pr), rel=0.2)


def test_air_gap_laminar_limit_is_conduction_and_branches_meet():
    """Becker-Kaye: Nu = 2 below Ta_m 1700 is conduction across the gap: h 2 pi r L equals the
    shell conductance 2 pi k L / ln(r2/r1) to O(delta/r).  The three branches meet within 2 % at
    Ta_m 1700 and 0.2 % at 1e4; F_g -> 0.9955 for a thin gap."""
    r, delta = 0.055, 0.5e-3
    p = air(40.0)
    h = cv.gap_h(2 * r, delta, 1.0, 40.0)
    g_shell = cylindrical_shell_conductance(r, r + delta, 0.18, p.conductivity_W_mK)
    g_conv = h * 2 * math.pi * (r + 0.5 * delta) * 0.18
    assert g_conv == pytest.approx(g_shell, rel=2 * delta / r)
    assert 0.128 * 1700 ** 0.367 == pytest.approx(2.0, rel=0.02)
    assert 0.128 * 1e4 ** 0.367 == pytest.approx(0.409 * 1e4 ** 0.241, rel=2e-3)
    assert cv.gap_geometric_factor(0.1, 1e-6) == pytest.approx(0.9955, abs=1e-4)
    hs = [cv.gap_h(0.11, 0.5e-3, w, 40.0) for w in np.linspace(0, 2600, 60)]
    assert np.all(np.diff(hs) >= 0) and hs[-1] > 3 * hs[0]   # 54.7 -> 202 W/(m2 K) at 0-25,000 rpm


def test_rotating_shaft_and_sphere():
    """Kendoush 0.133 Re^(2/3) Pr^(1/3): D 20 mm at 10,000 rpm in air at 27 degC (nu 1.575e-5):
    Re = Omega D^2 / nu = 2.66e4, Nu = 0.133 * 891.3 * 0.8908 = 105.6 by hand.  Whitaker: Nu -> 2 (conduction into still fluid) at Re -> 0."""
    p = air(27.0)
    re = 10000 * math.pi / 30 * 0.02 ** 2 / p.kinematic_viscosity_m2_s
    assert re == pytest.approx(2.66e4, rel=0.01)
    assert cv.rotating_cylinder_nusselt(re, p.prandtl) == pytest.approx(0.133 * re ** (2 / 3) * p.prandtl ** (1 / 3))
    assert cv.rotating_cylinder_nusselt(2.66e4, 0.707) == pytest.approx(105.6, rel=2e-3)
    # at rest the shaft falls back on free convection
    assert cv.rotating_shaft_h(0.02, 0.0, 60.0, 20.0) == pytest.approx(cv.free_cylinder_h(0.02, 60.0, 20.0), rel=1e-12)
    assert cv.whitaker_sphere_nusselt(0.0, 0.7) == 2.0
    assert cv.radiation_h(20.0, 20.0, 1.0) == pytest.approx(4 * 5.670374419e-8 * 293.15 ** 3, rel=1e-12)


def test_contact_conductance_cmy():
    """Yovanovich's plastic contact h_c = 1.25 k_s (m/sigma)(P/H_c)^0.95 for steel on steel (k 42.3,
    sigma 1 um, m 0.1, 10 MPa, H_c 3 GPa): 1.25 * 42.3 * 1e5 * (3.333e-3)^0.95 = 23,420 W/(m2 K)."""
    h = contact_conductance_cmy(42.3, 42.3, 0.7071e-6, 0.7071e-6, 0.07071, 0.07071, 10e6, 3e9)
    assert h == pytest.approx(1.25 * 42.3 * 0.1 / 1e-6 * (10e6 / 3e9) ** 0.95, rel=1e-3)
    assert h == pytest.approx(23420.0, rel=2e-3)


def test_bearing_contact_ellipse_and_constriction():
    """Hamrock-Brewe ellipse within 3 % of the exact Hertz solution (spindlesim.contact.hertz);
    circle: R = 1/(4 k a) (Holm); the ring-balls conductance grows as Q^(1/3)."""
    from spindlesim.contact.hertz import point_contact

    D, dm, a15 = 12.7e-3, 90e-3, math.radians(15)
    e_prime = 2.0 / (2 * (1 - 0.09) / 208e9)
    for race, f in (("inner", 0.52), ("outer", 0.53)):
        rx, ry = race_radii(D, dm, a15, f, race)
        a1, b1 = contact_ellipse_unit(rx, ry, e_prime)
        a, b, _, _ = point_contact(200.0, 1 / rx, 1 / ry, e_prime / 2)
        assert a1 * 200 ** (1 / 3) == pytest.approx(a, rel=0.03)
        assert b1 * 200 ** (1 / 3) == pytest.approx(b, rel=0.03)
    assert ellipse_constriction_resistance(1e-3, 1e-3, 40.0) == pytest.approx(1 / (4 * 40.0 * 1e-3), rel=1e-12)
    kw = dict(speed_rad_s=0.0, balls=18, ball_diameter_m=D, pitch_diameter_m=dm, contact_angle_rad=a15,
              k_ball_W_mK=40.0, k_ring_W_mK=40.0, medium=air(40.0))
    g1 = ball_bearing_conductances(inner_axes_m=(1e-3, 2e-4), outer_axes_m=(1e-3, 2e-4), **kw)
    g8 = ball_bearing_conductances(inner_axes_m=(2e-3, 4e-4), outer_axes_m=(2e-3, 4e-4), **kw)
    assert g8.inner_balls_W_K == pytest.approx(2 * g1.inner_balls_W_K, rel=1e-12)
    film = ball_bearing_conductances(inner_axes_m=(1e-3, 2e-4), outer_axes_m=(1e-3, 2e-4),
                                     film_inner_m=0.3e-6, **kw)
    assert film.inner_balls_W_K < g1.inner_balls_W_K and film.balls_outer_W_K == g1.balls_outer_W_K
    fast = ball_bearing_conductances(inner_axes_m=(1e-3, 2e-4), outer_axes_m=(1e-3, 2e-4),
                                     **{**kw, "speed_rad_s": 2000.0})
    assert fast.balls_cavity_W_K > 5 * g1.balls_cavity_W_K


def test_motor_losses_and_windage():
    """P (1 - eta)/eta at the rated point: the iron part (40 %) in the stator, the copper part (60 %) split
    2/3 stator 1/3 rotor, summing to the total; no rotor heat at idle; the iron losses held above the base
    speed (field weakening); the laminar windage coefficient is Couette's 4/Re within 2 % at delta/R = 0.05
    and the Bilgen-Boulos branches meet within 6 %."""
    m = MotorRating(18e3, 0.9, 9000 * math.pi / 30)
    assert m.rated_loss_W == pytest.approx(2000.0)
    rated = motor_losses(m, m.rated_speed_rad_s, load_fraction=1.0)
    assert rated.electrical_W == pytest.approx(2000.0, rel=1e-12)
    assert rated.stator_W == pytest.approx(800.0 + 1200.0 * 2 / 3) and rated.rotor_W == pytest.approx(1200.0 / 3)
    idle = motor_losses(m, 2 * m.rated_speed_rad_s, load_fraction=0.0)
    assert idle.rotor_W == 0.0 and idle.stator_W == pytest.approx(800.0)
    w = motor_losses(m, 2 * m.rated_speed_rad_s, load_fraction=0.5, windage_W=90.0)
    assert w.stator_W + w.rotor_W == pytest.approx(w.electrical_W + 90.0, rel=1e-12)
    assert windage_torque_coefficient(30.0, 0.05) * 30.0 == pytest.approx(4.0, rel=0.02)
    for re in (64.0, 500.0, 1e4):
        lo, hi = windage_torque_coefficient(re * (1 - 1e-9), 0.05), windage_torque_coefficient(re, 0.05)
        assert hi == pytest.approx(lo, rel=0.06)
