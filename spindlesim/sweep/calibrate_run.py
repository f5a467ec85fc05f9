"""``spindlesim calibrate``: the calibration (``calibration.calibrate``) written: calibration.h5, calibrated.yaml
(the deck with the fitted values in place, its measurement paths taken from the output folder) and
calibration_frf.png.  A Ctrl-C during the fit writes the best values evaluated, marked incomplete."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any


def run_calibration(loaded: Any, outdir: Path, run_info: Any, progress=None) -> list[Path]:
    from ..deck import deck_folder
    from ..output.calibration_plots import calibration_figure
    from ..output.calibration_writer import calibrated_deck_text, write_calibration
    from ..output.drawing import draw, wait
    from ..output.hdf5 import write_text_atomic
    from ..runs.status import IncompleteRun
    from .calibration import calibrate

    base = deck_folder(loaded)
    interrupted = None
    try:
        res = calibrate(loaded, base, progress)
    except KeyboardInterrupt as exc:
        res = getattr(exc, "partial", None)
        if res is None:
            raise
        interrupted = exc
    outdir.mkdir(parents=True, exist_ok=True)
    moved = {}
    for i, m in enumerate(loaded.deck.calibration.measurements):  # the measurement files, from the new deck's folder
        p = Path(m.file.path)
        if not p.is_absolute():
            moved[f"calibration.measurements.{i}.file.path"] = os.path.relpath(base / p, outdir)
    paths = [write_calibration(outdir / "calibration.h5", run_info, res),
             write_text_atomic(outdir / "calibrated.yaml", calibrated_deck_text(res, loaded.source, moved))]
    paths.append(draw(outdir / "calibration_frf.png", calibration_figure, res, loaded.deck.title))
    if interrupted is not None:
        wait()
        raise IncompleteRun("calibration interrupted: the best values evaluated are written, without intervals",
                            paths, interrupted=True)
    return paths
