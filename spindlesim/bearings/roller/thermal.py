"""The cylindrical roller bearing's part of the spindle's thermal model (rigid-race model).

* :func:`at_temperatures`: the radial clearance as assembled plus half the change of the diametral clearance
  d_o' - d_i' - 2 D_w' of the grown rings and rollers (free rings: :func:`roller_operating_clearance` on
  :func:`spindlesim.thermal.growth_bearings.ring_growth`).
* :func:`heat`: Palmgren's global model for a cylindrical roller bearing with a cage
  (:func:`spindlesim.thermal.friction.roller_palmgren`, ``cylindrical_roller``: P1 = Fr, the radial load the
  rollers carry at the operating point), split to inner ring, rollers and outer ring as
  :func:`~spindlesim.thermal.friction.palmgren_parts_W` states.  Balls on rigid races (``element: ball``) have
  no load rating here for Palmgren's f1: no heat model (None).
* :func:`thermal_set`: its set in the spindle's thermal network (line contacts).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from ...contact.hertz import EXPONENT_POINT
from ...thermal.friction import palmgren_parts_W, roller_palmgren
from ...thermal.growth import BEARING_STEEL, ThermoElastic
from ...thermal.growth_bearings import BearingTemperatures, Mounting, RingGrowth, ring_growth
from ...thermal.layout import STEEL, BearingSet
from ..base import HeatReport, Lubrication
from ..conductance import roller_set


def at_temperatures(bearing, temperatures):
    """``bearing`` (a RigidRaceBearing) at the clearance of its parts at ``temperatures``."""
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


@dataclass(frozen=True)
class RollerClearance:
    """Operating clearance of a cylindrical roller bearing."""

    diametral_clearance_m: float      # d_o' - d_i' - 2 D_w' (< 0: interference)
    change_m: float
    rings: RingGrowth

    @property
    def radial_clearance_m(self) -> float:
        """Half the diametral clearance: the ``radial_clearance`` of spindlesim's roller model."""
        return 0.5 * self.diametral_clearance_m


def roller_operating_clearance(inner_raceway_diameter_m: float, outer_raceway_diameter_m: float,
                               roller_diameter_m: float, temps: BearingTemperatures,
                               ring: ThermoElastic = BEARING_STEEL, roller: ThermoElastic | None = None,
                               mounting: Mounting | None = None, speed_rad_s: float = 0.0) -> RollerClearance:
    """P_d' = d_o' - d_i' - 2 D_w' at temperature, with fits and the inner ring's centrifugal growth."""
    roller = ring if roller is None else roller
    rg = ring_growth(inner_raceway_diameter_m, outer_raceway_diameter_m, roller_diameter_m, temps, ring, roller,
                     mounting, speed_rad_s)
    P0 = outer_raceway_diameter_m - inner_raceway_diameter_m - 2.0 * roller_diameter_m
    ch = rg.outer_raceway_change_m - rg.inner_raceway_change_m - 2.0 * rg.element_change_m
    return RollerClearance(P0 + ch, ch, rg)


def thermal_set(e, z_m: float) -> BearingSet:
    """The spindle network's set of the cylindrical roller entry ``e`` (rigid races, rollers) centred at ``z_m``:
    line contacts (:class:`~spindlesim.bearings.conductance.RollerContactPaths`).  Rings: inner raceway diameter
    - 0.9 D_w, outer raceway diameter + 0.9 D_w (an N 1010 has d 50, F 57.5, E 72.5, D 80), width 1.5 x the
    roller length."""
    mm = 1e-3
    D, L = e.roller_diameter_mm * mm, e.width_mm * mm
    di, do = e.inner_raceway_diameter_mm * mm, e.outer_raceway_diameter_mm * mm
    return roller_set(e.name, z_m, di - 0.9 * D, do + 0.9 * D, 1.5 * L, e.rollers, D, 0.5 * (di + do), 0.0, 100.0,
                      ring=STEEL, ball=STEEL, ring_E_Pa=e.E_GPa * 1e9, ball_E_Pa=e.E_GPa * 1e9, roller_length_m=L)
