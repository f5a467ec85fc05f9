"""Deck bearing type ``linear``: stiffness and damping coefficients given directly.

    bearings:
      - {name: front, node: 7, type: linear,
         K_N_m: [[412.62e6, 373.86e6], [-338.35e6, 467.71e6]],   # [[Kxx, Kxy], [Kyx, Kyy]]
         C_Ns_m: [[3245.15e3, 67.45e3], [71.77e3, 3508.47e3]]}
      - {name: rear, node: 18, type: linear,
         table: {speed_rpm: [1000, 3000], K_N_m: [..2x2.., ..2x2..], C_Ns_m: [.., ..]}}

A table is interpolated linearly in speed and held constant outside its range.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal, Optional

from pydantic import Field, model_validator

from ...fields import DeckModel, Matrix2, NodeNumber, NonNegFloat
from ..plausible import Found, damping, stiffness

if TYPE_CHECKING:
    from .bearing import LinearBearing

RPM = 3.141592653589793 / 30.0


class CoefficientTable(DeckModel):
    """Speed-dependent coefficients, interpolated linearly in speed (held constant outside)."""

    speed_rpm: Annotated[list[NonNegFloat], Field(min_length=2, max_length=10_000)]
    """Speeds of the table, strictly increasing (at least two); the coefficients are interpolated linearly in
    speed and held constant outside the range."""
    K_N_m: Annotated[list[Matrix2], Field(max_length=10_000)]
    """One stiffness matrix [[Kxx, Kxy], [Kyx, Kyy]] per speed."""
    C_Ns_m: Annotated[list[Matrix2], Field(max_length=10_000)]
    """One damping matrix [[Cxx, Cxy], [Cyx, Cyy]] per speed."""

    @model_validator(mode="after")
    def _rows(self) -> "CoefficientTable":
        n = len(self.speed_rpm)
        if list(self.speed_rpm) != sorted(self.speed_rpm) or len(set(self.speed_rpm)) != n:
            raise ValueError("table.speed_rpm must be strictly increasing")
        for key in ("K_N_m", "C_Ns_m"):
            if len(getattr(self, key)) != n:
                raise ValueError(f"table.{key} needs {n} matrices, one per speed, got {len(getattr(self, key))}")
        return self


class LinearEntry(DeckModel):
    type: Literal["linear"]
    """Bearing type: linear (stiffness and damping coefficients given directly, acting on x and y)."""
    name: str
    """Bearing name, unique in the deck (output groups, sweep paths)."""
    node: NodeNumber
    """Shaft node of the bearing (1-based)."""
    K_N_m: Optional[Matrix2] = None
    """Stiffness matrix [[Kxx, Kxy], [Kyx, Kyy]]: force on the shaft f = -(K q + C q') on (x, y). Give it or
    `table`."""
    C_Ns_m: Optional[Matrix2] = None
    """Damping matrix [[Cxx, Cxy], [Cyx, Cyy]]. None: no damping."""
    table: Optional[CoefficientTable] = None
    """Speed-dependent coefficients instead of `K_N_m` and `C_Ns_m` (used when given)."""

    @model_validator(mode="after")
    def _given(self) -> "LinearEntry":
        if self.table is None and self.K_N_m is None:
            raise ValueError("a linear bearing needs K_N_m (and C_Ns_m) or a table")
        return self


def build(entry: LinearEntry) -> "LinearBearing":
    """Deck entry -> :class:`LinearBearing` (SI; node 0-based)."""
    import numpy as np

    from .bearing import LinearBearing

    if entry.table is not None:
        t = entry.table
        return LinearBearing(entry.name, entry.node - 1, np.asarray(t.speed_rpm) * RPM,
                             np.asarray(t.K_N_m, float), np.asarray(t.C_Ns_m, float))
    C = entry.C_Ns_m if entry.C_Ns_m is not None else [[0.0, 0.0], [0.0, 0.0]]
    return LinearBearing(entry.name, entry.node - 1, np.array([0.0]),
                         np.asarray([entry.K_N_m], float), np.asarray([C], float))


def plausibility(b: LinearEntry, at: tuple) -> Found:
    """Likely unit mistakes of the entry at the key path ``at``: a stiffness below 1e5 N/m (N/mm or N/um?), a
    damping whose ratio to it lies outside 1e-9 .. 1 s."""
    bad: Found = []
    if b.K_N_m is not None:
        if stiffness(b.K_N_m, at + ("K_N_m",), bad):
            damping(b.K_N_m, b.C_Ns_m, at + ("C_Ns_m",), bad)
    if b.table is not None:
        for j, K in enumerate(b.table.K_N_m):
            if not stiffness(K, at + ("table", "K_N_m", j), bad):
                break
            damping(K, b.table.C_Ns_m[j], at + ("table", "C_Ns_m", j), bad)
    return bad
