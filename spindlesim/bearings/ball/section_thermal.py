"""Deck keys of a ball bearing at temperature (``temperatures_C``, ``fits_um``, ``mounting``) and the
materials, with their checks and their conversion to SI for :func:`~.growth.at_temperature`; the entry's
plausibility (likely unit mistakes) and its set in the spindle's thermal network (its row of ``BEARING_TYPES``).

Only pydantic is imported at module level (docs/theory.md, "Spindle thermal model: heat generation and
growth", "Deck contract (ball bearings)").
"""

from __future__ import annotations

import math
from typing import Annotated, Optional

from pydantic import Field, model_validator

from ...fields import DeckModel, NonNegFloat, PositiveFloat
from ..plausible import Found, fits_and_expansions, metres, rolling_damping

#: coefficient of thermal expansion [1/K]: bearing steel (100Cr6 / AISI 52100, 11-12.5e-6) and
#: silicon nitride (about 3.2e-6); the default of a ball material below 5000 kg/m3 is the ceramic's
STEEL_EXPANSION_1_K = 11.5e-6
CERAMIC_EXPANSION_1_K = 3.2e-6
CERAMIC_DENSITY_BELOW_KG_M3 = 5000.0
#: largest interference (or clearance) of a fit, as a fraction of its diameter: above it the ring would be
#: strained beyond yield (about 0.2-0.5 % for hardened steel), so the number is almost surely in the wrong unit
MAX_FIT_FRACTION = 0.005
#: absolute zero [C]
ABSOLUTE_ZERO_C = -273.15

Expansion = Annotated[float, Field(ge=-1.0, le=1e-3)]  # sign checked below, with the reason
TemperatureC = Annotated[float, Field(ge=-1e4, le=2000.0)]  # absolute zero checked below, with the reason


def _check_expansion(value: float | None, key: str) -> None:
    if value is not None and not value >= 0.0:
        raise ValueError(f"{key} = {value:g} is negative: a thermal expansion coefficient in 1/K is positive "
                         f"(bearing steel about 11.5e-6, Si3N4 about 3.2e-6)")


class BallMaterial(DeckModel):
    E_GPa: PositiveFloat = 208.0
    """Young's modulus."""
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)] = 0.3
    """Poisson's ratio (dimensionless)."""
    density_kg_m3: PositiveFloat = 7850.0
    """Density (the balls' centrifugal force and gyroscopic moment)."""
    thermal_expansion_1_K: Optional[Expansion] = None
    """Linear thermal expansion coefficient [1/K] of this part's material, for the bearing at temperature
    (`temperatures_C`). None: bearing steel's 11.5e-6, or silicon nitride's 3.2e-6 when the density is below
    5000 kg/m3 (docs/theory.md, "Spindle thermal model: heat generation and growth")."""

    @model_validator(mode="after")
    def _expansion(self):
        _check_expansion(self.thermal_expansion_1_K, "thermal_expansion_1_K")
        return self

    def expansion_1_K(self) -> float:
        if self.thermal_expansion_1_K is not None:
            return self.thermal_expansion_1_K
        return CERAMIC_EXPANSION_1_K if self.density_kg_m3 < CERAMIC_DENSITY_BELOW_KG_M3 else STEEL_EXPANSION_1_K


class MountMaterial(DeckModel):
    """Shaft or housing body of a fit."""

    E_GPa: PositiveFloat
    """Young's modulus of the shaft or housing body."""
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)]
    """Poisson's ratio of the body (dimensionless)."""
    density_kg_m3: PositiveFloat
    """Density of the body (the shaft's centrifugal growth at speed)."""
    thermal_expansion_1_K: Expansion
    """Linear thermal expansion coefficient of the body [1/K] (steel about 11.5e-6, grey cast iron 10-11e-6)."""

    @model_validator(mode="after")
    def _expansion(self):
        _check_expansion(self.thermal_expansion_1_K, "thermal_expansion_1_K")
        return self


#: steel shaft; grey cast iron housing (E 110 GPa, 10-11e-6 1/K)
STEEL_SHAFT = dict(E_GPa=208.0, poisson=0.3, density_kg_m3=7850.0, thermal_expansion_1_K=11.5e-6)
CAST_IRON_HOUSING = dict(E_GPa=110.0, poisson=0.26, density_kg_m3=7200.0, thermal_expansion_1_K=10.5e-6)


