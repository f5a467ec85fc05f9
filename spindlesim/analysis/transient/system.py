"""What every transient method integrates: the rotor with its bearings' internal DOFs, the
excitation and the speed profile (one description, used by every method).

Equations of motion, x = [q (rotor DOFs), z_b (each bearing's internal DOFs)]::

    M x'' + C_s(Omega) x' + K_s(Omega) x = F(t) + sum_b f_b(x_b, x_b', t, Omega, phi)

M = blockdiag(M_rotor, diag(internal masses)); C_s = C_ground + eta_v K_B + Omega G and
K_s = a_h K_B + K_A + (eta_v Omega + b_h) K_C are the shaft's (seed 003 eq. 21) on the rotor
block; every bearing enters through its force (the contract), so the equations never ask which
bearings they hold.  F(t) = static loads and gravity + unbalance + harmonic and step loads.

Speed profile: Omega(t) = Omega_0 + (Omega_1 - Omega_0) t / T (constant when equal), shaft angle
phi(t) = Omega_0 t + (Omega_1 - Omega_0) t^2 / (2 T).  A rotating unbalance m e at angle phi + a
exerts m e [Omega^2 (cos, sin)(phi + a) + Omega' (-sin, cos)(phi + a)] on the shaft (the
reaction to the mass's centripetal and tangential acceleration).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from ...fe.assembly import ShaftMatrices
from ...model.rotor import Rotor


@dataclass(frozen=True)
class SpeedProfile:
    """Constant speed or a linear ramp from ``start`` to ``stop`` [rad/s] over ``duration_s``."""

    start_rad_s: float
    stop_rad_s: float
    duration_s: float

    @property
    def constant(self) -> bool:
        return self.start_rad_s == self.stop_rad_s

    @property
    def acceleration(self) -> float:
        return 0.0 if self.constant else (self.stop_rad_s - self.start_rad_s) / self.duration_s

    def speed(self, t: float) -> float:
        return self.start_rad_s + self.acceleration * t

    def angle(self, t: float) -> float:
        return self.start_rad_s * t + 0.5 * self.acceleration * t * t

    def time_at_angle(self, phi: np.ndarray) -> np.ndarray:
        """t >= 0 with angle(t) = phi (phi >= 0, the speed positive)."""
        phi = np.asarray(phi, float)
        a, w0 = self.acceleration, self.start_rad_s
        if a == 0.0:
            return phi / w0 if w0 > 0 else np.full_like(phi, np.inf)
        return (-w0 + np.sqrt(np.maximum(w0 * w0 + 2.0 * a * phi, 0.0))) / a


@dataclass(frozen=True)
class Unbalance:
    ix: int
    iy: int
    me_kg_m: float
    phase_rad: float = 0.0


@dataclass(frozen=True)
class TimeLoad:
    """Harmonic amplitude sin(w t + phase) (w fixed, or ``order`` x shaft angle), a step at t_on, or a
    ramp amplitude min(t / t_on, 1) (a load applied slowly)."""

    index: int
    amplitude_N: float
    kind: str = "harmonic"  # harmonic | step | ramp
    omega_rad_s: float = 0.0
    order: float = 0.0  # > 0: the phase is order x shaft angle
    phase_rad: float = 0.0
    t_on_s: float = 0.0


@dataclass(frozen=True)
class Excitation:
    unbalances: tuple[Unbalance, ...] = ()
    loads: tuple[TimeLoad, ...] = ()
    include_static: bool = True  # point loads and gravity of the rotor


@dataclass(frozen=True)
class RotorSystem:
    """The assembled equations of one run (module note)."""

    rotor: Rotor
    bearings: tuple  # frozen at the operating point
    shaft: ShaftMatrices
    Q: np.ndarray  # static rotor loads (size n)
    excitation: Excitation
    profile: SpeedProfile
    n_rotor: int
    index: tuple[np.ndarray, ...]  # per bearing: its DOFs in x (node DOFs then internal)
    M: np.ndarray  # (N, N)
    internal_offsets: tuple[int, ...] = field(default_factory=tuple)

    @property
    def size(self) -> int:
        return self.M.shape[0]

    def stiffness(self, speed: float) -> np.ndarray:
        K = np.zeros((self.size, self.size))
        K[: self.n_rotor, : self.n_rotor] = self.shaft.stiffness(speed)
        return K

    def damping(self, speed: float) -> np.ndarray:
        C = np.zeros((self.size, self.size))
        C[: self.n_rotor, : self.n_rotor] = self.shaft.damping(speed)
        return C

    def external(self, t: float, out: np.ndarray | None = None) -> np.ndarray:
        """F(t) on x (size N)."""
        F = np.zeros(self.size) if out is None else out
        if out is not None:
            F[:] = 0.0
        if self.excitation.include_static:
            F[: self.n_rotor] += self.Q
        p = self.profile
        W, A, phi = p.speed(t), p.acceleration, p.angle(t)
        for u in self.excitation.unbalances:
            c, s = math.cos(phi + u.phase_rad), math.sin(phi + u.phase_rad)
            F[u.ix] += u.me_kg_m * (W * W * c - A * s)
            F[u.iy] += u.me_kg_m * (W * W * s + A * c)
        for ld in self.excitation.loads:
            if ld.kind == "step":
                if t >= ld.t_on_s:
                    F[ld.index] += ld.amplitude_N
            elif ld.kind == "ramp":
                F[ld.index] += ld.amplitude_N * (min(t / ld.t_on_s, 1.0) if ld.t_on_s > 0 else 1.0)
            else:
                arg = ld.order * phi if ld.order > 0 else ld.omega_rad_s * t
                F[ld.index] += ld.amplitude_N * math.sin(arg + ld.phase_rad)
        return F

    @functools.cached_property
    def speed_affine(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(K0, K1, C0, C1) with stiffness(W) = K0 + W K1 and damping(W) = C0 + W C1 (the shaft's
        matrices are affine in the speed: internal damping's circulatory term, gyroscopics)."""
        K0, C0 = self.stiffness(0.0), self.damping(0.0)
        return K0, self.stiffness(1.0) - K0, C0, self.damping(1.0) - C0

    @functools.cached_property
    def _blocks(self) -> tuple:
        return tuple(np.ix_(gi, gi) for gi in self.index)

    def forces(self, x: np.ndarray, v: np.ndarray, t: float) -> np.ndarray:
        """f (N) of every bearing at (x, v, t), without tangents (the contract's ``force``)."""
        W, phi = self.profile.speed(t), self.profile.angle(t)
        f = np.zeros(self.size)
        for b, gi in zip(self.bearings, self.index):
            f[gi] += b.force(x[gi], v[gi], t, W, phi)
        return f

    def forces_and_tangents(self, x: np.ndarray, v: np.ndarray, t: float, K: np.ndarray, C: np.ndarray
                            ) -> np.ndarray:
        """f (N) of every bearing at (x, v, t); their tangents are added into K and C (N, N), block by
        block (no dense per-bearing matrices)."""
        W, phi = self.profile.speed(t), self.profile.angle(t)
        f = np.zeros(self.size)
        for b, gi, blk in zip(self.bearings, self.index, self._blocks):
            fb, kb, cb = b.force_and_tangent(x[gi], v[gi], t, W, phi)
            f[gi] += fb
            K[blk] += kb
            C[blk] += cb
        return f

    def bearing_forces(self, x: np.ndarray, v: np.ndarray, t: float, with_tangent: bool = True):
        """(f (N), K_t (N, N), C_t (N, N), per-bearing forces) of every bearing at (x, v, t)."""
        N = self.size
        W, phi = self.profile.speed(t), self.profile.angle(t)
        f = np.zeros(N)
        K = np.zeros((N, N)) if with_tangent else None
        C = np.zeros((N, N)) if with_tangent else None
        each = []
        for b, gi in zip(self.bearings, self.index):
            if with_tangent:
                fb, kb, cb = b.force_and_tangent(x[gi], v[gi], t, W, phi)
                K[np.ix_(gi, gi)] += kb
                C[np.ix_(gi, gi)] += cb
            else:
                fb = b.force(x[gi], v[gi], t, W, phi)
            f[gi] += fb
            each.append(fb)
        return f, K, C, each


def assemble_system(rotor: Rotor, bearings: tuple, shaft: ShaftMatrices, Q: np.ndarray, excitation: Excitation,
                    profile: SpeedProfile) -> RotorSystem:
    """The rotor's matrices extended by every bearing's internal DOFs (appended after the rotor's)."""
    n = rotor.dofs.size
    sizes = [b.internal_mass.size for b in bearings]
    N = n + sum(sizes)
    M = np.zeros((N, N))
    M[:n, :n] = shaft.M
    index, offsets, o = [], [], n
    for b, s in zip(bearings, sizes):
        node = rotor.dofs.at(b.node, b.dof_names)
        index.append(np.concatenate([node, np.arange(o, o + s)]).astype(int))
        offsets.append(o)
        M[o:o + s, o:o + s] = np.diag(b.internal_mass)
        o += s
    return RotorSystem(rotor, tuple(bearings), shaft, np.asarray(Q, float), excitation, profile, n, tuple(index), M,
                       tuple(offsets))
