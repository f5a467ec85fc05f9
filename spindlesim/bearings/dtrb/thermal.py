"""The DTRB's part of the spindle's thermal model: its heat at an operating point.

Each row is a single-row tapered roller bearing to Palmgren's global model
(:func:`spindlesim.thermal.friction.roller_palmgren`, ``tapered_roller``): M = f1 P1 d_m + M_v with
P1 = max(2 Y Fa, Fr), Y = 0.4 cot(alpha) the axial load factor of ISO 281 for the cup angle alpha, and the
row's radial and axial load Fr, Fa the resultant of its rollers' reactions on the cone (raceway and rib) in
the quasi-static state.  The heat goes to cones, rollers and cup as :func:`~spindlesim.thermal.friction.
palmgren_parts_W` states.  The rib-roller end sliding is inside f1 (Palmgren's coefficients are measured on
whole bearings); a local model of it is not.

Growth (:func:`dtrb_preload_change`, which ``DtrbBearing.at_temperatures`` applies): the misfit the parts'
growth (:func:`spindlesim.thermal.growth_bearings.ring_growth`) makes along the raceway normals, converted to
the change of delta0 (axial cone displacement).

Its set in the spindle's thermal network: :func:`thermal_set`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...thermal.friction import palmgren_parts_W, roller_palmgren
from ...thermal.growth import BEARING_STEEL, ThermoElastic
from ...thermal.growth_bearings import BearingTemperatures, Mounting, RingGrowth, ring_growth
from ...thermal.layout import STEEL, BearingSet
from ..base import HeatReport, Lubrication
from ..conductance import roller_set
from ..rolling import RING_PROPORTION

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


@dataclass(frozen=True)
class DtrbGrowth:
    """Change of the DTRB's axial preload delta0 (per row, cone towards the centre) from growth."""

    preload_change_m: float
    cone_misfit_m: float        # approach change at the cone's mid-roller contact, roller carried with the rings
    cup_misfit_m: float
    rings: RingGrowth


def dtrb_preload_change(geometry, temps: BearingTemperatures, ring: ThermoElastic = BEARING_STEEL,
                        roller: ThermoElastic | None = None, mounting: Mounting | None = None,
                        speed_rad_s: float = 0.0) -> DtrbGrowth:
    """Thermal (and fit) change of delta0 of a back-to-back DTRB (:mod:`spindlesim.bearings.dtrb`).

    Mid-roller contacts P_c (cone) and P_u (cup), normals N_c, N_u (force on the roller), in a row's
    meridional plane about the bearing centre; every part grows about the centre (the cones abut there),
    the roller about its mass centre G and is carried with the mean ring strain e_m.  The approach gained
    at a contact is (u_race - u_roller) . N with u_roller = e_r (P - G) + e_m G; a cone moved axially by
    delta0 gains sin(beta) delta0 at the cone, so delta0 changes by (m_cone + m_cup) / sin(beta).  Fits
    and the cone's centrifugal growth enter as radial raceway changes.  A uniform growth gives zero."""
    g = geometry
    roller = ring if roller is None else roller
    S = g.n_slices
    mid = S // 2
    P_c, P_u = g.point_m[mid], g.point_m[S + mid]
    N_c, N_u = g.normal[mid], g.normal[S + mid]
    G = np.array([g.mass_centre_radius_m, -g.large_end_offset_m + g.mass_centre_from_large_end_m *
                  math.cos(g.roller_axis_angle_rad)])
    d_c, d_u = 2.0 * P_c[0], 2.0 * P_u[0]
    rg = ring_growth(d_c, d_u, 2.0 * g.large_end_radius_m, temps, ring, roller, mounting, speed_rad_s)
    e_i, e_o, e_r = rg.inner_strain, rg.outer_strain, rg.element_strain
    e_m = 0.5 * (e_i + e_o)
    u_c = e_i * P_c + np.array([0.5 * rg.inner_raceway_change_m - e_i * P_c[0], 0.0])
    u_u = e_o * P_u + np.array([0.5 * rg.outer_raceway_change_m - e_o * P_u[0], 0.0])
    m_c = float((u_c - (e_r * (P_c - G) + e_m * G)) @ N_c)
    m_u = float((u_u - (e_r * (P_u - G) + e_m * G)) @ N_u)
    return DtrbGrowth((m_c + m_u) / math.sin(g.cone_angle_rad), m_c, m_u, rg)


def thermal_set(e, z_m: float) -> BearingSet:
    """The spindle network's set of the DTRB entry ``e`` centred at ``z_m``: both rows' rollers, line contacts
    (:class:`~spindlesim.bearings.conductance.RollerContactPaths`) at the cup angle.  Rings: d_m -+ 1.575 D (D the
    rollers' mean diameter: a 32010 has d 50, D 80, d_m about 65, D about 8.5), width 2 x 1.25 l (two rows, cup
    and cone lands beside the rollers)."""
    from .section import geometry_from

    g = geometry_from(e.geometry)
    d_mean = 2.0 * (g.large_end_radius_m - 0.5 * g.roller_length_m * math.tan(g.roller_half_angle_rad))
    dm = g.pitch_diameter_m
    mat = e.geometry.material
    return roller_set(e.name, z_m, dm - RING_PROPORTION * d_mean, dm + RING_PROPORTION * d_mean,
                      2 * 1.25 * g.roller_length_m, 2 * g.rollers_per_row, d_mean, dm, g.cup_angle_rad, 100.0,
                      ring=STEEL, ball=STEEL, ring_E_Pa=mat.E_GPa * 1e9, ring_poisson=mat.poisson,
                      ball_E_Pa=mat.E_GPa * 1e9, ball_poisson=mat.poisson, roller_length_m=g.roller_length_m)
