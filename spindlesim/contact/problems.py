"""Library entry points: roller/raceway line contact and ball (point) contact.

``solve_roller_contact`` and ``solve_point_contact`` take SI arguments and return a
:class:`~spindlesim.contact.result.ContactResult`.  Both solve the half-space problem
of seed 001 eqs. 42-46 with Love's rectangular-patch influence coefficients (eq. 45),
DC-FFT deflections and the Polonsky-Keer constrained conjugate-gradient method.
"""

from __future__ import annotations

import logging
import math
from typing import Literal

import numpy as np

from .geometry import RollerProfile, ball_gap, equivalent_radius, roller_gap
from .grid import edge_positions, nested_solve, value_at_x0
from .hertz import (
    combined_modulus,
    line_contact,
    point_contact_circular,
    point_contact_semi_axes_estimate,
)
from .result import ContactResult

log = logging.getLogger(__name__)

__all__ = ["solve_roller_contact", "solve_point_contact", "STEEL"]

#: bearing steel used by the references (REFERENCES.md): E [Pa], nu
STEEL = (208e9, 0.3)

_MAX_ENLARGE = 6


def _result(x, y, sol, load, nx, ny, singular=False, message="", inputs=None) -> ContactResult:
    p = sol.pressure
    dx, dy = x[1] - x[0], y[1] - y[0]
    k = np.unravel_index(int(np.argmax(p)), p.shape)
    left, right = edge_positions(x, p)
    hw = np.nan_to_num(0.5 * (right - left), nan=0.0)
    return ContactResult(
        x_m=x, y_m=y, pressure_Pa=p,
        max_pressure_Pa=float(p[k]), max_location_m=(float(x[k[0]]), float(y[k[1]])),
        load_N=float(dx * dy * p.sum()), applied_load_N=float(load),
        area_m2=float(np.count_nonzero(p > 0.0) * dx * dy),
        approach_m=sol.approach, half_width_m=hw,
        centreline_pressure_Pa=value_at_x0(x, p),
        edge_singular=singular, message=message, iterations=sol.iterations,
        grid=(nx, ny), inputs=dict(inputs or {}),
    )


