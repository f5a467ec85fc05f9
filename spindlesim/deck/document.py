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

from pydantic import AfterValidator, BaseModel, Field, create_model, model_validator

from ..bearings.ball.section import BallSection
from ..bearings.dtrb.section import DtrbSection
from ..chatter.section import ChatterSection
from ..bearings.types import BEARING_TYPES
from ..contact.section import ContactSection
from ..thermal.section import SpindleThermalSection
from ..fields import AnyNumber, DeckModel, Dof, NodeNumber, NonNegFloat, PositiveFloat, Range
from .studies import CalibrationSection, OptimizeSection
from .transient import RotorTransientSection, TransientSection

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
    "spindle_thermal": SpindleThermalSection,  # heat paths of a motor spindle on ball bearings (issue 22)
}


class InternalDamping(DeckModel):
    """Rotating (internal) damping of the shaft material, seed 003 eq. 17."""

    viscous_s: NonNegFloat = 0.0  # eta_v: K_B multiplier in C (s)
    """Viscous internal damping eta_v of the shaft material: the shaft's damping matrix gains eta_v K_B and its
    stiffness the circulatory term eta_v Omega K_C (seed 003 eq. 17; Omega the spin speed). 0: none."""
    hysteretic: Annotated[float, Field(ge=0, le=2.0)] = 0.0  # eta_h: loss factor
    """Hysteretic loss factor eta_h of the shaft material (dimensionless): bending stiffness (1 + eta_h)/sqrt(1
    + eta_h^2) K_B and circulatory term eta_h/sqrt(1 + eta_h^2) K_C (seed 003 eq. 17). 0: none."""


class Shaft(DeckModel):
    # one row per element: [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]
    elements: Annotated[list[ShaftRow], Field(min_length=1, max_length=500)]  # deck.limits.MAX_ROTOR_ELEMENTS
    """One row per Timoshenko beam element, from node 1 along +z; element i joins nodes i and i + 1. Row:
    [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N], each column in
    the unit its name gives and checked against that unit's range; outer diameter, length, density, E and G > 0,
    inner diameter >= 0 and smaller than the outer, Poisson's ratio in (-1, 0.5), axial force positive in
    tension (it stiffens the shaft)."""
    shear_coefficient: Optional[Annotated[float, Field(gt=0, le=10.0)]] = None  # overrides Cowper's hollow-circle formula
    """Timoshenko shear coefficient of every element (dimensionless). None: Cowper's formula for a hollow
    circle, per element from its Poisson's ratio and diameter ratio."""
    internal_damping: InternalDamping = InternalDamping()
    """Rotating (internal) damping of the shaft material; none by default."""
    start_z_mm: float = 0.0
    """Axial position z of node 1; the nodes follow at the element lengths."""


class ElementRows(DeckModel):
    # rows as the shaft's: [outer_dia_mm, inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N]
    elements: Annotated[list[ShaftRow], Field(min_length=1, max_length=200)]
    """One row per element, outwards from where the part is mounted, in the shaft's row layout: [outer_dia_mm,
    inner_dia_mm, length_mm, density_kg_m3, E_GPa, G_GPa, poisson, axial_force_N], checked as the shaft's rows.
    """


class ToolJoint(DeckModel):
    """Springs and dampers between two nodes, translational (x, y) and rotational (theta_x, theta_y):
    the tool in its holder (shrink fit, collet, Weldon), or the holder on the spindle (HSK, steep taper)."""

    translational_N_m: PositiveFloat
    """Stiffness of the joint's springs in x and in y (one spring per direction between the two nodes)."""
    rotational_Nm_rad: PositiveFloat
    """Tilt stiffness of the joint about x and about y."""
    translational_Ns_m: NonNegFloat = 0.0
    """Viscous damping of the joint in x and in y."""
    rotational_Nms_rad: NonNegFloat = 0.0
    """Viscous damping of the joint's tilt about x and about y."""


