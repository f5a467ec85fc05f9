"""Deck section ``dtrb:`` and bearing type ``dtrb`` (issue 6): double-row tapered roller bearing.

Keys carry their units; :func:`geometry_from` converts to SI (the one place for this
model).  Top-level section (what ``spindlesim dtrb`` computes)::

    dtrb:
      bearing:
        rollers_per_row: 20
        cup_angle_deg: 15.64            # alpha (catalogue e = 1.5 tan alpha)
        pitch_diameter_mm: 70.0         # circle through the roller mid-points
        large_end_diameter_mm: 10.0     # D_l
        roller_length_mm: 14.0          # effective length l
        large_end_offset_mm: 18.0       # rc: axial distance of the large-end centre from the bearing centre
        crown_radius_mm: 2680.0         # R of eq. 1; null = straight roller
        end_sphere_ratio: 0.9           # Rs / apex distance
        rib_contact_height_ratio: 0.5   # rib contact distance from the roller axis / (D_l / 2)
        slices: 30
        material: {E_GPa: 208.0, poisson: 0.3, density_kg_m3: 7850.0}
      preload_um: 30.0                  # delta0 per row (seed 001 eq. 10)
      speed_rpm: 3000.0
      load: {fx_N: 5000.0, fz_N: 5000.0}
      preload_sweep_um: {start: 0.1, stop: 70.0, count: 50}
      radial_sweep_N: {start: 2000.0, stop: 20000.0, count: 37}
      polar_preloads_um: [7.9, 54.0]
      polar_radial_loads_N: [4000.0, 16000.0]

Bearing type for rotor decks (``bearings:`` list)::

      - {type: dtrb, name: hub, node: 3, preload_um: 30, axial_load_N: 0, dofs: 5, geometry: {...as bearing above...},
         damping: {stiffness_proportional_s: 1.0e-5}}    # C = beta K (the default; 0: undamped)

``dofs: 5`` (default) couples the node's (x, y, z, theta_x, theta_y) and gives the rotor its axial
DOF (seed 001's 5 DOF/node model); ``dofs: 2`` adds only the radial 2x2 block.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from ...fields import AnyNumber, DeckModel, Load5, NodeNumber, PositiveFloat
from ..damping import RollingDamping
from ..plausible import Found, metres, rolling_damping
from ..temperatures import Expansion, PartTemperatures, body

Count = Annotated[int, Field(ge=2, le=2000)]
MAX_POLAR = 16


class DtrbMaterial(DeckModel):
    E_GPa: PositiveFloat = 208.0
    """Young's modulus of rollers and rings."""
    poisson: Annotated[float, Field(gt=-1.0, lt=0.5)] = 0.3
    """Poisson's ratio (dimensionless)."""
    density_kg_m3: PositiveFloat = 7850.0
    """Density of the rollers (centrifugal force)."""
    thermal_expansion_1_K: Expansion = None
    """Linear expansion coefficient of rings and rollers [1/K] (`temperatures_C`). None: bearing steel's
    11.5e-6."""


class DtrbGeometrySpec(DeckModel):
    rollers_per_row: Annotated[int, Field(ge=3, le=200)]
    """Number of rollers in each of the two rows; they must fit on the pitch circle."""
    cup_angle_deg: Annotated[float, Field(gt=0.0, lt=60.0)]
    """Cup (outer raceway) angle alpha (catalogue e = 1.5 tan alpha)."""
    pitch_diameter_mm: PositiveFloat
    """Diameter of the circle through the roller mid-points."""
    large_end_diameter_mm: PositiveFloat
    """Roller diameter at its large end, D_l; less than half the pitch diameter."""
    roller_length_mm: PositiveFloat
    """Effective roller length l."""
    large_end_offset_mm: PositiveFloat
    """Axial distance rc of the large end's centre from the bearing centre."""
    crown_radius_mm: Optional[PositiveFloat] = None
    """Crowning radius R of the roller profile (seed 001 eq. 1). None: a straight roller."""
    end_sphere_ratio: Annotated[float, Field(gt=0.3, le=1.2)] = 0.9
    """Radius of the roller's large-end sphere over the apex distance, Rs / apex distance (dimensionless)."""
    rib_contact_height_ratio: Annotated[float, Field(gt=0.0, lt=1.0)] = 0.5
    """Height of the rib contact above the roller axis over the large-end radius D_l / 2 (dimensionless)."""
    slices: Annotated[int, Field(ge=1, le=500)] = 30
    """Number of slices along each roller for the line contact."""
    material: DtrbMaterial = DtrbMaterial()
    """Material of rollers and rings (bearing steel by default)."""

    @model_validator(mode="after")
    def _fits(self) -> "DtrbGeometrySpec":
        if self.large_end_diameter_mm >= self.pitch_diameter_mm / 2:
            raise ValueError("large_end_diameter_mm must be smaller than half the pitch diameter")
        pitch = math.pi * self.pitch_diameter_mm / self.rollers_per_row
        if pitch <= self.large_end_diameter_mm:
            raise ValueError(f"{self.rollers_per_row} rollers of {self.large_end_diameter_mm} mm do not fit "
                             f"on a {self.pitch_diameter_mm} mm pitch circle")
        return self


