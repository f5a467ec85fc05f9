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
    """Outer race on the housing bore (seed 000 "surface contact"), per metre of bore circumference.

    Each segment gets these times its arc on the housing radius, so the support does not change
    with the number of segments.  Seed 000 gives no values; defaults: 1.2e11 N/m^2 (1e9 N/m on each
    of 12 segments, stiffer than a roller contact, ~1.5e8 N/m) and damping ~5% of critical per segment.
    """

    stiffness_N_m2: PositiveFloat = 1.2e11
    damping_Ns_m2: NonNegFloat = 2.0e4
    tangential_stiffness_N_m2: NonNegFloat = 1.2e9
    friction: NonNegFloat = 0.0
    # the segment's outer face sits on the bore (seed 000 "surface contact"): it resists rocking with
    # k s^2/12, s the segment's arc on the housing radius; false = point support (no rocking stiffness)
    surface_contact: bool = True


class TransientWaviness(DeckModel):
    surface: Literal["inner", "outer", "roller"]
    waves: Annotated[int, Field(ge=1)]
    amplitude_um: NonNegFloat
    phase_deg: float = 0.0


class TransientIntegrator(DeckModel):
    # RK4: compiled fixed-step RK4 (default); the others are scipy's adaptive solve_ivp methods on the
    # numpy right-hand side (slow: a cross-check).  step_us bounds the RK4 step (default: 1 us for the
    # rigid race, the stability limit for the flexible race); rtol is for the adaptive methods
    # (default 1e-7 rigid race, 1e-5 flexible race).
    method: Literal["RK4", "RK45", "DOP853", "LSODA", "BDF", "Radau"] = "RK4"
    step_us: Optional[PositiveFloat] = None
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
