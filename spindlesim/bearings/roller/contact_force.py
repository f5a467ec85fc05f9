"""Compliant contact force with friction, seed 000 eqs. 30-31.

    f_n = k delta^m1 + c (delta'/|delta'|) |delta'|^m2 delta^m3     (eq. 30)
    f_f = mu |f_n|, signed by the relative velocity at the contact  (eq. 31)

for penetration delta > 0 (zero otherwise).  m3 > 0 keeps the damping term
from jumping at first touch (seed 000).  Two implementation choices, both
documented in docs/theory.md: the normal force is clipped at
zero (a contact cannot pull; Hunt and Crossley 1975 discuss the sticky force
the unclipped form gives while separating), and the sign of the slip velocity
is regularised as v / sqrt(v^2 + v_reg^2) so the integrator sees a continuous
right-hand side (a standard smoothing of Coulomb friction, e.g. Pfeiffer and
Glocker, Multibody Dynamics with Unilateral Contacts, 1996).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CompliantContact:
    """Parameters of eqs. 30-31 (SI: k in N/m^m1, c in N (s/m)^m2 / m^m3)."""

    stiffness: float
    exponent: float = 1.0  # m1
    damping: float = 0.0  # c
    velocity_exponent: float = 1.0  # m2
    indentation_exponent: float = 1.0  # m3
    friction: float = 0.0  # mu
    slip_regularisation_m_s: float = 1e-3

    def normal_force(self, delta: np.ndarray, delta_dot: np.ndarray) -> np.ndarray:
        """f_n >= 0 for each contact, eq. 30."""
        d = np.maximum(np.asarray(delta, float), 0.0)
        f = self.stiffness * d**self.exponent
        if self.damping:
            dd = np.asarray(delta_dot, float)
            f = f + self.damping * np.sign(dd) * np.abs(dd) ** self.velocity_exponent * d**self.indentation_exponent
        return np.where(d > 0, np.maximum(f, 0.0), 0.0)

    def friction_force(self, normal_force: np.ndarray, slip_velocity: np.ndarray) -> np.ndarray:
        """Signed friction force opposing the slip velocity, eq. 31 (regularised sign)."""
        if not self.friction:
            return np.zeros_like(np.asarray(normal_force, float))
        v = np.asarray(slip_velocity, float)
        return -self.friction * np.abs(normal_force) * v / np.sqrt(v**2 + self.slip_regularisation_m_s**2)

    def energy_J(self, delta: np.ndarray) -> np.ndarray:
        """Elastic energy k delta^(m1+1)/(m1+1) stored in each contact."""
        d = np.maximum(np.asarray(delta, float), 0.0)
        return self.stiffness * d ** (self.exponent + 1.0) / (self.exponent + 1.0)
