"""``spindlesim fitmodes``: a measured FRF file -> its modes (``measured.identify_modes``) -> fitmodes.h5, modes.yaml
(pastes under ``chatter: frf: {modes: ...}``), fitmodes_stabilisation.png and fitmodes_overlay.png.

The run reads the file, calls the identification once, then only writes and draws its result; it returns the
result with the paths (the command prints the summary built from the result)."""

from __future__ import annotations

from pathlib import Path

#: the files the universal-file reader takes; any other suffix is read as CSV
UFF_SUFFIXES = (".uff", ".unv")


def read_measured_frf(path: Path, direction: str | None):
    """(the FRF of ``path``, CSV or UFF 58 by its suffix, in ``direction``; a note): a single-direction CSV file
    without a direction is taken as x, and the note says so."""
    from ..chatter.readers import read_frf

    if path.suffix.lower() in UFF_SUFFIXES:
        return read_frf(path, "uff", direction), None
    if direction is None and _single_direction(path):
        return read_frf(path, "csv", "x"), "a single-direction file, taken as x (--direction y for y)"
    return read_frf(path, "csv", direction), None


def _single_direction(path: Path) -> bool:
    from ..chatter.readers import csv_rows

    for _, fields in csv_rows(path):
        return "real_m_n" in {f.strip().lower() for f in fields}
    return False


def run(path: Path, outdir: Path, run_info, options: dict | None = None):
    """(the :class:`~spindlesim.measured.results.ModalIdentification`, the written paths)."""
    from ..measured import identify_modes
    from ..output.drawing import draw
    from ..output.fitmodes_plots import overlay_figure, stabilisation_figure
    from ..output.fitmodes_writer import write_fitmodes, write_modes_yaml

    opts = options or {}
    frf, note = read_measured_frf(Path(path), opts.get("direction"))
    kwargs = {"max_order": opts["max_order"]} if opts.get("max_order") else {}
    ident = identify_modes(frf, opts.get("band_hz"), direction=opts.get("direction"), **kwargs)
    if note:
        from dataclasses import replace

        ident = replace(ident, directions=tuple(replace(d, notes=(note,) + d.notes) for d in ident.directions))
    paths = [write_fitmodes(outdir / "fitmodes.h5", run_info, ident), write_modes_yaml(outdir / "modes.yaml", ident)]
    if opts.get("plots", True):
        paths.append(draw(outdir / "fitmodes_stabilisation.png", stabilisation_figure, ident))
        paths.append(draw(outdir / "fitmodes_overlay.png", overlay_figure, ident))
    return ident, paths
