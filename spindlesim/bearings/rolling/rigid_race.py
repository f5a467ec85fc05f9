"""Rigid-race rolling bearing: the classical 2-DOF rotor model.

Sunnersjo (J. Sound Vib. 58, 1978) and Harsha and Kankar (Int. J. Mech. Sci. 46,
2004, the waviness reference of seed 000): the races are rigid, the shaft
centre (x, y) moves in the plane, rolling element j sits at the orbit angle
theta_j = 2 pi j / N + omega_cage t (cage kinematics, seed 000 eq. 3) and
carries the Hertz force

    Q_j = K (x cos theta_j + y sin theta_j - gamma_0 + w_j(t))_+^n

with n = 3/2 for a ball (point contact) and n = 10/9 for a roller (line
contact, Palmgren), gamma_0 the radial internal clearance, and w_j the local
sum of surface waviness of inner race, outer race and rolling element.  The
bearing force on the shaft is -sum_j Q_j (cos theta_j, sin theta_j).  The
shaft equations of motion are

    m x'' + c x' = F_x + f_x,    m y'' + c y' = F_y + f_y.

Angles are measured from +x towards +y (spindlesim frame); the shaft spins
about +z, so the cage turns the same way.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .hertz import static_load_distribution
from .kinematics import CageKinematics


@dataclass(frozen=True)
class Waviness:
    """One harmonic of surface waviness, a radial deviation A cos(k phi + phase) [m].

    ``surface`` is "inner" (turns with the shaft), "outer" (stationary) or
    "roller" (turns with the roller spin, seed 000 eq. 4; it meets both races,
    on opposite sides of the roller).  Positive deviation = extra material,
    which adds to the contact deflection (Harsha and Kankar 2004).
    """

    surface: str
    waves: int
    amplitude_m: float
    phase_rad: float = 0.0

    def __post_init__(self) -> None:
        if self.surface not in ("inner", "outer", "roller"):
            raise ValueError(f"waviness surface must be inner, outer or roller, not {self.surface!r}")
        if self.waves < 1:
            raise ValueError("waviness needs at least one wave")


@dataclass(frozen=True)
class RigidRaceBearing:
    """Rolling bearing with rigid races and Hertz contacts (Sunnersjo 1978; Harsha and Kankar 2004).

    Satisfies ``spindlesim.bearings.base.NonlinearBearing``.
    """

    name: str
    node: int
    rollers: int
    stiffness: float  # K in Q = K delta^n, SI (N/m^n)
    exponent: float  # 1.5 ball, 10/9 roller
    kinematics: CageKinematics
    shaft_speed_rad_s: float
    radial_clearance_m: float = 0.0
    waviness: tuple[Waviness, ...] = field(default_factory=tuple)
    phase_rad: float = 0.0

    def __post_init__(self) -> None:
        if self.rollers < 3:
            raise ValueError("need at least 3 rolling elements")
        if self.stiffness <= 0 or self.exponent <= 0:
            raise ValueError("contact stiffness and exponent must be positive")

    @property
    def cage_speed_rad_s(self) -> float:
        return self.kinematics.cage_ratio * self.shaft_speed_rad_s

    @property
    def cage_frequency_hz(self) -> float:
        return self.cage_speed_rad_s / (2.0 * np.pi)

    @property
    def roller_pass_frequency_hz(self) -> float:
        return self.rollers * self.cage_frequency_hz

    def angles(self, t_s: float) -> np.ndarray:
        """Orbit angle of each rolling element [rad]."""
        return self.phase_rad + 2.0 * np.pi * np.arange(self.rollers) / self.rollers + self.cage_speed_rad_s * t_s

    def waviness_m(self, theta: np.ndarray, t_s: float) -> np.ndarray:
        """Sum of waviness deviations at each element's contacts [m]."""
        w = np.zeros_like(theta)
        for wv in self.waviness:
            if wv.surface == "outer":
                w += wv.amplitude_m * np.cos(wv.waves * theta + wv.phase_rad)
            elif wv.surface == "inner":
                w += wv.amplitude_m * np.cos(wv.waves * (theta - self.shaft_speed_rad_s * t_s) + wv.phase_rad)
            else:
                spin = self.kinematics.spin_ratio * self.shaft_speed_rad_s * t_s
                w += wv.amplitude_m * (np.cos(wv.waves * spin + wv.phase_rad)
                                       + np.cos(wv.waves * (spin + np.pi) + wv.phase_rad))
        return w

    def deflection_m(self, displacement_m: np.ndarray, t_s: float) -> tuple[np.ndarray, np.ndarray]:
        """(theta_j, signed contact deflection delta_j) for a shaft displacement (x, y)."""
        th = self.angles(t_s)
        d = displacement_m[0] * np.cos(th) + displacement_m[1] * np.sin(th) - self.radial_clearance_m
        if self.waviness:
            d = d + self.waviness_m(th, t_s)
        return th, d

    def roller_loads_N(self, displacement_m: np.ndarray, t_s: float) -> np.ndarray:
        """Contact load Q_j >= 0 of each rolling element [N]."""
        _, d = self.deflection_m(displacement_m, t_s)
        return self.stiffness * np.maximum(d, 0.0) ** self.exponent

    def force(self, displacement_m: np.ndarray, velocity_m_s: np.ndarray, t_s: float) -> np.ndarray:
        """Force [N] on the shaft, (x, y): -sum Q_j (cos theta_j, sin theta_j)."""
        th, d = self.deflection_m(np.asarray(displacement_m, dtype=float), t_s)
        q = self.stiffness * np.maximum(d, 0.0) ** self.exponent
        return -np.array([q @ np.cos(th), q @ np.sin(th)])

    def potential_energy_J(self, displacement_m: np.ndarray, t_s: float) -> float:
        """Elastic energy sum K delta_+^(n+1)/(n+1) (conservative at zero speed)."""
        _, d = self.deflection_m(np.asarray(displacement_m, dtype=float), t_s)
        n = self.exponent
        return float(np.sum(self.stiffness * np.maximum(d, 0.0) ** (n + 1.0) / (n + 1.0)))


