"""Fluid-film journal bearing implementing the linearised bearing protocol.

``FluidFilmBearing.linearized(speed, static_load)`` finds the thermal equilibrium
(seed 003 eqs. 4-14) at that speed and load, the journal equilibrium and the eight
coefficients, and returns them in the spindlesim (x horizontal, y vertical) frame, with
the bearing force on the shaft ``f = -(K q + C q')`` (spindlesim/bearings/base.py).

The Reynolds problem is solved directly in the x, y frame (angles from +x towards +y,
the direction of rotation), so the coefficients need no rotation; for an axisymmetric
360 deg bore the line-of-centres solution is rotated into x, y (:mod:`equilibrium`).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from spindlesim.bearings.fluidfilm.geometry import BearingGeometry
from spindlesim.bearings.fluidfilm.reynolds import (
    DEFAULT_AXIAL,
    DEFAULT_CIRCUMFERENTIAL,
    ReynoldsSolver,
)
from spindlesim.bearings.fluidfilm.results import ThermalResult
from spindlesim.bearings.fluidfilm.thermal import ThermalParameters, solve_thermal
from spindlesim.bearings.fluidfilm.viscosity import ConstantViscosity, WaltherViscosity


@functools.lru_cache(maxsize=32)
def cached_solver(geometry: BearingGeometry, n_circ: int, n_axial: int) -> ReynoldsSolver:
    """Grid and sparse pattern depend only on the (frozen) geometry and the grid size."""
    return ReynoldsSolver(geometry, n_circ, n_axial)


@dataclass(frozen=True)
class FluidFilmBearing:
    """A plain or multilobe journal bearing at a shaft node.

    ``load_N`` is the deck's own load magnitude (acting downward: the shaft presses the
    bearing in -y); when ``None`` the ``static_load_N`` vector passed to
    :meth:`linearized` (e.g. from the rotor's static equilibrium) is used.
    """

    name: str
    node: int
    geometry: BearingGeometry
    viscosity: WaltherViscosity | ConstantViscosity
    thermal: ThermalParameters
    load_N: float | None = None
    n_circ: int = DEFAULT_CIRCUMFERENTIAL
    n_axial: int = DEFAULT_AXIAL

    @property
    def solver(self) -> ReynoldsSolver:
        return cached_solver(self.geometry, self.n_circ, self.n_axial)

    def load_vector(self, static_load_N: np.ndarray | None = None) -> np.ndarray:
        """(x, y) force of the shaft on the bearing used for this bearing."""
        if self.load_N is not None:
            return np.array([0.0, -float(self.load_N)])
        if static_load_N is None:
            raise ValueError(
                f"bearing {self.name!r}: no load_N in the deck and no static load given")
        w = np.asarray(static_load_N, dtype=float).reshape(2)
        if not np.hypot(*w) > 0:
            raise ValueError(f"bearing {self.name!r}: zero static load")
        return w

    def analyze(self, speed_rad_s: float, static_load_N: np.ndarray | None = None) -> ThermalResult:
        """Thermal equilibrium and operating point at ``speed_rad_s``."""
        if not speed_rad_s > 0:
            raise ValueError(
                f"bearing {self.name!r}: a hydrodynamic bearing needs a positive speed "
                f"(got {speed_rad_s} rad/s)")
        load = self.load_vector(static_load_N)
        return _analyze_cached(self, float(speed_rad_s), float(load[0]), float(load[1]))

    def linearized(self, speed_rad_s: float, static_load_N: np.ndarray | None = None):
        """(K [2x2] N/m, C [2x2] N s/m) in the x, y frame at the thermal equilibrium."""
        res = self.analyze(speed_rad_s, static_load_N)
        return res.film.K_N_m.copy(), res.film.C_Ns_m.copy()


@functools.lru_cache(maxsize=256)
def _analyze_cached(bearing: FluidFilmBearing, speed_rad_s: float, wx: float, wy: float) -> ThermalResult:
    """Static, modal, FRF and Campbell ask for the same operating points: solve each once."""
    return solve_thermal(bearing.solver, bearing.viscosity, speed_rad_s, np.array([wx, wy]), bearing.thermal)


def rpm_to_rad_s(rpm: float) -> float:
    return rpm * math.pi / 30.0
