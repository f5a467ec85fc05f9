"""`DtrbBearing`: reaction, stiffness, load equilibrium and the bearing protocol.

Sign conventions: ``reaction(d)`` is the force/moment the bearing exerts on the shaft
(inner ring) at the ring displacement d = (dX, dY, dZ, phiX, phiY); ``stiffness(d)`` is
K = -dF/dd; ``solve(load)`` finds d with reaction(d) + load = 0, ``load`` being
the (FX, FY, FZ, MX, MY) the shaft puts on the bearing, and returns the state there; ``at(d)``
evaluates the state at a displacement.  ``preload_m`` is delta0 of
seed 001 eq. 10: each cone is pushed towards the bearing centre by delta0 (total axial
interference 2 delta0).  Speeds in rad/s (inner ring, outer ring fixed).
"""

from __future__ import annotations

import logging
import math
from typing import Sequence

import numpy as np

from ..base import FIVE, RADIAL, BearingBase, shaft_angle
from ..damping import check_beta, damped
from ..statics import damped_newton
from .geometry import DtrbGeometry
from .reactions import azimuths, projection, reaction_from, ring_motion, stiffness_from
from .results import DtrbState, DtrbSweep
from .roller_equilibrium import RollerSolution, operators, solve_rollers

log = logging.getLogger(__name__)

DOFS_2 = RADIAL
DOFS_5 = FIVE


