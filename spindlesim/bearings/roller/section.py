"""Deck keys of the cylindrical roller bearing of seed 000 (``type: roller``) and its builder.

``type: roller`` puts the bearing under any rotor (``bearings:`` list); its keys are the bearing's
geometry and materials (:class:`RollerGeometry`) plus the number of rollers, the model and its parts:

    bearings:
      - {type: roller, name: rear, node: 18, rollers: 12, model: rigid_race,
         inner_raceway_diameter_mm: 18.738, outer_raceway_diameter_mm: 28.262, roller_diameter_mm: 4.762,
         width_mm: 6.35, radial_clearance_mm: 0.0, waviness: [{surface: outer, waves: 8, amplitude_um: 0.5}],
         damping: {stiffness_proportional_s: 1.0e-5}}   # C = beta K (rigid_race; the default; 0: undamped)

The rig section ``transient:`` of the transient analysis (``spindlesim.deck.transient``) describes
seed 000's test rig with the same models.  Every key carries its unit; :func:`build` is the one
place where they become SI.  Defaults are seed 000's bearing (Table 1); see
``spindlesim/decks/transient.yaml`` for the source of every number.

Contact stiffness: ``contact_stiffness_N_per_m_n`` is the constant K of Q = K delta^n of a
rolling element's two contacts in series (as Harsha and Kankar quote 7.055e9 N/m^1.5 for their
ball bearing); the rigid-race model uses it as it is, the flexible-race model splits it into two
equal contacts (K 2^n each).  Without it, a roller takes Palmgren's line-contact constant
(``contact.hertz.palmgren_stiffness``) AS that in-series constant.  Palmgren's law is usually read
as one roller/raceway contact, which would make the in-series constant K / 2^(10/9): the default
is then 2.16 times stiffer than that reading.  It is kept because every roller deck and its
validation (seed 000's natural frequencies and roller-pass lines) were set on it; give
``contact_stiffness_N_per_m_n`` to choose.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal, Optional, Union

from pydantic import Field, model_validator

from ...fields import DeckModel, Fraction, NodeNumber, NonNegFloat, PositiveFloat
from ..damping import RollingDamping, damping_of
from ..plausible import Found, clearance, metres, rolling_damping
from ..temperatures import Expansion, PartTemperatures, body

if TYPE_CHECKING:
    from .bearing import FlexibleRaceBearing, RigidRaceBearing

Rollers = Annotated[int, Field(ge=3, le=100)]


class RollerGeometry(DeckModel):
    """Geometry, materials and contact law of the bearing (the rig's ``bearing:`` and every ``type: roller``
    entry)."""

    inner_raceway_diameter_mm: PositiveFloat = 18.738
    """Diameter of the inner raceway."""
    outer_raceway_diameter_mm: PositiveFloat = 28.262
    """Diameter of the outer raceway; the rollers must fit between the raceways."""
    roller_diameter_mm: PositiveFloat = 4.762  # seed 000 Table 1 says "radius"; it is the diameter
    """Roller diameter (seed 000 Table 1 calls it the radius; it is the diameter)."""
    width_mm: PositiveFloat = 6.35
    """Roller (and race) width: the contact length of Palmgren's stiffness and the width of the flexible outer
    race."""
    housing_radius_mm: PositiveFloat = 16.0
    """Radius of the housing bore, i.e. the outer radius of the outer race; must exceed the outer raceway radius
    (the race thickness is the difference)."""
    radial_clearance_mm: NonNegFloat = 0.0
    """Radial internal clearance per side: the inner ring moves this far from the centre before a roller is
    loaded (not the diametral clearance)."""
    slip_inner: Fraction = 0.0
    """Slip ratio of the rollers at the inner raceway (seed 000 eq. 3; 0: pure rolling); sets the cage speed."""
    slip_outer: Fraction = 0.0
    """Slip ratio of the rollers at the outer raceway (seed 000 eq. 3; 0: pure rolling)."""
    element: Literal["roller", "ball"] = "roller"
    """Rolling element: roller (line contact, n = 10/9) or ball (point contact, n = 1.5; rigid_race model only,
    needs contact_stiffness_N_per_m_n)."""
    # Hertz constant K of Q = K delta^n (total, both contacts); default: Palmgren for a roller
    contact_stiffness_N_per_m_n: Optional[PositiveFloat] = None
    """Constant K of Q = K delta^n of a rolling element's two contacts in series (unit N/m^n). None: Palmgren's
    line-contact constant for a roller of this width, taken as that in-series constant (about 2.16 times stiffer
    than reading it as one contact: module note)."""
    E_GPa: PositiveFloat = 208.0
    """Young's modulus of the outer race (flexible_race model)."""
    density_kg_m3: PositiveFloat = 7850.0
    """Density of the outer race and of the rollers (flexible_race model)."""


