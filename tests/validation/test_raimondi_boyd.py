"""Plain 360 deg bearing against Raimondi & Boyd (1958), ASLE Trans. 1, 159-209.

Table values as transcribed in /work/shared/REFERENCES.md ("Raimondi and Boyd (1958), full
360 deg bearing, Reynolds condition"; S = mu N L D (R/C)^2 / W with N in rev/s).
Tolerances from the brief: S within 2 %, attitude within 1 deg, friction variable (R/C) f
and flow variable Q/(R C N L) within 3 %; Qs/Q also within 3 %.
"""

import math

import numpy as np
import pytest

from spindlesim.bearings.fluidfilm.geometry import plain_geometry
from spindlesim.bearings.fluidfilm.performance import operating_point
from spindlesim.bearings.fluidfilm.reynolds import ReynoldsSolver

# L/D, eps, S, phi [deg], (R/C) f, Q/(R C N L), Qs/Q
RAIMONDI_BOYD = [
    (1.0, 0.2, 0.631, 74.02, 12.8, 3.59, 0.280),
    (1.0, 0.4, 0.264, 63.10, 5.79, 3.99, 0.497),
    (1.0, 0.6, 0.121, 50.58, 3.22, 4.33, 0.680),
    (1.0, 0.8, 0.0446, 36.24, 1.70, 4.62, 0.842),
    (0.5, 0.2, 2.03, 74.94, 40.9, 3.72, 0.318),
    (0.5, 0.6, 0.319, 48.14, 8.10, 4.85, 0.730),
    (0.5, 0.8, 0.0923, 33.31, 3.26, 5.41, 0.874),
    (0.25, 0.4, 2.83, 60.86, 61.1, 4.37, 0.567),
    (0.25, 0.8, 0.261, 31.04, 8.80, 5.60, 0.884),
]


@pytest.mark.parametrize("ld, eps, S_ref, phi_ref, f_ref, q_ref, qs_ref", RAIMONDI_BOYD)
def test_raimondi_boyd_prescribed_eccentricity(ld, eps, S_ref, phi_ref, f_ref, q_ref, qs_ref):
    # dimensionless groups are independent of D and C; the journal is displaced along +x
    solver = ReynoldsSolver(plain_geometry(0.1, 0.1 * ld, 1e-4))
    sol = solver.solve(eps, 0.0)
    F = sol.force
    W = float(np.hypot(*F))  # in units of mu omega R^4 / C^2
    S = 2.0 * ld / (math.pi * W)
    # attitude: from the load line (-F) to the eccentricity (+x), + in the rotation sense
    phi = math.degrees(math.atan2(F[1], -F[0]))
    f_var = sol.friction / W
    q_var = math.pi / ld * sol.inlet_flow
    qs_ratio = sol.side_flow / sol.inlet_flow
    assert S == pytest.approx(S_ref, rel=0.02)
    assert phi == pytest.approx(phi_ref, abs=1.0)
    assert f_var == pytest.approx(f_ref, rel=0.03)
    assert q_var == pytest.approx(q_ref, rel=0.03)
    assert qs_ratio == pytest.approx(qs_ref, rel=0.03)


def test_raimondi_boyd_load_driven_dimensional():
    """End to end: a dimensional bearing loaded to R&B's S = 0.121 (L/D = 1) sits at eps 0.6."""
    D, C, mu, N = 0.05, 50e-6, 0.02, 50.0  # m, m, Pa s, rev/s
    geo = plain_geometry(D, D, C)
    W = mu * N * D * D * (0.5 * D / C) ** 2 / 0.121
    res = operating_point(ReynoldsSolver(geo), mu, 2 * math.pi * N, np.array([0.0, -W]), 850.0)
    assert res.sommerfeld == pytest.approx(0.121, rel=1e-9)
    assert res.eccentricity_ratio == pytest.approx(0.6, abs=0.01)
    assert res.attitude_angle_deg == pytest.approx(50.58, abs=1.0)
    assert res.min_film_m == pytest.approx(C * (1 - res.eccentricity_ratio), rel=1e-3)
    # friction variable (R/C) f and flow variable in SI
    assert res.friction_coefficient * (0.5 * D / C) == pytest.approx(3.22, rel=0.03)
    assert res.inlet_flow_m3_s / (0.5 * D * C * N * D) == pytest.approx(4.33, rel=0.03)