def solve_roller_contact(
    load_N: float,
    roller_radius_m: float,
    roller_length_m: float,
    *,
    raceway_radius_m: float = math.inf,
    raceway: Literal["inner", "outer", "flat"] = "inner",
    profile: Literal["straight", "crowned", "logarithmic"] = "crowned",
    crown_radius_m: float | None = None,
    design_load_N: float | None = None,
    end_radius_m: float = 0.0,
    tilt_rad: float = 0.0,
    roller_E_Pa: float = STEEL[0], roller_nu: float = STEEL[1],
    raceway_E_Pa: float = STEEL[0], raceway_nu: float = STEEL[1],
    nx: int = 64, ny: int = 256,
    x_half_width_m: float | None = None,
    tol: float = 1e-5,
    check_edges: bool = True,
) -> ContactResult:
    """Contact pressure of a roller on an inner/outer raceway (or a flat).

    Parameters (SI)
    ---------------
    load_N : normal roller load Q [N].
    roller_radius_m, roller_length_m : roller radius and effective length [m].
    raceway_radius_m, raceway : raceway radius and whether it is the convex inner or the
        concave outer race; the equivalent radius combines both curvatures.
    profile, crown_radius_m, design_load_N, end_radius_m : roller profile, see
        :class:`~spindlesim.contact.geometry.RollerProfile` (seed 001 eq. 1 for the crown).
    tilt_rad : misalignment of the roller axis; positive loads the +y end.
    nx, ny : cells across and along the roller; the grid along y spans the roller.
    x_half_width_m : half-size of the domain across the roller; default 2.5 Hertz
        half-widths at Q / l, enlarged automatically while the contact reaches it.
    check_edges : when the contact reaches a sharp roller end, solve again with 2 ny
        cells; if the end pressure grows, flag ``edge_singular`` (half-space edge
        singularity: the grid value is not a converged stress).
    """
    if load_N <= 0:
        raise ValueError("load must be positive")
    e_star = combined_modulus(roller_E_Pa, roller_nu, raceway_E_Pa, raceway_nu)
    r_eq = equivalent_radius(roller_radius_m, raceway_radius_m, raceway)
    prof = RollerProfile(roller_length_m, profile if profile else "straight",
                         crown_radius_m, design_load_N, end_radius_m)
    half_l = 0.5 * roller_length_m
    if x_half_width_m is None:
        b_nom, _ = line_contact(load_N / roller_length_m, r_eq, e_star)
        x_half_width_m = 2.5 * b_nom

    def gap(x, y):
        return roller_gap(x, y, r_eq, prof, e_star, tilt_rad)

    def solve(nx_, ny_, xh):
        for _ in range(_MAX_ENLARGE):
            x, y, sol = nested_solve(gap, -xh, xh, -half_l, half_l, nx_, ny_, e_star, load_N, tol)
            p = sol.pressure
            if not (p[0, :].any() or p[-1, :].any()):
                return x, y, sol, xh
            xh *= 1.6
            log.info("contact reaches the x boundary; enlarging domain to +-%.3g m", xh)
        raise RuntimeError("contact keeps reaching the domain boundary; check the load/geometry")

    x, y, sol, xh = solve(nx, ny, x_half_width_m)
    inputs = dict(load_N=load_N, roller_radius_m=roller_radius_m, roller_length_m=roller_length_m,
                  raceway_radius_m=raceway_radius_m, raceway=raceway, profile=prof.kind,
                  crown_radius_m=crown_radius_m, design_load_N=design_load_N,
                  end_radius_m=end_radius_m, tilt_rad=tilt_rad, r_eq_m=r_eq, e_star_Pa=e_star)
    singular, message = False, ""
    p = sol.pressure
    ends_loaded = bool(p[:, 0].any() or p[:, -1].any())
    if ends_loaded and prof.sharp_ends:
        message = "contact reaches a sharp roller end"
        if check_edges:
            _, _, fine, _ = solve(nx, 2 * ny, xh)
            e_c = float(max(p[:, 0].max(), p[:, -1].max()))
            e_f = float(max(fine.pressure[:, 0].max(), fine.pressure[:, -1].max()))
            growth = e_f / e_c - 1.0
            singular = growth > 0.05
            message = (
                f"edge pressure {e_c / 1e9:.3f} GPa at ny={ny}, {e_f / 1e9:.3f} GPa at "
                f"ny={2 * ny} ({100 * growth:+.1f}%): "
                + ("half-space edge singularity at a sharp roller end; the edge value is "
                   "grid-dependent, not a converged stress" if singular else
                   "edge pressure stable under refinement")
            )
        else:
            singular = True
            message += " (edge singularity assumed; refinement check disabled)"
        if singular:
            log.warning("%s", message)
    return _result(x, y, sol, load_N, nx, ny, singular, message, inputs)


def solve_point_contact(
    load_N: float,
    rx_m: float,
    ry_m: float | None = None,
    *,
    E1_Pa: float = STEEL[0], nu1: float = STEEL[1],
    E2_Pa: float = STEEL[0], nu2: float = STEEL[1],
    n: int = 256,
    domain_factor: float = 1.5,
    tol: float = 1e-5,
) -> ContactResult:
    """Point contact (ball) with equivalent radii ``rx_m``, ``ry_m`` (default ry = rx).

    For a sphere of radius R on a flat, rx = ry = R.  The square n x n grid spans
    +-``domain_factor`` times the estimated semi-axes (Hamrock-Brewe), enlarged while
    the contact reaches the boundary.
    """
    if load_N <= 0:
        raise ValueError("load must be positive")
    ry_m = rx_m if ry_m is None else ry_m
    e_star = combined_modulus(E1_Pa, nu1, E2_Pa, nu2)
    ax, ay = point_contact_semi_axes_estimate(load_N, rx_m, ry_m, e_star)
    if rx_m == ry_m:
        ax = ay = point_contact_circular(load_N, rx_m, e_star)[0]
    hx, hy = domain_factor * ax, domain_factor * ay

    def gap(x, y):
        return ball_gap(x, y, rx_m, ry_m), np.ones((x.size, y.size), bool)

    for _ in range(_MAX_ENLARGE):
        x, y, sol = nested_solve(gap, -hx, hx, -hy, hy, n, n, e_star, load_N, tol)
        p = sol.pressure
        if not (p[0, :].any() or p[-1, :].any() or p[:, 0].any() or p[:, -1].any()):
            break
        hx, hy = 1.6 * hx, 1.6 * hy
    else:
        raise RuntimeError("point contact keeps reaching the domain boundary")
    inputs = dict(load_N=load_N, rx_m=rx_m, ry_m=ry_m, e_star_Pa=e_star)
    return _result(x, y, sol, load_N, n, n, inputs=inputs)
