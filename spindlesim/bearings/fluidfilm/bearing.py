"""Fluid-film journal bearing implementing the bearing contract (spindlesim/bearings/base.py).

``linearized(speed, static_load)`` finds the thermal equilibrium (seed 003 eqs. 4-14) at that
speed and load, the journal equilibrium and the eight coefficients, in the spindlesim (x
horizontal, y vertical) frame.  ``at_operating_point(speed, static_load)`` returns the bearing
with the viscosity of that thermal equilibrium held fixed (a transient is far faster than the
thermal time constants), and ``force_and_tangent`` gives the film force at any journal position
AND velocity (squeeze term) with its exact tangent, from the same Reynolds/LCP solver
(:mod:`film_model`).  For a time integration (``at_operating_point(..., transient=True)``) the
force comes from the deck's ``transient_film`` model: by default the per-land tables of the same
discrete solution (:mod:`film_table`: force within 0.4 % of the full solve for seed 003's 3-lobe
bearing, about 8 us a call), or the full solve at every call.

The Reynolds problem is solved directly in the x, y frame (angles from +x towards +y, the
direction of rotation), so the coefficients need no rotation; for an axisymmetric 360 deg bore
the line-of-centres solution is rotated into x, y (:mod:`equilibrium`).
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass

import numpy as np

from ..base import RADIAL, BearingBase
from .film_model import FilmForceModel
from .geometry import BearingGeometry
from .reynolds import DEFAULT_AXIAL, DEFAULT_CIRCUMFERENTIAL, ReynoldsSolver
from .results import ThermalResult
from .thermal import ThermalParameters, solve_thermal
from .viscosity import ConstantViscosity, WaltherViscosity


@functools.lru_cache(maxsize=32)
def cached_solver(geometry: BearingGeometry, n_circ: int, n_axial: int) -> ReynoldsSolver:
    """Grid and sparse pattern depend only on the (frozen) geometry and the grid size."""
    return ReynoldsSolver(geometry, n_circ, n_axial)


@functools.lru_cache(maxsize=32)
def film_model(geometry: BearingGeometry, n_circ: int, n_axial: int, method: str) -> FilmForceModel:
    """The dynamic film force of a geometry (exact or tabulated; tables are cached on disk)."""
    return FilmForceModel(geometry, n_circ, n_axial, method=method)


@dataclass(frozen=True)
class FluidFilmBearing(BearingBase):
    """A plain or multilobe journal bearing at a shaft node.

    ``load_N`` is the deck's own load magnitude (acting downward: the shaft presses the bearing
    in -y); when ``None`` the ``static_load`` passed to :meth:`linearized` (from the rotor's
    static equilibrium) is used.  ``viscosity_Pa_s`` is set by :meth:`at_operating_point`.
    """

    name: str
    node: int
    geometry: BearingGeometry
    viscosity: WaltherViscosity | ConstantViscosity
    thermal: ThermalParameters
    load_N: float | None = None
    n_circ: int = DEFAULT_CIRCUMFERENTIAL
    n_axial: int = DEFAULT_AXIAL
    viscosity_Pa_s: float | None = None  # frozen operating-point viscosity (transient, static Newton)
    transient_film: str = "table"  # film force of a time integration: "table" or "reynolds"
    film_method: str = "reynolds"  # the film force in use ("table" once frozen for a transient)
    dof_names: tuple[str, ...] = RADIAL

    @property
    def solver(self) -> ReynoldsSolver:
        return cached_solver(self.geometry, self.n_circ, self.n_axial)

    def load_vector(self, static_load: np.ndarray | None = None) -> np.ndarray:
        """(x, y) force of the shaft on the bearing used for this bearing."""
        if self.load_N is not None:
            return np.array([0.0, -float(self.load_N)])
        if static_load is None:
            raise ValueError(f"bearing {self.name!r}: no load_N in the deck and no static load given")
        w = np.asarray(static_load, dtype=float).reshape(2)
        if not np.hypot(*w) > 0:
            raise ValueError(f"bearing {self.name!r}: zero static load")
        return w

    def analyze(self, speed: float, static_load: np.ndarray | None = None) -> ThermalResult:
        """Thermal equilibrium and operating point at ``speed`` [rad/s]."""
        if not speed > 0:
            raise ValueError(f"bearing {self.name!r}: a hydrodynamic bearing needs a positive speed "
                             f"(got {speed * 30 / math.pi:.6g} rpm)")
        load = self.load_vector(static_load)
        base = self if self.viscosity_Pa_s is None else dataclasses.replace(  # frozen or not: one cache entry
            self, viscosity_Pa_s=None, film_method="reynolds")
        return _analyze_cached(base, float(speed), float(load[0]), float(load[1]))

    def linearized(self, speed: float, static_load: np.ndarray | None = None):
        """(K [2x2] N/m, C [2x2] N s/m) in the x, y frame at the thermal equilibrium."""
        res = self.analyze(speed, static_load)
        return res.film.K_N_m.copy(), res.film.C_Ns_m.copy()

    def static_displacement(self, speed: float, static_load: np.ndarray | None = None) -> np.ndarray:
        """The journal position of the thermal equilibrium at (speed, load)."""
        return self.analyze(speed, static_load).film.position_m.copy()

    def at_operating_point(self, speed: float, static_load: np.ndarray | None = None,
                           transient: bool = False) -> "FluidFilmBearing":
        """This bearing with the viscosity of the thermal equilibrium at (speed, load) held fixed; for a
        time integration with the deck's ``transient_film`` force model."""
        mu = self.analyze(speed, static_load).film.viscosity_Pa_s
        return dataclasses.replace(self, viscosity_Pa_s=float(mu),
                                   film_method=self.transient_film if transient else "reynolds")

    def force_and_tangent(self, q, v, t=0.0, speed=0.0, angle=None):
        """Film force on the journal at displacement q and velocity v, and its tangent (contract)."""
        mu = self.viscosity_Pa_s
        if mu is None:
            if self.load_N is None:
                raise ValueError(f"bearing {self.name!r}: the film force needs the operating point "
                                 "(static load) that fixes its thermal-equilibrium viscosity")
            mu = self.analyze(speed).film.viscosity_Pa_s
        model = film_model(self.geometry, self.n_circ, self.n_axial, self.film_method)
        return model.force_and_tangent(np.asarray(q, float), np.asarray(v, float), speed, mu)


@functools.lru_cache(maxsize=256)
def _analyze_cached(bearing: FluidFilmBearing, speed_rad_s: float, wx: float, wy: float) -> ThermalResult:
    """Static, modal, FRF and Campbell ask for the same operating points: solve each once."""
    return solve_thermal(bearing.solver, bearing.viscosity, speed_rad_s, np.array([wx, wy]), bearing.thermal)
