"""The bearing contract of the roller family: :class:`RigidRaceBearing` and :class:`FlexibleRaceBearing`.

Each is its model (``rigid_race.RigidRace``: rigid races and Hertz contacts; ``flexible_race.FlexibleRace``:
seed 000's flexible outer race, rollers and race segments as internal DOFs) with the contract of
``bearings/base.py``: the reaction and its tangent, the pitch-averaged linearisation about the static
state, the recorded outputs and the parameters of the compiled force (``rigid_race_kernel``,
``flexible_race_kernel``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from ..base import BearingBase, CompiledForce, shaft_angle
from ..damping import damped
from ..statics import equilibrium_under_load
from .flexible_race import FlexibleRace
from .load_distribution import static_load_distribution
from .rigid_race import SURFACE, RigidRace, Waviness

__all__ = ["FlexibleRaceBearing", "RigidRaceBearing", "Waviness"]

#: kernel number of each model in ``bearings.compiled``
RIGID_RACE_KIND = 2
FLEXIBLE_RACE_KIND = 3
#: cage positions over one pitch averaged by ``linearized``
RIGID_RACE_PITCH_POINTS = 24
FLEXIBLE_RACE_PITCH_POINTS = 4


@dataclass(frozen=True)
class RigidRaceBearing(RigidRace, BearingBase):
    """Rigid races and Hertz contacts (Sunnersjo 1978; Harsha and Kankar 2004); the bearing contract."""

    def frequencies_hz(self, speed: float) -> dict[str, float]:
        cage = self.kinematics.cage_ratio * speed / (2.0 * np.pi)
        return {"cage": cage, "roller_pass": self.rollers * cage}

    # the contract -------------------------------------------------------------
    def _at_angle(self, q: np.ndarray, angle: float) -> tuple[np.ndarray, np.ndarray]:
        th, d = self.deflection_m(q, angle)
        dp = np.maximum(d, 0.0)
        Q = self.stiffness * dp ** self.exponent
        k = self.stiffness * self.exponent * dp ** (self.exponent - 1.0)
        c, s = np.cos(th), np.sin(th)
        f = -np.array([Q @ c, Q @ s])
        K = np.array([[k @ (c * c), k @ (c * s)], [k @ (c * s), k @ (s * s)]])
        return f, K

    def force_and_tangent(self, q, v=None, t: float = 0.0, speed: float = 0.0, angle=None):
        """The contacts' reaction with the damping force -beta K_t v (``bearings.damping``); C_t = beta K_t."""
        f, K = self._at_angle(np.asarray(q, float)[:2], shaft_angle(speed, t, angle))
        vv = np.zeros(2) if v is None else np.asarray(v, float)[:2]
        f, C = damped(f, K, vv, self.damping_s, self.damping_held)
        return f, K, C

    def at_operating_point(self, speed: float, static_load=None, transient: bool = False) -> "RigidRaceBearing":
        """For a time integration: the bearing with its damping held at beta K of the operating point
        (``bearings.damping``); otherwise itself."""
        if not transient or self.damping_s == 0.0:
            return self
        return replace(self, damping_held=tuple(self.linearized(speed, static_load)[1].ravel()))

    def _pitch_angles(self) -> np.ndarray:
        """Shaft angles that move the cage evenly over one pitch (RIGID_RACE_PITCH_POINTS points)."""
        pitch = 2.0 * np.pi / self.rollers
        return pitch * np.arange(RIGID_RACE_PITCH_POINTS) / RIGID_RACE_PITCH_POINTS / self.kinematics.cage_ratio

    def pitch_average(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Force and tangent averaged over one roller pitch at a fixed displacement.

        With waviness the reaction does not repeat every pitch; the average is then over the
        same pitch positions with the waviness at shaft angle 0 + the cage travel, an
        approximation stated in docs/theory.md."""
        out = [self._at_angle(q, a) for a in self._pitch_angles()]
        return np.mean([o[0] for o in out], axis=0), np.mean([o[1] for o in out], axis=0)

    def static_displacement(self, speed: float = 0.0, static_load=None, start=None) -> np.ndarray:
        """Displacement at which the pitch-averaged reaction carries ``static_load`` (x, y); from the
        roller load distribution's estimate, not ``start``."""
        W = np.asarray(static_load if static_load is not None else np.zeros(2), float)[:2]
        fr = float(np.hypot(*W))
        if fr == 0.0:
            return np.zeros(2)
        dist = static_load_distribution(self.stiffness, self.exponent, self.rollers, fr,
                                        2.0 * self.radial_clearance_m)
        q0 = dist.displacement_m * W / fr
        scale = max(dist.displacement_m, 1e-9)
        return equilibrium_under_load(self.pitch_average, W, q0, scale, self.name, max_step=scale)

    def linearized(self, speed: float, static_load=None, start=None) -> tuple[np.ndarray, np.ndarray]:
        """The tangent at the static state averaged over one roller pitch; C = beta K (``damping_s``)."""
        _, K = self.pitch_average(self.static_displacement(speed, static_load))
        return K, self.damping_s * K

    def outputs(self, q, v, t, speed, angle=None) -> dict[str, tuple[np.ndarray, str]]:
        a = shaft_angle(speed, t, angle)
        th, d = self.deflection_m(np.asarray(q, float)[:2], a)
        Q = self.stiffness * np.maximum(d, 0.0) ** self.exponent
        return {"force": (self.force_and_tangent(q, v, t, speed, angle)[0], "N"), "roller_load_N": (Q, "N")}

    # the spindle's thermal model (contract: at_temperatures, heat) ------------
    def at_temperatures(self, temperatures) -> "RigidRaceBearing":
        """The bearing at the radial clearance its parts' growth gives (.thermal)."""
        from . import thermal

        return thermal.at_temperatures(self, temperatures)

    def heat(self, speed, static_load, lubrication, lubricant_C, displacement=None):
        """Palmgren's cylindrical-roller heat at the operating point (.thermal)."""
        from . import thermal

        return thermal.heat(self, speed, static_load, lubrication, lubricant_C, displacement)

    def compiled(self) -> CompiledForce:
        """floats: [K, n, gamma0, cage ratio, spin ratio, beta, held C (4, row-major), cos base (N), sin base
        (N), waviness (4 per row)]: beta K_t v, or with a held C (``at_operating_point``) C v and beta 0."""
        base = self.phase_rad + 2.0 * np.pi * np.arange(self.rollers) / self.rollers
        wav = np.array([[SURFACE[w.surface], w.waves, w.amplitude_m, w.phase_rad] for w in self.waviness],
                       dtype=float).reshape(-1, 4)
        k = self.kinematics
        floats = np.concatenate([[self.stiffness, self.exponent, self.radial_clearance_m, k.cage_ratio, k.spin_ratio,
                                  0.0 if self.damping_held is not None else self.damping_s],
                                 np.zeros(4) if self.damping_held is None else np.asarray(self.damping_held, float),
                                 np.cos(base), np.sin(base), wav.ravel()])
        return CompiledForce(RIGID_RACE_KIND, floats, np.array([self.rollers, len(self.waviness)], np.int64))


@dataclass(frozen=True)
class FlexibleRaceBearing(FlexibleRace, BearingBase):
    """Seed 000's bearing as a rotor bearing with the rollers and race segments as internal DOFs."""

    def frequencies_hz(self, speed: float) -> dict[str, float]:
        cage = self.kinematics.cage_ratio * speed / (2.0 * np.pi)
        return {"cage": cage, "roller_pass": self.rollers * cage}

    # the contract ----------------------------------------------------------------
    @cached_property
    def _packed(self):
        from . import flexible_race_kernel as kernel

        return kernel.pack(self)

    def force(self, q, v, t: float = 0.0, speed: float = 0.0, angle=None) -> np.ndarray:
        """Contract: the compiled force alone (the tangent is by differences of it)."""
        return self._force(q, v, speed, shaft_angle(speed, t, angle))

    def _force(self, q: np.ndarray, v: np.ndarray, speed: float, angle: float) -> np.ndarray:
        """Compiled force on the contract coordinates."""
        from . import flexible_race_kernel as kernel

        fl, it = self._packed
        out = np.empty(self.n_pos)
        kernel.force(fl, it, np.ascontiguousarray(q, dtype=float), np.ascontiguousarray(v, dtype=float),
                     speed, angle, out)
        return out

    def _steps(self) -> tuple[np.ndarray, np.ndarray]:
        """Difference steps per DOF: 1e-10 m and 1e-8 rad; velocities 1e-6 m/s."""
        N, n = self.rollers, self.ring.segments
        dq = np.concatenate([[1e-10] * (2 + N), np.tile([1e-10, 1e-10, 1e-8], n)])
        return dq, dq * 1e4

    def force_and_tangent(self, q, v, t: float = 0.0, speed: float = 0.0, angle=None):
        """Compiled force; K_t and C_t by central differences of it (the contract allows it)."""
        a = shaft_angle(speed, t, angle)
        q = np.asarray(q, float)
        v = np.asarray(v, float)
        f = self._force(q, v, speed, a)
        dq, dv = self._steps()
        n = q.size
        K = np.empty((n, n))
        C = np.empty((n, n))
        for k in range(n):
            e = np.zeros(n)
            e[k] = dq[k]
            K[:, k] = -(self._force(q + e, v, speed, a) - self._force(q - e, v, speed, a)) / (2 * dq[k])
            e[k] = dv[k]
            C[:, k] = -(self._force(q, v + e, speed, a) - self._force(q, v - e, speed, a)) / (2 * dv[k])
        return f, K, C

    def _condensed(self, q: np.ndarray, speed: float, angle: float) -> tuple[np.ndarray, np.ndarray]:
        """(node force, node stiffness) with the internal DOFs statically condensed (free rollers drop out)."""
        f, K, _ = self.force_and_tangent(q, np.zeros_like(q), 0.0, speed, angle)
        Kii = K[2:, 2:]
        return f[:2], K[:2, :2] - K[:2, 2:] @ np.linalg.pinv(Kii, rcond=1e-12) @ K[2:, :2]

    def _internal_scale(self) -> np.ndarray:
        return np.concatenate([[1e-7] * self.rollers, np.tile([1e-7, 1e-7, 1e-5], self.ring.segments)])

    def held_node(self, q_node: np.ndarray, speed: float, angle: float, internal0: np.ndarray,
                  force_scale: float = 1.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(node force, condensed node stiffness, internal DOFs) with the node held at ``q_node`` and
        the rollers and race in equilibrium (quasi-static: their modes are ~100 kHz); the internal
        forces are balanced to 1e-10 of ``force_scale`` (the bearing load) or their round-off floor."""
        qn = np.asarray(q_node, float)[:2]
        s = max(float(force_scale), 1.0)

        def ft(z):
            q = np.concatenate([qn, z])
            f, K, _ = self.force_and_tangent(q, np.zeros_like(q), 0.0, speed, angle)
            return f[2:] / s, K[2:, 2:] / s

        z = equilibrium_under_load(ft, np.zeros(1), internal0, self._internal_scale(), self.name, tol=1e-10)
        f, K = self._condensed(np.concatenate([qn, z]), speed, angle)
        return f, K, z

    def static_displacement(self, speed: float, static_load=None, angle: float = 0.0, start=None) -> np.ndarray:
        """Contract coordinates where the bearing alone carries ``static_load`` at a shaft angle (from the
        unloaded race, not ``start``)."""
        W = np.zeros(2) if static_load is None else np.asarray(static_load, float)[:2]
        scale = np.concatenate([[1e-7] * 2, self._internal_scale()])

        def ft(q):
            f, K, _ = self.force_and_tangent(q, np.zeros_like(q), 0.0, speed, angle)
            return f, K

        return equilibrium_under_load(ft, W, np.zeros(self.n_pos), scale, self.name, tol=1e-8)

    def _condensed_damping(self, q: np.ndarray, speed: float, angle: float) -> np.ndarray:
        """Node damping of the contacts' own damping (seed 000 eq. 30: rollers and housing) at the state q, the
        internal DOFs condensed quasi-statically: they follow the node as z = T x (T = -K_ii^+ K_in) and their
        forces balance to first order in the frequency, so C = [I, L] C_t [I; T] with L = -K_ni K_ii^+."""
        _, K, C = self.force_and_tangent(q, np.zeros_like(q), 0.0, speed, angle)
        Kii_pinv = np.linalg.pinv(K[2:, 2:], rcond=1e-12)
        T = np.vstack([np.eye(2), -Kii_pinv @ K[2:, :2]])
        L = np.hstack([np.eye(2), -K[:2, 2:] @ Kii_pinv])
        return L @ C @ T

    def linearized(self, speed: float, static_load=None, start=None) -> tuple[np.ndarray, np.ndarray]:
        """The tangent of the pitch-averaged reaction at the static state and the damping of its contacts.

        The node reaction with the rollers and race in equilibrium (condensed: their modes, ~100
        kHz, are quasi-static for a rotor) is averaged over FLEXIBLE_RACE_PITCH_POINTS cage positions of one
        roller pitch; the static state is the node displacement at which that average carries
        ``static_load`` (Newton on the two node DOFs), and K is the average of the condensed
        tangents there: the derivative of the averaged reaction, as the rigid race's
        ``pitch_average``.  (Averaging the tangents of each cage position's own equilibrium
        instead differs by the variation of the equilibrium over the pitch: 12 % in K_xx for the
        rotor of decks/validation/roller_rotor.yaml.)  C: the damping the model's contacts carry (seed 000
        eq. 30, rollers and housing; the transient integrates the same), condensed like K
        (:meth:`_condensed_damping`) and averaged over the same cage positions; no stiffness-proportional
        damping is added (``bearings.damping`` is for the models without damping of their own)."""
        W = np.zeros(2) if static_load is None else np.asarray(static_load, float)[:2]
        pitch = 2.0 * np.pi / self.rollers / self.kinematics.cage_ratio
        angles = pitch * np.arange(FLEXIBLE_RACE_PITCH_POINTS) / FLEXIBLE_RACE_PITCH_POINTS
        starts = [self.static_displacement(speed, static_load, a) for a in angles]
        qn = np.mean([s[:2] for s in starts], axis=0)
        internal = [s[2:] for s in starts]
        f_scale = max(float(np.max(np.abs(W))), 1.0)
        previous = np.inf
        for _ in range(30):
            held = [self.held_node(qn, speed, a, z, f_scale) for a, z in zip(angles, internal)]
            internal = [h[2] for h in held]
            F = np.mean([h[0] for h in held], axis=0)
            K = np.mean([h[1] for h in held], axis=0)
            r = F + W
            rn = float(np.max(np.abs(r)))
            # converged, or stalled at the round-off floor of the internal equilibria
            if rn <= 1e-10 * f_scale or (rn > 0.5 * previous and rn <= 1e-7 * f_scale):
                break
            previous = rn
            qn = qn + np.linalg.solve(K, r)
        else:
            raise ArithmeticError(f"bearing {self.name!r}: the pitch-averaged reaction found no static state "
                                  f"(residual {np.max(np.abs(r)):.3g} N)")
        C = np.mean([self._condensed_damping(np.concatenate([qn, z]), speed, a) for a, z in zip(angles, internal)],
                    axis=0)
        return K, C

    def outputs(self, q, v, t, speed, angle=None) -> dict[str, tuple[np.ndarray, str]]:
        from . import flexible_race_kernel as kernel

        fl, it = self._packed
        a = shaft_angle(speed, t, angle)
        qc, vc = np.ascontiguousarray(q, dtype=float), np.ascontiguousarray(v, dtype=float)
        loads = np.empty(self.rollers)
        kernel.outer_loads(fl, it, qc, vc, speed, a, loads)
        Q = qc[2 + self.rollers:].reshape(-1, 3)
        er = np.column_stack([np.cos(self.ring.phi), np.sin(self.ring.phi)])
        return {"force": (self._force(qc, vc, speed, a)[:2], "N"), "roller_load_N": (loads, "N"),
                "race_deflection_m": (np.sum(Q[:, 0:2] * er, axis=1), "m")}

    def compiled(self) -> CompiledForce:
        fl, it = self._packed
        return CompiledForce(FLEXIBLE_RACE_KIND, fl, it)
