"""Deck keys of the ball bearing (``type: ball``): rotor entry, standalone section, and ``build``.

Keys carry their units; :func:`build` is the one place where they become SI.  Only pydantic is
imported at module level (the physics is imported by ``build``), so loading a deck stays light.

Rotor deck entry (``bearings:`` list), 5 DOF at its node::

    - type: ball
      name: front
      node: 3
      balls: 18
      ball_diameter_mm: 12.7
      pitch_diameter_mm: 90.0
      contact_angle_deg: 15.0          # free contact angle as made; 0 for deep groove
      inner_conformity: 0.52           # groove radius / ball diameter
      outer_conformity: 0.53
      radial_clearance_um: 0.0         # operating radial (diametral) clearance; < 0: interference
      material: {E_GPa: 208.0, poisson: 0.3, density_kg_m3: 7850.0}
      ball_material: {E_GPa: 310.0, poisson: 0.26, density_kg_m3: 3200.0}   # optional (Si3N4)
      arrangement: DB                  # single | DB (back-to-back, O) | DF (face-to-face, X) | DT (tandem)
      rows: 2                          # 1 for single, 2-4 for sets
      row_spacing_mm: 20.0             # axial distance between adjacent ball rows
      axial_direction: "+z"            # thrust the tandem rows carry (single, DT, 3-row sets)
      preload: {kind: position, axial_um: 21.0}   # or {kind: spring, axial_N: 250.0, floating: outboard}
      model: outer_race_control        # or full
      dynamic_load_rating_N: null      # catalogue C of ONE bearing; null: ISO 281 from geometry
      reliability_percent: 90.0        # L_n = a_1 L_10

``preload``: ``position`` - ``axial_um`` is the total axial approach clamping imposes on the set
beyond first contact (catalogue preload offset), half of it taken by each opposed group; needs
DB or DF.  ``spring`` - ``axial_N`` is the constant force on the floating outer rings: the rows
with the thrust direction of the set's end row on the ``floating`` side (all rows of a single
bearing or tandem set).  ``floating: outboard`` (default) is the side facing the nearer end of
the shaft (where the springs of a rear set usually sit), ``inboard`` the other; ``+z`` / ``-z``
name the side in the deck's frame.  A bearing at the middle of the shaft, and the standalone
``bearing`` section, take outboard as +z.

Standalone section (``spindlesim bearing``), the same keys plus::

    bearing:
      type: ball
      ...
      load: {fx_N: 0.0, fy_N: 0.0, fz_N: 0.0, mx_Nm: 0.0, my_Nm: 0.0}   # shaft on bearing
      speed_rpm: 10000.0
      sweeps:
        preload: {start: 0.0, stop: 40.0, count: 21}   # axial_um or axial_N (the preload's kind)
        load: {component: fx_N, start: 0.0, stop: 5000.0, count: 11}
        speed_rpm: {start: 0.0, stop: 20000.0, count: 21}
"""

from __future__ import annotations

import math
from typing import Annotated, Literal, Optional, Union

from pydantic import Field, model_validator

from ...fields import DeckModel, Load5, NodeNumber, NonNegFloat, PositiveFloat, Range

LoadComponent = Literal["fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm"]
LOAD_COMPONENTS = ("fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm")


class BallMaterial(DeckModel):
    E_GPa: PositiveFloat = 208.0
    """Young's modulus."""
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)] = 0.3
    """Poisson's ratio (dimensionless)."""
    density_kg_m3: PositiveFloat = 7850.0
    """Density (the balls' centrifugal force and gyroscopic moment)."""


class PositionPreload(DeckModel):
    kind: Literal["position"]
    """position: the set is clamped to a fixed axial offset (needs opposed rows: DB or DF); spring: a constant
    axial force on the floating outer rings."""
    axial_um: NonNegFloat
    """Total axial approach the clamping imposes on the set beyond first contact (the catalogue preload offset
    of a matched pair); each opposed group takes half of it. 0: rows just touching."""


