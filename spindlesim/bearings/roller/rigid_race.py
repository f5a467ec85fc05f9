"""Rolling bearing with rigid races: Hertz contacts at the cage positions (the model; its contract is
``bearing.RigidRaceBearing``).

Sunnersjo (J. Sound Vib. 58, 1978) and Harsha and Kankar (Int. J. Mech. Sci. 46, 2004, the
waviness reference of seed 000): the races are rigid, the shaft centre (x, y) moves in the
plane, rolling element j sits at the orbit angle theta_j = phase + 2 pi j / N + c phi(t) (c the
cage ratio of seed 000 eq. 3, phi the shaft angle) and carries the Hertz force

    Q_j = K (x cos theta_j + y sin theta_j - gamma_0 + w_j(t))_+^n

with n = 3/2 for a ball (point contact) and n = 10/9 for a roller (line contact, Palmgren),
gamma_0 the radial internal clearance, and w_j the local sum of surface waviness of inner
race, outer race and rolling element.  The force on the shaft is -sum_j Q_j (cos, sin)
theta_j, minus the damping force beta K_t v of ``damping_s`` (``bearings.damping``: C = beta K_t,
K_t = sum_j k_j e_j e_j^T the tangent of the contacts, k_j = n K delta_j^(n-1)).  As the elements roll, the stiffness varies at the roller-pass frequency N f_cage
(the varying compliance).  Angles run from +x towards +y (spindlesim frame); the shaft spins
about +z, so the cage turns the same way.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..base import RADIAL
from ..damping import check_beta
from .kinematics import CageKinematics

#: code of each waviness surface in the compiled force
SURFACE = {"outer": 0, "inner": 1, "roller": 2}


@dataclass(frozen=True)
class Waviness:
    """One harmonic of surface waviness, a radial deviation A cos(k phi + phase) [m].

    ``surface`` is "inner" (turns with the shaft), "outer" (stationary) or "roller" (turns with
    the roller spin, seed 000 eq. 4; it meets both races, on opposite sides of the roller).
    Positive deviation = extra material, which adds to the contact deflection (Harsha and
    Kankar 2004).
    """

    surface: str
    waves: int
    amplitude_m: float
    phase_rad: float = 0.0

    def __post_init__(self) -> None:
        if self.surface not in SURFACE:
            raise ValueError(f"waviness surface must be inner, outer or roller, not {self.surface!r}")
        if self.waves < 1:
            raise ValueError("waviness needs at least one wave")


@dataclass(frozen=True)
class RigidRace:
    """Rigid races and Hertz contacts (Sunnersjo 1978; Harsha and Kankar 2004): the model; the bearing contract
    is ``bearing.RigidRaceBearing``."""

    name: str
    node: int
    rollers: int
    stiffness: float  # K of Q = K delta^n for the element's two contacts in series, SI (N/m^n)
    exponent: float  # 1.5 ball, 10/9 roller
    kinematics: CageKinematics
    radial_clearance_m: float = 0.0
    waviness: tuple[Waviness, ...] = field(default_factory=tuple)
    phase_rad: float = 0.0
    dof_names: tuple[str, ...] = RADIAL
    body: object = None  # rings' and rollers' thermal.growth.ThermoElastic (None: bearing steel), for at_temperatures
    made_clearance_m: float | None = None  # radial clearance as assembled (cold; None: radial_clearance_m)
    damping_s: float = 0.0  # beta [s] of the damping C = beta K_t (bearings.damping; 0: the contact model alone)
    damping_held: tuple[float, ...] | None = None  # C (2x2, row-major) held for a time integration, or None

    def __post_init__(self) -> None:
        if self.rollers < 3:
            raise ValueError("need at least 3 rolling elements")
        if self.stiffness <= 0 or self.exponent <= 0:
            raise ValueError("contact stiffness and exponent must be positive")
        check_beta(self.damping_s)

    # kinematics ---------------------------------------------------------------
    def angles(self, shaft_angle_rad: float) -> np.ndarray:
        """Orbit angle of each rolling element [rad] at a shaft angle."""
        return (self.phase_rad + 2.0 * np.pi * np.arange(self.rollers) / self.rollers
                + self.kinematics.cage_ratio * shaft_angle_rad)

    def waviness_m(self, theta: np.ndarray, shaft_angle_rad: float) -> np.ndarray:
        """Sum of waviness deviations at each element's contacts [m]."""
        w = np.zeros_like(theta)
        for wv in self.waviness:
            if wv.surface == "outer":
                w += wv.amplitude_m * np.cos(wv.waves * theta + wv.phase_rad)
            elif wv.surface == "inner":
                w += wv.amplitude_m * np.cos(wv.waves * (theta - shaft_angle_rad) + wv.phase_rad)
            else:
                spin = self.kinematics.spin_ratio * shaft_angle_rad
                w += wv.amplitude_m * (np.cos(wv.waves * spin + wv.phase_rad)
                                       + np.cos(wv.waves * (spin + np.pi) + wv.phase_rad))
        return w

    def deflection_m(self, q: np.ndarray, shaft_angle_rad: float) -> tuple[np.ndarray, np.ndarray]:
        """(theta_j, signed contact deflection delta_j) for a shaft displacement (x, y)."""
        th = self.angles(shaft_angle_rad)
        d = q[0] * np.cos(th) + q[1] * np.sin(th) - self.radial_clearance_m
        if self.waviness:
            d = d + self.waviness_m(th, shaft_angle_rad)
        return th, d

    def roller_loads_N(self, q: np.ndarray, shaft_angle_rad: float) -> np.ndarray:
        """Contact load Q_j >= 0 of each rolling element [N]."""
        _, d = self.deflection_m(np.asarray(q, float), shaft_angle_rad)
        return self.stiffness * np.maximum(d, 0.0) ** self.exponent

    def potential_energy_J(self, q: np.ndarray, shaft_angle_rad: float) -> float:
        """Elastic energy sum K delta_+^(n+1)/(n+1) (conservative at zero speed)."""
        _, d = self.deflection_m(np.asarray(q, float), shaft_angle_rad)
        n = self.exponent
        return float(np.sum(self.stiffness * np.maximum(d, 0.0) ** (n + 1.0) / (n + 1.0)))
