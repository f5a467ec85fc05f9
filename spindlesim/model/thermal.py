"""The deck's ``spindle_thermal:`` section and its rotor -> the SI thermal model of the spindle.

The thermal network's shaft segments are the rotor's shaft elements (the tool and holder stay outside:
their growth is taken at the nose temperature), its bearing sets those of the rotor's bearing entries whose
family enters the network (``bearings.types.network_bearings``; each family builds its own set, with its ring
estimates and contact paths: ``thermal_set`` in ``bearings/<family>/thermal.py``), the housing, the cooling
jacket and the motor the section's.

docs/theory.md, "Spindle thermal model".
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..bearings.base import Lubrication
from ..bearings.types import network_bearings, thermal_set
from ..thermal.friction import Lubricant
from ..thermal.layout import STEEL, CoolingJacket, HousingSegment, MotorLayout, ShaftSegment, Solid, SpindleLayout
from ..thermal.motor import MotorRating
from .rotor import Rotor

RPM = math.pi / 30.0


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
    sets = tuple(thermal_set(e, float(rotor.node_z_m[e.node - 1]) - z0) for _, e in entries)
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
