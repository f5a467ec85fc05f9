"""``spindlesim impact``: impact records (CSV or UFF 58 time records) -> the tap test's FRF
(``measured.frf_from_impacts``) -> frf_<direction>.csv (the chatter readers' single-direction layout with its
coherence), impact.h5, impact_records.png and impact_frf.png.

The run reads the records, calls the estimation once, then only writes and draws its result; it returns the
result with the paths (the command prints the summary built from the result)."""

from __future__ import annotations

from pathlib import Path


def run(paths: list[Path], outdir: Path, run_info, options: dict | None = None):
    """(the :class:`~spindlesim.measured.results.ImpactFrf`, the written paths; the FRF file first)."""
    from ..measured import frf_from_impacts, read_impact_records
    from ..output.drawing import draw
    from ..output.impact_plots import impact_frf_figure, records_figure
    from ..output.impact_writer import write_frf_file, write_impact

    opts = options or {}
    records = [r for p in paths for r in read_impact_records(Path(p))]
    res = frf_from_impacts(records, direction=opts.get("direction"), decay_1_s=opts.get("decay_1_s"))
    written = [write_frf_file(outdir / f"frf_{res.direction}.csv", res, [Path(p).name for p in paths]),
               write_impact(outdir / "impact.h5", run_info, res)]
    if opts.get("plots", True):
        written.append(draw(outdir / "impact_records.png", records_figure, res))
        written.append(draw(outdir / "impact_frf.png", impact_frf_figure, res))
    return res, written