class RollerOuterRace(DeckModel):
    segments: Annotated[int, Field(ge=3, le=360)] = 12
    """Number of rigid segments of the flexible outer race (flexible_race model)."""


class RollerContact(DeckModel):
    """Eq. 30-31 parameters of the roller contacts (flexible_race model)."""

    damping_Ns_m2: NonNegFloat = 1.8e9  # c, with m2 = 1, m3 = 1
    """Damping coefficient c of the contact law f = k delta^m1 + c sign(v) |v|^m2 delta^m3 (seed 000 eq. 30).
    Its unit is N (s/m)^m2 / m^m3: the key's N s/m2 holds with both exponents 1."""
    velocity_exponent: Annotated[float, Field(gt=0, le=10.0)] = 1.0
    """Exponent m2 of the penetration rate in the damping term (dimensionless)."""
    indentation_exponent: Annotated[float, Field(ge=0, le=10.0)] = 1.0
    """Exponent m3 of the penetration in the damping term (dimensionless); above 0 the damping force starts from
    zero at first touch."""
    friction: Annotated[float, Field(ge=0, le=10.0)] = 0.0
    """Coulomb friction coefficient mu at the roller contacts (seed 000 eq. 31; dimensionless)."""
    slip_regularisation_m_s: PositiveFloat = 1e-3
    """Slip velocity below which friction is smoothed: the sign of the slip v is taken as v / sqrt(v^2 +
    v_reg^2)."""


class RollerHousing(DeckModel):
    """Outer race on the housing bore (seed 000 "surface contact"), per metre of bore circumference.

    Each segment gets these times its arc on the housing radius, so the support does not change
    with the number of segments.  Seed 000 gives no values; defaults: 1.2e11 N/m^2 (1e9 N/m on each
    of 12 segments, stiffer than a roller contact, ~1.5e8 N/m) and damping ~5% of critical per segment.
    """

    stiffness_N_m2: PositiveFloat = 1.2e11
    """Radial stiffness of the housing under the outer race per metre of bore circumference (each segment gets
    it times its arc)."""
    damping_Ns_m2: NonNegFloat = 2.0e4
    """Radial damping of the housing per metre of bore circumference."""
    tangential_stiffness_N_m2: NonNegFloat = 1.2e9
    """Tangential (circumferential) stiffness of the housing per metre of bore circumference."""
    friction: Annotated[float, Field(ge=0, le=10.0)] = 0.0
    """Friction coefficient between the outer race and the housing bore (dimensionless)."""
    # the segment's outer face sits on the bore (seed 000 "surface contact"): it resists rocking with
    # k s^2/12, s the segment's arc on the housing radius; false = point support (no rocking stiffness)
    surface_contact: bool = True
    """true: each segment's outer face sits on the bore and resists rocking (k s^2 / 12, s its arc); false: a
    point support without rocking stiffness."""


class RollerWaviness(DeckModel):
    surface: Literal["inner", "outer", "roller"]
    """Surface with the waviness: inner raceway, outer raceway or roller."""
    waves: Annotated[int, Field(ge=1, le=10_000)]
    """Number of waves around the surface (the waviness order)."""
    amplitude_um: NonNegFloat
    """Amplitude of the waviness."""
    phase_deg: float = 0.0
    """Phase of the waviness."""


def check_geometry(b: "RollerGeometry", model: str) -> None:
    gap = b.outer_raceway_diameter_mm - b.inner_raceway_diameter_mm - 2 * b.roller_diameter_mm
    if gap < -1e-9:
        raise ValueError(f"rollers do not fit: outer - inner raceway diameter - 2 x roller diameter = {gap:.4g} mm")
    if b.housing_radius_mm <= 0.5 * b.outer_raceway_diameter_mm:
        raise ValueError("housing_radius_mm must exceed the outer raceway radius (it bounds the outer race)")
    if b.element == "ball" and b.contact_stiffness_N_per_m_n is None:
        raise ValueError("element 'ball' needs contact_stiffness_N_per_m_n (e.g. 7.055e9, Harsha and Kankar 2004)")
    if model == "flexible_race" and b.element == "ball":
        raise ValueError("the flexible_race model is a roller bearing (seed 000); use rigid_race for balls")


