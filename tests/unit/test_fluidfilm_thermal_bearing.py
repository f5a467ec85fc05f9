"""Thermal equilibrium (seed 003 eqs. 4-14) and the bearing protocol."""

import math

import numpy as np
import pytest

from spindlesim.bearings.base import Bearing
from spindlesim.bearings.fluidfilm.bearing import FluidFilmBearing
from spindlesim.bearings.fluidfilm.geometry import multilobe_geometry, plain_geometry
from spindlesim.bearings.fluidfilm.thermal import (
    ThermalEquilibriumError,
    ThermalParameters,
    heat_transfer_coefficient,
)
from spindlesim.bearings.fluidfilm.viscosity import ConstantViscosity, WaltherViscosity

GRID = dict(n_circ=96, n_axial=8)
OMEGA = 2170 * math.pi / 30


def seed_bearing(load=400.0, air=0.1, **kw):
    geo = multilobe_geometry(0.069965, 0.069965, 12e-6, 0.5, 3)
    oil = WaltherViscosity.from_grade("ISO VG 3", 805.0)
    th = ThermalParameters(inlet_C=25.0, ambient_C=20.0, density_kg_m3=805.0,
                           specific_heat_J_kgK=1940.681, air_velocity_m_s=air, **kw)
    return FluidFilmBearing("front", 6, geo, oil, th, load, **GRID)


@pytest.fixture(scope="module")
def seed_result():
    return seed_bearing().analyze(OMEGA)


def test_heat_balance_closes(seed_result):
    r = seed_result
    f = r.film
    lam = 1.0 / 3.0
    # eq. 6: H = T_f omega;  eq. 10: H = c rho q (theta_o - theta_i) + a A (theta - theta_E)
    assert r.heat_generated_W == pytest.approx(f.friction_torque_Nm * OMEGA, rel=1e-12)
    h1 = 1940.681 * 805.0 * f.side_flow_m3_s * (r.temperature_out_C - 25.0)
    h2 = r.housing_conductance_W_K * (r.temperature_mean_C - 20.0)
    assert r.heat_generated_W == pytest.approx(h1 + h2, rel=1e-5)
    # eq. 11 and the viscosity at the mean film temperature (eq. 14)
    assert r.temperature_mean_C == pytest.approx(lam * 25.0 + (1 - lam) * r.temperature_out_C)
    oil = WaltherViscosity.from_grade("ISO VG 3", 805.0)
    assert f.viscosity_Pa_s == pytest.approx(oil(r.temperature_mean_C), rel=1e-5)
    assert r.temperature_out_C > r.temperature_mean_C > 25.0


def test_more_cooling_gives_a_cooler_film(seed_result):
    cooler = seed_bearing(air=5.0).analyze(OMEGA)
    assert heat_transfer_coefficient(5.0) > heat_transfer_coefficient(0.1)
    assert cooler.temperature_mean_C < seed_result.temperature_mean_C - 1.0
    assert cooler.film.viscosity_Pa_s > seed_result.film.viscosity_Pa_s


def test_isoviscous_film_has_no_feedback():
    b = seed_bearing()
    iso = FluidFilmBearing("front", 6, b.geometry, ConstantViscosity(0.002, 805.0), b.thermal,
                           400.0, **GRID)
    r = iso.analyze(OMEGA)
    assert r.isoviscous and r.film.viscosity_Pa_s == 0.002
    assert r.film.sommerfeld == pytest.approx(1.881, rel=2e-3)


def test_no_equilibrium_is_reported_clearly():
    with pytest.raises(ThermalEquilibriumError, match="cannot carry"):
        seed_bearing(load=1.0e8).analyze(OMEGA)


def test_protocol_and_frames(seed_result):
    b = seed_bearing()
    assert isinstance(b, Bearing)
    K, C = b.linearized(OMEGA)
    np.testing.assert_allclose(K, seed_result.film.K_N_m, rtol=1e-6)
    np.testing.assert_allclose(C, seed_result.film.C_Ns_m, rtol=1e-6)
    # the deck load acts downward: the journal sinks (y < 0) and moves in the rotation sense
    pos = seed_result.film.position_m
    assert pos[1] < 0
    # a static load vector is used when the deck has none
    free = FluidFilmBearing("front", 6, b.geometry, b.viscosity, b.thermal, None, **GRID)
    K2, _ = free.linearized(OMEGA, np.array([0.0, -400.0]))
    np.testing.assert_allclose(K2, K, rtol=1e-6)
    with pytest.raises(ValueError):
        free.linearized(OMEGA)
    with pytest.raises(ValueError, match="positive speed"):
        b.linearized(0.0)


