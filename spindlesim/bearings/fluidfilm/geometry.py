"""Film thickness of plain and multilobe journal bearings.

Angles ``theta`` are measured in the spindlesim frame: from +x (horizontal) towards
+y (vertical up), i.e. in the direction of shaft rotation (spin about +z).  The
journal surface therefore moves in the +theta direction.

Film thickness of a land (a lobe, or the whole bore of a plain bearing), made
dimensionless with the *assembled* radial clearance ``Cb`` (REFERENCES.md,
"Multi-lobe film thickness"; e.g. Lund & Thomsen 1978, Someya 1989)::

    h = Cp - (Cp - Cb) cos(theta - theta_k) - e_x cos(theta) - e_y sin(theta)
    H = h / Cb = a - (a - 1) cos(theta - theta_k) - X cos(theta) - Y sin(theta)

with ``a = Cp / Cb = 1 / (1 - mp)``, ``mp = 1 - Cb/Cp`` the preload factor (seed 003
eq. 2), ``theta_k`` the direction of the lobe's preload (where the centred journal
sees the smallest film, ``Cb``), and ``X = e_x / Cb``, ``Y = e_y / Cb``.  A plain
bearing is the special case ``mp = 0`` (``Cp = Cb``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Land:
    """One pressure-generating arc of the bore.

    ``start_rad`` is the leading edge (oil enters there, the journal surface moves
    towards increasing theta), ``arc_rad`` the arc length in radians,
    ``preload_centre_rad`` the angle ``theta_k`` of the lobe's smallest film for a
    centred journal (irrelevant when the preload is zero).  ``periodic`` marks a
    full 360 deg bore without a groove: the film then closes on itself.
    """

    start_rad: float
    arc_rad: float
    preload_centre_rad: float = 0.0
    periodic: bool = False


@dataclass(frozen=True)
class BearingGeometry:
    """Geometry of a journal bearing in SI units.

    ``clearance_m`` is the assembled radial clearance ``Cb``; ``preload`` is
    ``mp = 1 - Cb/Cp``.  ``kind`` is ``"plain"`` or ``"multilobe"`` (informative).
    """

    diameter_m: float
    width_m: float
    clearance_m: float
    preload: float
    lands: tuple[Land, ...]
    kind: str = "plain"
    #: a 360 deg bore whose film start is held at ``lands[0].start_rad``, fixed in space
    #: (:func:`fixed_feed_geometry`): not axisymmetric
    fixed_feed: bool = False

    def __post_init__(self) -> None:
        if self.diameter_m <= 0 or self.width_m <= 0 or self.clearance_m <= 0:
            raise ValueError("diameter, width and clearance must be positive")
        if not 0.0 <= self.preload < 1.0:
            raise ValueError(f"preload factor mp must be in [0, 1), got {self.preload}")
        if not self.lands:
            raise ValueError("a bearing needs at least one land")
        total = sum(land.arc_rad for land in self.lands)
        if total > 2 * math.pi * (1 + 1e-12):
            raise ValueError("the lands cover more than 360 deg")

    @property
    def axisymmetric(self) -> bool:
        """True for a 360 deg plain bore (solved in the line-of-centres frame)."""
        return (not self.fixed_feed and self.preload == 0.0 and len(self.lands) == 1
                and abs(self.lands[0].arc_rad - 2 * math.pi) < 1e-12)

    @property
    def radius_m(self) -> float:
        return 0.5 * self.diameter_m

    @property
    def machined_clearance_m(self) -> float:
        """Machined (lobe) clearance Cp = Cb / (1 - mp)."""
        return self.clearance_m / (1.0 - self.preload)

    @property
    def l_over_d(self) -> float:
        return self.width_m / self.diameter_m

    @property
    def clearance_ratio(self) -> float:
        """Seed 003's psi = 2 Cp / D (eq. 3)."""
        return 2.0 * self.machined_clearance_m / self.diameter_m

    def film(self, land: Land, theta: np.ndarray, X: float, Y: float) -> np.ndarray:
        """Dimensionless film thickness H = h / Cb on ``land`` at angles ``theta``."""
        a = 1.0 / (1.0 - self.preload)
        theta = np.asarray(theta, dtype=float)
        H = a - (a - 1.0) * np.cos(theta - land.preload_centre_rad)
        return H - X * np.cos(theta) - Y * np.sin(theta)


