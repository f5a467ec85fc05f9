"""Layout of a motor spindle for its thermal network: small frozen dataclasses in SI.

Each field maps one-to-one onto a deck key in deck units (the deck section converts: mm -> m,
L/min -> m^3/s, rpm -> rad/s, deg -> rad; W and degC unchanged); docs/theory.md ("Spindle thermal
model: heat transfer", builder) has the table.  Positions ``*_m`` along the shaft axis z are
measured from the start of the first shaft segment (the spindle nose), like the rotor's nodes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

from .conduction import SEAT_CONDUCTANCE_W_M2K
from .motor import MotorRating


@dataclass(frozen=True)
class Solid:
    """Conductivity [W/(m K)], density [kg/m^3], specific heat [J/(kg K)]."""

    conductivity_W_mK: float
    density_kg_m3: float
    specific_heat_J_kgK: float

    @property
    def volumetric_heat_J_m3K(self) -> float:
        return self.density_kg_m3 * self.specific_heat_J_kgK


#: 1Cr-1/2Mo alloy steel at 300 K (Incropera et al., Table A.1): shafts, rings, housings
STEEL = Solid(42.3, 7858.0, 442.0)
#: silicon electrical steel lamination stack, in-plane (our estimate: 3 % Si steel, 20-30 W/(m K))
LAMINATION = Solid(25.0, 7650.0, 460.0)


@dataclass(frozen=True)
class ShaftSegment:
    """One shaft section: a node at its centre.  ``surroundings``: what its outer surface sees where
    no bearing or rotor covers it: "housing" (the spindle's inner air, a rotating annulus to the
    housing around it), "ambient" (outside: rotating cylinder in still air) or "none"."""

    length_m: float
    outer_diameter_m: float
    inner_diameter_m: float = 0.0
    surroundings: str = "housing"


@dataclass(frozen=True)
class HousingSegment:
    """One section of the housing (a sleeve around the shaft): a node at its centre; the outer
    surface loses heat to the ambient (free convection of a horizontal cylinder, radiation)."""

    length_m: float
    inner_diameter_m: float
    outer_diameter_m: float


@dataclass(frozen=True)
class BearingConductances:
    """Conductances [W/K] of one bearing (all rows together): inner ring -- rolling elements, rolling elements --
    outer ring, rolling elements -- bearing cavity (the oil-air, to the housing)."""

    inner_balls_W_K: float
    balls_outer_W_K: float
    balls_cavity_W_K: float


class ContactPaths(Protocol):
    """What the spindle's network asks a bearing set about its rolling elements: the family's answer (each
    family's set carries its own; ``spindlesim/bearings/conductance.py``).

    ``elements``: the last part of the rolling elements' node name ("balls", "rollers");
    ``elements_mass_kg(s)``: their mass in the set ``s``;
    ``conductances(s, speed_rad_s, inner_N, outer_N, film_inner_m, film_outer_m, cavity_C)``: the set's
    :class:`BearingConductances` at a speed, with the contact loads per rolling element at the inner and the
    outer race [N] (arrays), the lubricant films [m] and the temperature of the cavity's air [C]."""

    elements: str

    def elements_mass_kg(self, s: "BearingSet") -> float: ...

    def conductances(self, s: "BearingSet", speed_rad_s: float, inner_N, outer_N, film_inner_m, film_outer_m,
                     cavity_C: float) -> BearingConductances: ...


@dataclass(frozen=True)
class BearingSet:
    """A bearing set (all its rows) centred at ``position_m``: three nodes, inner ring, rolling elements,
    outer ring.  ``balls`` rolling elements (all rows) of (mean) diameter ``ball_diameter_m`` on the pitch
    diameter at ``contact_angle_rad`` (a tapered roller bearing's cup angle, 0 for a cylindrical one).  What
    the contacts conduct is the family's: ``paths`` (:class:`ContactPaths`; a family's ``thermal_set`` gives
    it).  Masses default to estimates from the geometry (ring shoulders at d_m -+ 0.35 D)."""

    name: str
    position_m: float
    bore_m: float
    outer_diameter_m: float
    width_m: float                      # total width of the set
    balls: int                          # all rows together
    ball_diameter_m: float
    pitch_diameter_m: float
    contact_angle_rad: float
    nominal_contact_load_N: float       # per ball, used when no contact loads are given (e.g. the preload's)
    inner_conformity: float = 0.52
    outer_conformity: float = 0.53
    ring: Solid = STEEL
    ball: Solid = STEEL
    ring_E_Pa: float = 208e9
    ring_poisson: float = 0.3
    ball_E_Pa: float = 208e9
    ball_poisson: float = 0.3
    inner_ring_mass_kg: float | None = None
    outer_ring_mass_kg: float | None = None
    inner_seat_W_m2K: float = SEAT_CONDUCTANCE_W_M2K
    outer_seat_W_m2K: float = SEAT_CONDUCTANCE_W_M2K
    paths: ContactPaths | None = None

    @property
    def contact_paths(self) -> ContactPaths:
        """``paths``, which the network needs (a ValueError names the set without them)."""
        if self.paths is None:
            raise ValueError(f"bearing set {self.name!r} has no contact paths (its family's thermal_set gives them)")
        return self.paths

    @property
    def elements_node(self) -> str:
        """The name of its rolling elements' node: ``bearing:<name>:balls`` or ``bearing:<name>:rollers``."""
        return f"bearing:{self.name}:{self.contact_paths.elements}"

    @property
    def inner_shoulder_m(self) -> float:
        return self.pitch_diameter_m - 0.7 * self.ball_diameter_m

    @property
    def outer_shoulder_m(self) -> float:
        return self.pitch_diameter_m + 0.7 * self.ball_diameter_m

    def inner_mass_kg(self) -> float:
        if self.inner_ring_mass_kg is not None:
            return self.inner_ring_mass_kg
        return self.ring.density_kg_m3 * 0.25 * math.pi * (self.inner_shoulder_m ** 2 - self.bore_m ** 2) * self.width_m

    def outer_mass_kg(self) -> float:
        if self.outer_ring_mass_kg is not None:
            return self.outer_ring_mass_kg
        return self.ring.density_kg_m3 * 0.25 * math.pi * (self.outer_diameter_m ** 2 - self.outer_shoulder_m ** 2) * self.width_m

    def balls_mass_kg(self) -> float:
        """Mass of the rolling elements (balls or rollers) [kg]."""
        return self.contact_paths.elements_mass_kg(self)


@dataclass(frozen=True)
class CoolingJacket:
    """Coolant channels in the housing from ``start_m`` over ``length_m`` of the axis: ``channels``
    parallel channels of hydraulic diameter D_h and developed length ``channel_length_m`` each,
    total flow ``flow_m3_s`` entering at ``inlet_C``; ``segments`` coolant nodes along the flow.
    ``channel_area_m2``: flow cross-section of one channel (default pi D_h^2 / 4)."""

    start_m: float
    length_m: float
    channels: int
    hydraulic_diameter_m: float
    channel_length_m: float
    flow_m3_s: float
    inlet_C: float
    coolant: str = "water"
    segments: int = 4
    channel_area_m2: float | None = None
    correlation: str = "gnielinski"     # or "dittus_boelter" (turbulent branch)

    @property
    def area_m2(self) -> float:
        return self.channel_area_m2 if self.channel_area_m2 is not None else 0.25 * math.pi * self.hydraulic_diameter_m ** 2


@dataclass(frozen=True)
class MotorLayout:
    """Built-in motor from ``start_m`` over ``length_m``: rotor (on the shaft) and stator (in the
    housing) across the gap ``gap_m``.  Masses default to the lamination volumes."""

    start_m: float
    length_m: float
    rotor_inner_diameter_m: float
    rotor_outer_diameter_m: float
    stator_outer_diameter_m: float
    gap_m: float
    rating: MotorRating
    rotor_mass_kg: float | None = None
    stator_mass_kg: float | None = None
    material: Solid = LAMINATION
    rotor_seat_W_m2K: float = SEAT_CONDUCTANCE_W_M2K
    stator_seat_W_m2K: float = SEAT_CONDUCTANCE_W_M2K

    @property
    def stator_bore_m(self) -> float:
        return self.rotor_outer_diameter_m + 2.0 * self.gap_m

    def rotor_mass(self) -> float:
        if self.rotor_mass_kg is not None:
            return self.rotor_mass_kg
        return self.material.density_kg_m3 * 0.25 * math.pi * (self.rotor_outer_diameter_m ** 2
                                                               - self.rotor_inner_diameter_m ** 2) * self.length_m

    def stator_mass(self) -> float:
        if self.stator_mass_kg is not None:
            return self.stator_mass_kg
        return self.material.density_kg_m3 * 0.25 * math.pi * (self.stator_outer_diameter_m ** 2
                                                               - self.stator_bore_m ** 2) * self.length_m


@dataclass(frozen=True)
class SpindleLayout:
    """The whole spindle.  The housing starts at ``housing_start_m`` and its segments follow each
    other along z."""

    shaft: tuple[ShaftSegment, ...]
    housing: tuple[HousingSegment, ...]
    bearings: tuple[BearingSet, ...]
    ambient_C: float = 20.0
    housing_start_m: float = 0.0
    jacket: CoolingJacket | None = None
    motor: MotorLayout | None = None
    shaft_material: Solid = STEEL
    housing_material: Solid = STEEL
    housing_emissivity: float = 0.0
    internal_air_C: float | None = None   # property temperature of the inner air (default: ambient + 20 K)
