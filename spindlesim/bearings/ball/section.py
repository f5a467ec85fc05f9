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
      model: outer_race_control        # or full
      dynamic_load_rating_N: null      # catalogue C of ONE bearing; null: ISO 281 from geometry
      reliability_percent: 90.0        # L_n = a_1 L_10
      # optional, the bearing at temperature (docs/deck-format.md); materials take thermal_expansion_1_K
      temperatures_C: {inner_ring: 40, outer_ring: 30, rolling_elements: 35, reference: 20}
      fits_um: {shaft: 3.0, housing: -2.0}                      # diametral; needs mounting
      mounting: {bore_mm: 70, outer_diameter_mm: 110, shaft_bore_mm: 30}

``preload``: ``position`` - ``axial_um`` is the total axial approach clamping imposes on the set
beyond first contact (catalogue preload offset), half of it taken by each opposed group; needs
DB or DF.  ``spring`` - ``axial_N`` is the constant force on the floating outer rings: the rows
whose thrust points the ``floating`` way (all rows of a single bearing or tandem set).
``floating: outward`` (default): the rows carrying thrust towards the nearer end of the shaft, which
the shaft's thermal growth would load; ``inward`` the others; ``+z`` / ``-z`` name the thrust in the
deck's frame.  A bearing at the middle of the shaft, and the standalone ``bearing`` section, take
outward as +z.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal, Optional, Union

from pydantic import Field, model_validator

from ...fields import DeckModel, Load5, NodeNumber, NonNegFloat, PositiveFloat, Range

LoadComponent = Literal["fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm"]
LOAD_COMPONENTS = ("fx_N", "fy_N", "fz_N", "mx_Nm", "my_Nm")


#: coefficient of thermal expansion [1/K]: bearing steel (100Cr6 / AISI 52100, 11-12.5e-6) and
#: silicon nitride (about 3.2e-6); the default of a ball material below 5000 kg/m3 is the ceramic's
STEEL_EXPANSION_1_K = 11.5e-6
CERAMIC_EXPANSION_1_K = 3.2e-6
CERAMIC_DENSITY_BELOW_KG_M3 = 5000.0
#: largest interference (or clearance) of a fit, as a fraction of its diameter: above it the ring would be
#: strained beyond yield (about 0.2-0.5 % for hardened steel), so the number is almost surely in the wrong unit
MAX_FIT_FRACTION = 0.005
#: absolute zero [C]
ABSOLUTE_ZERO_C = -273.15

Expansion = Annotated[float, Field(ge=-1.0, le=1e-3)]  # sign checked below, with the reason
TemperatureC = Annotated[float, Field(ge=-1e4, le=2000.0)]  # absolute zero checked below, with the reason


def _check_expansion(value: float | None, key: str) -> None:
    if value is not None and not value >= 0.0:
        raise ValueError(f"{key} = {value:g} is negative: a thermal expansion coefficient in 1/K is positive "
                         f"(bearing steel about 11.5e-6, Si3N4 about 3.2e-6)")


class BallMaterial(DeckModel):
    E_GPa: PositiveFloat = 208.0
    """Young's modulus."""
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)] = 0.3
    """Poisson's ratio (dimensionless)."""
    density_kg_m3: PositiveFloat = 7850.0
    """Density (the balls' centrifugal force and gyroscopic moment)."""
    thermal_expansion_1_K: Optional[Expansion] = None
    """Linear thermal expansion coefficient [1/K] of this part's material, for the bearing at temperature
    (`temperatures_C`). None: bearing steel's 11.5e-6, or silicon nitride's 3.2e-6 when the density is below
    5000 kg/m3 (docs/theory.md, "Spindle thermal model: heat generation and growth")."""

    @model_validator(mode="after")
    def _expansion(self):
        _check_expansion(self.thermal_expansion_1_K, "thermal_expansion_1_K")
        return self

    def expansion_1_K(self) -> float:
        if self.thermal_expansion_1_K is not None:
            return self.thermal_expansion_1_K
        return CERAMIC_EXPANSION_1_K if self.density_kg_m3 < CERAMIC_DENSITY_BELOW_KG_M3 else STEEL_EXPANSION_1_K


class MountMaterial(DeckModel):
    """Shaft or housing body of a fit."""

    E_GPa: PositiveFloat
    """Young's modulus of the shaft or housing body."""
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)]
    """Poisson's ratio of the body (dimensionless)."""
    density_kg_m3: PositiveFloat
    """Density of the body (the shaft's centrifugal growth at speed)."""
    thermal_expansion_1_K: Expansion
    """Linear thermal expansion coefficient of the body [1/K] (steel about 11.5e-6, grey cast iron 10-11e-6)."""

    @model_validator(mode="after")
    def _expansion(self):
        _check_expansion(self.thermal_expansion_1_K, "thermal_expansion_1_K")
        return self