def plain_geometry(
    diameter_m: float,
    width_m: float,
    clearance_m: float,
    grooves: int = 0,
    groove_width_deg: float = 20.0,
    groove_centre_deg: float | None = None,
    load_angle_deg: float = -90.0,
    feed: str = "max_film",
) -> BearingGeometry:
    """A plain cylindrical bearing, 360 deg (``grooves=0``) or with axial grooves.

    A 360 deg bearing is axisymmetric and is solved in the line-of-centres frame, in
    which this geometry is defined (journal displaced along +x).  ``feed="max_film"``
    (default) starts the film at the maximum film thickness with P = 0 there, the
    boundary condition of Raimondi & Boyd (1958); ``feed="periodic"`` closes the film
    on itself (pure Swift-Stieber on the whole circle, attitude angles a few degrees
    larger at low eccentricity).

    Grooves are equally spaced; by default the first groove is centred 90 deg from
    the load line (DESIGN.md section 4: grooves "centred by default 90 deg from the
    load line"), i.e. at ``load_angle_deg + 90``.  Grooves are held at ambient
    (zero gauge) pressure.
    """
    if grooves < 0:
        raise ValueError("grooves must be >= 0")
    if grooves == 0:
        if feed == "max_film":
            land = Land(start_rad=math.pi, arc_rad=2 * math.pi)
        elif feed == "periodic":
            land = Land(start_rad=0.0, arc_rad=2 * math.pi, periodic=True)
        else:
            raise ValueError("feed must be 'max_film' or 'periodic'")
        return BearingGeometry(diameter_m, width_m, clearance_m, 0.0, (land,), "plain")
    if not 0 < groove_width_deg * grooves < 360:
        raise ValueError("grooves cover the whole circumference")
    centre = load_angle_deg + 90.0 if groove_centre_deg is None else groove_centre_deg
    pitch = 360.0 / grooves
    arc = pitch - groove_width_deg
    lands = tuple(
        Land(
            start_rad=math.radians(centre + k * pitch + 0.5 * groove_width_deg),
            arc_rad=math.radians(arc),
        )
        for k in range(grooves)
    )
    return BearingGeometry(diameter_m, width_m, clearance_m, 0.0, lands, "plain")


def fixed_feed_geometry(geometry: BearingGeometry, feed_rad: float) -> BearingGeometry:
    """The 360 deg bore of ``geometry`` (``feed="max_film"``) with its film start held at the
    angle ``feed_rad``, fixed in space.

    ``feed="max_film"`` starts the film at the maximum film, which turns with the journal; that
    is a statement about a static operating point.  In motion about the point the oil supply
    stays where it is: the film start is the maximum film of the operating point, fixed.  The
    force of this bore equals the max-film force wherever the maximum film lies at ``feed_rad``
    (the same discrete problem on a grid turned by ``feed_rad - pi``), and its tangent there is
    the coefficients of the static solver (perturbation with the film start held), which the
    max-film force's own tangent is not (its film start turns with the journal: 9 % of max|K|
    apart at e/Cb 0.2, L/D 0.5; tests/unit/test_one_model_bearings.py).
    """
    if not geometry.axisymmetric or geometry.lands[0].periodic:
        raise ValueError("a fixed feed applies to a 360 deg bore with feed max_film")
    land = Land(start_rad=float(feed_rad), arc_rad=2 * math.pi)
    return BearingGeometry(geometry.diameter_m, geometry.width_m, geometry.clearance_m, 0.0, (land,),
                           geometry.kind, fixed_feed=True)


def multilobe_geometry(
    diameter_m: float,
    width_m: float,
    clearance_m: float,
    preload: float,
    lobes: int = 3,
    groove_width_deg: float = 20.0,
    offset: float = 0.5,
    load_angle_deg: float = -90.0,
    orientation: str = "on_lobe",
    first_lobe_centre_deg: float | None = None,
) -> BearingGeometry:
    """A multilobe bearing with ``lobes`` equal lobes separated by axial grooves.

    Each lobe spans ``360/lobes - groove_width_deg``.  ``offset`` is the lobe offset
    factor: the lobe's preload centre lies at ``start + offset * arc`` (0.5: symmetric
    lobe, > 0.5: the converging part is longer).  The lobe pattern is placed either
    by ``first_lobe_centre_deg`` (angle of the geometric centre of the first lobe's
    arc) or by ``orientation`` relative to ``load_angle_deg`` (the direction in which
    the shaft presses on the bearing, -90 deg for a downward load):

    - ``"on_lobe"``: a lobe's arc centre on the load line (load on lobe, LOP);
    - ``"between_lobes"``: a groove centre on the load line (load between lobes, LBP).
    """
    if lobes < 2:
        raise ValueError("a multilobe bearing needs at least 2 lobes")
    pitch = 360.0 / lobes
    arc = pitch - groove_width_deg
    if arc <= 0 or groove_width_deg < 0:
        raise ValueError("groove width must be in [0, 360/lobes)")
    if not 0.0 <= offset <= 1.0:
        raise ValueError("lobe offset factor must be in [0, 1]")
    if first_lobe_centre_deg is None:
        if orientation == "on_lobe":
            first_lobe_centre_deg = load_angle_deg
        elif orientation == "between_lobes":
            first_lobe_centre_deg = load_angle_deg + 0.5 * pitch
        else:
            raise ValueError("orientation must be 'on_lobe' or 'between_lobes'")
    lands = []
    for k in range(lobes):
        mid = first_lobe_centre_deg + k * pitch
        start = mid - 0.5 * arc
        lands.append(
            Land(
                start_rad=math.radians(start),
                arc_rad=math.radians(arc),
                preload_centre_rad=math.radians(start + offset * arc),
            )
        )
    return BearingGeometry(
        diameter_m, width_m, clearance_m, preload, tuple(lands), "multilobe"
    )
