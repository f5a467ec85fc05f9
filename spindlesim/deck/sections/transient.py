"""Deck section ``transient:`` (issue 4): rotor in a roller bearing, time integration.

Every key carries its unit; conversion to SI is in
``spindlesim.bearings.rolling.build.system_from_section``.  Defaults are seed
000's bearing (Table 1) with the shaft mass of Harsha and Kankar (2004); see
``spindlesim/decks/transient.yaml`` for the source of every number.
"""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from ..schema import DeckModel, NonNegFloat, PositiveFloat, register_section

Fraction = Annotated[float, Field(ge=0.0, lt=1.0)]


class TransientBearing(DeckModel):
    inner_raceway_diameter_mm: PositiveFloat = 18.738
    outer_raceway_diameter_mm: PositiveFloat = 28.262
    roller_diameter_mm: PositiveFloat = 4.762  # seed 000 Table 1 says "radius"; it is the diameter
    width_mm: PositiveFloat = 6.35
    housing_radius_mm: PositiveFloat = 16.0
    radial_clearance_mm: NonNegFloat = 0.0
    slip_inner: Fraction = 0.0
    slip_outer: Fraction = 0.0
    element: Literal["roller", "ball"] = "roller"
    # Hertz constant K of Q = K delta^n (total, both contacts); default: Palmgren for a roller
    contact_stiffness_N_per_m_n: Optional[PositiveFloat] = None
    E_GPa: PositiveFloat = 208.0
    density_kg_m3: PositiveFloat = 7850.0


class TransientShaft(DeckModel):
    mass_kg: PositiveFloat = 0.6
    damping_Ns_mm: NonNegFloat = 0.2
    radial_load_N: NonNegFloat = 6.0  # along -y (gravity direction)


class TransientOuterRace(DeckModel):
    segments: Annotated[int, Field(ge=3, le=360)] = 12


class TransientContact(DeckModel):
    """Eq. 30-31 parameters of the roller contacts (flexible_race model)."""

    damping_Ns_m2: NonNegFloat = 1.8e9  # c, with m2 = 1, m3 = 1
    velocity_exponent: PositiveFloat = 1.0
    indentation_exponent: NonNegFloat = 1.0
    friction: NonNegFloat = 0.0
    slip_regularisation_m_s: PositiveFloat = 1e-3


class TransientHousing(DeckModel):
    stiffness_N_m: PositiveFloat = 1e9  # per segment
    damping_Ns_m: NonNegFloat = 170.0  # per segment, ~5% of critical for a segment on its support
    tangential_stiffness_N_m: NonNegFloat = 1e7
    friction: NonNegFloat = 0.0


class TransientWaviness(DeckModel):
    surface: Literal["inner", "outer", "roller"]
    waves: Annotated[int, Field(ge=1)]
    amplitude_um: NonNegFloat
    phase_deg: float = 0.0


class TransientIntegrator(DeckModel):
    # defaults by model: rigid_race DOP853 / 1e-7; flexible_race RK45 / 1e-5 (measured fastest)
    method: Optional[Literal["RK45", "DOP853", "LSODA", "BDF", "Radau"]] = None
    rtol: Optional[Annotated[float, Field(gt=0, lt=1e-2)]] = None
    sample_rate_hz: Optional[PositiveFloat] = None
    chunks: Annotated[int, Field(ge=1, le=100000)] = 40


class TransientSection(DeckModel):
    model: Literal["flexible_race", "rigid_race"] = "flexible_race"
    rollers: Annotated[int, Field(ge=3, le=100)] = 8
    duration_s: PositiveFloat = 0.3
    settle_s: Optional[NonNegFloat] = None
    speed_rpm: NonNegFloat = 5000.0
    bearing: TransientBearing = TransientBearing()
    shaft: TransientShaft = TransientShaft()
    outer_race: TransientOuterRace = TransientOuterRace()
    contact: TransientContact = TransientContact()
    housing: TransientHousing = TransientHousing()
    waviness: list[TransientWaviness] = []
    integrator: TransientIntegrator = TransientIntegrator()

    @model_validator(mode="after")
    def _consistent(self) -> "TransientSection":
        b = self.bearing
        gap = b.outer_raceway_diameter_mm - b.inner_raceway_diameter_mm - 2 * b.roller_diameter_mm
        if gap < -1e-9:
            raise ValueError(f"rollers do not fit: outer - inner raceway diameter - 2 x roller diameter = {gap:.4g} mm")
        if b.housing_radius_mm <= 0.5 * b.outer_raceway_diameter_mm:
            raise ValueError("housing_radius_mm must exceed the outer raceway radius (it bounds the outer race)")
        if b.element == "ball" and b.contact_stiffness_N_per_m_n is None:
            raise ValueError("element 'ball' needs contact_stiffness_N_per_m_n (e.g. 7.055e9, Harsha and Kankar 2004)")
        if self.settle_s is not None and self.settle_s >= self.duration_s:
            raise ValueError("settle_s must be shorter than duration_s")
        if self.model == "flexible_race" and b.element == "ball":
            raise ValueError("the flexible_race model is a roller bearing (seed 000); use rigid_race for balls")
        return self


register_section("transient", TransientSection)
