"""The deck's ``spindle_thermal:`` section and its rotor -> the SI thermal model of the spindle.

The thermal network's shaft segments are the rotor's shaft elements (the tool and holder stay outside:
their growth is taken at the nose temperature), its bearing sets the rotor's rolling-bearing entries, the
housing, the cooling jacket and the motor the section's.  Ring dimensions (they set the rings' heat
capacity and seat areas) where the deck does not give them, our estimates from catalogue proportions:

- ball set: bore and outside diameter from its `mounting` when given, else d_m -+ 1.575 D_w (a 7014 has
  d 70, D 110, d_m 90, D_w 12.7); width 1.6 D_w a row, or the rows' spacing;
- DTRB: d_m -+ 1.575 D (D the rollers' mean diameter: a 32010 has d 50, D 80, d_m about 65, D about 8.5),
  width 2 x 1.25 l (two rows, cup and cone lands beside the rollers);
- cylindrical roller bearing: inner raceway diameter - 0.9 D_w, outer raceway diameter + 0.9 D_w (an N 1010
  has d 50, F 57.5, E 72.5, D 80), width 1.5 x the roller length.

docs/theory.md, "Spindle thermal model".
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..bearings.base import Lubrication
from ..thermal.friction import Lubricant
from ..thermal.layout import (STEEL, BearingSet, CoolingJacket, HousingSegment, MotorLayout, ShaftSegment, Solid,
                              SpindleLayout)
from ..thermal.motor import MotorRating
from ..thermal.section import network_bearings
from .rotor import Rotor

RPM = math.pi / 30.0
#: bore and outside diameter of an angular-contact bearing from its pitch and ball diameters: d_m -+ k D_w
RING_PROPORTION = 1.575
#: a ball material below this density is silicon nitride (its conductivity and heat capacity)
CERAMIC_BELOW_KG_M3 = 5000.0
SILICON_NITRIDE = Solid(25.0, 3200.0, 700.0)  # Si3N4: 20-30 W/(m K), c_p 680-800 J/(kg K)


@dataclass(frozen=True)
class WarmUpProfile:
    """Speed steps in time [s, rpm] from the cold spindle, the duration and the instants reported."""

    times_s: tuple[float, ...]
    speeds_rpm: tuple[float, ...]
    duration_s: float
    samples: int


@dataclass(frozen=True)
class SpindleThermalModel:
    """Everything the coupled thermal solve needs, in SI."""

    layout: SpindleLayout
    lubrication: Lubrication
    reference_C: float
    shaft_expansion_1_K: float
    housing_expansion_1_K: float
    load_fraction: float
    tolerance_K: float
    bearings: tuple[str, ...]  # the rolling-bearing sets in the network, by name
    analyses: str  # "none" | "steady" | "warm_up"
    speeds_rpm: tuple[float, ...]
    warm_up: WarmUpProfile | None = None
    analyses_at_s: float | None = None  # analyses "warm_up": the instant of the warm-up they take [s]


def build_spindle_thermal(deck: Any, rotor: Rotor) -> SpindleThermalModel | None:
    """The thermal model of a validated deck with a ``spindle_thermal:`` section (None without one)."""
    sec = getattr(deck, "spindle_thermal", None)
    if sec is None:
        return None
    mm = 1e-3
    el = rotor.elements
    n_shaft = len(deck.shaft.elements)
    z0 = float(rotor.node_z_m[0])
    h = sec.housing
    h_start, h_len = h.start_mm * mm, sum(r[2] for r in h.segments) * mm
    centres = z0 + np.cumsum(el.length_m[:n_shaft]) - 0.5 * el.length_m[:n_shaft]
    shaft = tuple(ShaftSegment(float(el.length_m[i]), float(el.outer_diameter_m[i]), float(el.inner_diameter_m[i]),
                               "housing" if h_start <= centres[i] <= h_start + h_len else "ambient")
                  for i in range(n_shaft))
    mat = h.material
    housing_solid = Solid(mat.conductivity_W_mK, mat.density_kg_m3, mat.specific_heat_J_kgK)
    housing = tuple(HousingSegment(r[2] * mm, r[0] * mm, r[1] * mm) for r in h.segments)
    entries = network_bearings(deck.bearings)[0]
    sets = tuple(_SETS[e.type](e, float(rotor.node_z_m[e.node - 1]) - z0) for _, e in entries)
    jacket = None
    if sec.cooling_jacket is not None:
        j = sec.cooling_jacket
        jacket = CoolingJacket(j.start_mm * mm - z0, j.length_mm * mm, j.channels, j.hydraulic_diameter_mm * mm,
                               j.channel_length_mm * mm, j.flow_l_min / 60e3, j.inlet_C, coolant=j.coolant,
                               segments=j.segments)
    motor = None
    load_fraction = 0.0
    if sec.motor is not None:
        m = sec.motor
        motor = MotorLayout(m.start_mm * mm - z0, m.length_mm * mm, m.rotor_inner_diameter_mm * mm,
                            m.rotor_outer_diameter_mm * mm, m.stator_outer_diameter_mm * mm, m.gap_mm * mm,
                            MotorRating(m.rated_power_kW * 1e3, m.efficiency, m.base_speed_rpm * RPM))
        load_fraction = m.load_fraction
    layout = SpindleLayout(shaft, housing, sets, sec.ambient_C, h_start - z0, jacket, motor,
                           shaft_material=STEEL, housing_material=housing_solid, housing_emissivity=h.emissivity)
    lub = sec.lubrication
    lubrication = Lubrication(Lubricant.from_grade(lub.grade), lub.method, lub.oil_fraction())
    warm = None
    if sec.warm_up is not None:
        w = sec.warm_up
        warm = WarmUpProfile(tuple(60.0 * t for t, _ in w.steps), tuple(float(s) for _, s in w.steps),
                             60.0 * w.duration_min, w.samples)
    return SpindleThermalModel(layout, lubrication, sec.reference_C, 11.5e-6, mat.thermal_expansion_1_K,
                               load_fraction, sec.tolerance_K, tuple(s.name for s in sets), sec.analyses,
                               tuple(sec.speeds_rpm), warm,
                               None if sec.warm_up_at_min is None else 60.0 * sec.warm_up_at_min)


def _bearing_set(e: Any, z_m: float) -> BearingSet:
    """The thermal network's bearing set of a ball-bearing entry centred at ``z_m`` (from the nose)."""
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
        q0 = 100.0  # a light preload's ball load: only the first estimate of the contact conductances
    bm = e.material if e.ball_material is None else e.ball_material
    ceramic = bm.density_kg_m3 < CERAMIC_BELOW_KG_M3
    return BearingSet(e.name, z_m, bore, od, width, rows * e.balls, D, dm, alpha, q0,
                      e.inner_conformity, e.outer_conformity, ring=STEEL, ball=SILICON_NITRIDE if ceramic else STEEL,
                      ring_E_Pa=e.material.E_GPa * 1e9, ring_poisson=e.material.poisson,
                      ball_E_Pa=bm.E_GPa * 1e9, ball_poisson=bm.poisson)