class DtrbBearing(BearingBase):
    """Quasi-static DTRB of seed 001 section 2-1, implementing the bearing contract.

    Immutable after construction: a warm start of the rollers is passed in (``roller_guess`` of
    :meth:`reaction_and_stiffness` and :meth:`at`); ``held``: z, phiX, phiY of a radial (x, y)
    bearing, fixed at an operating point (:meth:`at_operating_point`)."""

    def __init__(self, geometry: DtrbGeometry, preload_m: float = 0.0, *, name: str = "dtrb", node: int = 0,
                 axial_load_N: float = 0.0, row_offset_rad: Sequence[float] = (0.0, 0.0),
                 dof_names: Sequence[str] = DOFS_2, held: Sequence[float] = (0.0, 0.0, 0.0), body=None,
                 made_preload_m: float | None = None, damping_s: float = 0.0, damping_held=None):
        self.geometry = geometry
        #: beta [s] of the damping C = beta K (``bearings.damping``; 0: none, the contact model alone)
        self.damping_s = check_beta(damping_s)
        #: the damping matrix held for a time integration (``at_operating_point(..., transient=True)``), or None
        self.damping_held = None if damping_held is None else np.array(damping_held, float)
        self.preload_m = float(preload_m)
        #: rings' and rollers' ``thermal.growth.ThermoElastic`` (None: bearing steel) and delta0 as assembled
        #: (cold; None: ``preload_m``), the start of :meth:`at_temperatures`
        self.body = body
        self.made_preload_m = self.preload_m if made_preload_m is None else float(made_preload_m)
        self.name = name
        self.node = int(node)
        self.axial_load_N = float(axial_load_N)
        self.row_offset_rad = (float(row_offset_rad[0]), float(row_offset_rad[1]))
        if tuple(dof_names) not in (DOFS_2, DOFS_5):
            raise ValueError(f"dof_names must be {DOFS_2} or {DOFS_5}")
        self.dof_names = tuple(dof_names)
        self._ops = operators(geometry)
        self._held = np.array(held, float)  # z, phiX, phiY of a radial (x, y) bearing (at_operating_point)
        if self._held.shape != (3,):
            raise ValueError("held needs z, phiX and phiY")

    def with_preload(self, preload_m: float, held: Sequence[float] = (0.0, 0.0, 0.0),
                     made_preload_m: float | None = None) -> "DtrbBearing":
        """The same bearing at another preload (``held``: as in the constructor; ``made_preload_m``: the
        cold assembly's delta0 when this preload is that of a temperature, else the new preload itself)."""
        return DtrbBearing(self.geometry, preload_m, name=self.name, node=self.node,
                           axial_load_N=self.axial_load_N, row_offset_rad=self.row_offset_rad,
                           dof_names=self.dof_names, held=held, body=self.body, made_preload_m=made_preload_m,
                           damping_s=self.damping_s)

    def at_temperatures(self, temperatures) -> "DtrbBearing":
        """This bearing with the preload delta0 its parts' growth at ``temperatures``
        (``thermal.growth_bearings.BearingTemperatures``) gives: the assembled delta0 + the change of
        :func:`.thermal.dtrb_preload_change` (rings and rollers of ``body``).  A preload that
        growth takes below zero is a clearance (negative delta0)."""
        from ...thermal.growth import BEARING_STEEL
        from .thermal import dtrb_preload_change

        change = dtrb_preload_change(self.geometry, temperatures, BEARING_STEEL if self.body is None else self.body)
        return self.with_preload(self.made_preload_m + change.preload_change_m, held=self._held,
                                 made_preload_m=self.made_preload_m)

    def heat(self, speed, static_load, lubrication, lubricant_C, displacement=None):
        """Heat at the operating point: Palmgren's tapered-roller moment per row (.thermal)."""
        from . import thermal

        return thermal.heat(self, speed, static_load, lubrication, lubricant_C, displacement)

    # ---- inertia (eqs. 31-32) -------------------------------------------------------
    def inertia_load(self, speed_rad_s: float) -> np.ndarray:
        """(Fc cos gamma, -Fc sin gamma, -Mg) on each roller: eqs. 31-32 in the roller frame."""
        g = self.geometry
        wc = g.cage_ratio * speed_rad_s
        ww = g.spin_ratio * abs(speed_rad_s)
        Fc = g.roller_mass_kg * g.mass_centre_radius_m * wc ** 2
        Mg = g.roller_polar_inertia_kg_m2 * abs(wc) * ww * math.sin(g.roller_axis_angle_rad)
        gam = g.roller_axis_angle_rad
        return np.array([Fc * math.cos(gam), -Fc * math.sin(gam), -Mg])

    def _solve(self, d, speed_rad_s: float, angle_rad: float, u0=None):
        g = self.geometry
        psi = azimuths(g, g.cage_ratio * angle_rad, self.row_offset_rad)
        T = projection(psi)
        W = ring_motion(T, d, self.preload_m)
        sol = solve_rollers(g, self._ops, W, self.inertia_load(speed_rad_s), u0=u0)
        return psi, T, sol

    # ---- public API -------------------------------------------------------------------
    def reaction_and_stiffness(self, displacement, speed_rad_s: float = 0.0, angle_rad: float = 0.0,
                               roller_guess: np.ndarray | None = None):
        """(F (5,), K (5, 5), roller_u (2N, 3)) at one displacement; pass roller_u back as
        ``roller_guess`` on the next call (time step) for a warm start."""
        _, T, sol = self._solve(np.asarray(displacement, float), speed_rad_s, angle_rad, roller_guess)
        return reaction_from(T, self.geometry, sol), stiffness_from(T, self._ops, sol), sol.u

    def reaction(self, displacement, speed_rad_s: float = 0.0, angle_rad: float = 0.0) -> np.ndarray:
        """Force and moment on the shaft (FX, FY, FZ [N], MX, MY [N m]), eqs. 36-40."""
        _, T, sol = self._solve(np.asarray(displacement, float), speed_rad_s, angle_rad)
        return reaction_from(T, self.geometry, sol)

    def stiffness(self, displacement, speed_rad_s: float = 0.0, angle_rad: float = 0.0) -> np.ndarray:
        """K = -dF/dd, 5x5 in (X, Y, Z, phiX, phiY)."""
        _, T, sol = self._solve(np.asarray(displacement, float), speed_rad_s, angle_rad)
        return stiffness_from(T, self._ops, sol)

    def at(self, displacement, speed_rad_s: float = 0.0, angle_rad: float = 0.0, roller_guess=None) -> DtrbState:
        """The state at a given ring displacement (5): evaluated, no ring equilibrium solved."""
        d = np.asarray(displacement, float)
        psi, T, sol = self._solve(d, speed_rad_s, angle_rad, roller_guess)
        return self._state(d, psi, T, sol, speed_rad_s, sol.iterations, sol.converged)

    def _state(self, d, psi, T, sol: RollerSolution, speed, iterations, converged) -> DtrbState:
        g = self.geometry
        N, S = g.rollers_per_row, g.n_slices
        Q = sol.Q.reshape(2, N, -1)
        per_len = 1.0 / g.slice_width_m
        return DtrbState(
            displacement=d.copy(), reaction=reaction_from(T, g, sol), stiffness=stiffness_from(T, self._ops, sol),
            psi_rad=psi, roller_u=sol.u.reshape(2, N, 3),
            inner_load_N=g.inner(Q).sum(axis=-1), outer_load_N=g.outer(Q).sum(axis=-1), rib_load_N=g.rib(Q),
            inner_slice_N_m=g.inner(Q) * per_len, outer_slice_N_m=g.outer(Q) * per_len,
            preload_m=self.preload_m, speed_rad_s=float(speed), iterations=int(iterations),
            converged=bool(converged and sol.converged),
        )

    def _reference_stiffness(self) -> np.ndarray:
        """Diagonal scale: every contact at the secant stiffness of a 1 um approach."""
        g = self.geometry
        psi = azimuths(g)
        T = projection(psi)
        k = g.stiffness * g.exponent * 1e-6 ** (g.exponent - 1.0)
        sol = RollerSolution(np.zeros((psi.size, 3)), np.zeros((psi.size, g.n_contacts)),
                             np.zeros((psi.size, g.n_contacts)), np.tile(k, (psi.size, 1)), 0, True, 0.0)
        return np.diag(stiffness_from(T, self._ops, sol))

    def solve(self, load, speed_rad_s: float = 0.0, angle_rad: float = 0.0, d0=None,
              max_iter: int = 200) -> DtrbState:
        """The state under ``load``: the ring displacement where reaction(d) + load = 0 with its results
        (the one damped Newton of ``bearings.statics`` on the 5 DOFs; a warm start ``d0`` is passed in, the
        rollers' solution carried from one evaluation to the next).  A step is taken when it does not raise
        |R| in the metric of the damping, sqrt(sum R_k^2 / K_ref,k): with a row unloading the plain |R| can
        rise along every damped step (seed 001 Fig. 8 at 10 um preload under FX = FZ = 5 kN stalls at 1.6 kN),
        while in that metric the steady damped step is a descent direction of a symmetric stiffness.  A solve
        whose steps no longer lower |R| within 1e-8 of the load ends there (the rollers' own Newton leaves
        noise of about 1e-9 of it in the reaction)."""
        g = self.geometry
        L = np.asarray(load, float)
        pd = g.pitch_diameter_m
        w = np.array([1.0, 1.0, 1.0, 1.0 / pd, 1.0 / pd])  # moments as forces at the pitch diameter
        force_scale = max(1.0, float(np.abs(L[:3]).max()), float(np.abs(L[3:]).max() / pd))
        rollers = [None]  # the last roller solution: the next evaluation's start

        def evaluate(d):
            psi, T, sol = self._solve(d, speed_rad_s, angle_rad, rollers[0])
            rollers[0] = sol.u
            return reaction_from(T, g, sol) + L, stiffness_from(T, self._ops, sol), (psi, T, sol)

        ref = self._reference_stiffness()
        out = damped_newton(evaluate, np.zeros(5) if d0 is None else d0,
                            converged=lambda r, _: bool(np.all(np.abs(r * w) < 1e-9 * force_scale)),
                            merit=lambda r: float(np.linalg.norm(r / np.sqrt(ref))), cap=20e-6 * w, damping=ref,
                            lam0=1e-3, shrink=0.1, lam_min=1e-12, grow=10.0, max_iter=max_iter,
                            floor=lambda r, _: bool(np.all(np.abs(r * w) < 1e-8 * force_scale)))
        if not out.converged:
            raise ArithmeticError(f"DTRB equilibrium did not converge in {max_iter} iterations "
                                  f"(residual {np.abs(out.R).max():.3g})")
        psi, T, sol = out.data
        return self._state(out.x, psi, T, sol, speed_rad_s, out.iterations, True)

    def linearized_full(self, speed_rad_s: float, load_N) -> np.ndarray:
        """5x5 stiffness at the equilibrium under ``load_N`` (FX, FY, FZ, MX, MY)."""
        return self.solve(load_N, speed_rad_s).stiffness

    def full_load(self, static_load) -> np.ndarray:
        """(FX, FY, FZ, MX, MY) on the bearing: ``static_load`` on ``dof_names`` plus, for a radial
        (x, y) bearing, the deck's axial load."""
        load = np.array([0.0, 0.0, self.axial_load_N, 0.0, 0.0])
        if static_load is not None:
            q = np.asarray(static_load, float)
            load[: q.size] = q
        return load

    def linearized(self, speed: float, static_load: np.ndarray | None = None, start=None):
        """Contract: K at the load equilibrium on ``dof_names`` (solved from d = 0, not ``start``), C = beta K
        (``damping_s``).

        With ``dof_names`` (x, y) K is the (X, Y) block of the 5x5 stiffness: the axial load is
        the deck's, and axial motion and tilt stay at their equilibrium values (held, see
        :meth:`at_operating_point`); with all five DOFs it is the 5x5 matrix (theta about +X,
        +Y as phiX, phiY)."""
        K = self.linearized_full(speed, self.full_load(static_load))
        n = len(self.dof_names)
        return K[:n, :n].copy(), self.damping_s * K[:n, :n]

    def static_displacement(self, speed: float, static_load=None, start=None) -> np.ndarray:
        """Ring displacement at the equilibrium under the static (and the deck's axial) load (from d = 0, not
        ``start``)."""
        return self.solve(self.full_load(static_load), speed).displacement[: len(self.dof_names)].copy()

    def at_operating_point(self, speed: float, static_load=None, transient: bool = False) -> "DtrbBearing":
        """A radial (x, y) bearing holds axial motion and tilt at the equilibrium under the static
        load and the deck's axial load; a 5-DOF bearing has nothing to hold.  For a time integration the
        damping is held too, at beta K of the operating point (``bearings.damping``)."""
        held = self._held
        if len(self.dof_names) != 5:
            held = self.solve(self.full_load(static_load), speed).displacement[2:]
        if transient:
            return TimeSteppedDtrb(self.geometry, self.preload_m, name=self.name, node=self.node,
                                   axial_load_N=self.axial_load_N, row_offset_rad=self.row_offset_rad,
                                   dof_names=self.dof_names, held=held, body=self.body,
                                   made_preload_m=self.made_preload_m, damping_s=self.damping_s,
                                   damping_held=self.linearized(speed, static_load)[1] if self.damping_s else None)
        return self if len(self.dof_names) == 5 else self.with_preload(self.preload_m, held=held,
                                                                       made_preload_m=self.made_preload_m)

    def force_and_tangent(self, q, v=None, t: float = 0.0, speed: float = 0.0, angle=None):
        """Contract: (force on the shaft, K_t, C_t = beta K_t) on ``dof_names`` at the node
        displacement q, roller azimuths advanced by the cage angle (eq. 3: cage ratio times the
        shaft angle); the force carries the damping force -beta K_t v (``bearings.damping``), K_t is the tangent
        of the elastic reaction.  The rollers' Newton starts from its built-in guess (no call history: a warm
        start is passed to :meth:`reaction_and_stiffness`)."""
        q = np.asarray(q, float)
        d = np.zeros(5)
        d[2:] = self._held
        d[: q.size] = q
        F, K, _ = self.reaction_and_stiffness(d, speed, shaft_angle(speed, t, angle))
        return self._damped(F, K, q.size, v)

    def _damped(self, F, K, n: int, v):
        """(f, K_t, C_t) on the first n DOFs with the damping force of C = beta K_t."""
        vv = np.zeros(n) if v is None else np.asarray(v, float)[:n]
        f, C = damped(F[:n].copy(), K[:n, :n].copy(), vv, self.damping_s, self.damping_held)
        return f, K[:n, :n].copy(), C

    def frequencies_hz(self, speed: float) -> dict[str, float]:
        """Cage and roller-pass (outer race) frequencies at shaft speed [rad/s]."""
        cage = self.geometry.cage_ratio * speed / (2 * math.pi)
        return {"cage": cage, "roller_pass": self.geometry.rollers_per_row * cage}

    # ---- sweeps (seed 001 Figs. 8 and 10) --------------------------------------------------
    def preload_sweep(self, preloads_m, load_N, speed_rad_s: float = 0.0) -> DtrbSweep:
        return _sweep("preload_m", preloads_m,
                      lambda v: self.with_preload(v).solve(load_N, speed_rad_s))

    def load_sweep(self, component: int, values_N, load_N, speed_rad_s: float = 0.0) -> DtrbSweep:
        base = np.asarray(load_N, float)

        def run(v):
            L = base.copy()
            L[component] = v
            return self.solve(L, speed_rad_s)

        return _sweep(["FX_N", "FY_N", "FZ_N", "MX_Nm", "MY_Nm"][component], values_N, run)


