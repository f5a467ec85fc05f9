"""The ``dtrb`` analysis: deck section -> equilibrium, stiffness, sweeps -> dtrb.h5 and PNGs.

:func:`run_dtrb` follow ``spindlesim.runs`` (the RUNS table):
``(loaded_deck, outdir, run_info, options, progress) -> Written`` (the study and its files).  ``options`` may
override ``preload_um``, ``speed_rpm`` and ``sweeps`` (False skips the sweeps); None = deck.
"""

from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Any

import numpy as np

from ..bearings.dtrb.bearing import DtrbBearing
from .status import Written

log = logging.getLogger(__name__)

RPM = math.pi / 30.0


def _range(r) -> np.ndarray:
    return np.linspace(r.start, r.stop, r.count)


def run_dtrb(loaded: Any, outdir: Path, run: Any, options: dict | None = None, progress=None) -> Written:
    """The deck's ``dtrb`` section: its :class:`~spindlesim.bearings.dtrb.study.DtrbStudy`, dtrb.h5 and PNGs."""
    from ..bearings.dtrb.plots import plot_load_distribution, plot_stiffness_sweep
    from ..bearings.dtrb.section import at_deck_temperatures, geometry_from, material_body
    from ..bearings.dtrb.study import dtrb_study
    from ..deck import require_section
    from ..output.drawing import draw
    from ..output.dtrb_writer import write_dtrb

    sec = require_section(loaded, "dtrb", "dtrb", "bearing geometry, preload_um, speed_rpm, load, sweeps")
    opts = {k: v for k, v in (options or {}).items() if v is not None}
    preload = 1e-6 * float(opts.get("preload_um", sec.preload_um))
    do_sweeps = bool(opts.get("sweeps", True))
    bearing = at_deck_temperatures(DtrbBearing(geometry_from(sec.bearing), preload,
                                               body=material_body(sec.bearing.material)), sec.temperatures_C)
    shift = bearing.preload_m - preload  # the growth's change of delta0, applied to the swept preloads too
    if shift:
        log.info("DTRB at temperature: preload %.4g um -> %.4g um", preload * 1e6, bearing.preload_m * 1e6)
    st = dtrb_study(bearing, sec.load.vector(), RPM * float(opts.get("speed_rpm", sec.speed_rpm)),
                    1e-6 * _range(sec.preload_sweep_um) + shift if do_sweeps and sec.preload_sweep_um else (),
                    _range(sec.radial_sweep_N) if do_sweeps and sec.radial_sweep_N else (),
                    [1e-6 * p + shift for p in sec.polar_preloads_um], list(sec.polar_radial_loads_N), progress)
    paths = [write_dtrb(outdir / "dtrb.h5", run, bearing.geometry, st.preload_m, st.speed_rad_s, st.load, st.state,
                        st.sweeps, list(st.polar))]
    paths.append(draw(outdir / "dtrb_load_distribution.png", plot_load_distribution, list(st.polar)))
    if "preload_sweep" in st.sweeps:
        paths.append(draw(outdir / "dtrb_stiffness_preload.png", plot_stiffness_sweep,
                          st.sweeps["preload_sweep"], [(0, 0, "KXX"), (2, 2, "KZZ")], 1e6, "preload delta0 [um]",
                          f"Direct stiffness against preload (load {_load_text(st.load)}; seed 001 Fig. 8)"))
    if "radial_sweep" in st.sweeps:
        paths.append(draw(outdir / "dtrb_stiffness_radial.png", plot_stiffness_sweep,
                          st.sweeps["radial_sweep"], [(0, 0, "KXX")], 1e-3, "radial load FX [kN]",
                          f"KXX against radial load (delta0 = {st.preload_m * 1e6:g} um; seed 001 Fig. 10)"))
    return Written(st, tuple(paths))


def _load_text(load: np.ndarray) -> str:
    return f"FX {load[0] / 1e3:g} kN, FY {load[1] / 1e3:g} kN, FZ {load[2] / 1e3:g} kN"
