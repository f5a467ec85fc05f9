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
from ..plausible import Found, clearance, metres

if TYPE_CHECKING:
    from .bearing import FluidFilmBearing


class Oil(DeckModel):
    """Exactly one of: ``grade`` (ISO VG), ``viscosity_Pa_s`` (isoviscous), or
    ``walther_m`` + ``walther_k`` (ASTM D341, cSt and K, decadic logs)."""

    grade: Optional[str] = None
    """ISO 3448 viscosity grade, e.g. 'ISO VG 3' or 'VG32' (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220,
    320, 460, 680, 1000 or 1500): a generic mineral oil of that grade (Walther constants from its 40 degC
    mid-point viscosity and a typical 100 degC one). An unknown grade is reported when the bearing is built
    (exit code 1), not when the deck is read. Give exactly one of grade, viscosity_Pa_s, or walther_m with
    walther_k."""
    viscosity_Pa_s: Optional[PositiveFloat] = None
    """Constant dynamic viscosity: an isoviscous film (the viscosity does not follow the temperature). Density
    and specific heat may then be left out; without them no temperatures are computed."""
    walther_m: Optional[Annotated[float, Field(gt=0, le=100.0)]] = None  # slope B (dimensionless)
    """Walther (ASTM D341) slope m of log10 log10(nu + 0.8) = k - m log10(T), nu in cSt and T in K
    (dimensionless); goes with walther_k."""
    walther_k: Optional[Annotated[float, Field(gt=0, le=100.0)]] = None  # constant A (dimensionless)
    """Walther (ASTM D341) constant k of the same relation (dimensionless); goes with walther_m."""
    density_kg_m3: Optional[PositiveFloat] = None
    """Oil density, taken constant; required unless the oil is isoviscous."""
    specific_heat_J_kgK: Optional[PositiveFloat] = None
    """Specific heat of the oil (heat balance); required unless the oil is isoviscous."""
    inlet_C: float = 40.0
    """Oil supply temperature theta_i."""

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
    """Temperature of the air around the housing, theta_E."""
    air_velocity_m_s: NonNegFloat = 0.0
    """Air velocity over the housing; sets the default heat-transfer coefficient."""
    housing_area_m2: Optional[PositiveFloat] = None  # default 5 pi D L
    """Housing surface that gives heat to the air. None: 5 pi D L (a cylinder of diameter 2.5 D and length 2 L).
    """
    heat_transfer_W_m2K: Optional[PositiveFloat] = None  # default max(15, 7 + 12 sqrt(v))
    """Heat-transfer coefficient from the housing to the air. None: max(15, 7 + 12 sqrt(v)), v the air velocity
    in m/s."""


class ThermalOptions(DeckModel):
    mixing_lambda: Fraction = 1.0 / 3.0  # seed 003 eq. 11; 1/3 fits its Table 1
    """Mixing coefficient lambda of the mean film temperature theta = lambda theta_in + (1 - lambda) theta_out
    (seed 003 eq. 11); 1/3 reproduces seed 003's Table 1."""
    oil_flow: Literal["side", "inlet"] = "side"
    """Oil flow that carries the heat away: side (the lands' side leakage, replaced by fresh oil; the rest
    recirculates) or inlet (the lands' inlet flow: all oil renewed)."""


class GridOptions(DeckModel):
    circumferential: Annotated[int, Field(ge=24, le=4096)] = 192
    """Finite-difference intervals of the Reynolds equation around 360 deg."""
    axial: Annotated[int, Field(ge=2, le=256)] = 12
    """Finite-difference intervals across half the bearing width (the film is symmetric about the mid-plane)."""


class Lobes(DeckModel):
    count: Annotated[int, Field(ge=2, le=12)] = 3
    """Number of lobes (3 for a three-lobe bearing)."""
    groove_width_deg: Annotated[float, Field(ge=0.0, lt=180.0)] = 20.0
    """Angular width of each axial groove between lobes; less than 360 / count."""
    offset: Annotated[float, Field(ge=0.0, le=1.0)] = 0.5
    """Lobe offset factor (dimensionless): the lobe's preload centre lies at this fraction of its arc from the
    leading edge; 0.5: symmetric lobes."""
    orientation: Literal["on_lobe", "between_lobes"] = "on_lobe"
    """Where the load line falls: on_lobe (the first lobe's centre on the downward load line) or between_lobes
    (a groove on it)."""
    first_lobe_centre_deg: Optional[float] = None  # overrides orientation (from +x to +y)
    """Angle of the first lobe's centre, from +x towards +y; overrides `orientation`. None: from `orientation`.
    """