@dataclass(frozen=True)
class RigidRaceRotor:
    """2-DOF rotor (shaft + inner race) in a rigid-race bearing; a transient system.

    State y = [x, y, vx, vy] (m, m/s).  ``load_N`` is the constant external
    force on the shaft (default: the radial load downwards, -y).
    """

    bearing: RigidRaceBearing
    mass_kg: float
    damping_Ns_m: float
    load_N: tuple[float, float]
    load_ramp_s: float = 0.0  # >0: load grows linearly from 0 over this time (quasi-static loading)
    model_name: str = "rigid_race"

    def load_at(self, t: float) -> np.ndarray:
        f = np.asarray(self.load_N, dtype=float)
        return f * min(t / self.load_ramp_s, 1.0) if self.load_ramp_s > 0 else f

    @property
    def rollers(self) -> int:
        return self.bearing.rollers

    @property
    def cage_frequency_hz(self) -> float:
        return self.bearing.cage_frequency_hz

    @property
    def roller_pass_frequency_hz(self) -> float:
        return self.bearing.roller_pass_frequency_hz

    @property
    def n_state(self) -> int:
        return 4

    def initial_state(self) -> np.ndarray:
        """Start at the quasi-static displacement under the load (Stribeck), at rest."""
        f = np.asarray(self.load_N, dtype=float)
        fr = float(np.hypot(*f))
        y0 = np.zeros(4)
        if fr > 0 and self.load_ramp_s <= 0:
            load_angle = np.arctan2(f[1], f[0])
            dist = static_load_distribution(self.bearing.stiffness, self.bearing.exponent, self.rollers, fr,
                                            2.0 * self.bearing.radial_clearance_m,
                                            phase_rad=self.bearing.phase_rad - load_angle)
            y0[0:2] = dist.displacement_m * f / fr
        return y0

    def rhs(self, t: float, s: np.ndarray) -> np.ndarray:
        b = self.bearing
        th, d = b.deflection_m(s[0:2], t)
        q = b.stiffness * np.maximum(d, 0.0) ** b.exponent
        m, c = self.mass_kg, self.damping_Ns_m
        f = self.load_at(t) if self.load_ramp_s > 0 else self.load_N
        out = np.empty(4)
        out[0:2] = s[2:4]
        out[2] = (f[0] - c * s[2] - q @ np.cos(th)) / m
        out[3] = (f[1] - c * s[3] - q @ np.sin(th)) / m
        return out

    def compiled_stepper(self):
        """Compiled RK4 loop with this rotor's parameters (``rigid_race_kernel``; ``fixed_step.Stepper``)."""
        from . import rigid_race_kernel as kernel

        params = kernel.pack(self)
        return lambda y, t0, h, n, every, samples: kernel.rk4(y, t0, h, n, every, *params, samples)

    def default_step_s(self, y: np.ndarray) -> float:
        """1 us: the accuracy issue 4 asks for (RK4 with a 1 us step)."""
        return 1e-6

    def shaft_displacement(self, Y: np.ndarray) -> np.ndarray:
        """[t, 2] shaft centre (x, y) from states [t, n_state]."""
        return Y[:, 0:2]

    def roller_forces(self, t: np.ndarray, Y: np.ndarray) -> np.ndarray:
        """[t, N] contact load of each rolling element."""
        return np.array([self.bearing.roller_loads_N(y[0:2], ti) for ti, y in zip(t, Y)])

    def race_deflection(self, t: np.ndarray, Y: np.ndarray) -> np.ndarray | None:
        return None

    def energy_J(self, t: float, s: np.ndarray) -> float:
        """Kinetic + contact + load potential energy (conserved at zero speed with c = 0)."""
        ke = 0.5 * self.mass_kg * float(s[2] ** 2 + s[3] ** 2)
        return ke + self.bearing.potential_energy_J(s[0:2], t) - float(np.dot(self.load_at(t), s[0:2]))

    def state_scale(self) -> np.ndarray:
        """Typical magnitude of each state, for absolute tolerances: the static
        deflection under the load (or 1 um) and that times the contact frequency."""
        f = float(np.hypot(*self.load_N)) or 1.0
        d = max((f / self.bearing.stiffness) ** (1.0 / self.bearing.exponent), 1e-9)
        d = max(d, self.bearing.radial_clearance_m)
        w = np.sqrt(self.bearing.stiffness * self.bearing.exponent * d ** (self.bearing.exponent - 1.0)
                    * self.rollers / 2.0 / self.mass_kg)
        return np.array([d, d, d * w, d * w])