#: steel shaft; grey cast iron housing (E 110 GPa, 10-11e-6 1/K)
STEEL_SHAFT = dict(E_GPa=208.0, poisson=0.3, density_kg_m3=7850.0, thermal_expansion_1_K=11.5e-6)
CAST_IRON_HOUSING = dict(E_GPa=110.0, poisson=0.26, density_kg_m3=7200.0, thermal_expansion_1_K=10.5e-6)


class BallTemperatures(DeckModel):
    """Prescribed uniform temperatures of the parts [C] (as in MESYS): the bearing is computed with the
    operating clearance and preload that its growth gives.  shaft / housing default to the rings'."""

    inner_ring: TemperatureC
    """Uniform temperature of the inner ring(s) [C]."""
    outer_ring: TemperatureC
    """Uniform temperature of the outer ring(s) [C]."""
    rolling_elements: TemperatureC
    """Uniform temperature of the balls [C]."""
    reference: TemperatureC = 20.0
    """Temperature [C] at which the geometry, the clearance, the preload and the fits are given (the cold
    assembly); each part grows by its expansion coefficient times (T - reference)."""
    shaft: Optional[TemperatureC] = None
    """Temperature of the shaft at the inner-ring seat [C] (the inner fit). None: the inner ring's."""
    housing: Optional[TemperatureC] = None
    """Temperature of the housing at the outer-ring seat [C] (the outer fit). None: the outer ring's."""

    @model_validator(mode="after")
    def _above_absolute_zero(self):
        for key in ("inner_ring", "outer_ring", "rolling_elements", "reference", "shaft", "housing"):
            v = getattr(self, key)
            if v is not None and not v > ABSOLUTE_ZERO_C:
                raise ValueError(f"{key} = {v:g} C is at or below absolute zero (-273.15 C)")
        return self


class BallFits(DeckModel):
    """Diametral interference (> 0) or clearance (< 0) of the ring seats at the reference temperature [um]."""

    shaft: Annotated[float, Field(ge=-1e5, le=1e5)] = 0.0
    """Diametral interference of the inner ring on the shaft [um] at the reference temperature (> 0: a press
    fit; < 0: clearance)."""
    housing: Annotated[float, Field(ge=-1e5, le=1e5)] = 0.0
    """Diametral interference of the outer ring in the housing [um] at the reference temperature (> 0: a
    press fit; < 0: clearance, the usual loose housing fit of a floating set)."""


class BallMounting(DeckModel):
    """Seats of the fits (needed with ``fits_um``): bearing bore and outside diameter, shaft bore,
    housing outer diameter (null: a housing much thicker than the ring) and the two bodies."""

    bore_mm: PositiveFloat
    """Bearing bore d (the inner ring's seat on the shaft)."""
    outer_diameter_mm: PositiveFloat
    """Bearing outside diameter D (the outer ring's seat in the housing)."""
    shaft_bore_mm: NonNegFloat = 0.0
    """Bore of a hollow shaft at the seat (a drawbar bore); 0: solid."""
    housing_outer_diameter_mm: Optional[PositiveFloat] = None
    """Outer diameter of the housing around the seat. None: a housing much thicker than the ring (rigid)."""
    shaft_material: MountMaterial = MountMaterial(**STEEL_SHAFT)
    """Shaft body of the inner fit (default steel: 208 GPa, 0.3, 7850 kg/m3, 11.5e-6 1/K)."""
    housing_material: MountMaterial = MountMaterial(**CAST_IRON_HOUSING)
    """Housing body of the outer fit (default grey cast iron: 110 GPa, 0.26, 7200 kg/m3, 10.5e-6 1/K)."""

    @model_validator(mode="after")
    def _diameters(self):
        if not self.shaft_bore_mm < self.bore_mm:
            raise ValueError(f"shaft_bore_mm {self.shaft_bore_mm} must be smaller than bore_mm {self.bore_mm}")
        if not self.outer_diameter_mm > self.bore_mm:
            raise ValueError(f"outer_diameter_mm {self.outer_diameter_mm} must exceed bore_mm {self.bore_mm}")
        h = self.housing_outer_diameter_mm
        if h is not None and not h > self.outer_diameter_mm:
            raise ValueError(f"housing_outer_diameter_mm {h} must exceed outer_diameter_mm {self.outer_diameter_mm}")
        return self


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
    model: Literal["outer_race_control", "full"] = "outer_race_control"
    """Ball equilibrium: outer_race_control (the whole gyroscopic couple on the outer contact, Jones 1960) or
    full (the couple shared by both contacts, no race-control hypothesis)."""
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


