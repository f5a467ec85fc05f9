"""Two-dimensional (plane-strain) line contact: the infinitely long roller.

Same Polonsky-Keer CGM as the 3D solver, with the strip influence coefficients of
:class:`~spindlesim.contact.influence.HalfSpace2D`.  Its role is the Hertz line-contact
check (b, p0 of Johnson eqs. 4.43-4.45) and the slice-wise comparison of the 3D roller.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .grid import cell_centres, edge_positions
from .hertz import line_contact
from .influence import HalfSpace2D
from .solver import solve_cgm

__all__ = ["LineContact2D", "solve_line_contact_2d"]


@dataclass(frozen=True)
class LineContact2D:
    """x_m cell centres [m], pressure_Pa [Pa], max_pressure_Pa, half_width_m [m],
    load_per_length_N_m (integrated) [N/m]."""

    x_m: np.ndarray
    pressure_Pa: np.ndarray
    max_pressure_Pa: float
    half_width_m: float
    load_per_length_N_m: float


def solve_line_contact_2d(load_per_length_N_m: float, r_eq_m: float, e_star_Pa: float,
                          n: int = 512, domain_factor: float = 1.5,
                          tol: float = 1e-10) -> LineContact2D:
    """Plane-strain contact of a cylinder (equivalent radius ``r_eq_m``) on a flat.

    The domain is +-``domain_factor`` times the Hertz half-width, ``n`` strips.
    """
    b_h, _ = line_contact(load_per_length_N_m, r_eq_m, e_star_Pa)
    half = domain_factor * b_h
    x = cell_centres(-half, half, n)
    dx = 2 * half / n
    op = HalfSpace2D(n, dx, e_star_Pa)
    sol = solve_cgm(op.apply, x * x / (2 * r_eq_m), load_per_length_N_m, dx, tol=tol)
    p = sol.pressure
    left, right = edge_positions(x, p[:, None])
    return LineContact2D(x, p, float(p.max()), float(0.5 * (right[0] - left[0])),
                         float(dx * p.sum()))
