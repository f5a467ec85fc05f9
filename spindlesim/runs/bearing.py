"""``spindlesim bearing``: one bearing (set) under a load -> bearing.h5 and PNGs.

The deck's ``bearing:`` section (``type: ball``: displacement and 5x5 stiffness at the load and
speed with the held DOFs, ball loads, contact angles and pressures, race control and Jones'
criterion, truncation of the contact ellipses, ISO 281 / ISO/TS 16281 lives, sweeps over preload,
load and speed), or a ``dtrb:`` section (the DTRB analysis, dtrb.h5).  Layout of bearing.h5:
:mod:`spindlesim.output.bearing_writer` (docs/output-format.md, "Ball bearing: bearing.h5")."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import numpy as np

from .common import plots_wanted

log = logging.getLogger(__name__)


def _at_temperature(b, speed: float, temperatures):
    """The bearing ``b`` at the deck's temperatures and fits at ``speed`` [rad/s] (None: the deck gives none)."""
    from ..output.bearing_writer import AtTemperature

    gr = b.growth
    if gr is None:
        return None
    inner_fit = gr.rings.inner_fit
    if inner_fit is not None and b.speed_growth is not None:
        inner_fit = b.speed_growth.fit(speed)
    preload = None
    if b.preload.kind != "spring":  # a spring sets the preload force whatever the growth
        preload = np.asarray(b.solve(np.zeros(5), speed).row_axial_load_N, float)
    temps = {} if temperatures is None else {k: float(v) for k, v in temperatures.model_dump().items() if v is not None}
    return AtTemperature(gr, 0.0 if b.speed_growth is None else float(b.speed_growth(speed)),
                         b.preload.row_offsets(b.geometry.rows), preload, inner_fit, gr.rings.outer_fit, temps)


def run(loaded: Any, outdir: Path, run_info: Any, opts: dict, progress: Any = None) -> list[Path]:
    d = loaded.deck
    if d.bearing is None:
        if d.dtrb is not None:
            from .dtrb import run_dtrb

            return run_dtrb(loaded, outdir, run_info, opts, progress)
        from ..deck import require_section

        require_section(loaded, "bearing", "bearing", "type: ball and its geometry, or a 'dtrb' section")
    from ..bearings.ball.plots import figures
    from ..bearings.ball.sweeps import run as run_ball
    from ..output.bearing_writer import write_bearing
    from ..output.figures import save_figure

    res = run_ball(d.bearing)
    st = res.state
    at = _at_temperature(res.bearing, res.speed_rad_s, d.bearing.temperatures_C)
    paths = [write_bearing(outdir / "bearing.h5", run_info, res, at)]
    if plots_wanted(opts):
        paths += [save_figure(fig, outdir / f"{name}.png") for name, fig in figures(res).items()]
    log.info("bearing %s: K_xx %.4g N/um, K_zz %.4g N/um, L10 %s Mrev", res.bearing.name, st.stiffness[0, 0] / 1e6,
             st.stiffness[2, 2] / 1e6, st.life_L10_iso281_Mrev)
    return paths