class SweepRange(DeckModel):
    start: AnyNumber  # the unit of the sweep's key applies too (preload_sweep_um, radial_sweep_N)
    """First value, in the unit of the sweep's key (um of preload, N of radial load)."""
    stop: AnyNumber
    """Last value (included); greater than `start`."""
    count: Count
    """Number of evenly spaced values, both ends included."""

    @model_validator(mode="after")
    def _order(self) -> "SweepRange":
        if not self.stop > self.start:
            raise ValueError("stop must be greater than start")
        return self


class DtrbSection(DeckModel):
    """What `spindlesim dtrb` computes: the double-row tapered roller bearing at one load, with preload and
    radial-load sweeps and polar plots of the roller loads."""

    bearing: DtrbGeometrySpec
    """Geometry of the bearing."""
    preload_um: Annotated[float, Field(ge=0.0)] = 30.0
    """Preload delta0 of each row (seed 001 eq. 10): each cone is pushed towards the bearing centre by delta0
    beyond first contact (total axial interference 2 delta0)."""
    temperatures_C: Optional[PartTemperatures] = None
    """Temperatures of cones, cup and rollers: the bearing at the preload its growth gives; the preload sweep
    and polar preloads are shifted by the same change (dtrb.h5 holds the operating preloads). None: as
    assembled."""
    speed_rpm: Annotated[float, Field(ge=0.0)] = 0.0
    """Inner-ring speed (outer ring fixed): the rollers' centrifugal force and gyroscopic moment; 0:
    quasi-static."""
    load: Load5 = Load5()
    """Load of the shaft on the bearing at the operating point."""
    preload_sweep_um: Optional[SweepRange] = None
    """Sweep of the preload at the section's load (stiffness against preload, seed 001 Fig. 8); not negative.
    None: no sweep."""
    radial_sweep_N: Optional[SweepRange] = None
    """Sweep of the radial load fx_N at the section's preload (seed 001 Fig. 10). None: no sweep."""
    # one load distribution each (at most MAX_POLAR: every polar plot is a full equilibrium)
    polar_preloads_um: Annotated[list[Annotated[float, Field(ge=0.0)]], Field(max_length=MAX_POLAR)] = []
    """Preloads at which the roller-load distribution is drawn as a polar plot (seed 001 Fig. 9); each is a full
    equilibrium."""
    polar_radial_loads_N: Annotated[list[float], Field(max_length=MAX_POLAR)] = []
    """Radial loads fx_N at which the roller-load distribution is drawn as a polar plot (seed 001 Fig. 11)."""

    @model_validator(mode="after")
    def _ranges(self) -> "DtrbSection":
        if self.preload_sweep_um is not None and self.preload_sweep_um.start < 0:
            raise ValueError("preload_sweep_um must not be negative")
        return self