def test_seed_dimensionless_groups_on_cp(seed_result):
    f = seed_result.film
    W, Cb, Cp = 400.0, 12e-6, 24e-6
    assert f.k == pytest.approx(f.K_N_m * Cp / W)
    assert f.c == pytest.approx(f.C_Ns_m * Cp * OMEGA / W)
    # S_p = S_b (1 - mp)^2 (REFERENCES.md)
    assert f.sommerfeld == pytest.approx(f.sommerfeld_b * 0.25, rel=1e-12)
    mu, N, D = f.viscosity_Pa_s, OMEGA / (2 * math.pi), 0.069965
    assert f.sommerfeld == pytest.approx(mu * N * D * D / ((2 * Cp / D) ** 2 * W), rel=1e-12)
    assert f.reynolds_number == pytest.approx(805.0 * OMEGA * D / 2 * Cb / mu, rel=1e-12)


def test_grooved_plain_bearing_runs():
    geo = plain_geometry(0.05, 0.025, 40e-6, grooves=2, groove_width_deg=20)
    b = FluidFilmBearing("p", 0, geo, ConstantViscosity(0.01, 850.0),
                         ThermalParameters(40.0, 20.0, 850.0, 1900.0), 1500.0, **GRID)
    r = b.analyze(300.0)
    assert 0.0 < r.film.eccentricity_ratio < 1.0
    assert r.film.position_m[1] < 0
    assert np.all(np.linalg.eigvals(r.film.C_Ns_m + r.film.C_Ns_m.T).real > 0)


def test_start_from_a_neighbour_gives_the_same_equilibrium_in_fewer_films(seed_result):
    """A Campbell diagram starts each speed's thermal search from the previous speed's equilibrium:
    same root (to the 1e-6 degC tolerance), fewer film solutions (measured: cold 7, warm 6 from a
    neighbour 10 % faster; the cold search also needs a bracket from the inlet temperature up)."""
    from spindlesim.bearings.fluidfilm.thermal import solve_thermal

    b = seed_bearing()
    load = np.array([0.0, -400.0])
    cold = solve_thermal(b.solver, b.viscosity, OMEGA, load, b.thermal)
    neighbour = solve_thermal(b.solver, b.viscosity, 1.1 * OMEGA, load, b.thermal)
    warm = solve_thermal(b.solver, b.viscosity, OMEGA, load, b.thermal, near=neighbour)
    assert abs(warm.temperature_mean_C - cold.temperature_mean_C) < 1e-5
    np.testing.assert_allclose(warm.film.K_N_m, cold.film.K_N_m, rtol=1e-6, atol=1e-6 * np.abs(cold.film.K_N_m).max())
    assert warm.iterations < cold.iterations
    assert cold.temperature_mean_C == pytest.approx(seed_result.temperature_mean_C, abs=1e-5)


def test_secant_search_along_speeds_matches_the_cold_search_in_three_films():
    """Speed by speed as in a Campbell diagram (2 % steps): each search starts at the temperature
    extrapolated from the two previous equilibria with the previous balance slope (secant steps).
    Each root equals the cold bracket-and-Brent search's (1e-6 degC tolerance) and takes three film
    solutions after the first two speeds (the bracket and Brent's method took five per speed in the
    60-speed Campbell benchmark; the secant steps take 3.1)."""
    from spindlesim.bearings.fluidfilm.thermal import solve_thermal

    b = seed_bearing()
    load = np.array([0.0, -400.0])
    speeds = OMEGA * np.linspace(0.9, 1.1, 11)
    before, films = [], []
    for w in speeds:
        guess = None
        if len(before) == 2:
            (a, c) = before
            guess = c.temperature_mean_C + (w - c.film.speed_rad_s) / (c.film.speed_rad_s - a.film.speed_rad_s) * (
                c.temperature_mean_C - a.temperature_mean_C)
        r = solve_thermal(b.solver, b.viscosity, w, load, b.thermal, near=before[-1] if before else None, guess_C=guess)
        cold = solve_thermal(b.solver, b.viscosity, w, load, b.thermal)
        assert abs(r.temperature_mean_C - cold.temperature_mean_C) < 2e-6
        np.testing.assert_allclose(r.film.K_N_m, cold.film.K_N_m, rtol=1e-6, atol=1e-6 * np.abs(cold.film.K_N_m).max())
        films.append(r.iterations)
        assert r.balance_slope < 0 if before else True
        before = (before[-1], r) if before else [r]
    assert max(films[2:]) <= 3, films


