"""A parameter study as ``spindlesim sweep`` runs it: the swept values (the deck's ``sweep:`` section and
``--set`` overrides), every case's deck checked before any case runs, the cases run (resuming), then
sweep.h5, its plots and the results table, with a Ctrl-C held back until they are out."""

from __future__ import annotations

import logging
from collections import Counter
from pathlib import Path
from typing import Any, Callable, Iterable

from .cases import Case, parse_set_option, parse_values
from .runner import SweepResult

#: (written paths, table lines, table data) -> None: prints what a study wrote and its table
Show = Callable[[list, list, dict], None]


def study_parameters(section: Any, sets: Iterable[str]) -> dict[str, list]:
    """The values of every swept deck path: the deck's ``sweep.parameters`` (``section``: the deck's ``sweep:``
    section or None), then each ``PATH=VALUES`` of ``sets``, which replaces the deck's values of its path.
    ValueError: a ``PATH=VALUES`` that cannot be read."""
    params: dict = {}
    if section is not None:
        for path, spec in section.parameters.items():
            params[path] = list(spec) if isinstance(spec, list) else parse_values(f"{spec.start}:{spec.stop}:{spec.count}")
    for s in sets:
        path, values = parse_set_option(s)
        params[path] = values
    return params


def case_deck_issues(loaded: Any, cases: list[Case]) -> list:
    """The issues of every case's deck (each case's deck is validated before any case runs)."""
    from ..deck import DeckError, parse_deck

    bad = []
    for c in cases:
        try:
            parse_deck(c.deck_text, f"{loaded.source} [case {c.index}: {c.parameters}]")
        except DeckError as exc:
            bad.extend(exc.issues)
    return bad


def run_study(loaded: Any, cases: list[Case], analysis: str, out: Path, *, workers: int | None = None,
              scheduler: str | None = None, progress: Callable | None = None, command_line: str = "",
              show: Show | None = None) -> tuple[SweepResult, Any]:
    """Run ``cases`` into ``out`` (finished cases are skipped), then write sweep.h5, the scalar and overlay
    PNGs and the results table, and hand them to ``show``.  A Ctrl-C while the cases run stops them
    (the result is marked interrupted); a Ctrl-C after that waits until sweep.h5, its plots and ``show``
    are done.  Returns the result and what that wait saw (``late.interrupted``: a Ctrl-C during it)."""
    from ..runs import run_info_for
    from . import report
    from .execution import sigint_deferred, sigint_ignored
    from .runner import SweepInterrupted, run_sweep

    try:
        res = run_sweep(cases, out, workers=workers, scheduler=scheduler, progress=progress)
    except SweepInterrupted as exc:
        res = exc.result
    # every case is recorded: a Ctrl-C now waits until sweep.h5, its plots and the table are out
    with sigint_ignored() if res.interrupted else sigint_deferred() as late:
        run = run_info_for(loaded, command_line)
        title = f"{loaded.deck.title}\n{_operating_text(loaded.deck)}{len(cases)} cases of {analysis}"
        paths = [report.write_summary(res, run, analysis),
                 report.plot_scalars(res, out / "sweep_scalars.png", title=title),
                 report.plot_overlay(res, analysis, out / f"sweep_{analysis}_overlay.png", title=title)]
        try:
            lines, data = report.summary_table(res, max_scalars=4)
        except Exception as exc:  # a summary must never hide the results themselves
            logging.getLogger("spindlesim").warning("sweep results table unavailable: %s", exc)
            lines, data = [], {}
        if show is not None:
            show([p for p in paths if p is not None], lines, data)
    return res, late


def outcome_lines(res: SweepResult) -> list[str]:
    """How many cases ran and were skipped, and each case that failed or is incomplete with its first error line."""
    not_done = [r for r in res.records if r.get("status") != "done"]
    counts = ", ".join(f"{n} {s}" for s, n in Counter(r.get("status") for r in not_done).items())
    lines = [f"sweep: {len(res.ran)} run, {len(res.skipped)} already finished"
             + (f", not done: {counts}" if counts else ", 0 failed")]
    for r in not_done:
        if r.get("status") in ("failed", "incomplete"):
            lines.append(f"  case {r.get('index')} {r.get('parameters')}: {r.get('error', '').splitlines()[0]}")
    return lines


def _operating_text(deck) -> str:
    """The deck's operating point (speed, load, oil temperature) for the summary titles, or ""."""
    from ..deck.describe import operating_text

    rig = getattr(deck, "transient", None)
    speed = deck.operating.speed_rpm if deck.operating is not None else getattr(rig, "speed_rpm", None)
    text = ", ".join(p for p in (f"{speed:g} rpm" if speed is not None else "", operating_text(deck)) if p)
    return f"base deck {text}; " if text else ""