class ToolSection(DeckModel):
    """Holder and tool at the spindle nose: the tool tip becomes a node of the rotor.

    The holder's elements continue the shaft from ``holder_node`` (node 1: the nose) outwards, rigidly
    mounted, or through the ``interface`` joint (HSK, steep taper) when given; the ``joint`` holds the
    tool's first node at the holder's end; the tool's elements go on outwards to the tip.  New nodes
    are numbered after the shaft's: holder nodes (its first node too when there is an interface),
    then tool nodes; the tip is the last node."""

    holder_node: NodeNumber = 1
    """Shaft node the holder is mounted on: the spindle nose, which must be an end of the shaft (node 1 or the
    last node). The holder and the tool go outwards from it, away from the rest of the shaft."""
    interface: Optional[ToolJoint] = None
    """Joint between the spindle nose and the holder (HSK, steep taper). None: the holder's first node is the
    nose node itself (rigid mounting); given: the holder gets a node of its own at the nose, held by this joint.
    """
    holder: ElementRows
    """The holder's beam elements from the nose outwards."""
    joint: ToolJoint
    """Joint between the holder's last node and the tool's first node (shrink fit, collet, Weldon)."""
    tool: ElementRows
    """The tool's beam elements from the holder outwards; the last node is the tool tip (the default FRF point
    and the cutting point of `chatter`)."""


def _tool_name(name: str) -> str:
    """A tool's name names its group in tools.h5: no "/", no control character, no leading "."."""
    if "/" in name or any(ord(c) < 32 for c in name) or name.startswith("."):
        raise ValueError(f"a tool's name names its group in tools.h5: no '/', no control character and no leading "
                         f"'.' (got {name!r})")
    return name


ToolName = Annotated[str, Field(min_length=1, max_length=64), AfterValidator(_tool_name)]


class ToolEntry(DeckModel):
    """One tool of the library `spindlesim tools` couples onto the spindle (receptance coupling): any of the
    `tool:` section's parts; what the entry leaves out is the `tool:` section's."""

    name: ToolName
    """Name of the tool: its group in tools.h5, its line in the summary and the figures (unique in the list; no
    "/", not starting with ".")."""
    interface: Optional[ToolJoint] = None
    """Joint between the spindle nose and this tool's holder (HSK, steep taper). None: the `tool:` section's
    interface (and a rigid mounting where that has none)."""
    holder: Optional[ElementRows] = None
    """The holder's beam elements from the nose outwards. None: the `tool:` section's holder."""
    joint: Optional[ToolJoint] = None
    """Joint between the holder's last node and the tool's first node. None: the `tool:` section's joint."""
    tool: Optional[ElementRows] = None
    """The tool's beam elements from the holder outwards, the last node the tip. None: the `tool:` section's
    tool."""


def library_tools(deck: Any) -> list[tuple[str, ToolSection]]:
    """Every ``tools:`` entry as a complete :class:`ToolSection` (the parts it leaves out from ``tool:``), in
    deck order; an entry that leaves out a part the deck's ``tool:`` does not give raises ValueError naming it
    (the loader reports it located first)."""
    base = deck.tool
    out = []
    for entry in deck.tools or ():
        parts = {}
        for key in ("holder", "joint", "tool"):
            value = getattr(entry, key)
            if value is None:
                if base is None:
                    raise ValueError(f"tool {entry.name!r} needs {key!r} (the deck has no tool: section to take it "
                                     "from)")
                value = getattr(base, key)
            parts[key] = value
        interface = entry.interface if entry.interface is not None else (base.interface if base else None)
        out.append((entry.name, ToolSection(holder_node=base.holder_node if base else 1, interface=interface,
                                            **parts)))
    return out