class DtrbBearingEntry(DeckModel):
    type: Literal["dtrb"]
    """Bearing type: dtrb (double-row tapered roller bearing, back-to-back, quasi-static; nonlinear in
    `spindlesim transient`)."""
    name: str
    """Bearing name, unique in the deck."""
    node: NodeNumber
    """Shaft node of the bearing (1-based)."""
    geometry: DtrbGeometrySpec
    """Geometry of the bearing (the keys of `dtrb.bearing`)."""
    preload_um: Annotated[float, Field(ge=0.0)] = 0.0
    """Preload delta0 of each row (seed 001 eq. 10): each cone pushed towards the bearing centre by delta0."""
    temperatures_C: Optional[PartTemperatures] = None
    """Temperatures of cones, cup and rollers: the bearing at the preload its growth gives. None: as
    assembled."""
    axial_load_N: float = 0.0
    """Axial load FZ of the shaft on the bearing at which a `dofs: 2` bearing is linearised (the rotor has no
    axial DOF there to carry one). With `dofs: 5` the axial load comes from the rotor's statics and this key
    is not used."""
    dofs: Literal[2, 5] = 5  # 5: x, y, z, theta_x, theta_y (the rotor gets the axial DOF); 2: x, y only
    """5: the bearing couples x, y, z, theta_x, theta_y of its node and the rotor gets an axial DOF; 2: only its
    radial 2x2 block (x, y)."""
    damping: RollingDamping = RollingDamping()
    """Damping of the bearing: C = beta K on its tangent stiffness (5 x 5, or the radial 2 x 2 with `dofs: 2`),
    beta `stiffness_proportional_s` (default 1.0e-5 s; 0: undamped)."""


def geometry_from(spec: DtrbGeometrySpec):
    """SI geometry (:class:`DtrbGeometry`) from a validated spec (the one place for this conversion)."""
    from .geometry import dtrb_geometry

    m = spec.material
    return dtrb_geometry(
        rollers_per_row=spec.rollers_per_row, cup_angle_deg=spec.cup_angle_deg,
        pitch_diameter_m=1e-3 * spec.pitch_diameter_mm, large_end_diameter_m=1e-3 * spec.large_end_diameter_mm,
        roller_length_m=1e-3 * spec.roller_length_mm, large_end_offset_m=1e-3 * spec.large_end_offset_mm,
        crown_radius_m=math.inf if spec.crown_radius_mm is None else 1e-3 * spec.crown_radius_mm,
        end_sphere_ratio=spec.end_sphere_ratio, rib_contact_height_ratio=spec.rib_contact_height_ratio,
        youngs_modulus_Pa=1e9 * m.E_GPa, poisson=m.poisson, density_kg_m3=m.density_kg_m3, n_slices=spec.slices,
    )


def material_body(material: DtrbMaterial):
    """The rings' and rollers' ``ThermoElastic`` of the deck's material (its growth at temperature)."""
    return body(1e9 * material.E_GPa, material.poisson, material.density_kg_m3, material.thermal_expansion_1_K)


def build(entry: DtrbBearingEntry):
    """Rotor deck entry (deck units) -> :class:`DtrbBearing` (SI), at ``temperatures_C`` when given."""
    from .bearing import DOFS_2, DOFS_5, DtrbBearing

    b = DtrbBearing(geometry_from(entry.geometry), 1e-6 * entry.preload_um, name=entry.name,
                    node=entry.node - 1, axial_load_N=entry.axial_load_N,
                    dof_names=DOFS_5 if entry.dofs == 5 else DOFS_2, body=material_body(entry.geometry.material),
                    damping_s=entry.damping.stiffness_proportional_s)
    return at_deck_temperatures(b, entry.temperatures_C)


def at_deck_temperatures(bearing, temps: "PartTemperatures | None"):
    """``bearing`` at the deck's prescribed temperatures (itself without them)."""
    return bearing if temps is None else bearing.at_temperatures(temps.si())


# ---- what the family answers for itself (its row of BEARING_TYPES, bearings/types.py) ----------------------
def plausibility(entry: DtrbBearingEntry, at: tuple) -> Found:
    """Likely unit mistakes of the entry at the key path ``at``: its damping, its diameters (metres?)."""
    bad: Found = []
    rolling_damping(entry, at, bad)
    metres(entry.geometry, at + ("geometry",), ("pitch_diameter_mm", "large_end_diameter_mm"), bad)
    return bad


def holds_axially(entry: DtrbBearingEntry) -> bool:
    """With ``dofs: 5`` the bearing couples the rotor's axial DOF; with ``dofs: 2`` it acts on x and y only."""
    return entry.dofs == 5


def thermal_set(entry: DtrbBearingEntry, z_m: float):
    """Its set in the spindle's thermal network (:func:`.thermal.thermal_set`)."""
    from .thermal import thermal_set as of_entry

    return of_entry(entry, z_m)
