"""The ball bearing's part of the spindle's thermal model: the bearing at temperature and its heat.

* :func:`at_temperatures`: the bearing rebuilt from the geometry and preload it was made with (the cold
  assembly) at the parts' temperatures: :func:`.growth.at_temperature` (free growth of rings and balls,
  fits, the operating clearance and preload offsets), the inner ring's centrifugal growth with a mounting.
* :func:`thermal_set`: the set in the spindle's thermal network (its ``BearingSet`` with the Hertz ellipses of
  :class:`~spindlesim.bearings.conductance.BallContactPaths`).
* :func:`heat`: the heat of the set at its operating point, from its quasi-static state (per-ball contact
  loads, angles and Hertz ellipses): the local model of :func:`.heat.ball_bearing_heat`
  (spin over the Hertz ellipse, EHL rolling and hysteresis, drag of the balls in the oil-air), split to the
  inner ring, the balls (with the drag) and the outer ring.

docs/theory.md, "Spindle thermal model: heat generation and growth".
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...thermal.growth import BEARING_STEEL, SI3N4, ThermoElastic
from ...thermal.layout import STEEL, BearingSet, Solid
from ..base import HeatReport, Lubrication
from ..conductance import ball_set
from ..rolling import RING_PROPORTION
from .heat import STARVATION_K_RS, ContactFrictionOptions, ball_bearing_heat
from .section_thermal import CERAMIC_DENSITY_BELOW_KG_M3

#: a ball material below this density is a ceramic (silicon nitride: its expansion, conductivity and heat capacity)
CERAMIC_BELOW_KG_M3 = CERAMIC_DENSITY_BELOW_KG_M3
#: Si3N4 balls in the thermal network: 20-30 W/(m K), c_p 680-800 J/(kg K)
SILICON_NITRIDE = Solid(25.0, 3200.0, 700.0)
#: a light preload's ball load [N]: the first estimate of the contact conductances only
NOMINAL_BALL_LOAD_N = 100.0


@dataclass(frozen=True)
class MadeAs:
    """The bearing as assembled (cold): geometry and preload before any growth, the ring and ball materials'
    thermo-elastic data and the mounting (fits; None: free rings)."""

    geometry: object
    preload: object
    ring: ThermoElastic = BEARING_STEEL
    ball: ThermoElastic | None = None
    mounting: object = None

    @classmethod
    def of(cls, geometry, preload) -> "MadeAs":
        """Default materials: bearing steel rings, steel or silicon nitride balls (by their density)."""
        ceramic = geometry.ball.density_kg_m3 < CERAMIC_BELOW_KG_M3
        ring = ThermoElastic(geometry.ring.E_Pa, geometry.ring.poisson, geometry.ring.density_kg_m3,
                             BEARING_STEEL.expansion_1_K)
        ball = ThermoElastic(geometry.ball.E_Pa, geometry.ball.poisson, geometry.ball.density_kg_m3,
                             (SI3N4 if ceramic else BEARING_STEEL).expansion_1_K)
        return cls(geometry, preload, ring, ball)


def at_temperatures(bearing, temperatures):
    """``bearing`` (a BallBearing) rebuilt at ``temperatures`` from the way it was made."""
    from .growth import SpeedGrowth, at_temperature

    made = bearing.made
    geometry, preload, growth = at_temperature(made.geometry, made.preload, temperatures, made.ring, made.ball,
                                               made.mounting)
    speed_growth = SpeedGrowth(made.geometry, temperatures, made.ring, made.mounting) if made.mounting else None
    return bearing._copy(geometry=geometry, preload=preload, speed_growth=speed_growth, growth=growth)


def heat(bearing, speed: float, static_load, lubrication: Lubrication, lubricant_C: float,
         displacement=None) -> HeatReport:
    """The set's heat at the operating point (module note): its state at ``displacement`` when given (the
    rotor's static state has it), else under ``static_load``."""
    if displacement is not None:
        state = bearing.at(np.asarray(displacement, float)[:5], speed)
    else:
        state = bearing.solve(np.zeros(5) if static_load is None else np.asarray(static_load, float), speed)
    options = ContactFrictionOptions(oil_volume_fraction=lubrication.oil_volume_fraction,
                                     starvation_K_rs=STARVATION_K_RS.get(lubrication.method, 0.0))
    h = ball_bearing_heat(state, bearing.geometry, lubrication.lubricant, lubricant_C, options, model=bearing.model)
    parts = h.parts_W(drag_to_balls=True)
    return HeatReport(parts["inner_ring"], parts["balls"], parts["outer_ring"],
                      np.ravel(state.element_load_inner_N), np.ravel(state.element_load_outer_N),
                      row_thrust_N=np.asarray(state.row_axial_load_N, float),
                      contact_angle_inner_deg=np.mean(state.contact_angle_inner_deg, axis=1),
                      contact_angle_outer_deg=np.mean(state.contact_angle_outer_deg, axis=1), detail=h)


def thermal_set(e, z_m: float) -> BearingSet:
    """The spindle network's set of the ball-bearing entry ``e`` (deck units) centred at ``z_m`` (from the nose).

    Ring dimensions (the rings' heat capacity and seat areas): bore and outside diameter from the entry's
    ``mounting`` when given, else d_m -+ 1.575 D_w (:data:`~spindlesim.bearings.rolling.RING_PROPORTION`); width
    1.6 D_w a row, or the rows' spacing.  The balls' nominal load: a spring preload's share, else 100 N (only the
    first estimate: the network takes the loads of the operating state)."""
    mm = 1e-3
    D, dm = e.ball_diameter_mm * mm, e.pitch_diameter_mm * mm
    rows = e.row_count
    if e.mounting is not None:
        bore, od = e.mounting.bore_mm * mm, e.mounting.outer_diameter_mm * mm
    else:
        bore, od = dm - RING_PROPORTION * D, dm + RING_PROPORTION * D
    width = rows * (e.row_spacing_mm * mm if rows > 1 and e.row_spacing_mm else 1.6 * D)
    alpha = math.radians(max(e.contact_angle_deg, 1.0))
    pre = e.preload
    if pre is not None and pre.kind == "spring":
        q0 = pre.axial_N / (e.balls * math.sin(alpha))
    else:
        q0 = NOMINAL_BALL_LOAD_N
    bm = e.material if e.ball_material is None else e.ball_material
    ceramic = bm.density_kg_m3 < CERAMIC_BELOW_KG_M3
    return ball_set(e.name, z_m, bore, od, width, rows * e.balls, D, dm, alpha, q0,
                    e.inner_conformity, e.outer_conformity, ring=STEEL, ball=SILICON_NITRIDE if ceramic else STEEL,
                    ring_E_Pa=e.material.E_GPa * 1e9, ring_poisson=e.material.poisson,
                    ball_E_Pa=bm.E_GPa * 1e9, ball_poisson=bm.poisson)
