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

from .common import plots_wanted
from .status import Written

log = logging.getLogger(__name__)


def run(loaded: Any, outdir: Path, run_info: Any, opts: dict, progress: Any = None) -> Written:
    """The deck's ball bearing: :class:`~spindlesim.bearings.ball.study.BallStudy` and bearing.h5 (a deck with a
    ``dtrb`` section instead: the ``dtrb`` analysis, its result and dtrb.h5)."""
    d = loaded.deck
    if d.bearing is None:
        if d.dtrb is not None:
            from .dtrb import run_dtrb

            done = run_dtrb(loaded, outdir, run_info, opts, progress)
            return Written(done.result, done.paths, "dtrb")
        from ..deck import require_section

        require_section(loaded, "bearing", "bearing", "type: ball and its geometry, or a 'dtrb' section")
    from ..bearings.ball.plots import figures
    from ..bearings.ball.study import ball_study
    from ..output.bearing_writer import write_bearing
    from ..output.figures import save_figure

    study = ball_study(d.bearing)
    res, st = study.run, study.run.state
    paths = [write_bearing(outdir / "bearing.h5", run_info, res, study.at)]
    if plots_wanted(opts):
        paths += [save_figure(fig, outdir / f"{name}.png") for name, fig in figures(res).items()]
    log.info("bearing %s: K_xx %.4g N/um, K_zz %.4g N/um, L10 %s Mrev", res.bearing.name, st.stiffness[0, 0] / 1e6,
             st.stiffness[2, 2] / 1e6, st.life_L10_iso281_Mrev)
    return Written(study, tuple(paths))
