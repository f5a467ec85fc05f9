"""Runs: one module per analysis; each reads the deck, calls the physics and hands the results to the writers
and figures of :mod:`spindlesim.output` (HDF5 and PNG files).

The scriptable API the CLI wraps::

    from spindlesim.deck import load_deck
    from spindlesim.runs import run_analysis
    paths = run_analysis("modal", load_deck("spindle.yaml"), "out/spindle")

Every run is ``run(loaded_deck, outdir, run_info, options, progress) -> list[Path]``; :data:`RUNS`
(module, function), derived from the registry (spindlesim/registry.py), is imported only when a run
is asked for.
"""

from __future__ import annotations

import importlib
import logging
from pathlib import Path
from typing import Any, Callable

from ..deck.describe import FLUID_FILM_TYPES, bearing_entries
from ..deck.loader import ANALYSES, LoadedDeck
from ..output import drawing
from ..output.hdf5 import RunInfo
from .common import RunContext
from .status import Written
from ..registry import analysis, default_rows, file_writers

log = logging.getLogger(__name__)

Progress = Callable[[int, int], None] | None

#: analysis name (aliases included) -> (module in spindlesim.runs, function)
RUNS: dict[str, tuple[str, str]] = {name: tuple(analysis(name).run.split(":")) for name in ANALYSES}


def analyses() -> tuple[str, ...]:
    return tuple(RUNS)


def run_info_for(loaded: "LoadedDeck | RunContext", command_line: str | None = None) -> RunInfo:
    kw = {} if command_line is None else {"command_line": command_line}
    return RunInfo(deck_text=loaded.text, deck_source=loaded.source, deck_sha256=loaded.sha256, **kw)


def run_analysis(name: str, loaded: "LoadedDeck | RunContext", outdir: str | Path,
                 options: dict[str, Any] | None = None, progress: Progress = None,
                 run: RunInfo | None = None) -> list[Path]:
    """Run analysis ``name`` and write its outputs into ``outdir``; returns the written paths
    (:func:`perform_analysis` returns the result too)."""
    return list(perform_analysis(name, loaded, outdir, options, progress, run).paths)


def perform_analysis(name: str, loaded: "LoadedDeck | RunContext", outdir: str | Path,
                     options: dict[str, Any] | None = None, progress: Progress = None,
                     run: RunInfo | None = None) -> Written:
    """Run analysis ``name``, write its outputs into ``outdir``; returns :class:`~.status.Written`: the
    analysis's frozen result and the written paths.

    ``loaded``: a loaded deck (its analysis solves what it needs), or a :class:`~.common.RunContext` of it
    shared by several calls (``spindlesim run``: one shaft assembly, each operating point solved once).
    Every file is on disk when it returns, figures drawn by a figure process included (they are
    waited for; a failed figure raises here, a failed or interrupted run cancels the ones not started)."""
    from .common import context_of

    loaded = context_of(loaded)
    if name not in RUNS:
        raise KeyError(f"unknown analysis {name!r}; known: {', '.join(RUNS)}")
    ran = analysis(analysis_for(name, loaded.deck)).name
    module, function = RUNS[ran]
    fn = getattr(importlib.import_module(f"{__name__}.{module}"), function)
    status = importlib.import_module(f"{__name__}.status")
    status.remove_stale_temporaries(outdir)  # a killed run's *.tmp
    try:
        written = fn(loaded, Path(outdir), run or run_info_for(loaded), options or {}, progress)
    except status.IncompleteRun as exc:  # its files, figures included, are written: marked incomplete
        exc.analysis = ran
        drawing.wait()
        raise
    except BaseException:
        drawing.abandon()
        raise
    drawing.wait()
    if not isinstance(written, Written):
        raise TypeError(f"the run of {ran!r} returned {type(written).__name__}, not runs.status.Written")
    # the analysis whose result it is (``bearing`` on a dtrb deck hands back the dtrb analysis's)
    return Written(written.result, tuple(written.paths), written.analysis or ran, written.also)


#: what ``spindlesim run`` does when the deck has no ``analyses`` list: every analysis the deck has the
#: sections for, in this order (analyses, what the deck needs for them; from the registry).
#: :func:`default_analyses` applies it; ``spindlesim run --help`` prints it.
DEFAULT_RUN: tuple[tuple[tuple[str, ...], str], ...] = default_rows()


def _has(deck, section: str) -> bool:
    """Whether ``deck`` has ``section`` of a registry entry's ``runs_on`` ("rotor": shaft or journal; "fluid_film":
    a bearing of type three_lobe or plain; else the deck section of that name)."""
    if section == "rotor":
        return deck.shaft is not None or deck.journal is not None
    if section == "fluid_film":
        return bool(bearing_entries(deck, *FLUID_FILM_TYPES))
    return getattr(deck, section, None) is not None


def analysis_for(name: str, deck) -> str:
    """The analysis that runs for ``name``: itself; for the name of a file that several analyses write (the
    ``thermal`` command's thermal.h5: the fluid-film bearings' or the spindle_thermal section's), the first of them
    whose leading section (the first of a ``runs_on`` alternative) the deck has, else ``name`` itself."""
    writers = file_writers().get(analysis(name).name, ())
    if len(writers) > 1:
        for other in writers:
            if any(_has(deck, sections[0]) for sections in analysis(other).runs_on):
                return other
    return name


def default_analyses(loaded: LoadedDeck) -> list[str]:
    """What ``spindlesim run`` does when the deck has no ``analyses`` list: every analysis the deck has the
    sections for (:data:`DEFAULT_RUN`; each analysis's ``runs_on`` in the registry), of analyses that write one
    file the first only."""
    d = loaded.deck
    if (d.shaft is not None or d.journal is not None) and d.operating is None:
        log.warning("the deck has a rotor but no 'operating' section: the rotor analyses are not run")
    chosen: list[str] = []
    for names, _ in DEFAULT_RUN:
        for name in names:
            a = analysis(name)
            if any(all(_has(d, s) for s in sections) for sections in a.runs_on) and \
                    all(analysis(c).stem != a.stem for c in chosen):
                chosen.append(name)
    return chosen