def _dtrb_set(e: Any, z_m: float) -> BearingSet:
    """The thermal network's set of a DTRB entry centred at ``z_m``: both rows' rollers (module note)."""
    from ..bearings.dtrb.section import geometry_from

    g = geometry_from(e.geometry)
    d_mean = 2.0 * (g.large_end_radius_m - 0.5 * g.roller_length_m * math.tan(g.roller_half_angle_rad))
    dm = g.pitch_diameter_m
    mat = e.geometry.material
    return BearingSet(e.name, z_m, dm - RING_PROPORTION * d_mean, dm + RING_PROPORTION * d_mean,
                      2 * 1.25 * g.roller_length_m, 2 * g.rollers_per_row, d_mean, dm, g.cup_angle_rad, 100.0,
                      ring=STEEL, ball=STEEL, ring_E_Pa=mat.E_GPa * 1e9, ring_poisson=mat.poisson,
                      ball_E_Pa=mat.E_GPa * 1e9, ball_poisson=mat.poisson, element="roller",
                      roller_length_m=g.roller_length_m)


def _roller_set(e: Any, z_m: float) -> BearingSet:
    """The thermal network's set of a cylindrical roller entry centred at ``z_m`` (module note)."""
    mm = 1e-3
    D, L = e.roller_diameter_mm * mm, e.width_mm * mm
    di, do = e.inner_raceway_diameter_mm * mm, e.outer_raceway_diameter_mm * mm
    return BearingSet(e.name, z_m, di - 0.9 * D, do + 0.9 * D, 1.5 * L, e.rollers, D, 0.5 * (di + do), 0.0, 100.0,
                      ring=STEEL, ball=STEEL, ring_E_Pa=e.E_GPa * 1e9, ball_E_Pa=e.E_GPa * 1e9, element="roller",
                      roller_length_m=L)


_SETS = {"ball": _bearing_set, "dtrb": _dtrb_set, "roller": _roller_set}
