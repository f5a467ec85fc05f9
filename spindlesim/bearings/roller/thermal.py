"""The cylindrical roller bearing's part of the spindle's thermal model (rigid-race model).

* :func:`at_temperatures`: the radial clearance as assembled plus half the change of the diametral clearance
  d_o' - d_i' - 2 D_w' of the grown rings and rollers (free rings:
  :func:`spindlesim.thermal.growth_bearings.roller_operating_clearance`).
* :func:`heat`: Palmgren's global model for a cylindrical roller bearing with a cage
  (:func:`spindlesim.thermal.friction.roller_palmgren`, ``cylindrical_roller``: P1 = Fr, the radial load the
  rollers carry at the operating point), split to inner ring, rollers and outer ring as
  :func:`~spindlesim.thermal.friction.palmgren_parts_W` states.  Balls on rigid races (``element: ball``) have
  no load rating here for Palmgren's f1: no heat model (None).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ...contact.hertz import EXPONENT_POINT
from ...thermal.friction import palmgren_parts_W, roller_palmgren
from ..base import HeatReport, Lubrication


def at_temperatures(bearing, temperatures):
    """``bearing`` (a RigidRaceBearing) at the clearance of its parts at ``temperatures``."""
    from ...thermal.growth import BEARING_STEEL
    from ...thermal.growth_bearings import roller_operating_clearance

    k = bearing.kinematics
    made = bearing.radial_clearance_m if bearing.made_clearance_m is None else bearing.made_clearance_m
    grown = roller_operating_clearance(k.inner_raceway_diameter_m, k.outer_raceway_diameter_m, k.roller_diameter_m,
                                       temperatures, BEARING_STEEL if bearing.body is None else bearing.body)
    return dataclasses.replace(bearing, radial_clearance_m=made + 0.5 * grown.change_m, made_clearance_m=made)


def heat(bearing, speed: float, static_load, lubrication: Lubrication, lubricant_C: float,
         displacement=None) -> HeatReport | None:
    """The bearing's heat at the operating point (module note): its displacement ``displacement`` (x, y) when
    given, else the one that carries ``static_load``."""
    if bearing.exponent == EXPONENT_POINT:
        return None
    if displacement is None:
        q = bearing.static_displacement(speed, static_load)
    else:
        q = np.asarray(displacement, float)[:2]
    f, _ = bearing.pitch_average(q)
    k = bearing.kinematics
    dm = 0.5 * (k.inner_raceway_diameter_m + k.outer_raceway_diameter_m)
    m = roller_palmgren(family="cylindrical_roller", pitch_diameter_m=dm, radial_N=float(np.hypot(*f)),
                        speed_rad_s=speed, viscosity_m2_s=lubrication.lubricant.kinematic_m2_s(lubricant_C),
                        lubrication=lubrication.method)
    inner, rollers, outer = palmgren_parts_W([m])
    Q = bearing.roller_loads_N(q, 0.0)
    return HeatReport(inner, rollers, outer, Q, Q, detail={"rows": [m], "radial_N": np.hypot(*f)})