class Grooves(DeckModel):
    count: Annotated[int, Field(ge=0, le=12)] = 0
    """Number of axial grooves of a plain bearing; 0: a 360 deg bore."""
    width_deg: Annotated[float, Field(gt=0.0, lt=180.0)] = 20.0
    """Angular width of each groove; together they must leave some bore."""
    centre_deg: Optional[float] = None  # default: 90 deg from the (downward) load line
    """Angle of the first groove's centre, from +x towards +y. None: 90 deg from the downward load line."""


class _FluidFilm(DeckModel):
    name: str
    """Bearing name, unique in the deck (output groups, sweep paths)."""
    node: NodeNumber
    """Shaft node of the bearing (1-based)."""
    diameter_mm: PositiveFloat
    """Journal diameter D."""
    width_mm: PositiveFloat
    """Bearing width L."""
    clearance_mm: PositiveFloat
    """Assembled radial clearance Cb (per side: bore radius minus journal radius at the closest point of a
    centred journal)."""
    load_N: Optional[PositiveFloat] = None
    """A downward load on the bearing (shaft on bearing, along -y) in addition to the rotor's own static
    reaction; the film runs at the eccentricity that carries both, and in a rotor the journal is measured from
    the position carrying `load_N` alone. None: the bearing carries what the rotor's static equilibrium gives it
    (`thermal` and `coefficients` then need the rotor)."""
    oil: Oil
    """The lubricant: exactly one viscosity model (grade, viscosity_Pa_s, or walther_m and walther_k) and, for
    the heat balance, density and specific heat."""
    ambient: Ambient = Ambient()
    """Air around the housing (heat given off by the housing)."""
    thermal: ThermalOptions = ThermalOptions()
    """Options of the thermal equilibrium."""
    grid: GridOptions = GridOptions()
    """Finite-difference grid of the Reynolds equation."""
    # the film force of a transient: per-land tables of the same discrete Reynolds solution (within
    # 0.4-1.7 % of the full solve, microseconds a call) or the full solve at every Newton iteration
    transient_film: Literal["table", "reynolds"] = "table"
    """Film force in a time integration: table (per-land tables of the same discrete Reynolds solution, within
    about 0.4 to 1.7 % of it and far faster) or reynolds (the full solution at every call)."""


class ThreeLobeBearing(_FluidFilm):
    type: Literal["three_lobe"]
    """Bearing type: three_lobe (an n-lobe fluid-film bearing, `lobes.count` lobes; coefficients from the
    Reynolds equation at thermal equilibrium)."""
    preload: Fraction = 0.5
    """Preload factor mp = 1 - Cb/Cp (dimensionless), Cp the lobes' own clearance."""
    lobes: Lobes = Lobes()
    """Lobe layout."""

    @model_validator(mode="after")
    def _lobes_fit(self) -> "ThreeLobeBearing":
        if self.lobes.groove_width_deg >= 360.0 / self.lobes.count:
            raise ValueError("lobes.groove_width_deg must be smaller than 360 / lobes.count")
        return self


class PlainBearing(_FluidFilm):
    type: Literal["plain"]
    """Bearing type: plain (a cylindrical fluid-film journal bearing, 360 deg or with axial grooves)."""
    preload: Annotated[float, Field(ge=0.0, le=0.0)] = 0.0  # a plain bore has no preload
    """Preload factor: always 0 for a plain bore."""
    grooves: Grooves = Grooves()
    """Axial grooves of the bore."""
    feed: Literal["max_film", "periodic"] = "max_film"
    """Film boundary of a 360 deg bore: max_film (the film starts at its largest gap, Raimondi and Boyd 1958) or
    periodic (the film closes on itself)."""

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


def plausibility(entry, at: tuple) -> Found:
    """Likely unit mistakes of a fluid-film entry at the key path ``at``: its diameter and width (metres?), a
    clearance over 1 % of the journal diameter (micrometres?)."""
    bad: Found = []
    metres(entry, at, ("diameter_mm", "width_mm"), bad)
    c = entry.clearance_mm
    clearance(c, entry.diameter_mm, "clearance_mm", "the journal diameter", at, bad, f" ({c:g} um = {c * 1e-3:g} mm)")
    return bad
