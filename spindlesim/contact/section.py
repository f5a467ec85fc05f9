"""Deck section ``contact:`` (issue 5): roller/raceway or ball contact pressure.

Keys carry their units; :func:`solve_from_section` converts them to SI and solves the contact.  Either ``load_N`` (the roller load
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

import logging
import math
from typing import TYPE_CHECKING, Annotated, Literal, Optional

from pydantic import Field, model_validator

from ..fields import DeckModel, NonNegFloat, PositiveFloat

if TYPE_CHECKING:
    from .result import ContactResult

log = logging.getLogger(__name__)

GridSize = Annotated[int, Field(ge=8, le=4096)]
#: most cells of a grid, nx * ny: the influence sums (DC-FFT on 2nx x 2ny) take about 10 s at this size
MAX_CELLS = 131_072


class ContactMaterial(DeckModel):
    E_GPa: PositiveFloat = 208.0
    """Young's modulus."""
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)] = 0.3
    """Poisson's ratio (dimensionless)."""


class ContactGrid(DeckModel):
    nx: GridSize = 64   # cells across the contact (rolling direction)
    """Cells across the contact (rolling direction); nx x ny at most 131,072."""
    ny: GridSize = 256  # cells along the roller (or the ball's second axis)
    """Cells along the roller (or along the ball contact's second axis)."""

    @model_validator(mode="after")
    def _cells(self) -> "ContactGrid":
        if self.nx * self.ny > MAX_CELLS:
            raise ValueError(f"nx x ny = {self.nx * self.ny} cells; the limit is {MAX_CELLS} (e.g. nx: 64, ny: 2048)")
        return self


class MostLoadedRoller(DeckModel):
    """Roller load from Stribeck: Q_max = 4.08 F_r / Z (zero clearance, line contact)."""

    radial_load_N: PositiveFloat
    """Radial load F_r of the bearing."""
    rollers: Annotated[int, Field(ge=1, le=1000)]
    """Number of rollers Z; the most loaded roller then carries Q_max = 4.08 F_r / Z (Stribeck, zero clearance).
    """


class BallContact(DeckModel):
    """Point contact with equivalent radii (a sphere on a flat: both = sphere radius)."""

    rx_mm: PositiveFloat
    """Equivalent radius of the point contact in the rolling direction (a sphere on a flat: the sphere's
    radius)."""
    ry_mm: Optional[PositiveFloat] = None
    """Equivalent radius across the rolling direction. None: equal to `rx_mm`."""


class ContactSection(DeckModel):
    """What `spindlesim contact` computes: the pressure of one roller (or ball) on a raceway, frictionless
    normal contact of elastic half-spaces."""

    load_N: Optional[PositiveFloat] = None
    """Normal load of the roller (or ball) on the raceway. Give this or `most_loaded_roller`, not both."""
    most_loaded_roller: Optional[MostLoadedRoller] = None
    """The load from a bearing's radial load instead of `load_N`."""
    roller_radius_mm: PositiveFloat = 5.0
    """Roller radius."""
    roller_length_mm: PositiveFloat = 10.0
    """Roller length."""
    profile: Literal["straight", "crowned", "logarithmic"] = "crowned"
    """Roller profile along its axis: straight, crowned (a circular crown of `crown_radius_mm`, seed 001 eq. 1)
    or logarithmic (Johns-Gohar, sized for `design_load_N`)."""
    crown_radius_mm: Optional[PositiveFloat] = None
    """Crowning radius of a crowned roller; required by profile crowned."""
    design_load_N: Optional[PositiveFloat] = None  # logarithmic profile (Johns-Gohar)
    """Load the logarithmic profile is designed for; required by profile logarithmic."""
    end_radius_mm: NonNegFloat = 0.0  # 0 = sharp roller ends
    """Radius of the rounded roller ends; 0: sharp ends. At most half the roller length."""
    raceway: Literal["inner", "outer", "flat"] = "inner"
    """inner (convex raceway), outer (concave) or flat."""
    raceway_radius_mm: Optional[PositiveFloat] = None
    """Raceway radius; required unless the raceway is flat; an outer raceway's must exceed the roller radius."""
    tilt_deg: Annotated[float, Field(ge=-5.0, le=5.0)] = 0.0
    """Misalignment of the roller; positive loads its +y end."""
    roller_material: ContactMaterial = ContactMaterial()
    """Material of the roller (bearing steel by default)."""
    raceway_material: ContactMaterial = ContactMaterial()
    """Material of the raceway (bearing steel by default)."""
    grid: ContactGrid = ContactGrid()
    """Grid of the contact pressure solution."""
    check_edges: bool = True
    """true: when a sharp roller end is in contact, solve again with twice the cells along the roller and flag
    the edge stress (edge_singular)."""
    ball: Optional[BallContact] = None
    """A point contact with these equivalent radii instead of the roller (checks against Hertz); the roller's
    profile keys are then not used. None: the roller."""

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