def test_a_secant_search_that_does_not_settle_hands_over_to_the_bracket():
    """A neighbour's balance slope far too shallow (-1e-4 instead of about -1) sends the first secant
    step out of the temperature range: the bracket and Brent's method find the root all the same."""
    import dataclasses

    from spindlesim.bearings.fluidfilm.thermal import solve_thermal

    b = seed_bearing()
    load = np.array([0.0, -400.0])
    cold = solve_thermal(b.solver, b.viscosity, OMEGA, load, b.thermal)
    misleading = dataclasses.replace(cold, balance_slope=-1e-4)
    warm = solve_thermal(b.solver, b.viscosity, 1.05 * OMEGA, load, b.thermal, near=misleading)
    ref = solve_thermal(b.solver, b.viscosity, 1.05 * OMEGA, load, b.thermal)
    assert abs(warm.temperature_mean_C - ref.temperature_mean_C) < 2e-6


@pytest.mark.parametrize("rpm, films", [(200.0, 4), (1000.0, 6), (2170.0, 7), (5000.0, 8), (12000.0, 9)])
def test_a_cold_search_equals_brents_root(rpm, films):
    """Without a neighbour the search takes secant steps from the inlet temperature (from the eq. 12 temperature at
    its viscosity); its root equals Brent's method's on the same balance to a tight 1e-10 degC (scipy's brentq,
    called here: an independent search) within the search's 1e-6 degC.  Film solutions measured on this bearing
    (400 N): 4, 6, 7 at 200, 1,000 and 2,170 rpm (the bracket and Brent's method took 5, 7 and 7); at 5,000 and
    12,000 rpm the first step leaves the temperature range and the bracket and Brent's method decide (8 and 9, as
    before)."""
    from scipy.optimize import brentq

    from spindlesim.bearings.fluidfilm import thermal
    from spindlesim.bearings.fluidfilm.performance import operating_point

    b = seed_bearing()
    load = np.array([0.0, -400.0])
    w = rpm * math.pi / 30
    got = thermal.solve_thermal(b.solver, b.viscosity, w, load, b.thermal)
    aA = b.thermal.conductance(b.solver.geometry)

    def g(theta):
        film = operating_point(b.solver, b.viscosity(theta), w, load, b.thermal.density_kg_m3)
        return thermal._balance(b.thermal, aA, film)[0] - theta

    lo = min(b.thermal.inlet_C, b.thermal.ambient_C)  # heating there (g > 0); cooling 1 degC above the root found
    ref = brentq(g, lo, got.temperature_mean_C + 1.0, xtol=1e-10, rtol=1e-12)
    assert abs(got.temperature_mean_C - ref) <= 1e-6
    assert got.iterations == films


def _sweep(b, load, rpm, joint=True, monkeypatch=None):
    """Thermal equilibria speed by speed as a Campbell diagram solves them (each from its neighbour, the
    temperature extrapolated from the two before); with ``joint=False`` the nested search alone."""
    from spindlesim.bearings.fluidfilm import thermal

    if not joint:
        monkeypatch.setattr(thermal, "_joint_root", lambda *a, **k: (None, 0))
    before, out = [], []
    for w in np.asarray(rpm) * math.pi / 30:
        guess = None
        if len(before) == 2:
            a, c = before
            guess = c.temperature_mean_C + (w - c.film.speed_rad_s) / (c.film.speed_rad_s - a.film.speed_rad_s) * (
                c.temperature_mean_C - a.temperature_mean_C)
        r = thermal.solve_thermal(b.solver, b.viscosity, w, load, b.thermal, near=before[-1] if before else None,
                                  guess_C=guess)
        out.append(r)
        before = (before[-1], r) if before else [r]
    if not joint:
        monkeypatch.undo()
    return out