class BallTemperatures(DeckModel):
    """Prescribed uniform temperatures of the parts [C] (as in MESYS): the bearing is computed with the
    operating clearance and preload that its growth gives.  shaft / housing default to the rings'."""

    inner_ring: TemperatureC
    """Uniform temperature of the inner ring(s) [C]."""
    outer_ring: TemperatureC
    """Uniform temperature of the outer ring(s) [C]."""
    rolling_elements: TemperatureC
    """Uniform temperature of the balls [C]."""
    reference: TemperatureC = 20.0
    """Temperature [C] at which the geometry, the clearance, the preload and the fits are given (the cold
    assembly); each part grows by its expansion coefficient times (T - reference)."""
    shaft: Optional[TemperatureC] = None
    """Temperature of the shaft at the inner-ring seat [C] (the inner fit). None: the inner ring's."""
    housing: Optional[TemperatureC] = None
    """Temperature of the housing at the outer-ring seat [C] (the outer fit). None: the outer ring's."""

    @model_validator(mode="after")
    def _above_absolute_zero(self):
        for key in ("inner_ring", "outer_ring", "rolling_elements", "reference", "shaft", "housing"):
            v = getattr(self, key)
            if v is not None and not v > ABSOLUTE_ZERO_C:
                raise ValueError(f"{key} = {v:g} C is at or below absolute zero (-273.15 C)")
        return self


class BallFits(DeckModel):
    """Diametral interference (> 0) or clearance (< 0) of the ring seats at the reference temperature [um]."""

    shaft: Annotated[float, Field(ge=-1e5, le=1e5)] = 0.0
    """Diametral interference of the inner ring on the shaft [um] at the reference temperature (> 0: a press
    fit; < 0: clearance)."""
    housing: Annotated[float, Field(ge=-1e5, le=1e5)] = 0.0
    """Diametral interference of the outer ring in the housing [um] at the reference temperature (> 0: a
    press fit; < 0: clearance, the usual loose housing fit of a floating set)."""


class BallMounting(DeckModel):
    """Seats of the fits (needed with ``fits_um``): bearing bore and outside diameter, shaft bore,
    housing outer diameter (null: a housing much thicker than the ring) and the two bodies."""

    bore_mm: PositiveFloat
    """Bearing bore d (the inner ring's seat on the shaft)."""
    outer_diameter_mm: PositiveFloat
    """Bearing outside diameter D (the outer ring's seat in the housing)."""
    shaft_bore_mm: NonNegFloat = 0.0
    """Bore of a hollow shaft at the seat (a drawbar bore); 0: solid."""
    housing_outer_diameter_mm: Optional[PositiveFloat] = None
    """Outer diameter of the housing around the seat. None: a housing much thicker than the ring (rigid)."""
    shaft_material: MountMaterial = MountMaterial(**STEEL_SHAFT)
    """Shaft body of the inner fit (default steel: 208 GPa, 0.3, 7850 kg/m3, 11.5e-6 1/K)."""
    housing_material: MountMaterial = MountMaterial(**CAST_IRON_HOUSING)
    """Housing body of the outer fit (default grey cast iron: 110 GPa, 0.26, 7200 kg/m3, 10.5e-6 1/K)."""

    @model_validator(mode="after")
    def _diameters(self):
        if not self.shaft_bore_mm < self.bore_mm:
            raise ValueError(f"shaft_bore_mm {self.shaft_bore_mm} must be smaller than bore_mm {self.bore_mm}")
        if not self.outer_diameter_mm > self.bore_mm:
            raise ValueError(f"outer_diameter_mm {self.outer_diameter_mm} must exceed bore_mm {self.bore_mm}")
        h = self.housing_outer_diameter_mm
        if h is not None and not h > self.outer_diameter_mm:
            raise ValueError(f"housing_outer_diameter_mm {h} must exceed outer_diameter_mm {self.outer_diameter_mm}")
        return self


