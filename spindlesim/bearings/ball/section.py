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
      preload: {kind: position, axial_um: 21.0}   # or {kind: spring, axial_N: 250.0, floating: outward}
      model: outer_race_control        # or inner_race_control, full
      dynamic_load_rating_N: null      # catalogue C of ONE bearing; null: ISO 281 from geometry
      reliability_percent: 90.0        # L_n = a_1 L_10
      # optional, the bearing at temperature (docs/deck-format.md); materials take thermal_expansion_1_K
      temperatures_C: {inner_ring: 40, outer_ring: 30, rolling_elements: 35, reference: 20}
      fits_um: {shaft: 3.0, housing: -2.0}                      # diametral; needs mounting
      mounting: {bore_mm: 70, outer_diameter_mm: 110, shaft_bore_mm: 30}
      damping: {stiffness_proportional_s: 1.0e-5}   # C = beta K (the default; 0: undamped)

``preload``: ``position`` - ``axial_um`` is the total axial approach clamping imposes on the set
beyond first contact (catalogue preload offset), half of it taken by each opposed group; needs
DB or DF.  ``spring`` - ``axial_N`` is the constant force on the floating outer rings: the rows
whose thrust points the ``floating`` way (all rows of a single bearing or tandem set).
``floating: outward`` (default): the rows carrying thrust towards the nearer end of the shaft, which
the shaft's thermal growth would load; ``inward`` the others; ``+z`` / ``-z`` name the thrust in the
deck's frame.  A bearing at the middle of the shaft, and the standalone ``bearing`` section, take
outward as +z.

Standalone section (``spindlesim bearing``), the same keys plus::

    bearing:
      type: ball
      ...
      load: {fx_N: 0.0, fy_N: 0.0, fz_N: 0.0, mx_Nm: 0.0, my_Nm: 0.0}   # shaft on bearing
      speed_rpm: 10000.0
      held: {theta_x_mrad: 0.0, theta_y_mrad: 0.0}   # DOFs held at a displacement, the others free (x_um ...)
      model: auto                      # the section also takes auto: Jones' criterion per ball and point
      shoulders: {inner_height_mm: 3.8, outer_height_mm: 3.8}   # or *_angle_deg; default 0.3 D each
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
from ..damping import RollingDamping
from .section_thermal import (BallFits, BallMaterial, BallMounting, BallTemperatures, growth_checks,  # noqa: F401
                              growth_plausibility, plausibility, thermal_inputs, thermal_set)

LoadComponent = Literal["fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm"]
LOAD_COMPONENTS = ("fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm")
#: held-DOF keys, the DOF each names, its load component and the factor to SI
HELD_KEYS = (("x_um", "x", "fx_N", 1e-6), ("y_um", "y", "fy_N", 1e-6), ("z_um", "z", "fz_N", 1e-6),
             ("theta_x_mrad", "theta_x", "mx_Nm", 1e-3), ("theta_y_mrad", "theta_y", "my_Nm", 1e-3))
