"""The deck document: the rotor sections, the analysis sections and one table of the rest.

Bearing entries come from ``spindlesim.bearings.types.BEARING_TYPES`` (a discriminated union
on ``type``); the other top-level sections of bearing families and physics packages are listed
in :data:`SECTIONS`.  Both are explicit tables: adding a family means adding a row.  Every key
carries its unit; the conversion to SI happens in ``spindlesim.model.build`` (rotor) and in
each family's builder (bearings).
"""

from __future__ import annotations

from functools import lru_cache
from types import UnionType
from typing import Annotated, Any, Literal, Optional, Union, get_args, get_origin

from pydantic import BaseModel, Field, create_model, model_validator

from ..bearings.ball.section import BallSection
from ..bearings.dtrb.section import DtrbSection
from ..bearings.roller.section import TransientSection
from ..chatter.section import ChatterSection
from ..bearings.types import BEARING_TYPES
from ..contact.section import ContactSection
from ..fields import ANY_NUMBER, AnyNumber, DeckModel, Dof, NodeNumber, NonNegFloat, PositiveFloat, Range

FrequencyRange = Range  # {start, stop, count}
#: [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]; the loader
#: checks each column against its unit's range (deck/loader.py, _row_checks)
ShaftRow = Annotated[list[AnyNumber], Field(min_length=8, max_length=8)]
#: top-level sections contributed by bearing families and physics packages: name -> model
SECTIONS: dict[str, type[BaseModel]] = {
    "bearing": BallSection,  # `spindlesim bearing`: one bearing (set) under a load (type: ball)
    "chatter": ChatterSection,  # `spindlesim chatter`: the cutting process and the FRF's source
    "contact": ContactSection,
    "dtrb": DtrbSection,
    "transient": TransientSection,
}


class InternalDamping(DeckModel):
    """Rotating (internal) damping of the shaft material, seed 003 eq. 17."""

    viscous_s: NonNegFloat = 0.0  # eta_v: K_B multiplier in C (s)
    hysteretic: Annotated[float, Field(ge=0, le=2.0)] = 0.0  # eta_h: loss factor


class Shaft(DeckModel):
    # one row per element: [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]
    elements: Annotated[list[ShaftRow], Field(min_length=1, max_length=500)]  # deck.limits.MAX_ROTOR_ELEMENTS
    shear_coefficient: Optional[Annotated[float, Field(gt=0, le=10.0)]] = None  # overrides Cowper's hollow-circle formula
    internal_damping: InternalDamping = InternalDamping()
    start_z_mm: float = 0.0


class ElementRows(DeckModel):
    # rows as the shaft's: [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]
    elements: Annotated[list[ShaftRow], Field(min_length=1, max_length=200)]


class ToolJoint(DeckModel):
    """Springs and dampers between two nodes, translational (x, y) and rotational (theta_x, theta_y):
    the tool in its holder (shrink fit, collet, Weldon), or the holder on the spindle (HSK, steep taper)."""

    translational_N_m: PositiveFloat
    rotational_Nm_rad: PositiveFloat
    translational_Ns_m: NonNegFloat = 0.0
    rotational_Nms_rad: NonNegFloat = 0.0


class ToolSection(DeckModel):
    """Holder and tool at the spindle nose: the tool tip becomes a node of the rotor.

    The holder's elements continue the shaft from ``holder_node`` (node 1: the nose) outwards, rigidly
    mounted, or through the ``interface`` joint (HSK, steep taper) when given; the ``joint`` holds the
    tool's first node at the holder's end; the tool's elements go on outwards to the tip.  New nodes
    are numbered after the shaft's: holder nodes (its first node too when there is an interface),
    then tool nodes; the tip is the last node."""

    holder_node: NodeNumber = 1
    interface: Optional[ToolJoint] = None
    holder: ElementRows
    joint: ToolJoint
    tool: ElementRows


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
    # the operating speed range for API 684 separation margins (default: speed_rpm alone)
    min_operating_rpm: Optional[PositiveFloat] = None
    max_continuous_rpm: Optional[PositiveFloat] = None

    @model_validator(mode="after")
    def _range(self) -> "Operating":
        lo, hi = self.min_operating_rpm, self.max_continuous_rpm
        if lo is not None and hi is not None and lo > hi:
            raise ValueError("min_operating_rpm exceeds max_continuous_rpm")
        return self

    @property
    def speed_range_rpm(self) -> tuple[float, float] | None:
        """(minimum operating, maximum continuous speed) [rpm], each defaulting to speed_rpm; None when
        neither is known (speed_rpm 0 and no range given)."""
        lo = self.min_operating_rpm if self.min_operating_rpm is not None else self.speed_rpm
        hi = self.max_continuous_rpm if self.max_continuous_rpm is not None else self.speed_rpm
        lo, hi = (lo or hi), (hi or lo)
        return (float(min(lo, hi)), float(max(lo, hi))) if lo and hi else None


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
    # also the diagram with every bearing's coefficients frozen at this speed (e.g. 0: the stiffness at
    # rest), drawn over the speed-dependent one: what the speed effects of the bearings change
    compare_frozen_rpm: Optional[NonNegFloat] = None