class SpringPreload(DeckModel):
    kind: Literal["spring"]
    """position: the set is clamped to a fixed axial offset (needs opposed rows: DB or DF); spring: a constant
    axial force on the floating outer rings."""
    axial_N: PositiveFloat
    """Constant axial force of the springs on the floating outer rings (they slide in the housing, so these rows
    add no axial stiffness)."""
    # which rows float: those with the thrust direction of the set's end row on this side; outboard /
    # inboard: the side facing the nearer / farther end of the shaft (resolved by ``placed``)
    floating: Literal["outboard", "inboard", "+z", "-z"] = "outboard"
    """Which rows float: those with the thrust direction of the set's end row on this side. outboard: the side
    facing the nearer end of the shaft (where the springs of a rear set usually sit); inboard: the other side;
    +z, -z: the side in the deck's frame. A bearing at the middle of the shaft and the standalone `bearing`
    section take outboard as +z."""


SIDES = {"+z": 1, "-z": -1}


PreloadSpec = Annotated[Union[PositionPreload, SpringPreload], Field(discriminator="kind")]


class _BallKeys(DeckModel):
    """Keys shared by the rotor entry and the standalone section."""

    balls: Annotated[int, Field(ge=3, le=1000)]
    """Number of balls in each row; they must fit on the pitch circle."""
    ball_diameter_mm: PositiveFloat
    """Ball diameter D; less than half the pitch diameter."""
    pitch_diameter_mm: PositiveFloat
    """Pitch diameter d_m: the circle through the ball centres."""
    contact_angle_deg: Annotated[float, Field(ge=0.0, lt=60.0)]
    """Free contact angle the bearing is made with (15, 25 ... for angular-contact bearings; 0 for a deep-groove
    bearing)."""
    inner_conformity: Annotated[float, Field(gt=0, le=10.0)]  # 0.5 .. 1 (checked below, with the reason)
    """Inner groove radius over the ball diameter, f_i = r_i / D (dimensionless); must lie between 0.5 and 1
    (0.52 is usual)."""
    outer_conformity: Annotated[float, Field(gt=0, le=10.0)]
    """Outer groove radius over the ball diameter, f_o = r_o / D (dimensionless); between 0.5 and 1 (0.53 is
    usual)."""
    radial_clearance_um: float = 0.0
    """Operating radial internal clearance P_d: the total radial play of the inner ring (diametral clearance,
    not per side); negative: interference from fits and temperature. Limited so that the free contact angle
    stays below 60 deg."""
    material: BallMaterial = BallMaterial()
    """Rings' material (and the balls' unless `ball_material` is given): through-hardened bearing steel by
    default."""
    ball_material: Optional[BallMaterial] = None
    """Balls' material when it differs from the rings' (e.g. silicon nitride in a hybrid bearing: E_GPa 310,
    poisson 0.26, density_kg_m3 3200); a key left out takes the steel default below, not `material`'s value.
    None: as `material`."""
    arrangement: Literal["single", "DB", "DF", "DT"] = "single"
    """single: one row; a matched set: DB (back-to-back, O), DF (face-to-face, X), DT (tandem, every row carries
    the same thrust direction)."""
    rows: Optional[Annotated[int, Field(ge=1, le=4)]] = None
    """Number of ball rows: 1 for single, 2 to 4 for a set. None: 1 for single, 2 for a set."""
    row_spacing_mm: Optional[PositiveFloat] = None
    """Axial distance between adjacent ball rows of a set (e.g. the bearing width for matched bearings side by
    side); required for a set, at least the ball diameter. The rows sit symmetrically about the node."""
    axial_direction: Literal["+z", "-z"] = "+z"
    """Thrust direction of the shaft on the bearing that the rows carry: for a single row and a tandem set, and
    the tandem pair of a 3-row set; +z: the shaft pushing along +z. Has no meaning for a DB or DF set with an
    even number of rows."""
    preload: Optional[PreloadSpec] = None
    """Preload of the set: {kind: position, axial_um} or {kind: spring, axial_N, floating}. None: no preload
    (only the clearance and the loads)."""
    model: Literal["outer_race_control", "full"] = "outer_race_control"
    """Ball equilibrium: outer_race_control (the whole gyroscopic couple on the outer contact, Jones 1960) or
    full (the couple shared by both contacts, no race-control hypothesis)."""
    dynamic_load_rating_N: Optional[PositiveFloat] = None
    """Basic dynamic load rating C of ONE bearing (a catalogue value) for the rating lives. None: computed from
    the geometry (ISO 281)."""
    reliability_percent: Annotated[float, Field(ge=90.0, le=99.95)] = 90.0
    """Reliability of the rating life L_n = a_1 L_10 (ISO 281 a_1 factor): 90 gives L_10."""

    @property
    def row_count(self) -> int:
        return self.rows if self.rows is not None else (1 if self.arrangement == "single" else 2)

    @model_validator(mode="after")
    def _consistent(self):
        D, dm, Z = self.ball_diameter_mm, self.pitch_diameter_mm, self.balls
        for key in ("inner_conformity", "outer_conformity"):
            f = getattr(self, key)
            if not 0.5 < f < 1.0:
                raise ValueError(f"{key} (groove radius / ball diameter) must lie between 0.5 and 1.0, not {f}: "
                                 "at 0.5 the groove fits the ball exactly (conforming contact, no Hertz solution)")
        if D >= 0.5 * dm:
            raise ValueError(f"ball_diameter_mm {D} must be smaller than half the pitch diameter ({0.5 * dm})")
        chord = dm * math.sin(math.pi / Z)
        if chord <= D:
            raise ValueError(f"{Z} balls of {D} mm do not fit on the {dm} mm pitch circle: adjacent ball centres are "
                             f"{chord:.3f} mm apart (at most {int(math.pi / math.asin(D / dm))} balls fit)")
        A0_um = 1e3 * (self.inner_conformity + self.outer_conformity - 1.0) * D
        radial_um = A0_um * math.cos(math.radians(self.contact_angle_deg)) - 0.5 * self.radial_clearance_um
        if radial_um <= 0.5 * A0_um:
            raise ValueError(f"radial_clearance_um {self.radial_clearance_um} is too large for the grooves: the balls "
                             f"would take a free contact angle above 60 deg (groove-centre distance "
                             f"(f_i + f_o - 1) D = {A0_um:.1f} um)")
        n = self.row_count
        if self.arrangement == "single":
            if n != 1:
                raise ValueError("arrangement single has rows: 1 (use DB, DF or DT for a set)")
        else:
            if not 2 <= n <= 4:
                raise ValueError(f"a {self.arrangement} set has 2 to 4 rows, not {n}")
            if self.row_spacing_mm is None:
                raise ValueError(f"row_spacing_mm is required for a {self.arrangement} set (axial distance between "
                                 "adjacent ball rows, e.g. the bearing width for matched bearings)")
            if self.row_spacing_mm < D:
                raise ValueError(f"row_spacing_mm {self.row_spacing_mm} is smaller than the ball diameter {D}")
        if "axial_direction" in self.model_fields_set and self.arrangement in ("DB", "DF") and n % 2 == 0:
            raise ValueError(f"axial_direction has no meaning for a symmetric {self.arrangement} set of {n} rows")
        if isinstance(self.preload, PositionPreload) and self.arrangement not in ("DB", "DF"):
            raise ValueError(f"a position preload needs opposed rows (arrangement DB or DF), not {self.arrangement}: "
                             "give a spring preload, or preload through the opposed bearing of the rotor")
        return self