class Journal(DeckModel):
    """A rigid journal: a rotor of one node with mass and no shaft (seed 000's 2-DOF test rig)."""

    mass_kg: PositiveFloat
    """Mass of the rigid journal: the whole rotor, one node with translations x and y only (no shaft, no tilt,
    no axial DOF: its point loads take fx_N and fy_N only)."""
    damping_Ns_mm: NonNegFloat = 0.0  # viscous damping of the journal to ground, x and y
    """Viscous damping of the journal to ground in x and in y (in N s/mm: 1 N s/mm = 1000 N s/m)."""


class Disk(DeckModel):
    node: NodeNumber
    """Node the rigid disk is attached to (1-based)."""
    mass_kg: NonNegFloat
    """Mass of the disk."""
    Ip_kg_m2: NonNegFloat
    """Polar mass moment of inertia of the disk (about the shaft axis): the gyroscopic term."""
    Id_kg_m2: NonNegFloat
    """Diametral (transverse) mass moment of inertia of the disk, about an axis across the shaft through its
    centre."""
    name: Optional[str] = None
    """Name of the disk in the output files; default disk1, disk2 ... in deck order."""


class Operating(DeckModel):
    speed_rpm: NonNegFloat
    """Shaft speed of the rotor analyses and of the bearings' operating point (spin about +z); `modal.speed_rpm`,
    `frf.speed_rpm` and a command's `--speed` override it where they exist."""
    gravity: bool = False
    """true: the weight of the shaft, tool, holder and disks acts along -y (a static load of every rotor
    analysis)."""
    g_m_s2: PositiveFloat = 9.80665
    """Gravitational acceleration used when `gravity` is true."""
    min_operating_rpm: Optional[PositiveFloat] = None
    """Minimum operating speed: the lower edge of the range from which API 684 separation margins of the
    critical speeds below it are measured. None: speed_rpm."""
    max_continuous_rpm: Optional[PositiveFloat] = None
    """Maximum continuous speed: the upper edge of the range from which API 684 separation margins of the
    critical speeds above it are measured. None: speed_rpm."""

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
    """Node number (1-based) the load acts on."""
    fx_N: float = 0.0
    """Static force along x (horizontal) on the shaft at the node."""
    fy_N: float = 0.0
    """Static force along y (vertical, up) on the shaft at the node."""
    fz_N: float = 0.0  # axial; adds the axial DOF to the model
    """Static axial force along +z on the shaft at the node. A non-zero value gives the rotor its axial DOF and
    needs a bearing that holds the shaft axially (type ball, or dtrb with dofs: 5)."""
    mx_Nm: float = 0.0
    """Static moment about x on the shaft at the node (right-hand rule)."""
    my_Nm: float = 0.0
    """Static moment about y on the shaft at the node (right-hand rule)."""


class NodeDof(DeckModel):
    node: NodeNumber
    """Node number (1-based)."""
    dof: Dof = "x"
    """Direction at the node: x, y (translations) or theta_x, theta_y (rotations about x and y, right-hand
    rule)."""


class StaticSection(DeckModel):
    stiffness_at: NodeDof = NodeDof(node=1, dof="x")
    """Node and direction of the static stiffness reported by `static`: the inverse of the static compliance
    there (N/m for x or y, N m/rad for a rotation)."""


class ModalSection(DeckModel):
    speed_rpm: Optional[NonNegFloat] = None
    """Shaft speed of the modal analysis; none: `operating.speed_rpm` (`spindlesim modal --speed` overrides
    both)."""
    modes: Annotated[int, Field(ge=1, le=1000)] = 8
    """Number of modes computed, lowest natural frequencies first."""


class CampbellSection(DeckModel):
    speeds_rpm: FrequencyRange = FrequencyRange(start=0.0, stop=12000.0, count=50)
    """Shaft speeds of the Campbell diagram (the bearings' state is solved again at each one)."""
    modes: Annotated[int, Field(ge=1, le=1000)] = 8
    """Number of modes tracked over the speeds."""
    # also the diagram with every bearing's coefficients frozen at this speed (e.g. 0: the stiffness at
    # rest), drawn over the speed-dependent one: what the speed effects of the bearings change
    compare_frozen_rpm: Optional[NonNegFloat] = None
    """Also draw the diagram with every bearing held at its coefficients of this speed (e.g. 0: the stiffness at
    rest) while the gyroscopic terms follow the speed, over the speed-dependent one: what the bearings' speed
    effects change (campbell_frozen.png and the frozen results in campbell.h5). None: not drawn."""


