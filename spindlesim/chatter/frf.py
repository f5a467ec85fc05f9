"""Tool-point inputs of the chatter analyses: modal parameters and a sampled receptance matrix.

Directions.  ``x`` and ``y`` are the two translations of the tool tip in the plane normal to the
spindle axis, in the frame the FRF was measured or computed in (the spindle's x and y).  Each
process states how its own directions sit in that frame (``feed_direction_rad`` of
:mod:`spindlesim.chatter.process`): by default the feed (chip-thickness direction in turning,
feed direction in milling) is +x and, for milling, the normal direction of Altintas and Budak is
+y.  Inputs are forces on the tool tip, outputs tool-tip displacements; ``H[f, i, j]`` is the
displacement in direction ``i`` per unit force in direction ``j`` [m/N].
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

__all__ = ["Mode", "ToolPointFrf", "DIRECTIONS"]

DIRECTIONS = ("x", "y")


@dataclass(frozen=True)
class Mode:
    """One tap-test mode in one direction: H_dd(w) = 1 / (k (1 - r^2 + 2 j zeta r)), r = w / w_n."""

    direction: Literal["x", "y"]
    frequency_hz: float
    damping_ratio: float
    stiffness_N_m: float

    def __post_init__(self) -> None:
        if self.direction not in DIRECTIONS:
            raise ValueError(f"mode direction must be 'x' or 'y', not {self.direction!r}")
        if not (np.isfinite(self.frequency_hz) and self.frequency_hz > 0):
            raise ValueError(f"mode frequency must be positive, got {self.frequency_hz}")
        if not (0.0 < self.damping_ratio < 1.0):
            raise ValueError(f"mode damping ratio must be in (0, 1), got {self.damping_ratio}")
        if not (np.isfinite(self.stiffness_N_m) and self.stiffness_N_m != 0.0):
            raise ValueError(f"mode stiffness must be finite and non-zero, got {self.stiffness_N_m}")

    @property
    def index(self) -> int:
        return DIRECTIONS.index(self.direction)

    @property
    def mass_kg(self) -> float:
        return self.stiffness_N_m / (2 * np.pi * self.frequency_hz) ** 2

    def receptance(self, frequency_hz: np.ndarray) -> np.ndarray:
        r = np.asarray(frequency_hz, float) / self.frequency_hz
        return 1.0 / (self.stiffness_N_m * (1.0 - r**2 + 2j * self.damping_ratio * r))


@dataclass(frozen=True, eq=False)
class ToolPointFrf:
    """Sampled tool-point receptance ``H[f, 2, 2]`` [m/N] at ``frequency_hz[f]`` [Hz] (strictly increasing).

    A measured FRF may carry its ``coherence[f, 2, 2]`` (0 to 1; NaN for a term not measured; None: no term
    has one) and the decay [1/s] of an exponential window its measurement applied, per direction (x, y):
    the window moved every pole of that direction by -decay, i.e. it added decay / w_n to every damping
    ratio (``spindlesim fitmodes`` takes it off; a sampled FRF used as it is keeps it).  A tool point of the
    protocol of :mod:`spindlesim.chatter.tool` (no state space: the methods that need one fit it)."""

    frequency_hz: np.ndarray
    H: np.ndarray
    source: str = ""
    coherence: np.ndarray | None = None
    window_decay_1_s: tuple[float, float] = (0.0, 0.0)

    def __post_init__(self) -> None:
        f = np.asarray(self.frequency_hz, float)
        H = np.asarray(self.H, complex)
        if f.ndim != 1 or len(f) < 1:
            raise ValueError("frequency_hz must be a non-empty 1-D array")
        if H.shape != (len(f), 2, 2):
            raise ValueError(f"H must have shape ({len(f)}, 2, 2), got {H.shape}")
        if not np.all(np.isfinite(f)) or f[0] < 0 or np.any(np.diff(f) <= 0):
            raise ValueError("frequency_hz must be finite, non-negative and strictly increasing")
        if not np.all(np.isfinite(H)):
            raise ValueError("H holds non-finite values")
        object.__setattr__(self, "frequency_hz", f)
        object.__setattr__(self, "H", H)
        if self.coherence is not None:
            c = np.asarray(self.coherence, float)
            if c.shape != H.shape:
                raise ValueError(f"coherence must have shape {H.shape}, got {c.shape}")
            seen = c[np.isfinite(c)]
            if np.any(np.isinf(c)) or np.any(seen < 0) or np.any(seen > 1 + 1e-9):
                raise ValueError("coherence must be within [0, 1] (NaN: not measured)")
            object.__setattr__(self, "coherence", np.minimum(c, 1.0))
        decay = tuple(float(v) for v in self.window_decay_1_s)
        if len(decay) != 2 or not all(np.isfinite(v) and v >= 0 for v in decay):
            raise ValueError(f"window_decay_1_s must be two finite values >= 0 (x, y), got {self.window_decay_1_s}")
        object.__setattr__(self, "window_decay_1_s", decay)

    def _like(self, f: np.ndarray, H: np.ndarray, coherence: np.ndarray | None) -> "ToolPointFrf":
        return ToolPointFrf(f, H, self.source, coherence, self.window_decay_1_s)

    @property
    def omega(self) -> np.ndarray:
        return 2 * np.pi * self.frequency_hz

    # -- the tool-point protocol (spindlesim/chatter/tool.py) -----------------------------------------
    @property
    def state_space(self) -> None:
        return None

    def frf(self, frequency_hz: np.ndarray | None = None) -> "ToolPointFrf":
        """Itself; on ``frequency_hz``, interpolated (:meth:`interpolated`)."""
        return self if frequency_hz is None else self.interpolated(frequency_hz)

    def receptance(self, omega: np.ndarray) -> np.ndarray:
        """H [len(omega), 2, 2] at angular frequencies ``omega`` [rad/s] inside the band (:meth:`interpolated`)."""
        return self.interpolated(np.atleast_1d(np.asarray(omega, float)) / (2 * np.pi)).H

    def band(self, f_min_hz: float | None = None, f_max_hz: float | None = None) -> "ToolPointFrf":
        """The samples within [f_min_hz, f_max_hz]."""
        f = self.frequency_hz
        keep = np.ones(len(f), bool)
        if f_min_hz is not None:
            keep &= f >= f_min_hz
        if f_max_hz is not None:
            keep &= f <= f_max_hz
        return self._like(f[keep], self.H[keep], None if self.coherence is None else self.coherence[keep])

    def interpolated(self, frequency_hz: np.ndarray) -> "ToolPointFrf":
        """Linear interpolation of real and imaginary parts (no extrapolation)."""
        f = np.asarray(frequency_hz, float)
        if f.min() < self.frequency_hz[0] or f.max() > self.frequency_hz[-1]:
            raise ValueError("interpolation outside the measured band")
        H = np.empty((len(f), 2, 2), complex)
        C = None if self.coherence is None else np.empty((len(f), 2, 2))
        for i in range(2):
            for j in range(2):
                H[:, i, j] = (np.interp(f, self.frequency_hz, self.H[:, i, j].real)
                              + 1j * np.interp(f, self.frequency_hz, self.H[:, i, j].imag))
                if C is not None:
                    C[:, i, j] = np.interp(f, self.frequency_hz, self.coherence[:, i, j])
        return self._like(f, H, C)

    def magnitude_peak(self) -> tuple[float, float]:
        """(frequency [Hz], largest singular value [m/N]) of the most compliant sample."""
        s = np.linalg.svd(self.H, compute_uv=False)[:, 0]
        k = int(np.argmax(s))
        return float(self.frequency_hz[k]), float(s[k])
