"""The one bearing protocol every analysis uses (docs/decisions.md, DESIGN.md section 3).

Frame: x horizontal, y vertical (gravity along -y), shaft spin about +z, so a
positive speed turns x towards y. Coefficient matrices act on the bearing
node's translations (x, y): the force the bearing exerts on the shaft is
``f = -(K q + C q')``.
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

import numpy as np


@runtime_checkable
class LinearizedBearing(Protocol):
    """A bearing that can be linearised about an operating point."""

    name: str
    node: int  # 0-based node index on the shaft

    def linearized(
        self, speed_rad_s: float, static_load_N: np.ndarray | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """Return (K [2x2] N/m, C [2x2] N s/m) in the (x, y) frame.

        ``static_load_N`` is the (x, y) force the shaft puts on the bearing at
        static equilibrium, for bearings whose coefficients depend on load;
        bearings with a load of their own in the deck use that instead.
        """
        ...


@runtime_checkable
class NonlinearBearing(Protocol):
    """A bearing that gives reaction forces for a state (transient, nonlinear static)."""

    name: str
    node: int

    def force(
        self, displacement_m: np.ndarray, velocity_m_s: np.ndarray, t_s: float
    ) -> np.ndarray:
        """Force [N] the bearing exerts on the shaft at the node, (x, y)."""
        ...