# ----------------------------------------------------------------------------------------------
# deck units -> SI: the solvers take metres, pascals and radians (imported here when asked for, so that
# loading a deck does not import them)


def solve_from_section(sec: ContactSection, options: dict | None = None) -> ContactResult:
    """Convert a validated ``contact:`` section (deck units) to SI and solve it.  ``options`` may override
    ``load_N``, ``tilt_deg``, ``nx``, ``ny`` (None: the deck's)."""
    from .hertz import stribeck_max_roller_load
    from .problems import solve_point_contact

    opts = {k: v for k, v in (options or {}).items() if v is not None}
    if "load_N" in opts:
        load = float(opts["load_N"])
    elif sec.load_N is not None:
        load = sec.load_N
    else:
        m = sec.most_loaded_roller
        load = stribeck_max_roller_load(m.radial_load_N, m.rollers, line_contact_=sec.ball is None)
        log.info("most loaded element (Stribeck 4.08 Fr/Z): %.4g N", load)
    nx = int(opts.get("nx", sec.grid.nx))
    ny = int(opts.get("ny", sec.grid.ny))
    rm, wm = sec.roller_material, sec.raceway_material
    if sec.ball is not None:
        ry = sec.ball.ry_mm if sec.ball.ry_mm is not None else sec.ball.rx_mm
        return solve_point_contact(load, 1e-3 * sec.ball.rx_mm, 1e-3 * ry,
                                   E1_Pa=1e9 * rm.E_GPa, nu1=rm.poisson,
                                   E2_Pa=1e9 * wm.E_GPa, nu2=wm.poisson, n=max(nx, ny))
    return _solve_roller(sec, load, nx, ny, opts)


def _mm_to_m(value: float | None, none: float | None = None) -> float | None:
    """A length in mm as metres; None as ``none``."""
    return none if value is None else 1e-3 * value


def _solve_roller(sec: ContactSection, load: float, nx: int, ny: int, opts: dict) -> ContactResult:
    from .problems import solve_roller_contact

    rm, wm = sec.roller_material, sec.raceway_material
    return solve_roller_contact(
        load, 1e-3 * sec.roller_radius_mm, 1e-3 * sec.roller_length_mm,
        raceway_radius_m=_mm_to_m(sec.raceway_radius_mm, math.inf), raceway=sec.raceway,
        profile=sec.profile,
        crown_radius_m=_mm_to_m(sec.crown_radius_mm),
        design_load_N=sec.design_load_N, end_radius_m=1e-3 * sec.end_radius_mm,
        tilt_rad=math.radians(float(opts.get("tilt_deg", sec.tilt_deg))),
        roller_E_Pa=1e9 * rm.E_GPa, roller_nu=rm.poisson,
        raceway_E_Pa=1e9 * wm.E_GPa, raceway_nu=wm.poisson,
        nx=nx, ny=ny, check_edges=sec.check_edges,
    )
