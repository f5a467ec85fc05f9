"""Deck schema: pydantic v2 models for every deck section (keys carry their units).

Extension points (docs/decisions.md): a bearing type registers its model with
``register_bearing_type(model)`` (the model has a ``type: Literal[...]`` field);
an optional top-level section registers with ``register_section(name, model)``.
Registration happens on import of ``spindlesim.deck.sections``.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Optional, Union

from pydantic import BaseModel, ConfigDict, Field, create_model


class DeckModel(BaseModel):
    """Base for deck models: unknown keys rejected, strict types, immutable."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True)


PositiveFloat = Annotated[float, Field(gt=0)]
NonNegFloat = Annotated[float, Field(ge=0)]
NodeNumber = Annotated[int, Field(ge=1, description="1-based node number")]
Matrix2 = Annotated[
    list[Annotated[list[float], Field(min_length=2, max_length=2)]],
    Field(min_length=2, max_length=2),
]
ShaftRow = Annotated[list[float], Field(min_length=8, max_length=8)]
Dof = Literal["x", "y", "theta_x", "theta_y"]


class InternalDamping(DeckModel):
    """Rotating (internal) damping of the shaft material, seed 003 eq. 17."""

    viscous_s: NonNegFloat = 0.0  # eta_v: K_B multiplier in C (s)
    hysteretic: NonNegFloat = 0.0  # eta_h: loss factor


class Shaft(DeckModel):
    # one row per element: [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]
    elements: Annotated[list[ShaftRow], Field(min_length=1)]
    shear_coefficient: Optional[PositiveFloat] = None  # overrides Cowper's hollow-circle formula
    internal_damping: InternalDamping = InternalDamping()
    start_z_mm: float = 0.0


class Disk(DeckModel):
    node: NodeNumber
    mass_kg: NonNegFloat
    Ip_kg_m2: NonNegFloat
    Id_kg_m2: NonNegFloat
    name: Optional[str] = None


class CoefficientTable(DeckModel):
    """Speed-dependent coefficients, interpolated linearly in speed (held constant outside)."""

    speed_rpm: Annotated[list[NonNegFloat], Field(min_length=2)]
    K_N_m: list[Matrix2]
    C_Ns_m: list[Matrix2]


class LinearBearing(DeckModel):
    type: Literal["linear"]
    name: str
    node: NodeNumber
    K_N_m: Optional[Matrix2] = None
    C_Ns_m: Optional[Matrix2] = None
    table: Optional[CoefficientTable] = None


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


class FrequencyRange(DeckModel):
    start: NonNegFloat
    stop: PositiveFloat
    count: Annotated[int, Field(ge=2, le=1_000_000)]


class StaticSection(DeckModel):
    stiffness_at: NodeDof = NodeDof(node=1, dof="x")


class ModalSection(DeckModel):
    speed_rpm: Optional[NonNegFloat] = None
    modes: Annotated[int, Field(ge=1)] = 8


class CampbellSection(DeckModel):
    speeds_rpm: FrequencyRange = FrequencyRange(start=0.0, stop=12000.0, count=50)
    modes: Annotated[int, Field(ge=1)] = 8


class FrfSection(DeckModel):
    input: NodeDof = NodeDof(node=1, dof="x")
    output: NodeDof = NodeDof(node=1, dof="x")
    frequencies_hz: Union[FrequencyRange, Annotated[list[PositiveFloat], Field(min_length=1)]] = FrequencyRange(
        start=10.0, stop=5000.0, count=1000
    )
    speed_rpm: Optional[NonNegFloat] = None


class UnbalanceSection(DeckModel):
    node: NodeNumber
    amount_g_mm: PositiveFloat
    phase_deg: float = 0.0
    output: NodeDof = NodeDof(node=1, dof="x")
    speeds_rpm: FrequencyRange


AnalysisName = Literal["static", "modal", "campbell", "frf", "unbalance"]

_BEARING_TYPES: dict[str, type[BaseModel]] = {"linear": LinearBearing}
_SECTIONS: dict[str, Any] = {}


def register_bearing_type(model: type[BaseModel]) -> None:
    """Add a bearing model to the ``bearings`` union; its ``type`` literal is the tag."""
    tag = model.model_fields["type"].annotation.__args__[0]  # type: ignore[union-attr]
    _BEARING_TYPES[tag] = model
    _deck_model_cache.clear()


def register_section(name: str, model: Any) -> None:
    """Add an optional top-level deck section ``name`` validated by ``model``."""
    _SECTIONS[name] = model
    _deck_model_cache.clear()


def bearing_types() -> dict[str, type[BaseModel]]:
    return dict(_BEARING_TYPES)


_deck_model_cache: dict[str, type[BaseModel]] = {}


def deck_model() -> type[BaseModel]:
    """The top-level Deck model built from the registered bearing types and sections."""
    if "deck" in _deck_model_cache:
        return _deck_model_cache["deck"]
    models = tuple(_BEARING_TYPES.values())
    bearing = models[0] if len(models) == 1 else Annotated[Union[models], Field(discriminator="type")]
    extra = {name: (Optional[m], None) for name, m in _SECTIONS.items()}
    model = create_model(
        "Deck",
        __base__=DeckModel,
        title=(str, "untitled"),
        shaft=(Optional[Shaft], None),
        disks=(list[Disk], []),
        bearings=(list[bearing], []),  # type: ignore[valid-type]
        operating=(Optional[Operating], None),
        loads=(list[PointLoad], []),
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
    _deck_model_cache["deck"] = model
    return model


class SweepSection(DeckModel):
    """A parameter study (issue 7): ``spindlesim sweep DECK`` runs ``analysis`` for every case."""

    analysis: str
    mode: Literal["grid", "list"] = "grid"
    # deck path -> list of values, or {start, stop, count}
    parameters: Annotated[dict[str, Union["SweepRange", Annotated[list[Any], Field(min_length=1)]]],
                          Field(min_length=1)]


class SweepRange(DeckModel):
    start: float
    stop: float
    count: Annotated[int, Field(ge=1, le=100_000)]


SweepSection.model_rebuild()


class RotorTransientSection(DeckModel):
    """Time response of a rotor with nonlinear bearings (seed 001 section 2-2): ``spindlesim transient``."""

    duration_s: PositiveFloat = 0.5
    time_step_s: PositiveFloat = 5e-5  # rounded down so a revolution is a whole number of steps
    record_node: Optional[NodeNumber] = None  # default: the first nonlinear bearing's node
    settle_fraction: Annotated[float, Field(ge=0.0, lt=1.0)] = 0.3  # start of the steady part for the spectrum
    unbalance: bool = True  # apply the deck's unbalance section
    perturbation: Optional["Perturbation"] = None


class Perturbation(DeckModel):
    """A static force held until t = 0 and then released (free vibration from a smooth shape)."""

    node: NodeNumber
    dof: Dof = "x"
    force_N: float = 100.0


RotorTransientSection.model_rebuild()