Tilt_mrad = Annotated[float, Field(ge=-100.0, le=100.0)]


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
    floating: Literal["outward", "inward", "+z", "-z"] = "outward"
    """Which rows float: those whose thrust (the axial load they carry from the shaft) points this way.
    outward: towards the nearer end of the shaft, so that the shaft's thermal growth, which pushes the inner
    rings outward, is taken by the springs and does not raise the preload (the usual rear set of a motor
    spindle); inward: the other rows; +z, -z: the direction in the deck's frame. A single row or a tandem set
    floats whole. A bearing at the middle of the shaft and the standalone `bearing` section take outward as
    +z."""


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
    model: Literal["outer_race_control", "inner_race_control", "full"] = "outer_race_control"
    """Race control of the balls (Jones 1960): outer_race_control (the balls roll without spin on the outer
    race, which carries the whole gyroscopic couple), inner_race_control (the same on the inner race) or full
    (the couple shared by both contacts, no race-control hypothesis). Jones' criterion in the output of
    `spindlesim bearing` says which one the contacts can hold."""
    dynamic_load_rating_N: Optional[PositiveFloat] = None
    """Basic dynamic load rating C of ONE bearing (a catalogue value) for the rating lives. None: computed from
    the geometry (ISO 281)."""
    reliability_percent: Annotated[float, Field(ge=90.0, le=99.95)] = 90.0
    """Reliability of the rating life L_n = a_1 L_10 (ISO 281 a_1 factor): 90 gives L_10."""
    temperatures_C: Optional[BallTemperatures] = None
    """Prescribed temperatures of the parts: the bearing is computed at the operating clearance and preload
    its thermal growth gives (as in MESYS). None: every part at the reference temperature (as made)."""
    fits_um: Optional[BallFits] = None
    """Ring fits on the shaft and in the housing (diametral interference); needs `mounting`. None: free rings."""
    mounting: Optional[BallMounting] = None
    """Seat diameters and the shaft and housing bodies of the fits (and of the rings' growth at speed)."""

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
    node, damped by `damping`)."""
    name: str
    """Bearing name, unique in the deck (output groups, sweep paths)."""
    node: NodeNumber
    """Shaft node of the bearing (1-based); the rows sit about it."""
    damping: RollingDamping = RollingDamping()
    """Damping of the set: C = beta K on its 5 x 5 tangent stiffness (x, y, z, tilts), beta
    `stiffness_proportional_s` (default 1.0e-5 s; 0: undamped)."""


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


class HeldDofs(DeckModel):
    """DOFs of the inner ring held at a prescribed displacement from the bearing centre; the other DOFs are free
    and carry the load. A held DOF takes no load component: the bearing's reaction there is balanced by what
    holds it, reported as the holding load."""

    x_um: Optional[float] = None
    """Radial displacement along x held at this value. None: free (carries fx_N)."""
    y_um: Optional[float] = None
    """Radial displacement along y held at this value. None: free (carries fy_N)."""
    z_um: Optional[float] = None
    """Axial displacement held at this value. None: free (carries fz_N)."""
    theta_x_mrad: Optional[Tilt_mrad] = None
    """Tilt about x held at this value [mrad]; 0 with theta_y_mrad 0 is a row on a shaft that does not let its
    inner ring tilt. None: free (carries mx_Nm)."""
    theta_y_mrad: Optional[Tilt_mrad] = None
    """Tilt about y held at this value [mrad]. None: free (carries my_Nm)."""

    def held(self):
        """The SI :class:`~.equilibrium.Held` of these keys."""
        from .equilibrium import Held

        given = {dof: getattr(self, key) * f for key, dof, _, f in HELD_KEYS if getattr(self, key) is not None}
        return Held.of(**given)


class BallShoulders(DeckModel):
    """Thrust-side shoulders of the rings (the high shoulder of an angular-contact ring), for the check of the
    contact ellipse against the land: each ring as a height or as an angle, not both."""

    inner_height_mm: Optional[PositiveFloat] = None
    """Height of the inner ring's shoulder above its groove bottom (radial). None: inner_angle_deg, or 0.3 times
    the ball diameter."""
    outer_height_mm: Optional[PositiveFloat] = None
    """Height of the outer ring's shoulder above its groove bottom (radial). None: outer_angle_deg, or 0.3 times
    the ball diameter."""
    inner_angle_deg: Optional[Annotated[float, Field(gt=0.0, lt=90.0)]] = None
    """Angle at the inner groove's curvature centre, from the radial direction, where the shoulder ends the
    groove: arccos(1 - h / (f_i D)) for a shoulder of height h. None: from inner_height_mm."""
    outer_angle_deg: Optional[Annotated[float, Field(gt=0.0, lt=90.0)]] = None
    """Angle at the outer groove's curvature centre where the shoulder ends the groove. None: from
    outer_height_mm."""

    @model_validator(mode="after")
    def _one_per_ring(self):
        for ring in ("inner", "outer"):
            if getattr(self, f"{ring}_height_mm") is not None and getattr(self, f"{ring}_angle_deg") is not None:
                raise ValueError(f"give {ring}_height_mm or {ring}_angle_deg, not both")
        return self


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
    model: Literal["outer_race_control", "inner_race_control", "full", "auto"] = "outer_race_control"
    """Race control of the balls: outer_race_control, inner_race_control or full (as for a rotor entry), or auto:
    at every operating point each ball takes the race Jones' criterion admits at its own state, and shares the
    couple (full) when the criterion sends it back and forth (docs/theory.md, "Race control")."""
    held: HeldDofs = HeldDofs()
    """DOFs held at prescribed displacements, e.g. {theta_x_mrad: 0, theta_y_mrad: 0} for a single row whose
    tilt the shaft holds; the others free under `load`. Default: every DOF free (the load alone decides)."""
    shoulders: BallShoulders = BallShoulders()
    """Shoulder heights or angles of the rings for the truncation check of the contact ellipses. Default: 0.3
    times the ball diameter on both rings."""

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
    return Preload("spring", axial_N=pre.axial_N, floating_thrust=SIDES.get(pre.floating, 1))


def placed(entry: BallBearingEntry, node_z_m: float, shaft_z_m: tuple[float, float]) -> BallBearingEntry:
    """The entry with ``floating: outward / inward`` resolved to a thrust direction along z, from where the
    bearing sits on the shaft (its node's z within the shaft's [z_min, z_max])."""
    pre = entry.preload
    if not isinstance(pre, SpringPreload) or pre.floating in SIDES:
        return entry
    outward = "+z" if node_z_m >= 0.5 * (shaft_z_m[0] + shaft_z_m[1]) else "-z"
    thrust = outward if pre.floating == "outward" else ("-z" if outward == "+z" else "+z")
    return entry.model_copy(update={"preload": pre.model_copy(update={"floating": thrust})})


def preload_unit_to_si(entry: _BallKeys, value: float) -> float:
    """A swept preload value in deck units (um or N) -> SI (m or N)."""
    return 1e-6 * value if isinstance(entry.preload, PositionPreload) else float(value)


def section_checks(sec: BallSection) -> list[tuple[tuple, str]]:
    """Checks of the held DOFs and the shoulders of a standalone section: (key path, message)."""
    bad: list[tuple[tuple, str]] = []
    load = sec.load.model_dump()
    for key, dof, comp, _ in HELD_KEYS:
        if getattr(sec.held, key) is None:
            continue
        if load[comp] != 0.0:
            bad.append((("held", key), f"{dof} is held, so load.{comp} ({load[comp]:g}) cannot act on it: a held DOF "
                                       f"carries what holds it (the holding load); drop load.{comp} or free {dof}"))
        if sec.sweeps.load is not None and sec.sweeps.load.component == comp:
            bad.append((("sweeps", "load", "component"), f"{comp} is the load of the held DOF {dof} (held.{key})"))
    A0_um = 1e3 * (sec.inner_conformity + sec.outer_conformity - 1.0) * sec.ball_diameter_mm
    R_mm = 0.5 * sec.pitch_diameter_mm
    for key, size in (("x_um", 1.0), ("y_um", 1.0), ("z_um", 1.0), ("theta_x_mrad", R_mm), ("theta_y_mrad", R_mm)):
        v = getattr(sec.held, key)
        if v is not None and abs(v) * size >= A0_um:
            bad.append((("held", key), f"{v:g} moves the inner groove centre {abs(v) * size:.4g} um at a ball, beyond "
                                       f"the groove-centre distance (f_i + f_o - 1) D = {A0_um:.4g} um: the rings "
                                       "would pass through the balls"))
    if sec.held.z_um is not None and isinstance(sec.preload, SpringPreload) and sec.arrangement in ("single", "DT"):
        bad.append((("held", "z_um"), "every row floats on the spring preload, so the set carries exactly the spring "
                                      "force axially wherever the inner ring sits: z cannot be held"))
    D = sec.ball_diameter_mm
    for ring, f in (("inner", sec.inner_conformity), ("outer", sec.outer_conformity)):
        h = getattr(sec.shoulders, f"{ring}_height_mm")
        if h is not None and not h < f * D:
            bad.append((("shoulders", f"{ring}_height_mm"), f"{h:g} mm is not below the groove radius f D = "
                                                            f"{f * D:.4g} mm: the groove ends at 90 deg there"))
    return bad


def located_checks(entry) -> list[tuple[tuple, str]]:
    """Checks that pydantic cannot place on their key: (key path in the entry, message).  The deck loader
    reports them located: the growth keys (:func:`.section_thermal.growth_checks`) and, for the
    standalone section, the held DOFs and the shoulders (:func:`section_checks`)."""
    bad = growth_checks(entry)
    if isinstance(entry, BallSection):
        bad += section_checks(entry)
    return bad


def build(entry: _BallKeys):
    """Deck entry or section (deck units) -> :class:`~.bearing.BallBearing` (SI, 0-based node).

    With temperatures_C (or fits_um / mounting) the bearing is the one at those temperatures: a new
    frozen geometry with the operating clearance and the preload offsets its growth gives
    (:func:`~.growth.at_temperature`); with ``mounting`` the inner ring's centrifugal growth on the shaft
    is added at every speed.  ``bearing.growth`` keeps what changed (None without these keys)."""
    import logging

    from .bearing import BallBearing
    from .rating import RatingInputs

    from .thermal import MadeAs

    geometry, preload = geometry_from(entry), preload_from(entry)
    growth = speed_growth = None
    thermal = thermal_inputs(entry)
    made_as = _made_as(entry, geometry, preload)
    if thermal is not None:
        from .growth import SpeedGrowth, at_temperature

        temps, ring, ball, mounting = thermal
        made_as = MadeAs(geometry, preload, ring, ball, mounting)
        made = geometry
        try:
            geometry, preload, growth = at_temperature(made, preload, temps, ring, ball, mounting)
        except ValueError as exc:
            raise ValueError(f"bearing {entry.name!r}: {exc}") from exc
        if mounting is not None:
            speed_growth = SpeedGrowth(made, temps, ring, mounting)
        logging.getLogger(__name__).info(
            "bearing %r at %s: operating clearance %.4g um (%+.4g um), preload offset change %+.4g um",
            entry.name, "temperature" if entry.temperatures_C is not None else "its fits", growth.clearance_m * 1e6,
            growth.clearance_change_m * 1e6, growth.preload_offset_change_m * 1e6)
    shoulders = None
    sh = getattr(entry, "shoulders", None)
    if sh is not None:
        from .checks import shoulders_of

        rad = math.radians
        shoulders = shoulders_of(
            geometry, None if sh.inner_height_mm is None else 1e-3 * sh.inner_height_mm,
            None if sh.outer_height_mm is None else 1e-3 * sh.outer_height_mm,
            None if sh.inner_angle_deg is None else rad(sh.inner_angle_deg),
            None if sh.outer_angle_deg is None else rad(sh.outer_angle_deg))
    return BallBearing(
        geometry, preload, name=entry.name, node=getattr(entry, "node", 1) - 1, shoulders=shoulders,
        model="outer_race_control" if entry.model == "auto" else entry.model,
        rating=RatingInputs(dynamic_load_rating_N=entry.dynamic_load_rating_N,
                            reliability_percent=entry.reliability_percent),
        speed_growth=speed_growth, growth=growth, made=made_as,
        damping_s=entry.damping.stiffness_proportional_s if isinstance(entry, BallBearingEntry) else 0.0)


def _made_as(entry: _BallKeys, geometry, preload):
    """The cold assembly with the entry's materials (expansion coefficients) and no fits."""
    from ...thermal.growth import ThermoElastic
    from .thermal import MadeAs

    def thermo(m):
        return ThermoElastic(1e9 * m.E_GPa, m.poisson, m.density_kg_m3, m.expansion_1_K())

    bm = entry.material if entry.ball_material is None else entry.ball_material
    return MadeAs(geometry, preload, thermo(entry.material), thermo(bm))


# ---- what the family answers for itself (its row of BEARING_TYPES, bearings/types.py; the plausibility and the
# thermal set with the keys of the growth: section_thermal.py) ----------------------------------------------------
def holds_axially(entry: BallBearingEntry) -> bool:
    """A ball bearing (set) carries axial load (its contact angle; a deep-groove bearing's under load)."""
    return True
