"""The ``contact`` analysis: deck section -> solver -> contact.h5 and PNGs.

Signature of :func:`run_contact` follow ``spindlesim.runs`` (the RUNS table):
``(loaded_deck, outdir, run_info, options, progress) -> Written`` (the ContactResult and its files).  ``options`` may
override ``load_N``, ``tilt_deg``, ``nx``, ``ny`` (None = use the deck).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .status import Written

__all__ = ["run_contact"]


def run_contact(loaded: Any, outdir: Path, run: Any, options: dict | None = None,
                progress: Any = None) -> Written:
    """Solve the deck's ``contact:`` section; write contact.h5 and two PNGs into ``outdir``."""
    from ..contact.plots import pressure_map_figure, roller_profile_figure
    from ..contact.section import solve_from_section
    from ..output.contact_writer import write_contact
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
    return Written(res, tuple(paths))