class RollerEntry(RollerGeometry):
    """``type: roller`` in a rotor deck's ``bearings:`` list."""

    type: Literal["roller"]
    """Bearing type: roller (cylindrical roller bearing of seed 000 under any rotor; nonlinear in `spindlesim
    transient`, acts on x and y)."""
    name: str
    """Bearing name, unique in the deck."""
    node: NodeNumber
    """Shaft node of the bearing (1-based)."""
    rollers: Rollers = 8
    """Number of rollers."""
    model: Literal["rigid_race", "flexible_race"] = "rigid_race"
    """rigid_race: rings rigid, roller contacts only (2 DOF); flexible_race: the outer race as rigid segments on
    the housing (seed 000)."""
    outer_race: RollerOuterRace = RollerOuterRace()
    """The flexible outer race (flexible_race model)."""
    contact: RollerContact = RollerContact()
    """Damping and friction of the roller contacts (flexible_race model)."""
    housing: RollerHousing = RollerHousing()
    """Support of the outer race by the housing (flexible_race model)."""
    waviness: Annotated[list[RollerWaviness], Field(max_length=64)] = []
    """Surface waviness of the raceways or rollers (rigid_race model only)."""
    temperatures_C: Optional[PartTemperatures] = None
    """Temperatures of the rings and rollers: the bearing at the radial clearance their growth gives, half of
    d_o' - d_i' - 2 D_w' (below zero: the rollers preloaded). None: as assembled."""
    thermal_expansion_1_K: Expansion = None
    """Linear expansion coefficient of rings and rollers [1/K] (`temperatures_C`). None: bearing steel's
    11.5e-6."""
    damping: Optional[RollingDamping] = None
    """Damping of the rigid_race model: C = beta K on its 2 x 2 tangent stiffness, beta
    `stiffness_proportional_s` (0: undamped). None: 1.0e-5 s for rigid_race; the flexible_race model is damped
    by its own contacts (`contact`, `housing`: seed 000 eq. 30) and takes no `damping`."""

    @model_validator(mode="after")
    def _consistent(self) -> "RollerEntry":
        check_geometry(self, self.model)
        if self.model == "flexible_race" and self.waviness:
            raise ValueError("waviness is modelled in the rigid_race model only")
        if self.model == "flexible_race" and self.damping is not None:
            raise ValueError("damping: the flexible_race model is damped by its roller and housing contacts "
                             "(contact.damping_Ns_m2, housing.damping_Ns_m2; seed 000 eq. 30), not by C = beta K; "
                             "`damping` applies to rigid_race")
        return self


def operating_clearance_mm(e: RollerEntry) -> float:
    """The entry's radial clearance, at ``temperatures_C`` when given: plus half the change of the
    diametral clearance d_o' - d_i' - 2 D_w' (:func:`.thermal.roller_operating_clearance`)."""
    if e.temperatures_C is None:
        return e.radial_clearance_mm
    from .thermal import roller_operating_clearance

    grown = roller_operating_clearance(e.inner_raceway_diameter_mm * 1e-3, e.outer_raceway_diameter_mm * 1e-3,
                                       e.roller_diameter_mm * 1e-3, e.temperatures_C.si(), _body(e))
    return e.radial_clearance_mm + 0.5e3 * grown.change_m


def _body(e: RollerEntry):
    """Rings' and rollers' ``ThermoElastic`` (free rings: E and nu do not enter their growth)."""
    return body(e.E_GPa * 1e9, 0.3, e.density_kg_m3, e.thermal_expansion_1_K)