class FrfSection(DeckModel):
    """Receptance output/input; without them, x/x at the tool tip (deck section ``tool``) or node 1."""

    input: Optional[NodeDof] = None
    """Node and direction of the exciting force (or moment). None: x at the tool tip when the deck has a `tool`
    section, else x at node 1."""
    output: Optional[NodeDof] = None
    """Node and direction of the response. None: the same default as `input`."""
    frequencies_hz: Union[FrequencyRange, Annotated[list[PositiveFloat], Field(min_length=1, max_length=100_000)]] \
        = FrequencyRange(start=10.0, stop=5000.0, count=1000)
    """Frequencies of the receptance: a range, or an explicit list of positive frequencies."""
    speed_rpm: Optional[NonNegFloat] = None
    """Shaft speed of the FRF; none: `operating.speed_rpm` (`spindlesim frf --speed` overrides both)."""


class UnbalanceSection(DeckModel):
    node: NodeNumber
    """Node number (1-based) that carries the unbalance."""
    amount_g_mm: PositiveFloat
    """Unbalance m e: the unbalance mass times its distance from the axis (1 g mm = 1e-6 kg m)."""
    phase_deg: float = 0.0
    """Angular position of the unbalance at t = 0, from +x towards +y."""
    output: NodeDof = NodeDof(node=1, dof="x")
    """Node and direction of the response plotted and written over speed."""
    speeds_rpm: FrequencyRange
    """Shaft speeds of the synchronous response (stop greater than start). `rotor_transient` also applies the
    unbalance when its `unbalance` key is true."""


class SweepRange(DeckModel):
    start: AnyNumber
    """First value of the parameter, in the unit of the deck key it sets."""
    stop: AnyNumber
    """Last value of the parameter (included)."""
    count: Annotated[int, Field(ge=1, le=100_000)]
    """Number of evenly spaced values; whole numbers when start and stop are integers and the step is whole."""


class SweepSection(DeckModel):
    """A parameter study (issue 7): ``spindlesim sweep DECK`` runs ``analysis`` for every case."""

    analysis: str
    """Analysis run for every case (an analysis name of `analyses`, e.g. modal, campbell, static; checked when
    the sweep starts, not when the deck is read); `spindlesim sweep --analysis` overrides it."""
    mode: Literal["grid", "list"] = "grid"
    """grid: every combination of the parameters' values; list: the i-th values of all parameters together (the
    lists must have the same length)."""
    # deck path -> list of values, or {start, stop, count}
    parameters: Annotated[dict[str, Union[SweepRange, Annotated[list[Any], Field(min_length=1, max_length=10_000)]]],
                          Field(min_length=1, max_length=20)]
    """Deck path -> its values: a list, or {start, stop, count}. A path walks the deck by key, list index
    (0-based) or the name of a named item: operating.speed_rpm, bearings.front.K_N_m.0.0, shaft.elements.3.2.
    `--set PATH=...` on the command line overrides the entry with the same path."""


def bearing_types() -> dict[str, type[BaseModel]]:
    """Deck model of each bearing type, by its ``type`` tag."""
    return {name: t.entry for name, t in BEARING_TYPES.items()}


def _first_paragraph(doc: str | None) -> str:
    import inspect

    return inspect.cleandoc(doc or "").split("\n\n")[0]


