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

What the operating point holds (one model for static, modal and transient, issue "One spindle
model"):

- the viscosity of the thermal equilibrium;
- for a 360 deg bore fed at the maximum film (``feed="max_film"``), the film start: at the
  maximum film of the operating point, fixed in space (:func:`geometry.fixed_feed_geometry`).
  Its force there is the max-film force and its tangent the static solver's coefficients, so
  ``linearized`` is the tangent of ``force_and_tangent`` at the static state (a film start that
  turned with the journal would make them differ by the motion of the film start: 5.6 % in the
  whirl frequency of tests/validation/test_one_model_oil_whirl.py's rotor);
- for the tabulated film of a transient, the table's force error at the operating point, removed
  as a constant (``force_offset_N``): the tabulated film carries the static load at exactly the
  static position of the full solve, so a run starts in equilibrium at the state of ``static``
  (without it the two differ by the table's error, some 0.1 % of the deflection).

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

from ..base import RADIAL, BearingBase, SpeedRequiredError
from .film_model import FilmForceModel
from .geometry import BearingGeometry, fixed_feed_geometry
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

    ``load_N`` is a load the deck puts on the bearing (acting downward: the shaft presses the
    bearing in -y) besides what the rotor's own static equilibrium gives it (``static_load``): the
    film works at the eccentricity that carries both.  In a rotor the journal is measured from the
    position that carries ``load_N`` alone (``journal_offset``), so the reaction on the shaft,
    f(q) = f_film(q + e_0) + (0, -load_N), is zero at q = 0, its tangent is :meth:`linearized`, and
    static, modal and transient analyses see the same film (without ``load_N`` e_0 = 0 and the
    rotor's load is the bearing's).  ``viscosity_Pa_s`` is set by :meth:`at_operating_point`.
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
    free_geometry: BearingGeometry | None = None  # the deck's geometry when frozen with a fixed feed
    force_offset_N: tuple[float, float] = (0.0, 0.0)  # tabulated film: its error at the operating point
    journal_offset_m: tuple[float, float] | None = None  # e_0 held by an operating point (load_N decks)
    #: (speed, q_x, q_y, f_x, f_y, K (4), C (4)) at the held operating point: the film force and tangent
    #: there are those of the thermal equilibrium already solved (a static solver starting at the
    #: operating point needs no new film solution to see that it balances)
    held_state: tuple[float, ...] | None = None
    dof_names: tuple[str, ...] = RADIAL

    @property
    def solver(self) -> ReynoldsSolver:
        return cached_solver(self.geometry, self.n_circ, self.n_axial)

    def load_vector(self, static_load: np.ndarray | None = None) -> np.ndarray:
        """(x, y) force of the shaft on the bearing: ``load_N`` (if any) plus ``static_load``."""
        if self.load_N is not None:
            extra = np.zeros(2) if static_load is None else np.asarray(static_load, dtype=float).reshape(2)
            return np.array([0.0, -float(self.load_N)]) + extra
        if static_load is None:
            raise ValueError(f"bearing {self.name!r}: no load_N in the deck and no static load given")
        w = np.asarray(static_load, dtype=float).reshape(2)
        if not np.hypot(*w) > 0:
            raise ValueError(f"bearing {self.name!r}: zero static load")
        return w

    def analyze(self, speed: float, static_load: np.ndarray | None = None) -> ThermalResult:
        """Thermal equilibrium and operating point at ``speed`` [rad/s]."""
        if not speed > 0:
            raise SpeedRequiredError(f"bearing {self.name!r}: a hydrodynamic bearing needs a positive speed "
                             f"(got {speed * 30 / math.pi:.6g} rpm)")
        load = self.load_vector(static_load)
        base = self if self.viscosity_Pa_s is None else dataclasses.replace(  # frozen or not: one cache entry
            self, viscosity_Pa_s=None, film_method="reynolds", force_offset_N=(0.0, 0.0), journal_offset_m=None,
            held_state=None)
        return _analyze_cached(base, float(speed), float(load[0]), float(load[1]))

    def free(self) -> "FluidFilmBearing":
        """The bearing as the deck gives it (nothing held by an operating point)."""
        if self.viscosity_Pa_s is None and self.free_geometry is None:
            return self
        return dataclasses.replace(self, geometry=self.free_geometry or self.geometry, free_geometry=None,
                                   viscosity_Pa_s=None, film_method="reynolds", force_offset_N=(0.0, 0.0),
                                   journal_offset_m=None, held_state=None)

    def journal_offset(self, speed: float, viscosity_Pa_s: float | None = None, near=None) -> np.ndarray:
        """e_0: the journal position carrying ``load_N`` alone at the film's viscosity of the operating
        point (``viscosity_Pa_s``; by default that of ``load_N`` alone), zero without ``load_N``.
        Any fixed reference would do (the static, modal and transient analyses all measure from it);
        this one makes the rotor's static deflection at the bearing the part its own loads cause."""
        if self.load_N is None:
            return np.zeros(2)
        if self.journal_offset_m is not None:
            return np.asarray(self.journal_offset_m, float)
        free = self.free()
        mu = free.analyze(speed).film.viscosity_Pa_s if viscosity_Pa_s is None else viscosity_Pa_s
        return _offset(free, float(speed), float(mu), near).copy()

    def linearized(self, speed: float, static_load: np.ndarray | None = None, start=None):
        """(K [2x2] N/m, C [2x2] N s/m) in the x, y frame at the thermal equilibrium (``start`` unused: the film
        keeps its own starts)."""
        res = self.analyze(speed, static_load)
        return res.film.K_N_m.copy(), res.film.C_Ns_m.copy()

    def static_displacement(self, speed: float, static_load: np.ndarray | None = None, start=None) -> np.ndarray:
        """The journal position of the thermal equilibrium at (speed, load), from ``journal_offset``."""
        film = self.analyze(speed, static_load).film
        return film.position_m - self.journal_offset(speed, film.viscosity_Pa_s, near=film)

    def at_operating_point(self, speed: float, static_load: np.ndarray | None = None,
                           transient: bool = False) -> "FluidFilmBearing":
        """This bearing with what the operating point at (speed, load) sets held fixed (module note):
        the viscosity of the thermal equilibrium, a max-film bore's film start; for a time
        integration with the deck's ``transient_film`` force model."""
        free = self.free()
        film = free.analyze(speed, static_load).film
        offset = tuple(float(v) for v in free.journal_offset(speed, film.viscosity_Pa_s, near=film)) if self.load_N is not None else None
        free = dataclasses.replace(free, journal_offset_m=offset)
        geo, base = free.geometry, None
        if geo.axisymmetric and not geo.lands[0].periodic:  # feed max_film: the film start stays put
            x, y = film.position_m
            geo, base = fixed_feed_geometry(geo, math.atan2(y, x) + math.pi), free.geometry
        held = dataclasses.replace(free, geometry=geo, free_geometry=base, viscosity_Pa_s=float(film.viscosity_Pa_s))
        method = self.transient_film if transient else "reynolds"
        if method == "reynolds":
            q_s = np.asarray(film.position_m, float) - (np.asarray(offset) if offset is not None else 0.0)
            f_s = -free.load_vector(static_load) + (np.array([0.0, -float(self.load_N)]) if self.load_N is not None else 0.0)
            state = (float(speed), *q_s, *f_s, *np.ravel(film.K_N_m), *np.ravel(film.C_Ns_m))
            return dataclasses.replace(held, held_state=tuple(float(v) for v in state))
        held = dataclasses.replace(held, held_state=None)
        table = film_model(geo, self.n_circ, self.n_axial, method)
        q0 = np.asarray(film.position_m, float)
        f_table = table.force_and_tangent(q0, np.zeros(2), speed, float(film.viscosity_Pa_s))[0]
        f_exact = -free.load_vector(static_load)
        return dataclasses.replace(held, film_method=method, force_offset_N=tuple(float(v) for v in f_exact - f_table))

    def force_and_tangent(self, q, v, t=0.0, speed=0.0, angle=None):
        """Film force on the journal at displacement q and velocity v, and its tangent (contract);
        with ``load_N``, f_film(q + e_0) + (0, -load_N) (class note)."""
        mu = self.viscosity_Pa_s
        if mu is None:
            if self.load_N is None:
                raise ValueError(f"bearing {self.name!r}: the film force needs the operating point "
                                 "(static load) that fixes its thermal-equilibrium viscosity")
            mu = self.analyze(speed).film.viscosity_Pa_s
        h = self.held_state
        q = np.asarray(q, float)
        if (h is not None and speed == h[0] and not np.any(v) and abs(q[0] - h[1]) <= 1e-12 * abs(h[1]) + 1e-18
                and abs(q[1] - h[2]) <= 1e-12 * abs(h[2]) + 1e-18):
            return np.array(h[3:5]), np.array(h[5:9]).reshape(2, 2), np.array(h[9:13]).reshape(2, 2)
        model = film_model(self.geometry, self.n_circ, self.n_axial, self.film_method)
        if self.load_N is not None:
            q = q + self.journal_offset(speed)
        f, K, C = model.force_and_tangent(q, np.asarray(v, float), speed, mu)
        if self.force_offset_N != (0.0, 0.0):
            f = f + np.asarray(self.force_offset_N)
        if self.load_N is not None:
            f = f + np.array([0.0, -float(self.load_N)])
        return f, K, C


_OFFSETS: dict[tuple, np.ndarray] = {}


def _offset(bearing: FluidFilmBearing, speed_rad_s: float, viscosity_Pa_s: float, near=None) -> np.ndarray:
    """The isoviscous journal position carrying ``load_N`` alone (``journal_offset``), solved once per
    (bearing, speed, viscosity); ``near`` (the operating point's film) starts the Newton iteration.
    The solution does not depend on the start beyond the solver's tolerance."""
    from .performance import equilibrium

    key = (bearing, speed_rad_s, viscosity_Pa_s)
    if key not in _OFFSETS:
        start = {} if near is None else {"initial": np.asarray(near.position_m) / bearing.geometry.clearance_m,
                                          "full_film_guess": near.full_film, "initial_solution": near.solution}
        eq = equilibrium(bearing.solver, viscosity_Pa_s, speed_rad_s, np.array([0.0, -float(bearing.load_N)]),
                         **start)
        if len(_OFFSETS) > 256:
            _OFFSETS.clear()
        _OFFSETS[key] = np.array([eq.X, eq.Y]) * bearing.geometry.clearance_m
    return _OFFSETS[key]


#: the last thermal equilibrium of each bearing: the start of its next one (a neighbouring speed)
_NEAR: dict[FluidFilmBearing, tuple[ThermalResult, ...]] = {}


@functools.lru_cache(maxsize=256)
def _analyze_cached(bearing: FluidFilmBearing, speed_rad_s: float, wx: float, wy: float) -> ThermalResult:
    """Static, modal, FRF and Campbell ask for the same operating points: solve each once, each
    started from the bearing's previous equilibrium (a Campbell diagram's neighbouring speed; the
    result does not depend on the start, :func:`solve_thermal`)."""
    before = _NEAR.get(bearing, ())
    res = solve_thermal(bearing.solver, bearing.viscosity, speed_rad_s, np.array([wx, wy]), bearing.thermal,
                        near=before[-1] if before else None, guess_C=_extrapolated(before, speed_rad_s, wx, wy))
    if len(_NEAR) > 64:
        _NEAR.clear()
    _NEAR[bearing] = (before[-1], res) if before else (res,)
    return res


def _extrapolated(before: tuple, speed_rad_s: float, wx: float, wy: float) -> float | None:
    """The mean film temperature at ``speed_rad_s`` on the line through the last two equilibria of the
    bearing (a Campbell diagram's previous speeds), when both had this load (within 1 %); else None."""
    if len(before) < 2:
        return None
    a, b = before
    wa, wb = a.film.speed_rad_s, b.film.speed_rad_s
    w = np.array([wx, wy])
    tol = 0.01 * max(float(np.hypot(wx, wy)), 1e-12)  # the guess only saves film solutions: 1 % will do
    same_load = max(np.max(np.abs(a.film.load_N - w)), np.max(np.abs(b.film.load_N - w))) <= tol
    if not same_load or wa == wb:
        return None
    t = (speed_rad_s - wb) / (wb - wa)
    if not 0.0 < t <= 2.0:  # extrapolate forward, at most two steps
        return None
    return b.temperature_mean_C + t * (b.temperature_mean_C - a.temperature_mean_C)
