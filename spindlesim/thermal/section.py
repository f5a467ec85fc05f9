"""Deck section ``spindle_thermal:``: the heat paths of a motor spindle on rolling bearings (issue 22).

The shaft, the bearings and the tool come from the rotor part of the deck; this section adds what the
rotor does not say: the housing around the shaft, the cooling jacket, the built-in motor, the lubrication
and the ambient; and when the analyses take the thermal state.  Every key carries its unit; the SI layout
is built in ``spindlesim.model.thermal`` (it needs the rotor; each bearing family builds its own set)::

    spindle_thermal:
      ambient_C: 20
      lubrication: {method: oil_air, grade: ISO VG 32}
      housing:
        start_mm: 20                              # from node 1 along z
        segments:                                 # [inner_dia_mm, outer_dia_mm, length_mm], along +z
          - [110, 170, 30]
          - [160, 210, 180]
      cooling_jacket: {start_mm: 120, length_mm: 180, hydraulic_diameter_mm: 8, channel_length_mm: 5340,
                       flow_l_min: 4, inlet_C: 20}
      motor: {start_mm: 120, length_mm: 180, rotor_inner_diameter_mm: 75, rotor_outer_diameter_mm: 110,
              stator_outer_diameter_mm: 160, gap_mm: 0.5, rated_power_kW: 18, efficiency: 0.9,
              base_speed_rpm: 9000, load_fraction: 0.3}
      analyses: steady                            # none | steady: static, modal, ... at thermal equilibrium
      speeds_rpm: [6000, 12000, 18000, 24000]     # what `spindlesim thermal` tabulates
      warm_up: {steps: [[0, 6000], [30, 12000], [60, 18000]], duration_min: 120}   # [time_min, speed_rpm]
"""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from ..fields import DeckModel, PositiveFloat

Expansion = Annotated[float, Field(ge=0.0, le=1e-3)]


HousingRow = Annotated[list[Annotated[float, Field(gt=0.0, le=1e5)]], Field(min_length=3, max_length=3)]


class SolidMaterial(DeckModel):
    """Heat and growth properties of a solid (housing, shaft)."""

    conductivity_W_mK: PositiveFloat = 42.3
    """Thermal conductivity. Default: low-alloy steel at 300 K (Incropera et al., Table A.1)."""
    density_kg_m3: PositiveFloat = 7858.0
    """Density (the heat capacity of the warm-up)."""
    specific_heat_J_kgK: PositiveFloat = 442.0
    """Specific heat capacity."""
    thermal_expansion_1_K: Expansion = 11.5e-6
    """Linear thermal expansion coefficient [1/K] (the axial growth of shaft and housing between the bearing
    sets and to the tool tip). Steel about 11.5e-6, grey cast iron 10-11e-6."""


class Housing(DeckModel):
    """The housing (sleeve) around the shaft: sections along z from `start_mm`."""

    start_mm: float = 0.0
    """Axial position of the housing's front face, measured like the shaft's nodes (node 1 at 0 unless
    `shaft.start_z_mm`); the machine holds the housing there (the origin of the thermal growth)."""
    segments: Annotated[list[HousingRow], Field(min_length=1, max_length=200)]
    """One row per housing section along +z: [inner_dia_mm, outer_dia_mm, length_mm]; the outer surface loses
    heat to the ambient air (free convection of a horizontal cylinder)."""
    material: SolidMaterial = SolidMaterial()
    """Material of the housing."""
    emissivity: Annotated[float, Field(ge=0.0, le=1.0)] = 0.0
    """Emissivity of the housing's outer surface for radiation to the surroundings (0: none)."""

    @model_validator(mode="after")
    def _walls(self):
        for i, (di, do, _) in enumerate(self.segments):
            if not do > di:
                raise ValueError(f"segments[{i}]: outer_dia_mm {do} must exceed inner_dia_mm {di}")
        return self