@pytest.mark.parametrize("load", [(0.0, -400.0), (0.0, -2000.0), (300.0, -50.0)])
def test_joint_steps_find_the_nested_searchs_equilibria_in_fewer_film_solutions(load, monkeypatch):
    """From a neighbour the search takes one film solution per step on the temperature and the journal position
    together (thermal._joint_root) instead of the journal's Newton iteration at every trial temperature.  Over
    a 60-speed diagram of the seed 003 bearing (200..12,000 rpm) both find the same equilibria: the temperature
    within 2e-6 degC (the search's 1e-6 each), the stiffness within 1e-7 of its largest term.  Reynolds
    solutions counted (measured 196 against 318 at 400 N, 255 against 356 at 2 kN, 182 against 320 for a
    sideways load): at most 80 % of the nested search's; the old code (no joint steps) took them all."""
    b = seed_bearing()
    calls = {"n": 0}
    solve = b.solver.solve

    def counted(*args, **kw):
        calls["n"] += 1
        return solve(*args, **kw)

    monkeypatch.setattr(b.solver, "solve", counted)
    rpm = np.linspace(200.0, 12000.0, 60)
    load = np.array(load)
    nested = _sweep(b, load, rpm, joint=False, monkeypatch=monkeypatch)
    monkeypatch.setattr(b.solver, "solve", counted)
    n_nested, calls["n"] = calls["n"], 0
    joint = _sweep(b, load, rpm)
    for r, ref in zip(joint, nested):
        assert abs(r.temperature_mean_C - ref.temperature_mean_C) < 2e-6
        np.testing.assert_allclose(r.film.K_N_m, ref.film.K_N_m, rtol=0, atol=1e-7 * np.abs(ref.film.K_N_m).max())
        np.testing.assert_allclose(r.film.position_m, ref.film.position_m, rtol=0, atol=1e-7 * 12e-6)
    assert calls["n"] <= 0.8 * n_nested, (calls["n"], n_nested)
    # every warm speed settled by the joint steps (their count is Reynolds solutions: two to six)
    assert max(r.iterations for r in joint[2:]) <= 6
    # and each is the equilibrium by its definition, checked without either search: the film solved afresh (from
    # the centred journal) at the viscosity of the temperature found carries the load, and eq. 12 at that film
    # gives the same temperature back (within the search's 1e-6 degC times |dg/dtheta| ~ 1-2)
    from spindlesim.bearings.fluidfilm import thermal
    from spindlesim.bearings.fluidfilm.performance import operating_point

    monkeypatch.undo()
    aA = b.thermal.conductance(b.geometry)
    for r in joint[5::11]:
        f = operating_point(b.solver, b.viscosity(r.temperature_mean_C), r.film.speed_rad_s, load,
                            b.thermal.density_kg_m3)
        assert abs(thermal._balance(b.thermal, aA, f)[0] - r.temperature_mean_C) < 5e-6
        np.testing.assert_allclose(f.position_m, r.film.position_m, rtol=0, atol=1e-7 * 12e-6)


def test_joint_steps_from_a_far_neighbour_hand_over_to_the_nested_search():
    """A neighbour at 200 rpm for an equilibrium at 12,000 rpm: the journal's first step is longer than a
    quarter of the clearance, so the joint steps stop and the nested search (secant steps, then the bracket)
    finds the cold search's root."""
    from spindlesim.bearings.fluidfilm import thermal

    b = seed_bearing()
    load = np.array([0.0, -400.0])
    w_far, w = 200 * math.pi / 30, 12000 * math.pi / 30
    far = thermal.solve_thermal(b.solver, b.viscosity, w_far, load, b.thermal)
    got, spent = thermal._joint_root(b.solver, b.viscosity, w, load, b.thermal, b.thermal.conductance(b.geometry),
                                     far, far.temperature_mean_C, 1e-6)
    assert got is None and spent == 0
    warm = thermal.solve_thermal(b.solver, b.viscosity, w, load, b.thermal, near=far)
    cold = thermal.solve_thermal(b.solver, b.viscosity, w, load, b.thermal)
    assert abs(warm.temperature_mean_C - cold.temperature_mean_C) < 2e-6


def test_joint_steps_whose_film_is_refused_hand_over_to_the_nested_search(monkeypatch):
    """Where the operating point at the joint steps' temperature is refused (the equilibrium's own checks, e.g. a
    film thinner than it accepts), the nested search runs from the neighbour as it did before the joint steps and
    says what it meets in its own words; here the refusal is planted once and the nested search's root is the
    cold search's."""
    from spindlesim.bearings.fluidfilm import thermal
    from spindlesim.bearings.fluidfilm.equilibrium import EquilibriumError

    b = seed_bearing()
    load = np.array([0.0, -400.0])
    near = thermal.solve_thermal(b.solver, b.viscosity, 0.98 * OMEGA, load, b.thermal)
    real, calls = thermal.operating_point, []

    def refused_once(*args, **kw):
        calls.append(1)
        if len(calls) == 1:
            raise EquilibriumError("load too large: minimum film below 0.1 % of Cb")
        return real(*args, **kw)

    monkeypatch.setattr(thermal, "operating_point", refused_once)
    got = thermal.solve_thermal(b.solver, b.viscosity, OMEGA, load, b.thermal, near=near)
    monkeypatch.undo()
    cold = thermal.solve_thermal(b.solver, b.viscosity, OMEGA, load, b.thermal)
    assert len(calls) > 1 and abs(got.temperature_mean_C - cold.temperature_mean_C) < 2e-6