def growth_checks(entry) -> list[tuple[tuple, str]]:
    """Checks of the growth keys that pydantic cannot place on their key: (key path in the entry, message).
    The deck loader reports them located; with temperatures the bearing at temperature is built once."""
    bad: list[tuple[tuple, str]] = []
    if entry.fits_um is not None and entry.mounting is None:
        bad.append((("fits_um",), "fits_um needs mounting: {bore_mm, outer_diameter_mm} (the seat diameters), and "
                                  "optionally shaft_bore_mm, housing_outer_diameter_mm and the two materials"))
    m = entry.mounting
    if entry.fits_um is not None and m is not None:
        for key, value, dia in (("shaft", entry.fits_um.shaft, m.bore_mm),
                                ("housing", entry.fits_um.housing, m.outer_diameter_mm)):
            if abs(value) > MAX_FIT_FRACTION * dia * 1e3:
                bad.append((("fits_um", key), f"{value:g} um is {abs(value) / (dia * 1e3) * 100:.3g} % of the {dia:g} mm "
                                              f"seat (more than {MAX_FIT_FRACTION * 100:g} %: a hardened ring would "
                                              "yield); fits are diametral interferences in micrometres"))
    if m is not None:
        dm, D = entry.pitch_diameter_mm, entry.ball_diameter_mm
        if not m.bore_mm < dm - D:
            bad.append((("mounting", "bore_mm"), f"{m.bore_mm:g} mm must be below the inner raceway (about pitch "
                                                 f"diameter - ball diameter = {dm - D:g} mm)"))
        if not m.outer_diameter_mm > dm + D:
            bad.append((("mounting", "outer_diameter_mm"), f"{m.outer_diameter_mm:g} mm must exceed the outer raceway "
                                                           f"(about pitch diameter + ball diameter = {dm + D:g} mm)"))
    if bad or thermal_inputs(entry) is None:
        return bad
    from .growth import at_temperature
    from .section import geometry_from, preload_from

    temps, ring, ball, mounting = thermal_inputs(entry)
    try:
        at_temperature(geometry_from(entry), preload_from(entry), temps, ring, ball, mounting)
    except ValueError as exc:
        key = "temperatures_C" if entry.temperatures_C is not None else "fits_um"
        bad.append(((key,), str(exc)))
    return bad


def growth_plausibility(entry, at: tuple) -> Found:
    """Likely unit mistakes among the keys of the growth (``fits_um``, the materials' expansion coefficients) of a
    ball entry or the ``bearing:`` section at the key path ``at`` (``spindlesim/bearings/plausible.py``)."""
    bad: Found = []
    fits_and_expansions(entry, at, bad)
    return bad


def thermal_inputs(entry):
    """(temperatures, ring, ball, mounting) in SI for :func:`~.growth.at_temperature`, or None when the
    entry has none of temperatures_C, fits_um, mounting (the bearing as made, at the reference state)."""
    if entry.temperatures_C is None and entry.fits_um is None and entry.mounting is None:
        return None
    from ...thermal.growth import ThermoElastic
    from ...thermal.growth_bearings import BearingTemperatures, Mounting

    def thermo(m, expansion):
        return ThermoElastic(1e9 * m.E_GPa, m.poisson, m.density_kg_m3, expansion)

    t = entry.temperatures_C
    if t is None:
        temps = BearingTemperatures.uniform(20.0)
    else:
        temps = BearingTemperatures(t.inner_ring, t.outer_ring, t.rolling_elements, t.reference, t.shaft, t.housing)
    ring = thermo(entry.material, entry.material.expansion_1_K())
    bm = entry.material if entry.ball_material is None else entry.ball_material
    ball = thermo(bm, bm.expansion_1_K())
    mounting = None
    if entry.mounting is not None:
        m, f = entry.mounting, entry.fits_um if entry.fits_um is not None else BallFits()
        mounting = Mounting(
            bore_m=1e-3 * m.bore_mm, outer_diameter_m=1e-3 * m.outer_diameter_mm,
            shaft_interference_m=1e-6 * f.shaft, housing_interference_m=1e-6 * f.housing,
            shaft_bore_m=1e-3 * m.shaft_bore_mm,
            housing_outer_diameter_m=math.inf if m.housing_outer_diameter_mm is None else 1e-3 * m.housing_outer_diameter_mm,
            shaft=thermo(m.shaft_material, m.shaft_material.thermal_expansion_1_K),
            housing=thermo(m.housing_material, m.housing_material.thermal_expansion_1_K))
    return temps, ring, ball, mounting


def plausibility(entry, at: tuple) -> Found:
    """Likely unit mistakes of a ball entry at the key path ``at``: its damping, its diameters (metres?), its fits
    and expansion coefficients."""
    bad: Found = []
    rolling_damping(entry, at, bad)
    metres(entry, at, ("pitch_diameter_mm", "ball_diameter_mm"), bad)
    return bad + growth_plausibility(entry, at)


def thermal_set(entry, z_m: float):
    """Its set in the spindle's thermal network (:func:`.thermal.thermal_set`)."""
    from .thermal import thermal_set as of_entry

    return of_entry(entry, z_m)
