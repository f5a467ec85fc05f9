"""Set equilibrium of a ball bearing under mixed load / displacement control.

Each of the five DOFs q = (x, y, z, theta_x, theta_y) of the inner ring is either free (it moves
until the bearing's reaction balances the load on it) or held at a prescribed value (it does not
move; the bearing's reaction there is balanced by whatever holds it: the shaft, a fixture).  With
every DOF free this is the bearing under a load, as a bearing program computes it by default; with
the tilts held at 0 it is a single row on a shaft that does not let the inner ring tilt.

Unknowns: the free DOFs.  Equations: f(q) + L = 0 on the free DOFs (f: reaction on the shaft,
L: load of the shaft on the bearing).  On a held DOF the load L_k must be 0 (the deck refuses a
load there); the holding load H_k = -f_k(q) is what the constraint must put on the bearing, so
that the bearing carries L + H in all.

The one damped Newton (``bearings.statics.damped_newton``) with Levenberg-Marquardt damping lambda D
(D: every ball at 1 um approach, the same for every DOF once tilts are measured at the groove-centre
radius R_i), steps capped at 20 um at the balls, converged when every free component of the residual
is <= 1e-10 of the load scale.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..base import FIVE
from ..statics import damped_newton


class BallEquilibriumError(ArithmeticError):
    """A ball, floating ring or set equilibrium did not converge."""


@dataclass(frozen=True)
class Held:
    """DOFs held at prescribed displacements (SI: m, rad); the others free under the load."""

    mask: tuple[bool, bool, bool, bool, bool] = (False,) * 5
    values: tuple[float, float, float, float, float] = (0.0,) * 5

    @classmethod
    def of(cls, **dofs: float) -> "Held":
        """``Held.of(theta_x=0.0, theta_y=0.0)``: the named DOFs (x, y, z, theta_x, theta_y) held."""
        bad = set(dofs) - set(FIVE)
        if bad:
            raise ValueError(f"unknown DOF(s) {sorted(bad)}: the DOFs are {FIVE}")
        return cls(tuple(n in dofs for n in FIVE), tuple(float(dofs.get(n, 0.0)) for n in FIVE))

    @property
    def any(self) -> bool:
        return any(self.mask)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(n for n, m in zip(FIVE, self.mask) if m)

    def label(self) -> str:
        if not self.any:
            return "all DOFs free"
        units = {"x": (1e6, "um"), "y": (1e6, "um"), "z": (1e6, "um"), "theta_x": (1e3, "mrad"),
                 "theta_y": (1e3, "mrad")}
        parts = [f"{n} {v * units[n][0]:.4g} {units[n][1]}" for n, m, v in zip(FIVE, self.mask, self.values) if m]
        return "held " + ", ".join(parts)


FREE = Held()


class Work:
    """What one call carries from one evaluation of the set to the next, never kept on the bearing: each
    ball's centre (its Newton start; NaN: the built-in start), the floating outer rings' last axial position
    (``floating.shift``'s start: (u, q, du/dq); None: where one ball carries its share) and the kernel parameters at the
    speed.  Each solve or evaluation makes its own."""

    def __init__(self, bearing: "BallBearing"):
        g = bearing.geometry
        self.centres = np.full((g.rows, g.balls, 2), np.nan)
        self.shift: tuple[float, np.ndarray, np.ndarray] | None = None
        self._params: tuple["BallBearing", float, np.ndarray] | None = None

    def params(self, b: "BallBearing", om: float) -> np.ndarray:
        """The kernel parameters of ``b`` at the speed om: A_r grown by its ``speed_growth``."""
        if b.speed_growth is None or om == 0.0:
            return b._p
        if self._params is None or self._params[0] is not b or self._params[1] != om:
            from . import kernel as kn  # not at import: a deck that reads Held stays light

            p = b._p.copy()
            p[kn.A_RAD0] += float(b.speed_growth(om))
            self._params = (b, om, p)
        return self._params[2]

    def forget(self) -> None:
        """Back to the built-in starts (after a failed evaluation or solve)."""
        self.centres[:] = np.nan
        self.shift = None


def reference_stiffness(geometry) -> np.ndarray:
    """Diagonal scale of the Levenberg-Marquardt damping of the set Newton: every ball at 1 um
    approach, the same for every DOF once tilts are measured at the groove-centre radius (a
    clearance or an unloaded row then gives steps along the residual, not along one DOF)."""
    g = geometry
    k1 = 1.5 * g.K_series * math.sqrt(1e-6) * g.balls * g.rows * 0.5
    R = g.inner_centre_radius_m
    return k1 * np.array([1.0, 1.0, 1.0, R * R, R * R])


def check_held(bearing, load: np.ndarray, held: Held) -> None:
    """ValueError unless the load has no component on a held DOF and a held z can act."""
    if held.mask[2] and bearing.fully_floating:
        raise ValueError(f"bearing {bearing.name!r}: z cannot be held when every row floats on the spring (the "
                         "set carries exactly the spring force axially wherever the inner ring sits)")
    for k, name in enumerate(FIVE):
        if held.mask[k] and load[k] != 0.0:
            raise ValueError(f"bearing {bearing.name!r}: {name} is held, so the load cannot have a component on "
                             f"it ({load[k]:g}); a held DOF carries what holds it (the holding load)")


def solve(bearing, load, speed: float, phi: float, q0=None, max_iter: int = 100, held: Held = FREE, work=None):
    """(q, evaluation, iterations) with reaction(q) + load = 0 on the free DOFs, the held DOFs at
    their values (damped Newton; ``bearing`` a :class:`~.bearing.BallBearing`; ``work``: the call's
    :class:`~.bearing.Work`, its warm starts from evaluation to evaluation)."""
    g = bearing.geometry
    L = np.asarray(load, float)
    check_held(bearing, L, held)
    mask = np.asarray(held.mask, bool)
    R = g.inner_centre_radius_m
    wgt = np.array([1.0, 1.0, 1.0, 1.0 / R, 1.0 / R])
    pre = bearing.preload.axial_N if bearing.preload.kind == "spring" else 0.0
    f_scale = max(1.0, float(np.max(np.abs(L * wgt))), pre)
    tol = 1e-10 * f_scale
    free = ~mask
    if bearing.fully_floating:
        free[2] = False
        thrust = bearing._s_float * bearing.preload.axial_N
        if abs(L[2] - thrust) > 1e-9 * max(abs(thrust), abs(L[2])):
            raise ValueError(
                f"bearing {bearing.name!r}: every row floats on the spring, so it carries exactly the spring "
                f"force axially; the axial load must be fz = {thrust:g} N, not {L[2]:g} N")
    dofs = np.flatnonzero(free)
    q = np.zeros(5) if q0 is None else np.array(q0, float)
    q[mask] = np.asarray(held.values, float)[mask]
    ev = bearing._evaluate(q, speed, phi, work)
    if dofs.size == 0:
        return q, ev, 0
    # the reaction's noise follows the rows' own forces, not only the external load: a position
    # preload holds hundreds of N between rows that cancel in the set reaction, and each ball's
    # own equilibrium is solved to about 1e-11 of them (seed 001's pair under a 0.25 N load at
    # 6000 rpm: the same q gave -1.4e-9 and -3.4e-9 N, with 461 N in a row)
    tol = max(tol, 1e-11 * float(np.max(np.abs(ev.rows.f_rows * wgt))))
    w = wgt[dofs]

    def residual(qq, e):
        return (e.f + L)[dofs], e.K[np.ix_(dofs, dofs)], (qq, e)

    def evaluate(x):
        qq = q.copy()
        qq[dofs] = x
        return residual(qq, bearing._evaluate(qq, speed, phi, work))

    # acceptance: the weighted 2-norm (descent of LM; equal merit taken: inside a clearance the reaction does
    # not change); convergence: every weighted component
    out = damped_newton(evaluate, q[dofs], converged=lambda r, _: float(np.max(np.abs(r * w))) <= tol,
                        merit=lambda r: float(np.linalg.norm(r * w)), cap=20e-6 * w,
                        damping=reference_stiffness(g)[dofs], lam0=1e-4, shrink=0.01, grow=10.0, lam_max=1e10,
                        max_iter=max_iter, evaluated=residual(q, ev))
    if out.converged:
        return out.data[0], out.data[1], out.iterations
    worst = float(np.max(np.abs(out.R * w)))
    raise BallEquilibriumError(
        f"bearing {bearing.name!r}: no set equilibrium under the load {np.round(L, 6).tolist()} (N, N m) at "
        f"{speed * 30 / math.pi:.6g} rpm, cage angle {math.degrees(phi):.3g} deg ({bearing.preload.label()}; "
        f"{held.label()}): damped Newton on the free DOFs of (x, y, z, theta_x, theta_y), {max_iter} iterations, "
        f"residual {worst:.3g} N")


def holding_load(reaction: np.ndarray, load: np.ndarray, held: Held) -> np.ndarray:
    """What the constraints put on the bearing at the held DOFs (0 at the free ones): -(f + L) there."""
    out = np.zeros(5)
    mask = np.asarray(held.mask, bool)
    out[mask] = -(np.asarray(reaction, float) + np.asarray(load, float))[mask]
    return out