@lru_cache(maxsize=1)
def deck_model() -> type[BaseModel]:
    """The top-level Deck model: rotor and analysis sections, the bearing union, :data:`SECTIONS`.

    The description of a section of :data:`SECTIONS` is the first paragraph of its model's docstring."""
    from .loader import ANALYSES

    models = tuple(bearing_types().values())
    bearing = Annotated[Union[models], Field(discriminator="type")]
    extra = {name: (Optional[m], Field(None, description=_first_paragraph(m.__doc__))) for name, m in SECTIONS.items()}
    return create_model(
        "Deck",
        __base__=DeckModel,
        title=(str, Field("untitled", description="Free text naming the machine or study (the `spindlesim decks` "
                          "list, sweep plot titles); the whole deck text is stored in every output file.")),
        shaft=(Optional[Shaft], Field(None, description="The flexible rotor: Timoshenko beam elements along z. "
                                      "Give this or `journal`.")),
        tool=(Optional[ToolSection], Field(None, description=_first_paragraph(ToolSection.__doc__) + " Needs "
                                           "`shaft`.")),
        tools=(Optional[Annotated[list[ToolEntry], Field(min_length=1, max_length=100)]],
               Field(None, description="A tool library (`spindlesim tools`): named tools, each any of the `tool:` "
                                       "section's parts (interface, holder, joint, tool; what an entry leaves out "
                                       "is the `tool:` section's), coupled onto the spindle by receptance "
                                       "coupling. Needs `shaft`.")),
        journal=(Optional[Journal], Field(None, description=_first_paragraph(Journal.__doc__) + " Give this or "
                                          "`shaft`.")),
        disks=(Annotated[list[Disk], Field(max_length=1000)],
               Field([], description="Rigid disks at nodes: mass and inertia (wheels, motor rotors, clamping units).")),
        bearings=(Annotated[list[bearing], Field(max_length=200)],  # type: ignore[valid-type]
                  Field([], description="The bearings between rotor nodes and ground, one entry each; `type` chooses "
                                        "the bearing family and so the entry's other keys.")),
        operating=(Optional[Operating], Field(None, description="Operating point of the rotor analyses: speed and "
                                                                "gravity.")),
        loads=(Annotated[list[PointLoad], Field(max_length=1000)],
               Field([], description="Static forces and moments on the rotor at nodes.")),
        analyses=(Optional[Annotated[list[str], Field(max_length=50)]],
                  Field(None, description="The analyses `spindlesim run` does, in this order; names: "
                                          f"{', '.join(ANALYSES)}. None (or an empty list): every analysis the deck "
                                          "has the sections for (`spindlesim run --help` lists them).")),
        static=(StaticSection, Field(StaticSection(), description="Settings of the static analysis.")),
        modal=(ModalSection, Field(ModalSection(), description="Settings of the modal analysis (damped modes).")),
        campbell=(CampbellSection, Field(CampbellSection(), description="Settings of the Campbell diagram.")),
        frf=(FrfSection, Field(FrfSection(), description="Settings of the frequency response (receptance) between "
                                                     "two DOFs.")),
        unbalance=(Optional[UnbalanceSection], Field(None, description="An unbalance and the synchronous response "
                                                     "to it over speed (`spindlesim unbalance`); `rotor_transient` "
                                                     "applies it too.")),
        calibration=(Optional[CalibrationSection], Field(None, description=_first_paragraph(
            CalibrationSection.__doc__) + " Not run by `spindlesim run`.")),
        optimize=(Optional[OptimizeSection], Field(None, description=_first_paragraph(
            OptimizeSection.__doc__) + " Not run by `spindlesim run`.")),
        sweep=(Optional[SweepSection], Field(None, description="A parameter study: `spindlesim sweep DECK` runs "
                                             "`analysis` for every case of the parameters' values (not run by "
                                             "`spindlesim run`).")),
        rotor_transient=(Optional[RotorTransientSection],
                         Field(None, description=_first_paragraph(RotorTransientSection.__doc__) + " Every key is "
                               "optional; without the section `spindlesim transient` uses the defaults.")),
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
