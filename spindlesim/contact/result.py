"""Result of a normal contact analysis (frozen; arrays are SI)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["ContactResult"]


@dataclass(frozen=True)
class ContactResult:
    """Pressure field and derived quantities of one contact.

    Axes: x across the contact (rolling direction), y along the roller axis (for a
    ball, the second principal direction); ``pressure_Pa[i, j]`` is at
    ``(x_m[i], y_m[j])`` (cell centres).

    Attributes
    ----------
    x_m, y_m : cell-centre coordinates [m].
    pressure_Pa : contact pressure [Pa], shape (len(x_m), len(y_m)).
    max_pressure_Pa : largest cell pressure [Pa] (a grid value: see ``edge_singular``).
    max_location_m : (x, y) of that cell [m].
    load_N : integrated load dA * sum p [N] (equals the applied load to solver tolerance).
    applied_load_N : the load that was asked for [N].
    area_m2 : contact area, cells with p > 0 [m^2].
    approach_m : rigid approach of the two bodies (elastic compliance only) [m].
    half_width_m : contact half-width in x for each y slice [m] (0 where no contact).
    centreline_pressure_Pa : pressure on x = 0 for each y slice [Pa].
    edge_singular : True when the pressure at a sharp roller end grows on grid
        refinement (a singularity of the half-space model, not a converged stress).
    message : human-readable note (why edge_singular was set, edge peaks at both grids).
    iterations : CGM iterations on the final grid; grid : (nx, ny).
    """

    x_m: np.ndarray
    y_m: np.ndarray
    pressure_Pa: np.ndarray
    max_pressure_Pa: float
    max_location_m: tuple[float, float]
    load_N: float
    applied_load_N: float
    area_m2: float
    approach_m: float
    half_width_m: np.ndarray
    centreline_pressure_Pa: np.ndarray
    edge_singular: bool = False
    message: str = ""
    iterations: int = 0
    grid: tuple[int, int] = (0, 0)
    inputs: dict = field(default_factory=dict)