def located_checks(entry: _BallKeys) -> list[tuple[tuple, str]]:
    """Checks of the growth keys that pydantic cannot place on their key: (key path in the entry, message).
    The deck loader reports them located; with temperatures the bearing at temperature is built once."""
    bad: list[tuple[tuple, str]] = []
    if entry.fits_um is not None and entry.mounting is None:
        bad.append((("fits_um",), "fits_um needs mounting: {bore_mm, outer_diameter_mm} (the seat diameters), and "
                                  "optionally shaft_bore_mm, housing_outer_diameter_mm and the two materials"))
    m = entry.mounting
    if entry.fits_um is not None and m is not None:
        for key, value, dia in (("shaft", entry.fits_um.shaft, m.bore_mm),
                                ("housing", entry.fits_um.housing, m.outer_diameter_mm)):
            if abs(value) > MAX_FIT_FRACTION * dia * 1e3:
                bad.append((("fits_um", key), f"{value:g} um is {abs(value) / (dia * 1e3) * 100:.3g} % of the {dia:g} mm "
                                              f"seat (more than {MAX_FIT_FRACTION * 100:g} %: a hardened ring would "
                                              "yield); fits are diametral interferences in micrometres"))
    if m is not None:
        dm, D = entry.pitch_diameter_mm, entry.ball_diameter_mm
        if not m.bore_mm < dm - D:
            bad.append((("mounting", "bore_mm"), f"{m.bore_mm:g} mm must be below the inner raceway (about pitch "
                                                 f"diameter - ball diameter = {dm - D:g} mm)"))
        if not m.outer_diameter_mm > dm + D:
            bad.append((("mounting", "outer_diameter_mm"), f"{m.outer_diameter_mm:g} mm must exceed the outer raceway "
                                                           f"(about pitch diameter + ball diameter = {dm + D:g} mm)"))
    if bad or thermal_inputs(entry) is None:
        return bad
    from .growth import at_temperature

    temps, ring, ball, mounting = thermal_inputs(entry)
    try:
        at_temperature(geometry_from(entry), preload_from(entry), temps, ring, ball, mounting)
    except ValueError as exc:
        key = "temperatures_C" if entry.temperatures_C is not None else "fits_um"
        bad.append(((key,), str(exc)))
    return bad


def thermal_inputs(entry: _BallKeys):
    """(temperatures, ring, ball, mounting) in SI for :func:`~.growth.at_temperature`, or None when the
    entry has none of temperatures_C, fits_um, mounting (the bearing as made, at the reference state)."""
    if entry.temperatures_C is None and entry.fits_um is None and entry.mounting is None:
        return None
    from ...thermal.growth import ThermoElastic
    from ...thermal.growth_bearings import BearingTemperatures, Mounting

    def thermo(m, expansion):
        return ThermoElastic(1e9 * m.E_GPa, m.poisson, m.density_kg_m3, expansion)

    t = entry.temperatures_C
    if t is None:
        temps = BearingTemperatures.uniform(20.0)
    else:
        temps = BearingTemperatures(t.inner_ring, t.outer_ring, t.rolling_elements, t.reference, t.shaft, t.housing)
    ring = thermo(entry.material, entry.material.expansion_1_K())
    bm = entry.material if entry.ball_material is None else entry.ball_material
    ball = thermo(bm, bm.expansion_1_K())
    mounting = None
    if entry.mounting is not None:
        m, f = entry.mounting, entry.fits_um if entry.fits_um is not None else BallFits()
        mounting = Mounting(
            bore_m=1e-3 * m.bore_mm, outer_diameter_m=1e-3 * m.outer_diameter_mm,
            shaft_interference_m=1e-6 * f.shaft, housing_interference_m=1e-6 * f.housing,
            shaft_bore_m=1e-3 * m.shaft_bore_mm,
            housing_outer_diameter_m=math.inf if m.housing_outer_diameter_mm is None else 1e-3 * m.housing_outer_diameter_mm,
            shaft=thermo(m.shaft_material, m.shaft_material.thermal_expansion_1_K),
            housing=thermo(m.housing_material, m.housing_material.thermal_expansion_1_K))
    return temps, ring, ball, mounting


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
    return BallBearing(
        geometry, preload, name=entry.name, node=getattr(entry, "node", 1) - 1, model=entry.model,
        rating=RatingInputs(dynamic_load_rating_N=entry.dynamic_load_rating_N,
                            reliability_percent=entry.reliability_percent),
        speed_growth=speed_growth, growth=growth, made=made_as)


def _made_as(entry: _BallKeys, geometry, preload):
    """The cold assembly with the entry's materials (expansion coefficients) and no fits."""
    from ...thermal.growth import ThermoElastic
    from .thermal import MadeAs

    def thermo(m):
        return ThermoElastic(1e9 * m.E_GPa, m.poisson, m.density_kg_m3, m.expansion_1_K())

    bm = entry.material if entry.ball_material is None else entry.ball_material
    return MadeAs(geometry, preload, thermo(entry.material), thermo(bm))
