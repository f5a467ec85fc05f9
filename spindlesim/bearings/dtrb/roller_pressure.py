"""Contact pressure of the most loaded DTRB roller with the half-space solver (seed 001 eqs. 42-46).

From a quasi-static DTRB state (seed 001 eqs. 23-27: slice loads Q_j = K_j delta_j^(10/9)) the
roller with the largest inner-raceway load is taken. Its misalignment against the cone comes from
the slice approaches themselves: delta_j + crown_j = a + theta (z_j - l/2) is fitted over the loaded
slices (least squares), so the tilt is the one the bearing model produced (ring tilt, roller
tilt phi_y and load distribution together). The half-space problem then uses

* load: Q_i of that roller; length l; crown radius of eq. 1;
* radii in the plane normal to the contact line: roller r_mid / cos(eps), inner cone
  rho_mid / cos(beta) (curvature radius of a cone normal to its generatrix);
* tilt theta, positive towards the small end (+y in the contact solver).

The edge check of the contact solver flags a sharp-end singularity: such a maximum pressure is a
grid value, not a converged edge stress.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...contact.problems import solve_roller_contact
from ...contact.result import ContactResult


@dataclass(frozen=True)
class RollerPressure:
    contact: ContactResult
    row: int  # 0 or 1
    roller: int
    roller_load_N: float
    tilt_rad: float
    slice_z_m: np.ndarray  # from the roller's large end
    slice_load_N_m: np.ndarray  # DTRB slice loads per length (eq. 27)


def most_loaded_roller_pressure(geometry, state, nx: int = 64, ny: int = 256) -> RollerPressure:
    g = geometry
    row, k = np.unravel_index(int(np.argmax(state.inner_load_N)), state.inner_load_N.shape)
    q = state.inner_slice_N_m[row, k]  # N/m per slice
    Q_i = float(state.inner_load_N[row, k])
    if not Q_i > 0:
        raise ValueError("no roller is loaded by the inner ring: nothing to solve")
    S = g.n_slices
    z = np.asarray(g.slice_z_m, float)
    Qj = q * g.slice_width_m
    K = np.asarray(g.stiffness[:S], float)
    n = np.asarray(g.exponent[:S], float)
    delta = np.where(Qj > 0, (np.maximum(Qj, 0) / K) ** (1.0 / n), 0.0)
    crown = np.asarray(g.gap_m[:S], float)
    loaded = Qj > 1e-9 * max(Qj.max(), 1e-30)
    zc = z - 0.5 * g.roller_length_m
    if loaded.sum() >= 2:
        A = np.column_stack([np.ones(loaded.sum()), zc[loaded]])
        (a, theta), *_ = np.linalg.lstsq(A, delta[loaded] + crown[loaded], rcond=None)
    else:
        theta = 0.0
    r_mid = g.large_end_radius_m - 0.5 * g.roller_length_m * math.tan(g.roller_half_angle_rad)
    rho_in = float(np.mean(g.point_m[:S, 0]))
    res = solve_roller_contact(
        Q_i, r_mid / math.cos(g.roller_half_angle_rad), g.roller_length_m,
        raceway_radius_m=rho_in / math.cos(g.cone_angle_rad), raceway="inner",
        profile="straight" if math.isinf(g.crown_radius_m) else "crowned",
        crown_radius_m=None if math.isinf(g.crown_radius_m) else g.crown_radius_m,
        tilt_rad=float(theta), roller_E_Pa=g.youngs_modulus_Pa, roller_nu=g.poisson,
        raceway_E_Pa=g.youngs_modulus_Pa, raceway_nu=g.poisson, nx=nx, ny=ny)
    return RollerPressure(contact=res, row=int(row), roller=int(k), roller_load_N=Q_i, tilt_rad=float(theta),
                          slice_z_m=z, slice_load_N_m=q)


def roller_pressure_under(bearing, static_load, speed_rad_s: float, nx: int = 64, ny: int = 256) -> RollerPressure:
    """:func:`most_loaded_roller_pressure` of a DTRB (``DtrbBearing``) under the static load the shaft puts
    on it (on its ``dof_names``) at ``speed_rad_s``."""
    state = bearing.solve(bearing.full_load(static_load), speed_rad_s)
    return most_loaded_roller_pressure(bearing.geometry, state, nx, ny)
