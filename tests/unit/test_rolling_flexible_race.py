"""Seed 000's flexible-race model: conservation, static limit, force balance.

Long-run checks (roller-pass line of the flexible model) are too slow for the
test suite with the pure-numpy right-hand side; see benchmarks/bench_transient.py
and docs/validation.md for the measured values.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from spindlesim.bearings.rolling.contact_force import CompliantContact
from spindlesim.bearings.rolling.flexible_race import FlexibleRaceModel, HousingSupport
from spindlesim.bearings.rolling.hertz import (
    palmgren_roller_stiffness, per_contact_stiffness)
from spindlesim.bearings.rolling.kinematics import CageKinematics
from spindlesim.bearings.rolling.outer_race import SegmentedRing

KIN = CageKinematics(18.738e-3, 28.262e-3, 4.762e-3)  # seed 000 Table 1
K_TOTAL = palmgren_roller_stiffness(6.35e-3)


def model(rollers=8, rpm=0.0, E=208e9, damped=False, mu=0.0, load=6.0):
    ring = SegmentedRing(12, 0.5 * (14.131e-3 + 16e-3), 1.869e-3, 6.35e-3, E, 7850.0)
    rc = CompliantContact(per_contact_stiffness(K_TOTAL, 10 / 9), 10 / 9, 1.8e9 if damped else 0.0, 1.0, 1.0, mu)
    hc = CompliantContact(1e9, 1.0, 170.0 if damped else 0.0, 1.0, 0.0, mu)
    return FlexibleRaceModel(KIN, rollers, ring, rc, HousingSupport(hc), rpm * np.pi / 30, 0.6,
                             200.0 if damped else 0.0, (0.0, -load), 6.35e-3)


def test_static_equilibrium_balances_the_load():
    m = model()
    p = m.static_equilibrium()
    v = np.zeros_like(p)
    assert np.max(np.abs(m.generalized_force(0.0, p, v))) < 1e-6
    cs = m.contact_state(0.0, p, v)
    assert np.all(cs["Q_out"] >= 0) and np.count_nonzero(cs["Q_out"] > 0.1) == 3
    # inner contacts carry the 6 N load; outer contacts pass it on to the race and housing
    assert np.sum(cs["Q_in"][:, None] * cs["n_in"], axis=0) == pytest.approx([0.0, -6.0], abs=1e-5)
    assert np.sum(cs["Q_out"][:, None] * cs["f"], axis=0) == pytest.approx([0.0, -6.0], abs=1e-5)
    # measured: the 12-segment race concentrates the load, Q_max Z / F_r = 4.73 (rigid races: 4.08)
    assert cs["Q_out"].max() * 8 / 6.0 > 4.08


@pytest.mark.parametrize("rollers, rpm", [(5, 5000.0), (12, 5000.0)])
def test_static_equilibrium_with_centrifugal_load(rollers, rpm):
    # at speed every roller is pressed on the outer race at least by m r omega_c^2 (0.455 N here)
    m = model(rollers=rollers, rpm=rpm)
    p = m.static_equilibrium()
    assert np.max(np.abs(m.generalized_force(0.0, p, np.zeros_like(p)))) < 1e-6
    cs = m.contact_state(0.0, p, np.zeros_like(p))
    fc = m.roller_mass_kg * p[2:2 + rollers] * m.cage_speed_rad_s**2
    assert fc == pytest.approx(0.455, abs=0.002)
    assert np.all(cs["Q_out"] >= fc * (1 - 1e-6))
    assert np.sum(cs["Q_in"][:, None] * cs["n_in"], axis=0) == pytest.approx([0.0, -6.0], abs=1e-5)


def test_energy_conserved_without_damping_and_friction():
    m = model(rollers=5)
    y0 = m.initial_state()
    n = m.n_pos
    y0[n:n + 2] = [1e-4, -2e-4]  # kick the shaft
    e0 = m.energy_J(0.0, y0)
    ref = 0.5 * 0.6 * (1e-4**2 + 2e-4**2)
    drift = []
    for rtol in (1e-5, 1e-7):
        sol = solve_ivp(m.rhs, (0, 3e-4), y0, method="DOP853", rtol=rtol, atol=rtol * m.state_scale())
        assert sol.status == 0
        e = np.array([m.energy_J(t, y) for t, y in zip(sol.t[::5], sol.y.T[::5])])
        drift.append(np.max(np.abs(e - e0)) / ref)
    assert drift[1] < drift[0]
    assert drift[1] < 1e-3


def test_satisfies_transient_system_interface():
    m = model(rollers=12, rpm=5000.0, damped=True, mu=0.05)
    assert m.cage_frequency_hz == pytest.approx(33.22, abs=0.005)
    assert m.roller_pass_frequency_hz == pytest.approx(398.7, abs=0.05)
    y0 = m.initial_state()
    dy = m.rhs(0.0, y0)
    assert dy.shape == (m.n_state,) and np.all(np.isfinite(dy))
    Y = np.vstack([y0, y0])
    assert m.roller_forces(np.array([0.0, 0.0]), Y).shape == (2, 12)
    assert m.race_deflection(np.array([0.0, 0.0]), Y).shape == (2, 12)
    # roller spin with no slip: the outer contact point of the roller is at rest (pure rolling)
    r = m.inner_radius_m + m.roller_radius_m
    assert r * m.cage_speed_rad_s + m.roller_spin_rad_s * m.roller_radius_m == pytest.approx(0.0, abs=1e-9)