class BallBearingEntry(_BallKeys):
    """Rotor deck entry ``type: ball`` (5 DOF at ``node``)."""

    type: Literal["ball"]
    """Bearing type: ball (angular-contact or deep-groove ball bearing, single row or matched set; 5 DOF at its
    node, no damping model)."""
    name: str
    """Bearing name, unique in the deck (output groups, sweep paths)."""
    node: NodeNumber
    """Shaft node of the bearing (1-based); the rows sit about it."""


class LoadSweep(DeckModel):
    component: LoadComponent
    """Load component swept; the other components keep their `load` values."""
    start: Annotated[float, Field(ge=-1e9, le=1e9)]  # N or N m
    """First value of the swept component (N for a force, N m for a moment)."""
    stop: Annotated[float, Field(ge=-1e9, le=1e9)]
    """Last value (included); must differ from `start`."""
    count: Annotated[int, Field(ge=2, le=100_000)]
    """Number of evenly spaced load values, both ends included."""

    @model_validator(mode="after")
    def _distinct(self):
        if self.stop == self.start:
            raise ValueError("load sweep: stop must differ from start")
        return self


class BallSweeps(DeckModel):
    preload: Optional[Range] = None     # in the preload's unit: axial_um (position) or axial_N (spring)
    """Preload sweep in the unit of the preload's kind: axial_um for position, axial_N for spring (a spring
    sweep must start above 0 N); needs `preload`."""
    load: Optional[LoadSweep] = None
    """Sweep of one load component at the section's speed."""
    speed_rpm: Optional[Range] = None
    """Speed sweep at the section's load (stiffness and contact angles over speed)."""