def build(e: RollerEntry) -> Union["RigidRaceBearing", "FlexibleRaceBearing"]:
    """Deck entry -> rigid-race or flexible-race bearing (SI; node 0-based)."""
    import numpy as np

    from ...contact.hertz import EXPONENT_LINE, EXPONENT_POINT, palmgren_stiffness
    from .kinematics import CageKinematics

    node = e.node - 1
    if e.element == "ball":
        K_total, n = float(e.contact_stiffness_N_per_m_n), EXPONENT_POINT
    else:
        n = EXPONENT_LINE
        # Palmgren's law taken as the constant of the element's two contacts in series (module note)
        K_total = float(e.contact_stiffness_N_per_m_n or palmgren_stiffness(e.width_mm * 1e-3))
    clearance_mm = operating_clearance_mm(e)
    r_out_mm = 0.5 * e.outer_raceway_diameter_mm + clearance_mm  # clearance enlarges the outer raceway
    if e.model == "rigid_race":
        from .bearing import RigidRaceBearing, Waviness

        kin = CageKinematics(e.inner_raceway_diameter_mm * 1e-3, e.outer_raceway_diameter_mm * 1e-3,
                             e.roller_diameter_mm * 1e-3, e.slip_inner, e.slip_outer)
        wav = tuple(Waviness(w.surface, w.waves, w.amplitude_um * 1e-6, np.radians(w.phase_deg)) for w in e.waviness)
        cold = RigidRaceBearing(e.name, node, e.rollers, K_total, n, kin, e.radial_clearance_mm * 1e-3, wav,
                                body=_body(e), damping_s=damping_of(e.damping))
        return cold if e.temperatures_C is None else cold.at_temperatures(e.temperatures_C.si())
    from .contact_force import CompliantContact
    from .bearing import FlexibleRaceBearing
    from .flexible_race import HousingSupport
    from .outer_race import SegmentedRing

    r_out, r_h = r_out_mm * 1e-3, e.housing_radius_mm * 1e-3
    ring = SegmentedRing(e.outer_race.segments, 0.5 * (r_out + r_h), r_h - r_out, e.width_mm * 1e-3,
                         e.E_GPa * 1e9, e.density_kg_m3)
    kin = CageKinematics(e.inner_raceway_diameter_mm * 1e-3, 2 * r_out, e.roller_diameter_mm * 1e-3,
                         e.slip_inner, e.slip_outer)
    c = e.contact
    rc = CompliantContact(K_total * 2.0 ** n, n, c.damping_Ns_m2, c.velocity_exponent,
                          c.indentation_exponent, c.friction, c.slip_regularisation_m_s)
    h = e.housing
    arc = 2.0 * np.pi * r_h / ring.segments  # each segment's share of the bore
    hc = CompliantContact(h.stiffness_N_m2 * arc, 1.0, h.damping_Ns_m2 * arc, 1.0, 0.0, h.friction,
                          c.slip_regularisation_m_s)
    support = HousingSupport(hc, 0.0, h.tangential_stiffness_N_m2 * arc,
                             rocking_arc_m=arc if h.surface_contact else 0.0)
    return FlexibleRaceBearing(e.name, node, kin, e.rollers, ring, rc, support, e.width_mm * 1e-3, e.density_kg_m3)


# ---- what the family answers for itself (its row of BEARING_TYPES, bearings/types.py) ----------------------
def plausibility(entry: RollerEntry, at: tuple) -> Found:
    """Likely unit mistakes of the entry at the key path ``at``: its damping, its raceway diameters (metres?),
    a radial clearance over 1 % of the inner raceway diameter (micrometres?)."""
    bad: Found = []
    rolling_damping(entry, at, bad)
    metres(entry, at, ("inner_raceway_diameter_mm", "outer_raceway_diameter_mm"), bad)
    clearance(entry.radial_clearance_mm, entry.inner_raceway_diameter_mm, "radial_clearance_mm",
              "the inner raceway diameter", at, bad, "")
    return bad


def thermal_refusal(entry: RollerEntry) -> str | None:
    """Why the entry cannot be in the spindle's thermal network (None: it can): the network takes Palmgren's
    cylindrical roller bearing, rigid races and rollers."""
    if entry.model != "rigid_race" or entry.element != "roller":
        return ("the spindle's thermal network takes a roller entry with model: rigid_race and element: roller "
                "(Palmgren's cylindrical roller bearing)")
    return None


def thermal_set(entry: RollerEntry, z_m: float):
    """Its set in the spindle's thermal network (:func:`.thermal.thermal_set`)."""
    from .thermal import thermal_set as of_entry

    return of_entry(entry, z_m)
