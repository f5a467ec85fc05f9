"""The ``contact`` analysis: deck section -> solver -> contact.h5 and PNGs.

Signature of :func:`run_contact` follow ``spindlesim.runs`` (the RUNS table):
``(loaded_deck, outdir, run_info, options, progress) -> list[Path]``.  ``options`` may
override ``load_N``, ``tilt_deg``, ``nx``, ``ny`` (None = use the deck).
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Any

from ..contact.hertz import stribeck_max_roller_load
from ..contact.result import ContactResult

log = logging.getLogger(__name__)

__all__ = ["solve_from_section", "run_contact", "write_contact"]


def solve_from_section(sec: Any, options: dict | None = None) -> ContactResult:
    """Convert a validated ``contact:`` section (deck units) to SI and solve it."""
    from ..contact.problems import solve_point_contact

    opts = {k: v for k, v in (options or {}).items() if v is not None}
    if "load_N" in opts:
        load = float(opts["load_N"])
    elif sec.load_N is not None:
        load = sec.load_N
    else:
        m = sec.most_loaded_roller
        load = stribeck_max_roller_load(m.radial_load_N, m.rollers, line_contact_=sec.ball is None)
        log.info("most loaded element (Stribeck 4.08 Fr/Z): %.4g N", load)
    nx = int(opts.get("nx", sec.grid.nx))
    ny = int(opts.get("ny", sec.grid.ny))
    rm, wm = sec.roller_material, sec.raceway_material
    if sec.ball is not None:
        ry = sec.ball.ry_mm if sec.ball.ry_mm is not None else sec.ball.rx_mm
        return solve_point_contact(load, 1e-3 * sec.ball.rx_mm, 1e-3 * ry,
                                   E1_Pa=1e9 * rm.E_GPa, nu1=rm.poisson,
                                   E2_Pa=1e9 * wm.E_GPa, nu2=wm.poisson, n=max(nx, ny))
    return _solve_roller(sec, load, nx, ny, opts)


def raceway_radius_mm_to_m(value: float | None) -> float:
    return math.inf if value is None else 1e-3 * value


def _solve_roller(sec: Any, load: float, nx: int, ny: int, opts: dict) -> ContactResult:
    from ..contact.problems import solve_roller_contact

    rm, wm = sec.roller_material, sec.raceway_material
    return solve_roller_contact(
        load, 1e-3 * sec.roller_radius_mm, 1e-3 * sec.roller_length_mm,
        raceway_radius_m=raceway_radius_mm_to_m(sec.raceway_radius_mm), raceway=sec.raceway,
        profile=sec.profile,
        crown_radius_m=None if sec.crown_radius_mm is None else 1e-3 * sec.crown_radius_mm,
        design_load_N=sec.design_load_N, end_radius_m=1e-3 * sec.end_radius_mm,
        tilt_rad=math.radians(float(opts.get("tilt_deg", sec.tilt_deg))),
        roller_E_Pa=1e9 * rm.E_GPa, roller_nu=rm.poisson,
        raceway_E_Pa=1e9 * wm.E_GPa, raceway_nu=wm.poisson,
        nx=nx, ny=ny, check_edges=sec.check_edges,
    )


def write_contact(path: Path, run: Any, res: ContactResult, extra_attrs: dict | None = None) -> Path:
    """Write contact.h5: /contact/x_m, /contact/y_m, /contact/pressure_Pa [x, y] and more."""
    from ..output.hdf5 import Data, write_h5

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


def run_contact(loaded: Any, outdir: Path, run: Any, options: dict | None = None,
                progress: Any = None) -> list[Path]:
    """Solve the deck's ``contact:`` section; write contact.h5 and two PNGs into ``outdir``."""
    from ..contact.plots import pressure_map_figure, roller_profile_figure
    from ..output.drawing import draw

    from ..deck import require_section

    sec = require_section(loaded, "contact", "contact", "load_N, roller_radius_mm, profile, raceway, grid")
    res = solve_from_section(sec, options)
    if progress is not None:
        progress(1, 1)
    outdir = Path(outdir)
    paths = [write_contact(outdir / "contact.h5", run, res)]
    paths.append(draw(outdir / "contact_pressure.png", pressure_map_figure, res))
    if sec.ball is None:
        paths.append(draw(outdir / "contact_roller.png", roller_profile_figure, res))
    return paths
