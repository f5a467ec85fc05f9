"""Hertz line contact: b = sqrt(4 w' R'/(pi E*)), p0 = sqrt(w' E*/(pi R')) (Johnson eqs. 4.43-4.45).

REFERENCES.md: steel roller R = 5 mm, l = 10 mm, 10 kN on a flat, E = 208 GPa, nu = 0.3:
b = 0.2360 mm, p0 = 2.697 GPa.
"""

import numpy as np
import pytest

from spindlesim.contact import combined_modulus, line_contact, solve_line_contact_2d, solve_roller_contact

E, NU, R, L, Q = 208e9, 0.3, 5e-3, 10e-3, 10e3
B_REF, P0_REF = 0.2360e-3, 2.697e9


@pytest.mark.parametrize("n", [256, 1024])
def test_plane_strain_roller_matches_hertz_within_1pct(n):
    r = solve_line_contact_2d(Q / L, R, combined_modulus(E, NU, E, NU), n=n)
    assert abs(r.max_pressure_Pa / P0_REF - 1) < 0.01
    assert abs(r.half_width_m / B_REF - 1) < 0.01
    assert r.load_per_length_N_m == pytest.approx(Q / L, rel=1e-9)


def test_plane_strain_converges():
    """Half-width error shrinks with refinement (64 -> 512 strips)."""
    es = combined_modulus(E, NU, E, NU)
    b, _ = line_contact(Q / L, R, es)
    errs = [abs(solve_line_contact_2d(Q / L, R, es, n=n).half_width_m / b - 1) for n in (64, 512)]
    assert errs[1] < errs[0] / 3 and errs[1] < 1e-3


def test_3d_roller_mid_length_is_hertzian():
    """Mid-length slice of the 3D half-space roller (rounded ends, no edge singularity):
    p0 and b match Hertz for the slice's own load per length (plane strain far from the
    ends), within 1% and 2%.  The nominal Q / l Hertz values hold within 5% only, because
    the rounded ends carry less and the middle more."""
    es = combined_modulus(E, NU, E, NU)
    r = solve_roller_contact(Q, R, L, raceway="flat", profile="straight", end_radius_m=1.0e-3,
                             nx=64, ny=128)
    j = len(r.y_m) // 2
    cols = slice(j - 1, j + 1)  # the two slices next to y = 0
    dx = r.x_m[1] - r.x_m[0]
    w_mid = dx * r.pressure_Pa[:, cols].sum(axis=0).mean()
    b_loc, p0_loc = line_contact(w_mid, R, es)
    assert r.centreline_pressure_Pa[cols].mean() == pytest.approx(p0_loc, rel=0.01)
    assert r.half_width_m[cols].mean() == pytest.approx(b_loc, rel=0.02)
    assert r.centreline_pressure_Pa[cols].mean() == pytest.approx(P0_REF, rel=0.05)
    assert not r.edge_singular
    assert r.load_N == pytest.approx(Q, rel=1e-9)
