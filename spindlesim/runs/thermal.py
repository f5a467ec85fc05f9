"""The ``thermal`` analysis: a spindle's thermal model when the deck has a ``spindle_thermal:`` section
(ball bearings, motor, housing: :mod:`.spindle_thermal`), else the fluid-film bearings' thermal
equilibrium (:mod:`.fluidfilm`)."""

from __future__ import annotations

from pathlib import Path
from typing import Any


def run(loaded: Any, outdir: Path, run_info: Any, options: dict | None = None, progress=None) -> list[Path]:
    if getattr(loaded.deck, "spindle_thermal", None) is not None:
        from .spindle_thermal import run as spindle

        return spindle(loaded, outdir, run_info, options, progress)
    from .fluidfilm import run_thermal

    return run_thermal(loaded, outdir, run_info, options, progress)