def _sweep(name, values, run) -> DtrbSweep:
    values = np.asarray(values, float)
    Ks, loaded, qmax = [], [], []
    for v in values:
        st = run(float(v))
        Ks.append(st.stiffness)
        loaded.append(st.loaded_rollers())
        qmax.append(st.outer_load_N.max(axis=1))
    return DtrbSweep(name, values, np.array(Ks), np.array(loaded), np.array(qmax))


class TimeSteppedDtrb(DtrbBearing):
    """The bearing of one time integration (``at_operating_point(..., transient=True)``): each
    ``force_and_tangent`` starts the rollers' Newton from the previous call's roller solution, a start
    only (the solution is the same to the solver's tolerance).  A fresh object per run, so the deck's
    bearing stays frozen; a time step evaluates the reaction at displacements a few nanometres apart,
    where this start halves the cost of a DTRB rotor's transient."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._start: np.ndarray | None = None

    def force_and_tangent(self, q, v=None, t: float = 0.0, speed: float = 0.0, angle=None):
        q = np.asarray(q, float)
        d = np.zeros(5)
        d[2:] = self._held
        d[: q.size] = q
        F, K, self._start = self.reaction_and_stiffness(d, speed, shaft_angle(speed, t, angle), self._start)
        return self._damped(F, K, q.size, v)
