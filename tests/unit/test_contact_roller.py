"""Roller on raceway: geometry, symmetry, load balance, edge singularity, crown/tilt trends
(seed 001 Fig. 20: edge peaks grow with crown radius and with tilt)."""

import math

import numpy as np
import pytest

from spindlesim.contact import RollerProfile, equivalent_radius, solve_roller_contact
from spindlesim.contact.geometry import profile_drop, roller_gap

R, L, Q = 5e-3, 10e-3, 10e3
ES = 1 / (2 * (1 - 0.3**2) / 208e9)
GRID = dict(nx=32, ny=128)


def test_equivalent_radius():
    # 1/R' = 1/r + 1/R_in (inner), 1/r - 1/R_out (outer)
    assert equivalent_radius(5e-3, 20e-3, "inner") == pytest.approx(4e-3)
    assert equivalent_radius(5e-3, 30e-3, "outer") == pytest.approx(6e-3)
    assert equivalent_radius(5e-3, math.inf, "flat") == 5e-3
    with pytest.raises(ValueError):
        equivalent_radius(5e-3, 4e-3, "outer")


def test_crown_drop_is_seed001_eq1():
    """Seed 001 eq. 1: drop (z - l/2)^2 / (2 R) measured from the mid-length."""
    prof = RollerProfile(L, "crowned", crown_radius_m=2.6)
    y = np.array([0.0, 2e-3, -5e-3])
    assert np.allclose(profile_drop(y, prof, R, ES), y**2 / (2 * 2.6))
    assert np.isinf(profile_drop(np.array([5.1e-3]), prof, R, ES))[0]


def test_log_profile_is_finite_and_matches_formula():
    prof = RollerProfile(L, "logarithmic", design_load_N=Q)
    d = profile_drop(np.array([0.0, 2.5e-3, 5e-3]), prof, R, ES)
    b = math.sqrt(4 * (Q / L) * R / (math.pi * ES))
    expect_end = Q / (math.pi * L * ES) * math.log(1 / (1 - (1 - (2 * b / L) ** 2)))
    assert d[0] == 0.0 and 0 < d[1] < d[2]
    assert d[2] == pytest.approx(expect_end, rel=1e-12)


def test_rounded_end_drop():
    prof = RollerProfile(L, "straight", end_radius_m=1e-3)
    d = profile_drop(np.array([3.9e-3, 4.5e-3, 5e-3]), prof, R, ES)
    assert d[0] == 0.0
    assert d[1] == pytest.approx(1e-3 - math.sqrt(1e-6 - 0.25e-6))
    assert d[2] == pytest.approx(1e-3)


def test_tilt_closes_gap_at_positive_end():
    prof = RollerProfile(L)
    h, mask = roller_gap(np.array([0.0]), np.array([-4e-3, 4e-3]), R, prof, ES, tilt_rad=1e-3)
    assert mask.all() and h[0, 1] < h[0, 0]
    assert h[0, 0] - h[0, 1] == pytest.approx(8e-3 * math.tan(1e-3))


@pytest.fixture(scope="module")
def crowned():
    return solve_roller_contact(Q, R, L, raceway_radius_m=20e-3, raceway="inner",
                                profile="crowned", crown_radius_m=0.3, nx=48, ny=128)


def test_untilted_roller_is_symmetric_and_balanced(crowned):
    p = crowned.pressure_Pa
    assert np.max(np.abs(p - p[:, ::-1])) < 1e-6 * p.max()
    assert np.max(np.abs(p - p[::-1, :])) < 1e-6 * p.max()
    assert crowned.load_N == pytest.approx(Q, rel=1e-9)
    assert abs(crowned.max_location_m[1]) < 2 * (crowned.y_m[1] - crowned.y_m[0])


