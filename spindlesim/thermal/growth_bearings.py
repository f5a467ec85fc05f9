"""Growth of a rolling bearing's rings and rolling elements at temperature (SI): what every family shares.

:class:`BearingTemperatures` (the parts' temperatures), :class:`Mounting` (fits and seats) and
:func:`ring_growth`: the diametral changes of the raceways (free thermal strain, the fit pressure, the
inner ring's centrifugal growth) and of the rolling element.  What growth does to one family's clearance or
preload is the family's own: the ball set's exact groove-centre vectors in
:mod:`spindlesim.bearings.ball.growth`, the DTRB's delta0 in :mod:`spindlesim.bearings.dtrb.thermal`, the
cylindrical roller bearing's operating clearance in :mod:`spindlesim.bearings.roller.thermal`
(docs/theory.md, "Spindle thermal model: heat generation and growth").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .growth import (CAST_IRON, STEEL_SHAFT, FitState, ThermoElastic, check_temperature,
                     inner_raceway_growth, inner_ring_fit, outer_raceway_growth, outer_ring_fit, thermal_strain)


@dataclass(frozen=True)
class BearingTemperatures:
    """Prescribed (or computed) uniform temperatures of the parts [C]; shaft and housing default to the
    inner and outer ring."""

    inner_ring_C: float
    outer_ring_C: float
    rolling_elements_C: float
    reference_C: float = 20.0
    shaft_C: float | None = None
    housing_C: float | None = None

    def __post_init__(self) -> None:
        for name in ("inner_ring_C", "outer_ring_C", "rolling_elements_C", "reference_C", "shaft_C", "housing_C"):
            v = getattr(self, name)
            if v is not None:
                check_temperature(v, name)

    @property
    def shaft(self) -> float:
        return self.inner_ring_C if self.shaft_C is None else self.shaft_C

    @property
    def housing(self) -> float:
        return self.outer_ring_C if self.housing_C is None else self.housing_C

    @classmethod
    def uniform(cls, temperature_C: float, reference_C: float = 20.0) -> "BearingTemperatures":
        return cls(temperature_C, temperature_C, temperature_C, reference_C)


@dataclass(frozen=True)
class Mounting:
    """Fits of a bearing: diametral interferences (> 0) or clearances (< 0) at the reference temperature,
    the seat diameters and the shaft and housing bodies (SI)."""

    bore_m: float                                # bearing bore d = shaft seat
    outer_diameter_m: float                      # bearing outside diameter = housing seat
    shaft_interference_m: float = 0.0
    housing_interference_m: float = 0.0
    shaft_bore_m: float = 0.0                    # 0: solid shaft
    housing_outer_diameter_m: float = math.inf   # inf: a housing wall much thicker than the ring
    shaft: ThermoElastic = STEEL_SHAFT
    housing: ThermoElastic = CAST_IRON


@dataclass(frozen=True)
class RingGrowth:
    """Diametral changes of the raceways and the rolling element, and the fits, at one operating point."""

    inner_raceway_diameter_m: float    # groove bottom (ball) or raceway (roller) at the reference state
    outer_raceway_diameter_m: float
    inner_raceway_change_m: float      # diametral, thermal + fit + centrifugal
    outer_raceway_change_m: float
    element_change_m: float            # ball or roller diameter change
    inner_strain: float                # free thermal strains
    outer_strain: float
    element_strain: float
    inner_fit: FitState | None
    outer_fit: FitState | None

    @property
    def fit_lost(self) -> bool:
        return any(f is not None and f.lost for f in (self.inner_fit, self.outer_fit))


def ring_growth(inner_raceway_diameter_m: float, outer_raceway_diameter_m: float, element_diameter_m: float,
                temps: BearingTemperatures, ring: ThermoElastic, element: ThermoElastic,
                mounting: Mounting | None = None, speed_rad_s: float = 0.0,
                outer_ring: ThermoElastic | None = None) -> RingGrowth:
    """Raceway and rolling-element diameter changes of a bearing with a rotating inner ring.

    Without ``mounting`` the rings are free (no fit) and the inner ring's centrifugal growth is not
    computed (its bore is unknown)."""
    ref = temps.reference_C
    outer_ring = ring if outer_ring is None else outer_ring
    e_i = thermal_strain(ring.expansion_1_K, temps.inner_ring_C, ref)
    e_o = thermal_strain(outer_ring.expansion_1_K, temps.outer_ring_C, ref)
    e_b = thermal_strain(element.expansion_1_K, temps.rolling_elements_C, ref)
    fi = fo = None
    if mounting is not None:
        m = mounting
        fi = inner_ring_fit(m.shaft_interference_m, m.bore_m, inner_raceway_diameter_m, ring, m.shaft_bore_m, m.shaft,
                            ring_strain=e_i, shaft_strain=thermal_strain(m.shaft.expansion_1_K, temps.shaft, ref),
                            speed_rad_s=speed_rad_s)
        fo = outer_ring_fit(m.housing_interference_m, m.outer_diameter_m, outer_raceway_diameter_m, outer_ring,
                            m.housing_outer_diameter_m, m.housing, ring_strain=e_o,
                            housing_strain=thermal_strain(m.housing.expansion_1_K, temps.housing, ref))
        d_in = inner_raceway_growth(inner_raceway_diameter_m, m.bore_m, ring, e_i, fi, speed_rad_s)
    else:
        d_in = inner_raceway_diameter_m * e_i
    d_out = outer_raceway_growth(outer_raceway_diameter_m, e_o, fo)
    return RingGrowth(inner_raceway_diameter_m, outer_raceway_diameter_m, d_in, d_out, element_diameter_m * e_b,
                      e_i, e_o, e_b, fi, fo)
