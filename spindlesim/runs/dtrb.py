"""The ``dtrb`` analysis: deck section -> equilibrium, stiffness, sweeps -> dtrb.h5 and PNGs.

:func:`run_dtrb` follow ``spindlesim.runs`` (the RUNS table):
``(loaded_deck, outdir, run_info, options, progress) -> list[Path]``.  ``options`` may
override ``preload_um``, ``speed_rpm`` and ``sweeps`` (False skips the sweeps); None = deck.
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Any

import numpy as np

from ..bearings.dtrb.bearing import DtrbBearing
from ..bearings.dtrb.results import DtrbSweep

log = logging.getLogger(__name__)

RPM = math.pi / 30.0


def _range(r) -> np.ndarray:
    return np.linspace(r.start, r.stop, r.count)


def run_dtrb(loaded: Any, outdir: Path, run: Any, options: dict | None = None, progress=None) -> list[Path]:
    from ..bearings.dtrb.plots import plot_load_distribution, plot_stiffness_sweep
    from ..bearings.dtrb.section import at_deck_temperatures, geometry_from, material_body
    from ..output.drawing import draw
    from ..output.dtrb_writer import write_dtrb

    from ..deck import require_section

    sec = require_section(loaded, "dtrb", "dtrb", "bearing geometry, preload_um, speed_rpm, load, sweeps")
    opts = {k: v for k, v in (options or {}).items() if v is not None}
    preload = 1e-6 * float(opts.get("preload_um", sec.preload_um))
    speed = RPM * float(opts.get("speed_rpm", sec.speed_rpm))
    do_sweeps = bool(opts.get("sweeps", True))
    load = np.asarray(sec.load.vector(), float)
    bearing = at_deck_temperatures(DtrbBearing(geometry_from(sec.bearing), preload,
                                               body=material_body(sec.bearing.material)), sec.temperatures_C)
    shift = bearing.preload_m - preload  # the growth's change of delta0, applied to the swept preloads too
    if shift:
        log.info("DTRB at temperature: preload %.4g um -> %.4g um", preload * 1e6, bearing.preload_m * 1e6)
        preload = bearing.preload_m
    g = bearing.geometry

    n_pre = sec.preload_sweep_um.count if (do_sweeps and sec.preload_sweep_um) else 0
    n_rad = sec.radial_sweep_N.count if (do_sweeps and sec.radial_sweep_N) else 0
    total = 1 + n_pre + n_rad
    done = 0

    def tick(n: int = 1) -> None:
        nonlocal done
        done += n
        if progress is not None:
            progress(done, total)

    st = bearing.solve(load, speed)
    tick()
    log.info("DTRB equilibrium: d = %s, loaded rollers %s", st.displacement, st.loaded_rollers())
    sweeps: dict[str, DtrbSweep] = {}
    if n_pre:
        values = 1e-6 * _range(sec.preload_sweep_um) + shift
        sweeps["preload_sweep"] = bearing.preload_sweep(values, load, speed)
        tick(n_pre)
    if n_rad:
        sweeps["radial_sweep"] = bearing.load_sweep(0, _range(sec.radial_sweep_N), load, speed)
        tick(n_rad)
    polar = [("applied load", st)]
    for p in sec.polar_preloads_um:
        polar.append((f"delta0 = {p:g} um", bearing.with_preload(1e-6 * p + shift).solve(load, speed)))
    for fx in sec.polar_radial_loads_N:
        L = load.copy()
        L[0] = fx
        polar.append((f"FX = {fx / 1e3:g} kN", bearing.solve(L, speed)))
    paths = [write_dtrb(outdir / "dtrb.h5", run, g, preload, speed, load, st, sweeps, polar)]
    figures = [draw(outdir / "dtrb_load_distribution.png", plot_load_distribution, polar)]
    if "preload_sweep" in sweeps:
        figures.append(draw(outdir / "dtrb_stiffness_preload.png", plot_stiffness_sweep,
                            sweeps["preload_sweep"], [(0, 0, "KXX"), (2, 2, "KZZ")], 1e6, "preload delta0 [um]",
                            f"Direct stiffness against preload (load {_load_text(load)}; seed 001 Fig. 8)"))
    if "radial_sweep" in sweeps:
        figures.append(draw(outdir / "dtrb_stiffness_radial.png", plot_stiffness_sweep,
                            sweeps["radial_sweep"], [(0, 0, "KXX")], 1e-3, "radial load FX [kN]",
                            f"KXX against radial load (delta0 = {preload * 1e6:g} um; seed 001 Fig. 10)"))
    return paths + figures


def _load_text(load: np.ndarray) -> str:
    return f"FX {load[0] / 1e3:g} kN, FY {load[1] / 1e3:g} kN, FZ {load[2] / 1e3:g} kN"