class CoolingJacket(DeckModel):
    """Coolant channels in the housing wall."""

    start_mm: float
    """Axial position where the jacket begins (along z, like the nodes)."""
    length_mm: PositiveFloat
    """Axial length of the housing the jacket covers."""
    channels: Annotated[int, Field(ge=1, le=1000)] = 1
    """Number of parallel channels (a helical groove is one channel)."""
    hydraulic_diameter_mm: PositiveFloat
    """Hydraulic diameter of one channel, 4 A / wetted perimeter."""
    channel_length_mm: PositiveFloat
    """Developed length of one channel (a helix: turns x pi x diameter)."""
    flow_l_min: Annotated[float, Field(gt=0.0, le=1e5)]
    """Total coolant flow. Zero flow is refused: without the jacket, leave the section out."""
    inlet_C: float = 20.0
    """Coolant inlet temperature."""
    coolant: Literal["water", "water_glycol_30", "water_glycol_50"] = "water"
    """Coolant: water, or water-glycol with 30 or 50 % glycol by mass."""
    segments: Annotated[int, Field(ge=1, le=100)] = 6
    """Coolant nodes along the flow (the coolant warms from inlet to outlet)."""


class Motor(DeckModel):
    """Built-in motor: rotor on the shaft, stator in the housing."""

    start_mm: float
    """Axial position of the rotor and stator stacks' front end (along z, like the nodes)."""
    length_mm: PositiveFloat
    """Stack length."""
    rotor_inner_diameter_mm: PositiveFloat
    """Bore of the rotor stack (its seat on the shaft)."""
    rotor_outer_diameter_mm: PositiveFloat
    """Outer diameter of the rotor stack."""
    stator_outer_diameter_mm: PositiveFloat
    """Outer diameter of the stator (its seat in the housing)."""
    gap_mm: PositiveFloat = 0.5
    """Radial air gap between rotor and stator."""
    rated_power_kW: PositiveFloat
    """Rated (S1) shaft power."""
    efficiency: Annotated[float, Field(gt=0.0, lt=1.0)]
    """Efficiency at rated power: the losses are P (1 - eta)/eta there."""
    base_speed_rpm: PositiveFloat
    """Base (corner) speed: constant torque below, constant power above."""
    load_fraction: Annotated[float, Field(ge=0.0, le=2.0)] = 0.0
    """Shaft power drawn as a fraction of the rated power at the current speed (0: idling, the usual
    condition of a warm-up test; 1: full load)."""

    @model_validator(mode="after")
    def _diameters(self):
        if not self.rotor_outer_diameter_mm > self.rotor_inner_diameter_mm:
            raise ValueError("rotor_outer_diameter_mm must exceed rotor_inner_diameter_mm")
        if not self.stator_outer_diameter_mm > self.rotor_outer_diameter_mm + 2 * self.gap_mm:
            raise ValueError("stator_outer_diameter_mm must exceed the rotor's outer diameter plus twice the gap")
        return self


class Lubrication(DeckModel):
    """The bearings' lubrication: method (Palmgren's f0) and oil."""

    method: Literal["grease", "oil_mist", "oil_air", "oil_bath", "oil_jet"] = "oil_air"
    """Lubrication method; it sets the viscous friction of the balls (Palmgren's f0) and the oil in the cavity."""
    grade: str = "ISO VG 32"
    """Oil (or grease base oil) ISO VG grade; its viscosity follows the balls' temperature (Walther)."""
    oil_volume_percent: Optional[Annotated[float, Field(ge=0.0, le=100.0)]] = None
    """Volume share of oil in the bearing cavity's oil-air mixture (the balls' drag). None: by the method, our
    estimates: grease 0, oil-air and oil-mist 0.05 %, oil jet 2 %, oil bath 10 %."""

    def oil_fraction(self) -> float:
        if self.oil_volume_percent is not None:
            return self.oil_volume_percent / 100.0
        return {"grease": 0.0, "oil_air": 5e-4, "oil_mist": 5e-4, "oil_jet": 0.02, "oil_bath": 0.1}[self.method]