def test_strongly_crowned_roller_has_no_edge_contact(crowned):
    p = crowned.pressure_Pa
    assert not p[:, 0].any() and not p[:, -1].any()
    assert not crowned.edge_singular
    # half-width largest at mid-length and zero beyond the contact
    hw = crowned.half_width_m
    assert hw[len(hw) // 2] == pytest.approx(hw.max(), rel=0.05)
    assert hw[0] == 0.0


def test_smooth_case_converges_with_grid(crowned):
    fine = solve_roller_contact(Q, R, L, raceway_radius_m=20e-3, raceway="inner",
                                profile="crowned", crown_radius_m=0.3, nx=96, ny=256)
    assert fine.max_pressure_Pa == pytest.approx(crowned.max_pressure_Pa, rel=0.005)
    assert fine.area_m2 == pytest.approx(crowned.area_m2, rel=0.03)


def test_sharp_straight_roller_edge_singularity_detected():
    """Edge peak of a sharp-ended straight roller grows ~ sqrt(2) per halving of dy
    (p ~ d^-1/2 at a flat-punch edge): reported as a singularity, not a stress."""
    r = solve_roller_contact(Q, R, L, raceway="flat", profile="straight", **GRID)
    assert r.edge_singular
    assert "singularity" in r.message
    coarse = solve_roller_contact(Q, R, L, raceway="flat", profile="straight", nx=32, ny=64,
                                  check_edges=False)
    growth = r.max_pressure_Pa / coarse.max_pressure_Pa
    assert 1.2 < growth < 1.6
    assert abs(r.max_location_m[1]) > 0.95 * L / 2  # the peak sits at an end


def test_rounded_ends_remove_singularity():
    r = solve_roller_contact(Q, R, L, raceway="flat", profile="straight", end_radius_m=1e-3, **GRID)
    assert not r.edge_singular and r.message == ""


def _edge_peak(r):
    return max(r.pressure_Pa[:, :4].max(), r.pressure_Pa[:, -4:].max())


def test_edge_peak_grows_with_crown_radius():
    """Seed 001 Fig. 20: larger crown radius (flatter roller) -> larger edge pressure."""
    peaks = []
    for kw in (dict(profile="crowned", crown_radius_m=1.3), dict(profile="crowned", crown_radius_m=2.6),
               dict(profile="crowned", crown_radius_m=3.9), dict(profile="straight")):
        r = solve_roller_contact(Q, R, L, raceway="flat", check_edges=False, **GRID, **kw)
        peaks.append(_edge_peak(r))
    assert all(b > a for a, b in zip(peaks, peaks[1:]))


def test_edge_peak_grows_with_tilt():
    """Seed 001 Fig. 20 / section 3.2: tilt raises the pressure at the loaded (+y) end."""
    ends = []
    for tilt in (0.0, 1e-4, 2e-4):
        r = solve_roller_contact(Q, R, L, raceway="flat", profile="crowned", crown_radius_m=2.6,
                                 tilt_rad=tilt, check_edges=False, **GRID)
        ends.append((r.pressure_Pa[:, -1].max(), r.pressure_Pa[:, 0].max()))
        assert r.load_N == pytest.approx(Q, rel=1e-9)
    plus = [e[0] for e in ends]
    minus = [e[1] for e in ends]
    assert plus[0] < plus[1] < plus[2]
    assert minus[0] > minus[1] > minus[2]


def test_outer_race_pressure_lower_than_inner():
    """Conformal (outer) contact has a larger R' and so a lower pressure at the same load."""
    kw = dict(profile="crowned", crown_radius_m=0.3, nx=32, ny=64)
    inner = solve_roller_contact(Q, R, L, raceway_radius_m=25e-3, raceway="inner", **kw)
    outer = solve_roller_contact(Q, R, L, raceway_radius_m=35e-3, raceway="outer", **kw)
    assert outer.max_pressure_Pa < inner.max_pressure_Pa


def test_bad_inputs():
    with pytest.raises(ValueError):
        solve_roller_contact(-1.0, R, L)
    with pytest.raises(ValueError):
        solve_roller_contact(Q, R, L, profile="crowned", crown_radius_m=None)


def test_log_profile_gives_uniform_hertz_pressure_at_design_load():
    """Lundberg's logarithmic profile is designed for an axially uniform pressure at its design
    load: along 80 % of the length the centre-line pressure equals the line-contact Hertz p0
    for Q / l (REFERENCES.md: 2.697 GPa for 10 kN on 10 mm, R = 5 mm) within 1.5 %."""
    r = solve_roller_contact(Q, R, L, raceway="flat", profile="logarithmic", design_load_N=Q, **GRID)
    inner = np.abs(r.y_m) <= 0.8 * L / 2
    assert np.all(np.abs(r.centreline_pressure_Pa[inner] / 2.697e9 - 1) < 0.015)
    assert not r.edge_singular
