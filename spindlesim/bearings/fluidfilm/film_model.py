"""Entry point of the dynamic fluid-film force: :class:`FilmForceModel`.

``FilmForceModel(geometry, n_circ, n_axial, method="table" | "reynolds")`` gives
``force_and_tangent(q_m, v_m_s, omega_rad_s, viscosity_Pa_s) -> (f, K_t, C_t)``: the force of
the film on the shaft [N] in spindlesim's x-y frame at journal displacement ``q`` [m] from
the bearing centre and velocity ``v`` [m/s], and ``K_t = -df/dq`` [N/m], ``C_t = -df/dv``
[N s/m].  ``"reynolds"`` solves the Reynolds LCP at every call (:mod:`film_force`, exact for
the discrete model, about 1-4 ms); ``"table"`` interpolates per-land tables of the same
discrete solution (:mod:`film_table`, tens of microseconds, within 1 % of the exact force on
the region studied in benchmarks/bench_film_force.py).  Both raise
:class:`~spindlesim.bearings.fluidfilm.reynolds.ReynoldsError` when the journal reaches the
bore.  The viscosity is an argument (the thermal-equilibrium value of the operating point).
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

import numpy as np

from spindlesim.bearings.fluidfilm.film_force import ExactFilmForce
from spindlesim.bearings.fluidfilm.geometry import BearingGeometry
from spindlesim.bearings.fluidfilm.reynolds import DEFAULT_AXIAL, DEFAULT_CIRCUMFERENTIAL

if TYPE_CHECKING:
    from spindlesim.bearings.fluidfilm.film_table import TableResolution

METHODS = ("table", "reynolds")


class FilmForceModel:
    """Nonlinear film force and tangent of one bearing (SI in, SI out)."""

    def __init__(self, geometry: BearingGeometry, n_circ: int = DEFAULT_CIRCUMFERENTIAL,
                 n_axial: int = DEFAULT_AXIAL, method: str = "table",
                 resolution: TableResolution | None = None,
                 cache_dir: str | os.PathLike | None = None) -> None:
        if method not in METHODS:
            raise ValueError(f"method must be one of {METHODS}, got {method!r}")
        self.geometry = geometry
        self.method = method
        if method == "table":
            from spindlesim.bearings.fluidfilm.film_table import TableFilmForce  # numba, scipy.interpolate

            self._impl = TableFilmForce(geometry, n_circ, n_axial, resolution, cache_dir)
        else:
            self._impl = ExactFilmForce(geometry, n_circ, n_axial)

    def force_and_tangent(self, q_m, v_m_s, omega_rad_s: float,
                          viscosity_Pa_s: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(f [N], K_t = -df/dq [N/m], C_t = -df/dv [N s/m]), x-y frame, force on the shaft."""
        return self._impl.force_and_tangent(q_m, v_m_s, omega_rad_s, viscosity_Pa_s)

    def force(self, q_m, v_m_s, omega_rad_s: float, viscosity_Pa_s: float) -> np.ndarray:
        return self.force_and_tangent(q_m, v_m_s, omega_rad_s, viscosity_Pa_s)[0]
