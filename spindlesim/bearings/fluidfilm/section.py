"""Deck bearing types ``three_lobe`` and ``plain`` (issue 3, fluid-film bearings).

Keys carry their units; conversion to SI happens in :func:`build` (the one place for this family).

    bearings:
      - name: front
        node: 7
        type: three_lobe          # n-lobe bearing (lobes.count, default 3)
        diameter_mm: 69.965       # journal diameter D
        width_mm: 69.965          # bearing width L
        clearance_mm: 0.012       # assembled radial clearance Cb
        preload: 0.5              # mp = 1 - Cb/Cp
        load_N: 400               # optional: downward load; else from the static state
        lobes: {count: 3, groove_width_deg: 20, offset: 0.5, orientation: on_lobe}
        oil: {grade: ISO VG 3, density_kg_m3: 805, specific_heat_J_kgK: 1940.681, inlet_C: 25}
        # or oil: {viscosity_Pa_s: 0.002}  (isoviscous)  or {walther_m: .., walther_k: ..}
        ambient: {temperature_C: 20, air_velocity_m_s: 0.1}
      - name: rear
        node: 18
        type: plain               # 360 deg bore; grooves: {count: 2, width_deg: 20}
        ...
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Literal, Optional

from pydantic import Field, model_validator

from ...fields import DeckModel, Fraction, NodeNumber, NonNegFloat, PositiveFloat

if TYPE_CHECKING:
    from .bearing import FluidFilmBearing


class Oil(DeckModel):
    """Exactly one of: ``grade`` (ISO VG), ``viscosity_Pa_s`` (isoviscous), or
    ``walther_m`` + ``walther_k`` (ASTM D341, cSt and K, decadic logs)."""

    grade: Optional[str] = None
    viscosity_Pa_s: Optional[PositiveFloat] = None
    walther_m: Optional[Annotated[float, Field(gt=0, le=100.0)]] = None  # slope B (dimensionless)
    walther_k: Optional[Annotated[float, Field(gt=0, le=100.0)]] = None  # constant A (dimensionless)
    density_kg_m3: Optional[PositiveFloat] = None
    specific_heat_J_kgK: Optional[PositiveFloat] = None
    inlet_C: float = 40.0

    @model_validator(mode="after")
    def _one_model(self) -> "Oil":
        walther = self.walther_m is not None or self.walther_k is not None
        given = [self.grade is not None, self.viscosity_Pa_s is not None, walther]
        if sum(given) != 1:
            raise ValueError("give exactly one of grade, viscosity_Pa_s, or walther_m + walther_k")
        if walther and (self.walther_m is None or self.walther_k is None):
            raise ValueError("walther_m and walther_k go together")
        if self.viscosity_Pa_s is None:
            missing = [k for k in ("density_kg_m3", "specific_heat_J_kgK") if getattr(self, k) is None]
            if missing:
                raise ValueError(f"the thermal balance needs {' and '.join(missing)}")
        return self


class Ambient(DeckModel):
    temperature_C: float = 20.0
    air_velocity_m_s: NonNegFloat = 0.0
    housing_area_m2: Optional[PositiveFloat] = None  # default 5 pi D L
    heat_transfer_W_m2K: Optional[PositiveFloat] = None  # default max(15, 7 + 12 sqrt(v))


class ThermalOptions(DeckModel):
    mixing_lambda: Fraction = 1.0 / 3.0  # seed 003 eq. 11; 1/3 fits its Table 1
    oil_flow: Literal["side", "inlet"] = "side"


class GridOptions(DeckModel):
    circumferential: Annotated[int, Field(ge=24, le=4096)] = 192
    axial: Annotated[int, Field(ge=2, le=256)] = 12


class Lobes(DeckModel):
    count: Annotated[int, Field(ge=2, le=12)] = 3
    groove_width_deg: Annotated[float, Field(ge=0.0, lt=180.0)] = 20.0
    offset: Annotated[float, Field(ge=0.0, le=1.0)] = 0.5
    orientation: Literal["on_lobe", "between_lobes"] = "on_lobe"
    first_lobe_centre_deg: Optional[float] = None  # overrides orientation (from +x to +y)


class Grooves(DeckModel):
    count: Annotated[int, Field(ge=0, le=12)] = 0
    width_deg: Annotated[float, Field(gt=0.0, lt=180.0)] = 20.0
    centre_deg: Optional[float] = None  # default: 90 deg from the (downward) load line


class _FluidFilm(DeckModel):
    name: str
    node: NodeNumber
    diameter_mm: PositiveFloat
    width_mm: PositiveFloat
    clearance_mm: PositiveFloat
    load_N: Optional[PositiveFloat] = None
    oil: Oil
    ambient: Ambient = Ambient()
    thermal: ThermalOptions = ThermalOptions()
    grid: GridOptions = GridOptions()
    # the film force of a transient: per-land tables of the same discrete Reynolds solution (within
    # 0.4-1.7 % of the full solve, microseconds a call) or the full solve at every Newton iteration
    transient_film: Literal["table", "reynolds"] = "table"


class ThreeLobeBearing(_FluidFilm):
    type: Literal["three_lobe"]
    preload: Fraction = 0.5
    lobes: Lobes = Lobes()

    @model_validator(mode="after")
    def _lobes_fit(self) -> "ThreeLobeBearing":
        if self.lobes.groove_width_deg >= 360.0 / self.lobes.count:
            raise ValueError("lobes.groove_width_deg must be smaller than 360 / lobes.count")
        return self


class PlainBearing(_FluidFilm):
    type: Literal["plain"]
    preload: Annotated[float, Field(ge=0.0, le=0.0)] = 0.0  # a plain bore has no preload
    grooves: Grooves = Grooves()
    feed: Literal["max_film", "periodic"] = "max_film"

    @model_validator(mode="after")
    def _grooves_fit(self) -> "PlainBearing":
        if self.grooves.count and self.grooves.count * self.grooves.width_deg >= 360.0:
            raise ValueError("the grooves cover the whole circumference")
        return self


def build(entry) -> "FluidFilmBearing":
    """Deck entry (deck units) -> :class:`FluidFilmBearing` (SI)."""
    from .bearing import FluidFilmBearing
    from .geometry import multilobe_geometry, plain_geometry
    from .thermal import ThermalParameters
    from .viscosity import ConstantViscosity, WaltherViscosity

    D, L, Cb = 1e-3 * entry.diameter_mm, 1e-3 * entry.width_mm, 1e-3 * entry.clearance_mm
    if entry.type == "three_lobe":
        lb = entry.lobes
        geo = multilobe_geometry(D, L, Cb, entry.preload, lb.count, lb.groove_width_deg,
                                 lb.offset, orientation=lb.orientation,
                                 first_lobe_centre_deg=lb.first_lobe_centre_deg)
    else:
        gr = entry.grooves
        geo = plain_geometry(D, L, Cb, gr.count, gr.width_deg, gr.centre_deg, feed=entry.feed)
    oil = entry.oil
    rho = oil.density_kg_m3 if oil.density_kg_m3 is not None else math.nan
    if oil.viscosity_Pa_s is not None:
        visc = ConstantViscosity(oil.viscosity_Pa_s, rho)
    elif oil.grade is not None:
        visc = WaltherViscosity.from_grade(oil.grade, rho)
    else:
        visc = WaltherViscosity(oil.walther_m, oil.walther_k, rho)
    amb = entry.ambient
    # an isoviscous oil without density / specific heat gets NaN temperatures and Re
    th = ThermalParameters(
        inlet_C=oil.inlet_C, ambient_C=amb.temperature_C, density_kg_m3=rho,
        specific_heat_J_kgK=(oil.specific_heat_J_kgK if oil.specific_heat_J_kgK is not None
                             else math.nan),
        air_velocity_m_s=amb.air_velocity_m_s, mixing_lambda=entry.thermal.mixing_lambda,
        housing_area_m2=amb.housing_area_m2, heat_transfer_W_m2K=amb.heat_transfer_W_m2K,
        oil_flow=entry.thermal.oil_flow)
    return FluidFilmBearing(entry.name, entry.node - 1, geo, visc, th, entry.load_N,
                            entry.grid.circumferential, entry.grid.axial, transient_film=entry.transient_film)