class BallSection(_BallKeys):
    """What `spindlesim bearing` computes: one ball bearing or matched set (``type: ball``) under a load:
    stiffness, ball loads, contact angles, pressures and lives, with optional sweeps."""

    type: Literal["ball"] = "ball"
    """Bearing type of the section: ball (the only type; a deck with a `dtrb` section runs that bearing
    instead)."""
    name: str = "ball"
    """Bearing name in the output file."""
    load: Load5 = Load5()
    """Load of the shaft on the bearing (forces and moments about the bearing centre)."""
    speed_rpm: NonNegFloat = 0.0
    """Inner-ring speed of the operating point (outer ring fixed)."""
    sweeps: BallSweeps = BallSweeps()
    """Optional sweeps over preload, load and speed, each around the operating point."""

    @model_validator(mode="after")
    def _sweeps(self):
        if self.sweeps.preload is not None:
            if self.preload is None:
                raise ValueError("sweeps.preload needs a preload (its kind sets the unit of the sweep)")
            if isinstance(self.preload, SpringPreload) and self.sweeps.preload.start <= 0.0:
                raise ValueError("sweeps.preload of a spring preload must start above 0 N")
        return self


def _material(m: BallMaterial):
    from .geometry import Material

    return Material(E_Pa=1e9 * m.E_GPa, poisson=m.poisson, density_kg_m3=m.density_kg_m3)


def geometry_from(entry: _BallKeys):
    """SI :class:`~.geometry.BallGeometry` of a validated entry or section."""
    from .geometry import ball_geometry

    return ball_geometry(
        balls=entry.balls, ball_diameter_m=1e-3 * entry.ball_diameter_mm,
        pitch_diameter_m=1e-3 * entry.pitch_diameter_mm,
        contact_angle_deg=entry.contact_angle_deg, inner_conformity=entry.inner_conformity,
        outer_conformity=entry.outer_conformity, clearance_m=1e-6 * entry.radial_clearance_um,
        ring=_material(entry.material), ball=None if entry.ball_material is None else _material(entry.ball_material),
        arrangement=entry.arrangement, rows=entry.row_count,
        row_spacing_m=0.0 if entry.row_spacing_mm is None else 1e-3 * entry.row_spacing_mm,
        direction=1 if entry.axial_direction == "+z" else -1)


def preload_from(entry: _BallKeys):
    """SI :class:`~.bearing.Preload` of an entry."""
    from .bearing import Preload

    pre = entry.preload
    if pre is None:
        return Preload()
    if isinstance(pre, PositionPreload):
        return Preload("position", axial_m=1e-6 * pre.axial_um)
    return Preload("spring", axial_N=pre.axial_N, floating_side=SIDES.get(pre.floating, 1))


def placed(entry: BallBearingEntry, node_z_m: float, shaft_z_m: tuple[float, float]) -> BallBearingEntry:
    """The entry with ``floating: outboard / inboard`` resolved to the side along z, from where the
    bearing sits on the shaft (its node's z within the shaft's [z_min, z_max])."""
    pre = entry.preload
    if not isinstance(pre, SpringPreload) or pre.floating in SIDES:
        return entry
    outboard = "+z" if node_z_m >= 0.5 * (shaft_z_m[0] + shaft_z_m[1]) else "-z"
    side = outboard if pre.floating == "outboard" else ("-z" if outboard == "+z" else "+z")
    return entry.model_copy(update={"preload": pre.model_copy(update={"floating": side})})


def preload_unit_to_si(entry: _BallKeys, value: float) -> float:
    """A swept preload value in deck units (um or N) -> SI (m or N)."""
    return 1e-6 * value if isinstance(entry.preload, PositionPreload) else float(value)


def build(entry: _BallKeys):
    """Deck entry or section (deck units) -> :class:`~.bearing.BallBearing` (SI, 0-based node)."""
    from .bearing import BallBearing
    from .rating import RatingInputs

    return BallBearing(
        geometry_from(entry), preload_from(entry), name=entry.name, node=getattr(entry, "node", 1) - 1,
        model=entry.model,
        rating=RatingInputs(dynamic_load_rating_N=entry.dynamic_load_rating_N,
                            reliability_percent=entry.reliability_percent))
