"""Runs: one module per analysis; each reads the deck, calls the physics and hands the results to the writers
and figures of :mod:`spindlesim.output` (HDF5 and PNG files).

The scriptable API the CLI wraps::

    from spindlesim.deck import load_deck
    from spindlesim.runs import run_analysis
    paths = run_analysis("modal", load_deck("spindle.yaml"), "out/spindle")

Every run is ``run(loaded_deck, outdir, run_info, options, progress) -> list[Path]``; :data:`RUNS`
is the one table of them (module, function), imported only when a run is asked for.
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

log = logging.getLogger(__name__)

Progress = Callable[[int, int], None] | None

#: analysis name -> (module in spindlesim.runs, function)
RUNS: dict[str, tuple[str, str]] = {
    "static": ("rotor", "run_static"),
    "modal": ("rotor", "run_modal"),
    "campbell": ("rotor", "run_campbell"),
    "frf": ("rotor", "run_frf"),
    "unbalance": ("rotor", "run_unbalance"),
    "transient": ("transient", "run"),
    "rotor_transient": ("transient", "run"),  # the name of seed 001 study decks (the same run)
    "thermal": ("thermal", "run"),
    "coefficients": ("fluidfilm", "run_coefficients"),
    "bearing": ("bearing", "run"),
    "dtrb": ("dtrb", "run_dtrb"),
    "contact": ("contact", "run_contact"),
    "chatter": ("chatter", "run"),
}
assert set(RUNS) == set(ANALYSES), "the deck's analysis names and the runs table must agree"


def analyses() -> tuple[str, ...]:
    return tuple(RUNS)


def run_info_for(loaded: LoadedDeck, command_line: str | None = None) -> RunInfo:
    kw = {} if command_line is None else {"command_line": command_line}
    return RunInfo(deck_text=loaded.text, deck_source=loaded.source, deck_sha256=loaded.sha256, **kw)


def run_analysis(name: str, loaded: LoadedDeck, outdir: str | Path, options: dict[str, Any] | None = None,
                 progress: Progress = None, run: RunInfo | None = None) -> list[Path]:
    """Run analysis ``name`` and write its outputs into ``outdir``; returns the written paths.

    Every file is on disk when it returns, figures drawn by a figure process included (they are
    waited for; a failed figure raises here, a failed or interrupted run cancels the ones not started)."""
    if name not in RUNS:
        raise KeyError(f"unknown analysis {name!r}; known: {', '.join(RUNS)}")
    module, function = RUNS[name]
    fn = getattr(importlib.import_module(f"{__name__}.{module}"), function)
    status = importlib.import_module(f"{__name__}.status")
    status.remove_stale_temporaries(outdir)  # a killed run's *.tmp
    try:
        paths = fn(loaded, Path(outdir), run or run_info_for(loaded), options or {}, progress)
    except status.IncompleteRun:  # its files, figures included, are written: marked incomplete
        drawing.wait()
        raise
    except BaseException:
        drawing.abandon()
        raise
    drawing.wait()
    return paths


#: what ``spindlesim run`` does when the deck has no ``analyses`` list: every analysis the deck has the
#: sections for, in this order (analyses, what the deck needs for them).  :func:`default_analyses`
#: applies it; ``spindlesim run --help`` says the same (tests/cli/test_run_default.py keeps them equal).
DEFAULT_RUN: tuple[tuple[tuple[str, ...], str], ...] = (
    (("thermal", "coefficients"), "fluid-film bearings (type three_lobe or plain) and operating; thermal "
                                  "alone: a spindle_thermal section and operating"),
    (("static", "modal", "campbell", "frf"), "a rotor (shaft or journal) and operating"),
    (("unbalance",), "a rotor, operating and an unbalance section"),
    (("transient",), "a rotor, operating and a rotor_transient section; or a transient section"),
    (("bearing",), "a bearing section"),
    (("dtrb",), "a dtrb section"),
    (("contact",), "a contact section"),
    (("chatter",), "a chatter section"),
)


def default_analyses(loaded: LoadedDeck) -> list[str]:
    """What ``spindlesim run`` does when the deck has no ``analyses`` list: every analysis the deck has the
    sections for (:data:`DEFAULT_RUN`)."""
    d = loaded.deck
    rotor = (d.shaft is not None or d.journal is not None) and d.operating is not None
    if (d.shaft is not None or d.journal is not None) and d.operating is None:
        log.warning("the deck has a rotor but no 'operating' section: the rotor analyses are not run")
    fluid = d.operating is not None and bool(bearing_entries(d, *FLUID_FILM_TYPES))
    spindle = d.operating is not None and d.spindle_thermal is not None
    has = {
        "thermal": fluid or spindle,
        "coefficients": fluid,
        "static": rotor,
        "unbalance": rotor and d.unbalance is not None,
        "transient": (rotor and d.rotor_transient is not None) or d.transient is not None,
        "bearing": d.bearing is not None,
        "dtrb": d.dtrb is not None,
        "contact": d.contact is not None,
        "chatter": d.chatter is not None,
    }
    for names, _ in DEFAULT_RUN:  # an analysis of a row runs with the row's first unless it has its own rule
        for name in names[1:]:
            has.setdefault(name, has[names[0]])
    return [name for names, _ in DEFAULT_RUN for name in names if has[name]]