class WarmUp(DeckModel):
    """A warm-up: speed steps in time (an ISO 230-3 test), integrated from the cold spindle."""

    steps: Annotated[list[Annotated[list[Annotated[float, Field(ge=0.0, le=1e6)]], Field(min_length=2, max_length=2)]],
                     Field(min_length=1, max_length=100)]
    """[time_min, speed_rpm] pairs: from each time on the spindle runs at that speed (the first at 0 min)."""
    duration_min: Annotated[float, Field(gt=0.0, le=1e5)]
    """How long the warm-up runs."""
    samples: Annotated[int, Field(ge=2, le=2000)] = 25
    """Instants at which the bearing states, stiffness and natural frequencies are reported (evenly spaced;
    each speed step within the duration adds its two sides)."""

    @model_validator(mode="after")
    def _times(self):
        times = [t for t, _ in self.steps]
        if times[0] != 0.0:
            raise ValueError("the first step starts at time 0")
        if any(b <= a for a, b in zip(times, times[1:])):
            raise ValueError("step times must increase")
        if times[-1] >= self.duration_min:
            raise ValueError("the last step must start before duration_min")
        return self


class SpindleThermalSection(DeckModel):
    """The thermal model of a motor spindle on ball bearings: housing, cooling jacket, motor, lubrication
    and ambient; bearing and motor heat, the spindle's temperatures, thermal growth and preload, at steady
    state and through a warm-up (docs/theory.md, "Spindle thermal model")."""

    ambient_C: float = 20.0
    """Temperature of the surrounding air."""
    reference_C: float = 20.0
    """Temperature at which the spindle was assembled (the bearings' preload and clearance as given)."""
    lubrication: Lubrication = Lubrication()
    """Lubrication of the ball bearings."""
    housing: Housing
    """The housing around the shaft."""
    cooling_jacket: Optional[CoolingJacket] = None
    """Coolant channels in the housing. None: the housing is cooled by the ambient air only."""
    motor: Optional[Motor] = None
    """Built-in motor. None: a belt- or coupling-driven spindle (no motor heat)."""
    analyses: Literal["none", "steady", "warm_up"] = "none"
    """steady: static, modal, campbell, frf, unbalance, chatter and transient take the bearings at the thermal
    equilibrium of each speed; warm_up: at the temperatures the `warm_up` has reached at `warm_up_at_min` (the
    bearings at those temperatures at each analysis's speed); none: the bearings as assembled (cold)."""
    warm_up_at_min: Optional[Annotated[float, Field(ge=0.0, le=1e5)]] = None
    """With `analyses: warm_up`: the time of the warm-up whose temperatures the analyses take (0: the cold
    start)."""
    speeds_rpm: Annotated[list[Annotated[float, Field(ge=0.0, le=1e6)]], Field(min_length=1, max_length=200)] = []
    """Speeds `spindlesim thermal` solves the thermal equilibrium at. Empty: the operating speed."""
    warm_up: Optional[WarmUp] = None
    """A warm-up for `spindlesim thermal` (temperatures, preload, tool-tip drift and modes in time)."""
    tolerance_K: Annotated[float, Field(gt=0.0, le=10.0)] = 0.01
    """Convergence of the coupled steady state: the largest temperature change between two iterations."""

    @model_validator(mode="after")
    def _warm_up_instant(self) -> "SpindleThermalSection":
        if self.analyses == "warm_up":
            if self.warm_up is None:
                raise ValueError("analyses: warm_up needs the warm_up section (the speed steps)")
            if self.warm_up_at_min is None:
                raise ValueError("analyses: warm_up needs warm_up_at_min (the instant the analyses take)")
            if self.warm_up_at_min > self.warm_up.duration_min:
                raise ValueError(f"warm_up_at_min {self.warm_up_at_min:g} lies beyond the warm-up's duration_min "
                                 f"{self.warm_up.duration_min:g}")
        elif self.warm_up_at_min is not None:
            raise ValueError("warm_up_at_min is read with analyses: warm_up only")
        return self
