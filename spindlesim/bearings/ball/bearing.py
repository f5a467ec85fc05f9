"""`BallBearing`: angular-contact / deep-groove ball bearing (single row or matched set), 5 DOF.

The bearing contract (``spindlesim.bearings.base``): q = (x, y, z, theta_x, theta_y) of the inner
ring (the shaft node) measured from the bearing centre; f the force and moment ON THE SHAFT;
K_t = -df/dq of the elastic reaction exact (implicit-function Jacobian through every ball equilibrium,
:mod:`.kernel`); damping C = beta K (``damping_s``, :mod:`..damping`): ``linearized`` returns C = beta K,
``force_and_tangent`` adds -beta K_t v to f with C_t = beta K_t.  Outer rings fixed, inner ring turning at
``speed``.

Inner-ring kinematics at ball j of row k (azimuth psi, row at z_k, thrust direction s_k; small
displacements, Jones 1960; Harris and Kotzalas 2007, *Advanced Concepts*, ch. 1 and 3): the inner
groove curvature centre O_i, at radius R_i = d_m/2 + (r_i - D/2) cos(alpha_f) and axial position
z_c = z_k + s_k (r_i - D/2) sin(alpha_f), moves by u = (x, y, z) + theta x O_i, so

    A_a = A0 sin(alpha0) + c_k - s_k w_k + s_k (z + R_i (theta_x sin psi - theta_y cos psi))
    A_r = A0 cos(alpha0) - P_d/2 + (x + z_c theta_y) cos psi + (y - z_c theta_x) sin psi

(c_k: position-preload offset; w_k: axial shift of a floating outer ring).  The ball forces
act at O_i (their line of action passes through it), so f = sum T^T G (+ the inner friction
couple, full model only) is the exact work conjugate of q and the rest tangent is symmetric.

Preload (one choice for the whole set):
- ``position``: ``axial_m`` is the total axial approach that clamping imposes on the set beyond
  first contact (the catalogue "preload offset" of a matched pair: the gap between the ring
  faces that the clamping closes).  Each row's inner ring then sits axial_m / 2 past first
  contact in its own thrust direction; the node's z absorbs any unequal split (3-row sets), so
  q = 0 is the centre of a symmetric set.  Needs opposed rows (DB or DF).
- ``spring`` (constant pressure): the outer rings of the floating rows slide axially in the
  housing and are pushed by a constant force ``axial_N``; their axial shift is solved for at
  every q and condensed out of the tangent (the floating rows add no axial stiffness).  The
  housing still holds them radially and in tilt.  The floating rows are those whose thrust points
  along ``floating_thrust`` (+1: +z, -1: -z); every row of a single bearing or tandem set.
- ``none``: rings at first contact (q = 0), clearance as given.

Equilibrium under a load (:mod:`.equilibrium`): every DOF free, or some held at a prescribed displacement
(``Held``; the state then reports the holding load).  Race control (``model``): outer_race_control,
inner_race_control or full (:mod:`.kernel`).

Ball positions: psi_j = phi + 2 pi j / Z in every row (rows aligned), phi = cage angle =
(1 - gamma)/2 times the shaft angle (kinematic cage ratio at alpha_f).  ``linearized`` averages
the tangent over ``pitch_samples`` cage positions within one ball pitch, each at its own
equilibrium under the load (the contract's rolling-bearing rule).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, replace

import numpy as np

from ..base import FIVE, BearingBase, shaft_angle
from ..damping import check_beta, damped
from . import checks, floating
from . import equilibrium as eq
from . import kernel as kn
from .equilibrium import FREE, BallEquilibriumError, Held, Work
from .geometry import BallGeometry
from .kinematics import RACE_CODES, ball_motion
from .rating import RatingInputs, lives
from .results import BallState

log = logging.getLogger(__name__)

MODELS = ("outer_race_control", "inner_race_control", "full")
#: traction coefficient above which the state warns that the gyroscopic couple exceeds friction
TRACTION_WARN = 0.1

__all__ = ["BallBearing", "BallEquilibriumError", "Held", "MODELS", "Preload", "Work"]


@dataclass(frozen=True)
class Preload:
    """Preload of the set in SI: kind none | position (axial_m) | spring (axial_N, on the floating rows:
    those carrying thrust along ``floating_thrust``, +1 / -1 along z)."""

    kind: str = "none"
    axial_m: float = 0.0
    axial_N: float = 0.0
    floating_thrust: int = 1
    #: position preload only: per-row axial offsets [m] added to axial_m / 2 (thermal growth of the rings,
    #: spindlesim.thermal.growth_bearings); None = none
    row_offsets_m: tuple[float, ...] | None = None

    def row_offsets(self, rows: int) -> np.ndarray:
        """Axial groove-centre offset c_k of each row [m] (0 unless position-preloaded)."""
        if self.kind != "position":
            return np.zeros(rows)
        c = np.full(rows, 0.5 * self.axial_m)
        if self.row_offsets_m is not None:
            if len(self.row_offsets_m) != rows:
                raise ValueError(f"row_offsets_m has {len(self.row_offsets_m)} entries for {rows} rows")
            c = c + np.asarray(self.row_offsets_m, float)
        return c

    def label(self) -> str:
        if self.kind == "position":
            if self.row_offsets_m is not None:
                extra = 2e6 * float(np.mean(self.row_offsets_m))
                return f"position preload {self.axial_m * 1e6:.3g} um, axial offset from growth {extra:+.3g} um"
            return f"position preload {self.axial_m * 1e6:.3g} um"
        if self.kind == "spring":
            return f"spring preload {self.axial_N:.4g} N"
        return "no preload"


@dataclass(frozen=True)
class _RowEval:
    f_rows: np.ndarray
    K_rows: np.ndarray
    Qi: np.ndarray
    Qo: np.ndarray
    ai: np.ndarray
    ao: np.ndarray
    Fc: np.ndarray
    Mg: np.ndarray
    psi: np.ndarray


@dataclass(frozen=True)
class _SetEval:
    f: np.ndarray
    K: np.ndarray
    rows: _RowEval
    shift: float  # outer-ring axial shift of the floating rows [m] (along z)


def _made_as(geometry, preload):
    from .thermal import MadeAs

    return MadeAs.of(geometry, preload)


class BallBearing(BearingBase):
    """Quasi-static ball bearing (set); immutable: a solve's warm starts live in its own :class:`Work`."""

    dof_names = FIVE
    internal_mass = np.zeros(0)

    def __init__(self, geometry: BallGeometry, preload: Preload = Preload(), *, name: str = "ball", node: int = 0,
                 model: str = "outer_race_control", rating: RatingInputs = RatingInputs(), pitch_samples: int = 4,
                 speed_growth=None, growth=None, shoulders: checks.Shoulders | None = None, race=None,
                 made=None, damping_s: float = 0.0, damping_held=None):
        if model not in MODELS:
            raise ValueError(f"model must be one of {MODELS}, not {model!r}")
        if race is not None and np.shape(race) != (geometry.rows, geometry.balls):
            raise ValueError(f"race needs one code per ball, shape {(geometry.rows, geometry.balls)}")
        if preload.kind not in ("none", "position", "spring"):
            raise ValueError(f"unknown preload kind {preload.kind!r}")
        s = geometry.row_sign
        if preload.kind == "position" and not (np.any(s > 0) and np.any(s < 0)):
            raise ValueError("a position preload needs opposed rows (arrangement DB or DF)")
        if preload.kind == "spring" and not preload.axial_N > 0.0:
            raise ValueError("a spring preload needs a positive axial force")
        if preload.floating_thrust not in (1, -1):
            raise ValueError("floating_thrust must be +1 or -1")
        if pitch_samples < 1:
            raise ValueError("pitch_samples must be >= 1")
        self.geometry = geometry
        self.preload = preload
        self.name = str(name)
        self.node = int(node)
        #: race control of every ball (RACE_CODES): the model's, or per ball (``race``, e.g. chosen by Jones'
        #: criterion: then ``model`` reads "auto" unless every ball has the same)
        self._race_given = None if race is None else np.array(race, dtype=np.int8)
        self.race = np.full((geometry.rows, geometry.balls), RACE_CODES[model], np.int8) if race is None \
            else self._race_given.copy()
        self.model = model if race is None else _race_label(self.race)
        self.rating = rating
        self.pitch_samples = int(pitch_samples)
        #: beta [s] of the damping C = beta K (:mod:`..damping`; 0: none, the contact model alone)
        self.damping_s = check_beta(damping_s)
        #: the damping matrix held for a time integration (``at_operating_point(..., transient=True)``), or None
        self.damping_held = None if damping_held is None else np.array(damping_held, float).reshape(5, 5)
        #: callable speed [rad/s] -> radial growth of the inner groove centre beyond rest [m] (None: rings rigid
        #: against speed); ``growth``: what the bearing's temperatures and fits changed (reporting only)
        self.speed_growth = speed_growth
        self.growth = growth
        #: how the bearing was made (the cold assembly: .thermal.MadeAs), the start of at_temperatures
        self.made = made if made is not None else _made_as(geometry, preload)
        #: thrust-side shoulders of the rings (truncation check); None: the typical ratio (checks.shoulders_of)
        self.shoulders = checks.shoulders_of(geometry) if shoulders is None else shoulders
        g = geometry
        D, dm = g.ball_diameter_m, g.pitch_diameter_m
        p = np.zeros(kn.N_PARAMS)
        p[kn.G_I] = (g.inner_conformity - 0.5) * D
        p[kn.G_O] = (g.outer_conformity - 0.5) * D
        p[kn.K_I], p[kn.K_O], p[kn.K_N] = g.inner.K, g.outer.K, g.K_series
        p[kn.GAMMA] = D / dm
        p[kn.M_HALF_DM] = g.ball_mass_kg * 0.5 * dm
        p[kn.J_BALL] = g.ball_inertia_kg_m2
        p[kn.D_BALL] = D
        p[kn.R_I_GROOVE] = g.inner_groove_radius_m
        # the race control of a uniform model (kernel.evaluate_rows sets these per ball from self.race)
        p[kn.RACE], p[kn.LAM_I], p[kn.LAM_O] = {"outer_race_control": (kn.RACE_OUTER, 0.0, 2.0),
                                                "inner_race_control": (kn.RACE_INNER, 2.0, 0.0),
                                                "full": (kn.RACE_FULL, 1.0, 1.0)}[model]
        p[kn.COUPLE] = 1.0
        p[kn.A_AX0], p[kn.A_RAD0] = g.reference_axial_m, g.reference_radial_m
        p[kn.R_I_CENTRE] = g.inner_centre_radius_m
        p[kn.A_0] = g.groove_distance_m
        p[kn.SPLIT_O] = 1.0 / (1.0 + (g.outer.K / g.inner.K) ** (2.0 / 3.0))
        p[kn.FC_FLOOR] = 1e-8 * g.K_series * 1e-9  # 1e-8 of the series Hertz load at 1 um
        self._p = p
        self._row_sign = np.ascontiguousarray(s, dtype=np.int64)
        self._row_zc = g.row_z_m + s * g.inner_centre_offset_m
        self._row_offset = preload.row_offsets(g.rows)
        # a single row or a tandem set floats whole, whatever the thrust named
        self._s_float = int(preload.floating_thrust) if np.any(s == preload.floating_thrust) else int(s[0])
        self._floating = (s == self._s_float) if preload.kind == "spring" else np.zeros(g.rows, bool)
        self.fully_floating = bool(self._floating.all())

    # ---- variants -------------------------------------------------------------------------
    def with_preload(self, value: float) -> "BallBearing":
        """Same bearing with another preload of the same kind: axial_m (position) or axial_N (spring)."""
        if self.preload.kind == "position":
            pre = replace(self.preload, axial_m=float(value))
        elif self.preload.kind == "spring":
            pre = replace(self.preload, axial_N=float(value))
        else:
            raise ValueError("the bearing has no preload to vary")
        return self._copy(preload=pre)

    def with_model(self, model: str) -> "BallBearing":
        return self._copy(model=model, race=None)

    def with_race(self, codes) -> "BallBearing":
        """Same bearing with a race control per ball (RACE_CODES, shape (rows, balls))."""
        return self._copy(race=codes)

    def _copy(self, **kw) -> "BallBearing":
        args = dict(preload=self.preload, name=self.name, node=self.node, model=self._base_model(),
                    rating=self.rating, pitch_samples=self.pitch_samples, speed_growth=self.speed_growth,
                    growth=self.growth, shoulders=self.shoulders, race=self._race_given, made=self.made,
                    damping_s=self.damping_s, damping_held=self.damping_held)
        args.update(kw)
        geometry = args.pop("geometry", self.geometry)
        return BallBearing(geometry, **args)

    # ---- the spindle's thermal model (contract: at_temperatures, heat) -------------------------------
    def at_temperatures(self, temperatures) -> "BallBearing":
        """The bearing rebuilt at the parts' temperatures from the way it was made (.thermal)."""
        from . import thermal

        return thermal.at_temperatures(self, temperatures)

    def heat(self, speed, static_load, lubrication, lubricant_C, displacement=None):
        """Heat of the set at its operating point, split to inner ring, balls and outer ring (.thermal)."""
        from . import thermal

        return thermal.heat(self, speed, static_load, lubrication, lubricant_C, displacement)

    def _base_model(self) -> str:
        return self.model if self.model in MODELS else "outer_race_control"

    # ---- kinematics -------------------------------------------------------------------------
    def cage_angle(self, shaft_angle_rad: float) -> float:
        return self.geometry.cage_ratio() * shaft_angle_rad

    def frequencies_hz(self, speed: float) -> dict[str, float]:
        """Kinematic frequencies at the mounted free contact angle (see BallGeometry)."""
        f = self.geometry.kinematic_frequencies_hz(speed)
        f.pop("shaft")
        return f

    # ---- evaluation ---------------------------------------------------------------------------
    def _rows(self, q: np.ndarray, om: float, phi: float, w: np.ndarray, idx: np.ndarray,
              work: Work | None = None) -> _RowEval:
        work = Work(self) if work is None else work
        g = self.geometry
        n, Z = idx.size, g.balls
        X = np.ascontiguousarray(work.centres[idx])
        f_rows, K_rows = np.empty((n, 5)), np.empty((n, 5, 5))
        out = [np.empty((n, Z)) for _ in range(7)]
        try:
            status = kn.evaluate_rows(np.ascontiguousarray(q, dtype=float), float(om), float(phi), work.params(self, om),
                                      self._row_sign[idx], self._row_zc[idx], self._row_offset[idx],
                                      np.ascontiguousarray(w[idx], dtype=float),
                                      np.ascontiguousarray(self.race[idx], dtype=np.float64), Z, X, f_rows, K_rows,
                                      *out)
        except ZeroDivisionError:  # a degenerate ball (e.g. opposite contact normals): the rings pass a ball
            work.forget()
            raise BallEquilibriumError(
                f"bearing {self.name!r}: the inner ring at q = {np.round(np.asarray(q) * 1e6, 4).tolist()} (um, urad) "
                f"moves its groove centre past the outer one at a ball (their distance as made: "
                f"{g.groove_distance_m * 1e6:.4g} um): no ball fits there") from None
        if status >= 0:
            k, j = idx[status // Z], status % Z
            psi = phi + 2.0 * math.pi * j / Z
            work.forget()
            raise BallEquilibriumError(
                f"bearing {self.name!r}: equilibrium of ball {j + 1} of row {k + 1} "
                f"(psi {math.degrees(psi) % 360:.1f} deg) "
                f"did not converge (damped Newton on the ball centre, {kn.MAX_NEWTON} iterations) at "
                f"{om * 30 / math.pi:.6g} rpm, inner ring at q = {np.round(np.asarray(q) * 1e6, 4).tolist()} "
                f"(um, urad), model {self.model}")
        work.centres[idx] = X
        Qi, Qo, ai, ao, Fc, Mg, psi = out
        return _RowEval(f_rows, K_rows, Qi, Qo, ai, ao, Fc, Mg, psi)

    def _evaluate(self, q: np.ndarray, om: float, phi: float, work: Work | None = None) -> _SetEval:
        """The set at q (``work``: the warm starts of the call, a fresh one by default)."""
        work = Work(self) if work is None else work
        rows = self.geometry.rows
        all_rows = np.arange(rows)
        if self.preload.kind != "spring":
            ev = self._rows(q, om, phi, np.zeros(rows), all_rows, work)
            return _SetEval(ev.f_rows.sum(axis=0), ev.K_rows.sum(axis=0), ev, 0.0)
        fl = np.flatnonzero(self._floating)
        shift, evf = floating.shift(self, q, om, phi, fl, work)
        w = np.zeros(rows)
        w[fl] = shift
        fixed = np.flatnonzero(~self._floating)
        ev = _merge(rows, fl, evf, fixed, self._rows(q, om, phi, w, fixed, work)) if fixed.size else evf
        Kg = evf.K_rows.sum(axis=0)
        Kc = Kg - np.outer(Kg[:, 2], Kg[2, :]) / Kg[2, 2]
        Kc[2, :] = 0.0
        Kc[:, 2] = 0.0
        K = Kc + (ev.K_rows.sum(axis=0) - Kg)
        return _SetEval(ev.f_rows.sum(axis=0), K, ev, shift)

    # ---- the contract ---------------------------------------------------------------------------
    def force_and_tangent(self, q, v, t, speed, angle=None):
        """(f, K_t, C_t) on (x, y, z, theta_x, theta_y): the elastic reaction with the damping force -beta K_t v,
        its tangent K_t and C_t = beta K_t (:mod:`..damping`)."""
        qq = np.asarray(q, float)
        ev = self._evaluate(qq, float(speed), self.cage_angle(shaft_angle(speed, t, angle)))
        vv = np.zeros(5) if v is None else np.asarray(v, float)[:5]
        f, C = damped(ev.f.copy(), ev.K.copy(), vv, self.damping_s, self.damping_held)
        return f, ev.K.copy(), C

    def linearized(self, speed, static_load=None, start=None):
        """(K, C) at the equilibrium under ``static_load`` (5 entries; None = 0), K averaged over
        ``pitch_samples`` cage positions within one ball pitch, the first from ``start`` (the contract's;
        default the unloaded ring), each next from the one before; C = beta K (``damping_s``)."""
        load = _five(static_load)
        pitch = 2.0 * math.pi / self.geometry.balls
        K, work = np.zeros((5, 5)), Work(self)
        q, ev = self._started(load, float(speed), start, work)
        for m in range(self.pitch_samples):
            if m:
                q, ev, _ = self._equilibrium(load, float(speed), m * pitch / self.pitch_samples, q, work=work)
            K += ev.K
        K = K / self.pitch_samples
        return K, self.damping_s * K

    def at_operating_point(self, speed, static_load=None, transient=False) -> "BallBearing":
        """For a time integration: the bearing with its damping held at beta K of the operating point
        (:mod:`..damping`); otherwise itself."""
        if not transient or self.damping_s == 0.0:
            return self
        return self._copy(damping_held=self.linearized(speed, static_load)[1])

    def static_displacement(self, speed, static_load=None, start=None) -> np.ndarray:
        """Inner-ring displacement carrying ``static_load`` at cage angle 0, from ``start`` (the contract)."""
        return self._started(_five(static_load), float(speed), start, Work(self))[0].copy()

    def _started(self, load, speed: float, start, work: Work):
        """(q, evaluation) of the equilibrium at cage angle 0 from ``start`` (None: the unloaded ring), or from
        the unloaded ring when Newton fails from there: the same root to the set tolerance."""
        if start is not None:
            q0 = np.array(start, float)[:5]
            if self.fully_floating:
                q0[2] = 0.0  # not solved for (the spring carries z): as from the unloaded ring
            try:
                return self._equilibrium(load, speed, 0.0, q0, work=work)[:2]
            except BallEquilibriumError:
                work.forget()
        return self._equilibrium(load, speed, 0.0, work=work)[:2]

    # ---- equilibrium and results ---------------------------------------------------------------
    def _equilibrium(self, load, speed: float, phi: float, q0=None, max_iter: int = 100, held: Held = FREE,
                     work: Work | None = None):
        """(q, evaluation, iterations) with reaction(q) + load = 0 on the free DOFs (:mod:`.equilibrium`)."""
        return eq.solve(self, load, speed, phi, q0, max_iter, held, Work(self) if work is None else work)

    def solve(self, load, speed: float = 0.0, cage_angle: float = 0.0, held: Held = FREE, q0=None,
              work: Work | None = None) -> BallState:
        """The state under ``load`` (Fx, Fy, Fz [N], Mx, My [N m], what the shaft puts on the bearing) at
        ``speed`` [rad/s]: the equilibrium with its results; ``held``: DOFs held at prescribed displacements
        (their load components must be 0); warm starts, passed in: ``q0`` the inner ring's, ``work`` the balls'
        (a :class:`Work` a chain of solves shares; default: the built-in starts)."""
        q, ev, its = self._equilibrium(load, float(speed), float(cage_angle), q0, held=held, work=work)
        return self._state(q, ev, float(speed), float(cage_angle), its, load, held)

    def rating_life_Mrev(self, speed, static_load) -> float | None:
        """ISO 281 basic rating life of the set in its equilibrium under ``static_load`` at ``speed`` [rad/s]."""
        return self.solve(_five(static_load), float(speed)).life_L10_iso281_Mrev

    def at(self, q, speed: float = 0.0, cage_angle: float = 0.0, work: Work | None = None) -> BallState:
        """The state at a given inner-ring displacement q (5): evaluated, nothing solved (``work``: as in
        :meth:`solve`)."""
        qq = np.array(q, float)
        return self._state(qq, self._evaluate(qq, float(speed), float(cage_angle), work), float(speed),
                           float(cage_angle), 0)

    def _state(self, q, ev: _SetEval, speed: float, phi: float, iterations: int, load=None,
               held: Held = FREE) -> BallState:
        """Results; ``load`` (the load the equilibrium carries on its free DOFs) plus the holding load at
        the held DOFs feeds ISO 281; default -reaction."""
        g = self.geometry
        r = ev.rows
        c_i, c_o = np.cbrt(np.maximum(r.Qi, 0.0)), np.cbrt(np.maximum(r.Qo, 0.0))
        row_axial = -g.row_sign * r.f_rows[:, 2]
        if load is None:
            load, hold = -ev.f, np.zeros(5)
        else:
            hold = eq.holding_load(ev.f, load, held)
            load = np.asarray(load, float) + hold
        lf = lives(g, self.rating, r.Qi, r.Qo, math.hypot(load[0], load[1]), load[2])
        traction = self._traction(r)
        if np.nanmax(traction, initial=0.0) > TRACTION_WARN:
            k, j = np.unravel_index(int(np.nanargmax(traction)), traction.shape)
            log.warning("bearing %r at %.6g rpm: the gyroscopic couple of ball %d of row %d needs a traction "
                        "coefficient of %.3g; above about %.2g the ball would pivot (gyroscopic slip), which this "
                        "quasi-static model does not represent", self.name, speed * 30 / math.pi, j + 1, k + 1,
                        traction[k, j], TRACTION_WARN)
        if g.contact_angle_rad > 0.0 and np.any((r.ai < 0.0) & (r.Qi > 0.0)):
            log.warning("bearing %r: loaded balls with a negative contact angle: an angular-contact ring would "
                        "run on its low shoulder (the groove is modelled as a full torus)", self.name)
        semi_i = np.stack([g.inner.a1 * c_i, g.inner.b1 * c_i], axis=-1)
        semi_o = np.stack([g.outer.a1 * c_o, g.outer.b1 * c_o], axis=-1)
        ai_deg, ao_deg = np.degrees(r.ai), np.degrees(r.ao)
        Msi, Mso = checks.spin_moments(g, r.Qi, r.Qo, semi_i, semi_o)
        motion = ball_motion(r.ai, r.ao, speed, g.pitch_diameter_m, g.ball_diameter_m, self.race)
        sym = g.contact_angle_rad == 0.0
        sh = self.shoulders
        edge_i = checks.edge_angles_deg(ai_deg, semi_i[..., 0], g.inner_groove_radius_m, sym)
        edge_o = checks.edge_angles_deg(ao_deg, semi_o[..., 0], g.outer_groove_radius_m, sym)
        return BallState(
            displacement=np.array(q, float), reaction=ev.f.copy(), load=load.copy(), holding_load=hold,
            held=tuple(bool(m) for m in held.mask), stiffness=ev.K.copy(), speed_rad_s=speed, model=self.model,
            race_used=self.race.copy(),
            cage_angle_rad=phi, psi_rad=r.psi.copy(), row_z_m=g.row_z_m.copy(), row_sign=g.row_sign.copy(),
            element_load_inner_N=r.Qi.copy(), element_load_outer_N=r.Qo.copy(),
            contact_angle_inner_deg=ai_deg, contact_angle_outer_deg=ao_deg,
            max_pressure_inner_Pa=g.inner.p1 * c_i, max_pressure_outer_Pa=g.outer.p1 * c_o,
            semi_axes_inner_m=semi_i, semi_axes_outer_m=semi_o,
            centrifugal_force_N=r.Fc.copy(), gyroscopic_moment_Nm=r.Mg.copy(), traction_ratio=traction,
            spin_moment_inner_Nm=Msi, spin_moment_outer_Nm=Mso,
            race_control=checks.race_control_criterion(Msi, Mso, ai_deg, ao_deg),
            spin_roll_inner=motion.spin_roll_inner, spin_roll_outer=motion.spin_roll_outer,
            edge_angle_inner_deg=edge_i, edge_angle_outer_deg=edge_o,
            shoulder_angle_inner_deg=math.degrees(sh.inner_angle_rad),
            shoulder_angle_outer_deg=math.degrees(sh.outer_angle_rad),
            truncated_inner=checks.truncated(edge_i, sh.inner_angle_rad, r.Qi, sym),
            truncated_outer=checks.truncated(edge_o, sh.outer_angle_rad, r.Qo, sym),
            row_axial_load_N=row_axial,
            floating_ring_axial_m=float(ev.shift), lives=lf, iterations=int(iterations),
        )

    def _traction(self, r: _RowEval) -> np.ndarray:
        """Friction force over normal load at the contacts that carry the gyroscopic couple (the larger
        of the two when both do); inf where that contact is unloaded but a couple is needed."""
        D = self.geometry.ball_diameter_m
        lam_i = np.where(self.race > 0, 0.0, np.where(self.race < 0, 2.0, 1.0))
        lam_o = 2.0 - lam_i
        out = np.zeros_like(r.Mg)
        with np.errstate(divide="ignore", invalid="ignore"):
            for lam, Q in ((lam_o, r.Qo), (lam_i, r.Qi)):
                out = np.maximum(out, np.where((r.Mg != 0.0) & (lam > 0.0), np.abs(lam * r.Mg / D) / Q, 0.0))
        return out


def _five(static_load) -> np.ndarray:
    """The contract's ``static_load`` on (x, y, z, theta_x, theta_y), zeros where not given."""
    load = np.zeros(5)
    if static_load is not None:
        sl = np.asarray(static_load, float)
        load[: sl.size] = sl
    return load


def _race_label(race: np.ndarray) -> str:
    """The model name of per-ball race codes: the common one, or "auto" when the balls differ."""
    for name, code in RACE_CODES.items():
        if np.all(race == code):
            return name
    return "auto"


def _merge(rows: int, ia: np.ndarray, ea: _RowEval, ib: np.ndarray, eb: _RowEval) -> _RowEval:
    """Row evaluations of two row subsets back in row order."""
    parts = {}
    for field in ("f_rows", "K_rows", "Qi", "Qo", "ai", "ao", "Fc", "Mg", "psi"):
        a = getattr(ea, field)
        out = np.empty((rows,) + a.shape[1:])
        out[ia] = a
        if ib.size:
            out[ib] = getattr(eb, field)
        parts[field] = out
    return _RowEval(**parts)
