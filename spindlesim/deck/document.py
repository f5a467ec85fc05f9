"""The deck document: the rotor sections, the analysis sections and one table of the rest.

Bearing entries come from ``spindlesim.bearings.types.BEARING_TYPES`` (a discriminated union
on ``type``); the other top-level sections of bearing families and physics packages are listed
in :data:`SECTIONS`.  Both are explicit tables: adding a family means adding a row.  Every key
carries its unit; the conversion to SI happens in ``spindlesim.model.build`` (rotor) and in
each family's builder (bearings).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Annotated, Any, Literal, Optional, Union

from pydantic import BaseModel, Field, create_model, model_validator

from ..bearings.dtrb.section import DtrbSection
from ..bearings.roller.section import TransientSection
from ..bearings.types import BEARING_TYPES
from ..contact.section import ContactSection
from ..fields import DeckModel, Dof, NodeNumber, NonNegFloat, PositiveFloat, Range

FrequencyRange = Range  # {start, stop, count}
ShaftRow = Annotated[list[float], Field(min_length=8, max_length=8)]
#: top-level sections contributed by bearing families and physics packages: name -> model
SECTIONS: dict[str, type[BaseModel]] = {
    "contact": ContactSection,
    "dtrb": DtrbSection,
    "transient": TransientSection,
}


class InternalDamping(DeckModel):
    """Rotating (internal) damping of the shaft material, seed 003 eq. 17."""

    viscous_s: NonNegFloat = 0.0  # eta_v: K_B multiplier in C (s)
    hysteretic: NonNegFloat = 0.0  # eta_h: loss factor


class Shaft(DeckModel):
    # one row per element: [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]
    elements: Annotated[list[ShaftRow], Field(min_length=1, max_length=5000)]
    shear_coefficient: Optional[PositiveFloat] = None  # overrides Cowper's hollow-circle formula
    internal_damping: InternalDamping = InternalDamping()
    start_z_mm: float = 0.0


class Journal(DeckModel):
    """A rigid journal: a rotor of one node with mass and no shaft (seed 000's 2-DOF test rig)."""

    mass_kg: PositiveFloat
    damping_Ns_mm: NonNegFloat = 0.0  # viscous damping of the journal to ground, x and y


class Disk(DeckModel):
    node: NodeNumber
    mass_kg: NonNegFloat
    Ip_kg_m2: NonNegFloat
    Id_kg_m2: NonNegFloat
    name: Optional[str] = None


class Operating(DeckModel):
    speed_rpm: NonNegFloat
    gravity: bool = False
    g_m_s2: PositiveFloat = 9.80665


class PointLoad(DeckModel):
    node: NodeNumber
    fx_N: float = 0.0
    fy_N: float = 0.0
    fz_N: float = 0.0  # axial; adds the axial DOF to the model
    mx_Nm: float = 0.0
    my_Nm: float = 0.0


class NodeDof(DeckModel):
    node: NodeNumber
    dof: Dof = "x"


class StaticSection(DeckModel):
    stiffness_at: NodeDof = NodeDof(node=1, dof="x")


class ModalSection(DeckModel):
    speed_rpm: Optional[NonNegFloat] = None
    modes: Annotated[int, Field(ge=1, le=1000)] = 8


class CampbellSection(DeckModel):
    speeds_rpm: FrequencyRange = FrequencyRange(start=0.0, stop=12000.0, count=50)
    modes: Annotated[int, Field(ge=1, le=1000)] = 8


class FrfSection(DeckModel):
    input: NodeDof = NodeDof(node=1, dof="x")
    output: NodeDof = NodeDof(node=1, dof="x")
    frequencies_hz: Union[FrequencyRange, Annotated[list[PositiveFloat], Field(min_length=1, max_length=1_000_000)]] \
        = FrequencyRange(start=10.0, stop=5000.0, count=1000)
    speed_rpm: Optional[NonNegFloat] = None


class UnbalanceSection(DeckModel):
    node: NodeNumber
    amount_g_mm: PositiveFloat
    phase_deg: float = 0.0
    output: NodeDof = NodeDof(node=1, dof="x")
    speeds_rpm: FrequencyRange


class SweepRange(DeckModel):
    start: float
    stop: float
    count: Annotated[int, Field(ge=1, le=100_000)]


class SweepSection(DeckModel):
    """A parameter study (issue 7): ``spindlesim sweep DECK`` runs ``analysis`` for every case."""

    analysis: str
    mode: Literal["grid", "list"] = "grid"
    # deck path -> list of values, or {start, stop, count}
    parameters: Annotated[dict[str, Union[SweepRange, Annotated[list[Any], Field(min_length=1)]]],
                          Field(min_length=1)]


class Perturbation(DeckModel):
    """A static force held until t = 0 and then released (free vibration from a smooth shape)."""

    node: NodeNumber
    dof: Dof = "x"
    force_N: float = 100.0


class SpeedRamp(DeckModel):
    """A linear speed ramp over the whole run (a run-up or run-down)."""

    start: NonNegFloat
    stop: NonNegFloat


class TimeLoad(DeckModel):
    """A force in time at a node: ``harmonic`` amplitude sin(2 pi f t + phase), f given in Hz or as
    an ``order`` of the shaft speed; a ``step`` switched on at ``time_s``; or a ``ramp`` that grows
    linearly to its amplitude at ``time_s``."""

    node: NodeNumber
    dof: Dof = "x"
    kind: Literal["harmonic", "step", "ramp"] = "harmonic"
    amplitude_N: float
    frequency_hz: Optional[PositiveFloat] = None
    order: Optional[PositiveFloat] = None
    phase_deg: float = 0.0
    time_s: NonNegFloat = 0.0

    @model_validator(mode="after")
    def _frequency(self) -> "TimeLoad":
        if self.kind == "harmonic" and (self.frequency_hz is None) == (self.order is None):
            raise ValueError("a harmonic load needs exactly one of frequency_hz and order")
        return self


class RotorTransientSection(DeckModel):
    """Time response of the rotor with its bearings' full nonlinear reactions (``spindlesim transient``)."""

    duration_s: PositiveFloat = 0.5
    # newmark: implicit average acceleration + Newton (any bearing); rk4: explicit fixed step with
    # compiled bearing forces; RK45, DOP853, Radau, BDF, LSODA: scipy's adaptive methods (a cross-check)
    method: Literal["newmark", "rk4", "RK45", "DOP853", "Radau", "BDF", "LSODA"] = "newmark"
    time_step_s: Optional[PositiveFloat] = None  # newmark default 5e-5; rk4 default: min(1 us, stability)
    sample_rate_hz: Optional[PositiveFloat] = None
    rtol: Optional[Annotated[float, Field(gt=0, lt=1e-2)]] = None  # scipy methods
    record_node: Optional[NodeNumber] = None  # default: the first bearing's node
    settle_fraction: Annotated[float, Field(ge=0.0, lt=1.0)] = 0.3  # start of the steady part for the spectrum
    unbalance: bool = True  # apply the deck's unbalance section
    speed_rpm: Optional[SpeedRamp] = None  # a run-up / run-down; default: operating.speed_rpm constant
    loads: Annotated[list[TimeLoad], Field(max_length=1000)] = []
    perturbation: Optional[Perturbation] = None


AnalysisName = Literal["static", "modal", "campbell", "frf", "unbalance"]


def bearing_types() -> dict[str, type[BaseModel]]:
    """Deck model of each bearing type, by its ``type`` tag."""
    return {name: t.entry for name, t in BEARING_TYPES.items()}


@lru_cache(maxsize=1)
def deck_model() -> type[BaseModel]:
    """The top-level Deck model: rotor and analysis sections, the bearing union, :data:`SECTIONS`."""
    models = tuple(bearing_types().values())
    bearing = Annotated[Union[models], Field(discriminator="type")]
    extra = {name: (Optional[m], None) for name, m in SECTIONS.items()}
    return create_model(
        "Deck",
        __base__=DeckModel,
        title=(str, "untitled"),
        shaft=(Optional[Shaft], None),
        journal=(Optional[Journal], None),
        disks=(Annotated[list[Disk], Field(max_length=5000)], []),
        bearings=(Annotated[list[bearing], Field(max_length=1000)], []),  # type: ignore[valid-type]
        operating=(Optional[Operating], None),
        loads=(Annotated[list[PointLoad], Field(max_length=5000)], []),
        analyses=(Optional[list[str]], None),
        static=(StaticSection, StaticSection()),
        modal=(ModalSection, ModalSection()),
        campbell=(CampbellSection, CampbellSection()),
        frf=(FrfSection, FrfSection()),
        unbalance=(Optional[UnbalanceSection], None),
        sweep=(Optional[SweepSection], None),
        rotor_transient=(Optional[RotorTransientSection], None),
        **extra,
    )