class FrfSection(DeckModel):
    """Receptance output/input; without them, x/x at the tool tip (deck section ``tool``) or node 1."""

    input: Optional[NodeDof] = None
    output: Optional[NodeDof] = None
    frequencies_hz: Union[FrequencyRange, Annotated[list[PositiveFloat], Field(min_length=1, max_length=100_000)]] \
        = FrequencyRange(start=10.0, stop=5000.0, count=1000)
    speed_rpm: Optional[NonNegFloat] = None


class UnbalanceSection(DeckModel):
    node: NodeNumber
    amount_g_mm: PositiveFloat
    phase_deg: float = 0.0
    output: NodeDof = NodeDof(node=1, dof="x")
    speeds_rpm: FrequencyRange


class SweepRange(DeckModel):
    start: AnyNumber
    stop: AnyNumber
    count: Annotated[int, Field(ge=1, le=100_000)]


class SweepSection(DeckModel):
    """A parameter study (issue 7): ``spindlesim sweep DECK`` runs ``analysis`` for every case."""

    analysis: str
    mode: Literal["grid", "list"] = "grid"
    # deck path -> list of values, or {start, stop, count}
    parameters: Annotated[dict[str, Union[SweepRange, Annotated[list[Any], Field(min_length=1, max_length=10_000)]]],
                          Field(min_length=1, max_length=20)]


class Perturbation(DeckModel):
    """A static force held until t = 0 and then released (free vibration from a smooth shape)."""

    node: NodeNumber
    dof: Dof = "x"
    force_N: float = 100.0


class SpeedRamp(DeckModel):
    """A linear speed ramp over the whole run (a run-up or run-down)."""

    start: Annotated[float, Field(ge=0, le=ANY_NUMBER)]
    stop: Annotated[float, Field(ge=0, le=ANY_NUMBER)]


class TimeLoad(DeckModel):
    """A force in time at a node: ``harmonic`` amplitude sin(2 pi f t + phase), f given in Hz or as
    an ``order`` of the shaft speed; a ``step`` switched on at ``time_s``; or a ``ramp`` that grows
    linearly to its amplitude at ``time_s``."""

    node: NodeNumber
    dof: Dof = "x"
    kind: Literal["harmonic", "step", "ramp"] = "harmonic"
    amplitude_N: float
    frequency_hz: Optional[PositiveFloat] = None
    order: Optional[Annotated[float, Field(gt=0, le=1000.0)]] = None
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
        tool=(Optional[ToolSection], None),
        journal=(Optional[Journal], None),
        disks=(Annotated[list[Disk], Field(max_length=1000)], []),
        bearings=(Annotated[list[bearing], Field(max_length=200)], []),  # type: ignore[valid-type]
        operating=(Optional[Operating], None),
        loads=(Annotated[list[PointLoad], Field(max_length=1000)], []),
        analyses=(Optional[Annotated[list[str], Field(max_length=50)]], None),
        static=(StaticSection, StaticSection()),
        modal=(ModalSection, ModalSection()),
        campbell=(CampbellSection, CampbellSection()),
        frf=(FrfSection, FrfSection()),
        unbalance=(Optional[UnbalanceSection], None),
        sweep=(Optional[SweepSection], None),
        rotor_transient=(Optional[RotorTransientSection], None),
        **extra,
    )


def _unwrap(ann: Any, value: Any) -> Any:
    """The member of ``ann`` (Optional, Union, Annotated) that fits ``value`` best."""
    while get_origin(ann) is Annotated:
        ann = get_args(ann)[0]
    if get_origin(ann) not in (Union, UnionType):
        return ann
    members = [_unwrap(a, value) for a in get_args(ann) if a is not type(None)]
    models = [m for m in members if isinstance(m, type) and issubclass(m, BaseModel)]
    if isinstance(value, dict) and models:
        tag = value.get("type", value.get("kind"))
        for m in models:
            lit = m.model_fields.get("type") or m.model_fields.get("kind")
            if lit is not None and tag in get_args(lit.annotation):
                return m
        return max(models, key=lambda m: len(set(m.model_fields) & set(value)))
    if isinstance(value, list):
        lists = [m for m in members if get_origin(m) is list]
        if lists:
            return lists[0]
    return members[0] if members else ann


def keys_at(data: Any, path: tuple[Any, ...]) -> list[str]:
    """The keys the schema allows in the mapping at ``path`` of the deck ``data`` ([] if not a model)."""
    ann: Any = deck_model()
    cur = data
    for item in (*path, None):
        ann = _unwrap(ann, cur)
        if item is None:
            break
        if isinstance(ann, type) and issubclass(ann, BaseModel) and item in ann.model_fields:
            ann = ann.model_fields[item].annotation
        elif get_origin(ann) is list and isinstance(item, int):
            ann = get_args(ann)[0]
        elif get_origin(ann) is dict:
            ann = get_args(ann)[1]
        else:
            return []
        cur = cur.get(item) if isinstance(cur, dict) else cur[item] if isinstance(cur, list) and \
            isinstance(item, int) and 0 <= item < len(cur) else None
    if isinstance(ann, type) and issubclass(ann, BaseModel):
        return list(ann.model_fields)
    return []
