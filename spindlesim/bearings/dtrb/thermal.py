"""The DTRB's part of the spindle's thermal model: its heat at an operating point.

Each row is a single-row tapered roller bearing to Palmgren's global model
(:func:`spindlesim.thermal.friction.roller_palmgren`, ``tapered_roller``): M = f1 P1 d_m + M_v with
P1 = max(2 Y Fa, Fr), Y = 0.4 cot(alpha) the axial load factor of ISO 281 for the cup angle alpha, and the
row's radial and axial load Fr, Fa the resultant of its rollers' reactions on the cone (raceway and rib) in
the quasi-static state.  The heat goes to cones, rollers and cup as :func:`~spindlesim.thermal.friction.
palmgren_parts_W` states.  The rib-roller end sliding is inside f1 (Palmgren's coefficients are measured on
whole bearings); a local model of it is not.  The growth at temperature is ``DtrbBearing.at_temperatures``.
"""

from __future__ import annotations

import math

import numpy as np

from ...thermal.friction import palmgren_parts_W, roller_palmgren
from ..base import HeatReport, Lubrication

#: ISO 281 axial load factor of a single-row tapered roller bearing: Y = 0.4 cot(alpha)
ISO281_Y_COT = 0.4


def row_loads_N(bearing, displacement: np.ndarray, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """(Fr, Fa) [N] of each row (2,): the resultant of its rollers' reactions on the shaft at ``displacement``
    (5: dX, dY, dZ, phiX, phiY), radial magnitude and axial magnitude."""
    psi, _, sol = bearing._solve(np.asarray(displacement, float), speed, 0.0)
    f_w = -(sol.Q @ bearing.geometry.A_w)  # (2N, 3): radial along psi, axial, tilt, per roller on the shaft
    n = bearing.geometry.rollers_per_row
    fr = f_w[:, 0].reshape(2, n)
    fx = np.sum(fr * np.cos(psi), axis=1)
    fy = np.sum(fr * np.sin(psi), axis=1)
    return np.hypot(fx, fy), np.abs(np.sum(f_w[:, 1].reshape(2, n), axis=1))


def heat(bearing, speed: float, static_load, lubrication: Lubrication, lubricant_C: float,
         displacement=None) -> HeatReport:
    """The bearing's heat at the operating point (module note): at ``displacement`` (the node DOFs of
    ``dof_names``; a radial bearing's z and tilts held where its operating point put them) when given, else
    at the equilibrium under ``static_load`` and the deck's axial load."""
    if displacement is not None:
        d = np.zeros(5)
        d[2:] = bearing._held
        q = np.asarray(displacement, float)[: len(bearing.dof_names)]
        d[: q.size] = q
    else:
        d = bearing.solve(bearing.full_load(static_load), speed).displacement
    state = bearing.at(d, speed)
    g = bearing.geometry
    Fr, Fa = row_loads_N(bearing, d, speed)
    y = ISO281_Y_COT / math.tan(g.cup_angle_rad)
    nu = lubrication.lubricant.kinematic_m2_s(lubricant_C)
    rows = [roller_palmgren(family="tapered_roller", pitch_diameter_m=g.pitch_diameter_m, radial_N=float(fr),
                            axial_N=float(fa), axial_factor_Y=y, speed_rad_s=speed, viscosity_m2_s=nu,
                            lubrication=lubrication.method) for fr, fa in zip(Fr, Fa)]
    inner, rollers, outer = palmgren_parts_W(rows)
    n = g.rollers_per_row
    return HeatReport(inner, rollers, outer, np.ravel(state.inner_load_N), np.ravel(state.outer_load_N),
                      row_thrust_N=Fa, contact_angle_inner_deg=np.full(2, math.degrees(g.cone_angle_rad)),
                      contact_angle_outer_deg=np.full(2, math.degrees(g.cup_angle_rad)),
                      detail={"rows": rows, "radial_N": Fr, "axial_N": Fa, "rollers": 2 * n})
