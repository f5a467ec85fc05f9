"""DTRB geometry (seed 001 Figs. 1-3, eqs. 1-9): apex condition, normals, rib sphere, mass.

Also the shared builders of the DTRB tests: the default deck's bearing (30210 pair, see
decks/dtrb_wheel_hub.yaml) and a fixture body registering the ``dtrb`` deck section.
"""

import importlib
import math

import numpy as np
import pytest

from spindlesim.bearings.dtrb import DtrbBearing, dtrb_geometry



def geometry(**over):
    kw = dict(rollers_per_row=20, cup_angle_deg=15.64, pitch_diameter_m=0.070, large_end_diameter_m=0.010,
              roller_length_m=0.014, large_end_offset_m=0.018, crown_radius_m=2.68, n_slices=30)
    kw.update(over)
    return dtrb_geometry(**kw)


def bearing(preload_um=30.0, **over):
    return DtrbBearing(geometry(**over), preload_um * 1e-6)


RPM = math.pi / 30.0


def registered_dtrb_deck():
    """Generator for a fixture: the family's deck module (deck models, builders)."""
    yield importlib.import_module("spindlesim.bearings.dtrb.section")


def _axis_crossing(p0, p1):
    """zeta where the line through p0, p1 (rho, zeta) meets rho = 0."""
    t = -p0[0] / (p1[0] - p0[0])
    return p0[1] + t * (p1[1] - p0[1])


def test_all_cones_meet_on_the_axis():
    g = geometry()
    S = g.n_slices
    P = g.point_m
    # the slice points are on the nominal (uncrowned) cone surfaces
    z_in = _axis_crossing(P[0], P[S - 1])
    z_out = _axis_crossing(P[S], P[2 * S - 1])
    C = np.array([g.large_end_centre_radius_m, -g.large_end_offset_m])
    e_a = np.array([-math.sin(g.roller_axis_angle_rad), math.cos(g.roller_axis_angle_rad)])
    z_axis = _axis_crossing(C, C + e_a)
    assert z_in == pytest.approx(z_axis, abs=1e-12)
    assert z_out == pytest.approx(z_axis, abs=1e-12)
    assert g.cup_angle_rad == pytest.approx(g.roller_axis_angle_rad + g.roller_half_angle_rad, rel=1e-14)
    assert g.cone_angle_rad == pytest.approx(g.roller_axis_angle_rad - g.roller_half_angle_rad, rel=1e-14)
    # the pitch diameter is the diameter of the roller mid-points
    mid = C + 0.5 * g.roller_length_m * e_a
    assert 2 * mid[0] == pytest.approx(g.pitch_diameter_m, rel=1e-12)


def test_normals_are_perpendicular_to_the_raceways_and_point_into_the_roller():
    g = geometry()
    S = g.n_slices
    P, N = g.point_m, g.normal
    for lo, hi in ((0, S), (S, 2 * S)):
        line = P[hi - 1] - P[lo]
        assert abs(line @ N[lo]) < 1e-12 * np.linalg.norm(line)
    # cone pushes the roller outwards, the cup inwards (Fig. 3b)
    assert N[0, 0] > 0 and N[S, 0] < 0
    assert np.allclose(np.linalg.norm(N, axis=1), 1.0)


def test_rib_contact_on_the_end_sphere():
    g = geometry()
    C = np.array([g.large_end_centre_radius_m, -g.large_end_offset_m])
    e_a = np.array([-math.sin(g.roller_axis_angle_rad), math.cos(g.roller_axis_angle_rad)])
    S_c = C + g.end_sphere_radius_m * math.cos(g.end_cap_half_angle_rad) * e_a  # eq. 6
    P_f = g.point_m[-1]
    assert np.linalg.norm(P_f - S_c) == pytest.approx(g.end_sphere_radius_m, rel=1e-12)
    # the rib normal passes through the sphere centre: no rib moment about it
    d = S_c - P_f
    assert abs(d[0] * g.normal[-1, 1] - d[1] * g.normal[-1, 0]) < 1e-15
    # rib contact below the roller axis, on the cone side (seed eqs. 33-35: angle gamma - theta)
    assert 0 < g.roller_axis_angle_rad - g.rib_angle_rad < 0.5
    assert math.sin(g.end_cap_half_angle_rad) * g.end_sphere_radius_m == pytest.approx(g.large_end_radius_m)


def test_mass_properties_of_the_frustum():
    g = geometry()
    r1 = g.large_end_radius_m
    r2 = r1 - g.roller_length_m * math.tan(g.roller_half_angle_rad)
    l, rho = g.roller_length_m, g.density_kg_m3
    mass = rho * math.pi * l * (r1 ** 2 + r1 * r2 + r2 ** 2) / 3
    Iw = rho * math.pi * l * (r1 ** 5 - r2 ** 5) / (10 * (r1 - r2))  # (3/10) m (r1^5 - r2^5)/(r1^3 - r2^3)
    assert g.roller_mass_kg == pytest.approx(mass, rel=1e-6)
    assert g.roller_polar_inertia_kg_m2 == pytest.approx(Iw, rel=1e-6)
    zc = l * (r1 ** 2 + 2 * r1 * r2 + 3 * r2 ** 2) / (4 * (r1 ** 2 + r1 * r2 + r2 ** 2))
    assert g.mass_centre_from_large_end_m == pytest.approx(zc, rel=1e-6)


def test_crowned_profile_eq1_and_gaps():
    g = geometry(crown_radius_m=2.68)
    l = g.roller_length_m
    drop = g.profile_radius_m(np.array([0.0, l])) - (g.large_end_radius_m - np.array([0.0, l]) * math.tan(g.roller_half_angle_rad))
    assert np.allclose(drop, -(0.5 * l) ** 2 / (2 * 2.68), rtol=1e-12)
    z = g.slice_z_m
    assert np.allclose(g.inner(g.gap_m), (z - l / 2) ** 2 / (2 * 2.68), rtol=1e-12)
    assert g.rib(g.gap_m) == 0.0


def test_pure_rolling_kinematics():
    g = geometry()
    S = g.n_slices
    rho_i, rho_o = g.point_m[:S, 0].mean(), g.point_m[S:2 * S, 0].mean()
    # cage: outer ring fixed, Omega_c / Omega_i = rho_i / (rho_i + rho_o) (e.g. Harris & Kotzalas)
    assert g.cage_ratio == pytest.approx(rho_i / (rho_i + rho_o), rel=1e-14)
    assert 0.4 < g.cage_ratio < 0.5


def test_bad_geometry_is_refused():
    with pytest.raises(ValueError):
        geometry(rollers_per_row=2)
    with pytest.raises(ValueError):
        geometry(cup_angle_deg=75.0)
