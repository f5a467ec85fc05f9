"""Deck section ``contact:`` (issue 5): roller/raceway or ball contact pressure.

Keys carry their units; the conversion to SI happens in
:func:`spindlesim.runs.contact.contact_inputs`.  Either ``load_N`` (the roller load
directly) or ``most_loaded_roller`` (Stribeck's estimate from a bearing's radial load) is
given; ``ball`` replaces the roller by a point contact (for checking against Hertz).

    contact:
      load_N: 10000
      roller_radius_mm: 5.0
      roller_length_mm: 10.0
      profile: crowned            # straight | crowned | logarithmic
      crown_radius_mm: 2600.0     # seed 001 eq. 1
      raceway: inner              # inner | outer | flat
      raceway_radius_mm: 25.0
      tilt_deg: 0.0
      grid: {nx: 64, ny: 256}   # nx, ny 8..4096, nx x ny at most 131072
"""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from ..fields import DeckModel, NonNegFloat, PositiveFloat

GridSize = Annotated[int, Field(ge=8, le=4096)]
#: most cells of a grid, nx * ny: the influence sums (DC-FFT on 2nx x 2ny) take about 10 s at this size
MAX_CELLS = 131_072


class ContactMaterial(DeckModel):
    E_GPa: PositiveFloat = 208.0
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)] = 0.3


class ContactGrid(DeckModel):
    nx: GridSize = 64   # cells across the contact (rolling direction)
    ny: GridSize = 256  # cells along the roller (or the ball's second axis)

    @model_validator(mode="after")
    def _cells(self) -> "ContactGrid":
        if self.nx * self.ny > MAX_CELLS:
            raise ValueError(f"nx x ny = {self.nx * self.ny} cells; the limit is {MAX_CELLS} (e.g. nx: 64, ny: 2048)")
        return self


class MostLoadedRoller(DeckModel):
    """Roller load from Stribeck: Q_max = 4.08 F_r / Z (zero clearance, line contact)."""

    radial_load_N: PositiveFloat
    rollers: Annotated[int, Field(ge=1, le=1000)]


class BallContact(DeckModel):
    """Point contact with equivalent radii (a sphere on a flat: both = sphere radius)."""

    rx_mm: PositiveFloat
    ry_mm: Optional[PositiveFloat] = None


class ContactSection(DeckModel):
    load_N: Optional[PositiveFloat] = None
    most_loaded_roller: Optional[MostLoadedRoller] = None
    roller_radius_mm: PositiveFloat = 5.0
    roller_length_mm: PositiveFloat = 10.0
    profile: Literal["straight", "crowned", "logarithmic"] = "crowned"
    crown_radius_mm: Optional[PositiveFloat] = None
    design_load_N: Optional[PositiveFloat] = None  # logarithmic profile (Johns-Gohar)
    end_radius_mm: NonNegFloat = 0.0  # 0 = sharp roller ends
    raceway: Literal["inner", "outer", "flat"] = "inner"
    raceway_radius_mm: Optional[PositiveFloat] = None
    tilt_deg: Annotated[float, Field(ge=-5.0, le=5.0)] = 0.0
    roller_material: ContactMaterial = ContactMaterial()
    raceway_material: ContactMaterial = ContactMaterial()
    grid: ContactGrid = ContactGrid()
    check_edges: bool = True
    ball: Optional[BallContact] = None

    @model_validator(mode="after")
    def _consistent(self) -> "ContactSection":
        if (self.load_N is None) == (self.most_loaded_roller is None):
            raise ValueError("give exactly one of load_N and most_loaded_roller")
        if self.ball is not None:
            return self
        if self.profile == "crowned" and self.crown_radius_mm is None:
            raise ValueError("profile 'crowned' needs crown_radius_mm")
        if self.profile == "logarithmic" and self.design_load_N is None:
            raise ValueError("profile 'logarithmic' needs design_load_N")
        if self.raceway != "flat" and self.raceway_radius_mm is None:
            raise ValueError(f"raceway '{self.raceway}' needs raceway_radius_mm")
        if self.raceway == "outer" and self.raceway_radius_mm <= self.roller_radius_mm:
            raise ValueError("an outer raceway radius must exceed the roller radius")
        if 2.0 * self.end_radius_mm > self.roller_length_mm:
            raise ValueError("end_radius_mm must be at most half the roller length")
        return self

