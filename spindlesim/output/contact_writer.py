"""contact.h5: the pressure of one roller (or ball) on its raceway (docs/output-format.md).

    /contact/x_m [x_m], /contact/y_m [y_m]            the grid: rolling direction, along the roller
    /contact/pressure_Pa [x_m, y_m]
    /contact/centreline_pressure_Pa [y_m]             at x = 0
    /contact/half_width_m [y_m]                       contact half-width in x (0: no contact)

Attributes of /contact: the peak pressure and where it is, the load carried and applied, the area, the
approach, whether a sharp roller end is in contact (``edge_singular``), the solver's message, grid and
iterations, and what the caller adds (where the load comes from).
"""

from __future__ import annotations

from pathlib import Path

from ..contact.result import ContactResult
from .hdf5 import Data, RunInfo, write_h5


def write_contact(path: Path, run: RunInfo, res: ContactResult, extra_attrs: dict | None = None) -> Path:
    """Write contact.h5: /contact/x_m, /contact/y_m, /contact/pressure_Pa [x, y] and more."""
    datasets = {
        "/contact/x_m": Data(res.x_m, "m", ("x_m",), "rolling direction"),
        "/contact/y_m": Data(res.y_m, "m", ("y_m",), "along the roller"),
        "/contact/pressure_Pa": (res.pressure_Pa, "Pa", ("x_m", "y_m")),
        "/contact/centreline_pressure_Pa": Data(res.centreline_pressure_Pa, "Pa", ("y_m",), "pressure at x = 0"),
        "/contact/half_width_m": Data(res.half_width_m, "m", ("y_m",), "contact half-width in x (0: no contact)"),
    }
    attrs = {
        "max_pressure_Pa": res.max_pressure_Pa,
        "max_location_m": list(res.max_location_m),
        "load_N": res.load_N,
        "applied_load_N": res.applied_load_N,
        "area_m2": res.area_m2,
        "approach_m": res.approach_m,
        "edge_singular": res.edge_singular,
        "message": res.message,
        "grid": list(res.grid),
        "iterations": res.iterations,
        **(extra_attrs or {}),
    }
    return write_h5(path, run, datasets, group_attrs={"/contact": attrs})
