import sys

import click

from ..registry import default_decks, default_rows
from .common import deck_argument, load_or_default, outdir_option, report_options, resolve_outdir


def _help() -> str:
    """The command's help; its table of what runs without an ``analyses`` list is the registry's."""
    rows = [(", ".join(names), needs) for names, needs in default_rows()]
    width = max(len(names) for names, _ in rows) + 3
    return _HELP.format(rows="\n".join(f"  {names.ljust(width)}{needs}" for names, needs in rows))


_HELP = """The analyses the deck lists under 'analyses', in that order; without that list, every analysis the
deck has the sections for, in this order:

\b
{rows}

A sweep section is run by `spindlesim sweep`, not here; a deck with nothing to run is a deck error.
Without DECK: the embedded deck 'spindle' (`spindlesim decks`).

Prints the written paths and a short summary of each file's key results, and writes report.html
into the output folder: one self-contained page (figures embedded) with the provenance, each
analysis's key results and figures, failures and warnings, to open in a browser or print.
Exit codes: 0 every analysis finished, 1 one failed (the others still run), 2 deck error, 3 one
ran but is incomplete (its files are marked complete = False), 130 interrupted (Ctrl-C: the
analyses not yet started are not run)."""


@click.command("run", help=_help())
@deck_argument
@outdir_option
@report_options
@click.option("--no-report", is_flag=True, help="Do not write report.html (the HDF5 and PNG files only).")
def command(deck, outdir, no_report):
    from ..output.drawing import figure_process

    with figure_process():  # before numpy is imported (spindlesim/output/drawing.py)
        _run(deck, outdir, report=not no_report)


def _run(deck, outdir, report: bool = True) -> None:
    from ..runs import default_analyses, perform_analysis, run_info_for
    from ..runs.status import IncompleteRun
    from ..deck import DeckError
    from ..output.report import RunReport
    from .common import print_results, report_deck_error, summaries_of, unit_hint
    from .exits import outcome_code

    loaded = load_or_default(deck, default_decks()["run"])
    names = loaded.deck.analyses or default_analyses(loaded)
    if not names:
        from ..deck.errors import DeckIssue

        report_deck_error(DeckError([DeckIssue(loaded.source, 1, 1, "analyses", "nothing to run: the deck lists no "
                                               "analyses and has none of the sections an analysis runs on (see "
                                               "`spindlesim run --help`)")]))
    out = resolve_outdir(outdir, loaded)
    info = run_info_for(loaded, " ".join(sys.argv))
    written, failed, incomplete = [], [], []
    results: list = []  # (Written, None or the reason an incomplete run's files carry): the summaries
    from ..runs.common import RunContext

    shared = RunContext(loaded)  # one assembly, each operating point and the thermal speed limit solved once
    with RunReport(loaded, info, out, names) as book:  # collects the warnings logged meanwhile
        for name in names:
            try:
                done = perform_analysis(name, shared, out, {}, run=info)
                written += done.paths
                results.append((done, None))
                book.done(name, done.paths, done)
            except DeckError as exc:
                report_deck_error(exc)
            except IncompleteRun as exc:  # written, marked complete = False
                written += exc.paths
                results.append((exc.written, exc.noted))
                book.incomplete(name, exc.paths, exc.reason, exc.written, exc.noted)
                click.echo(f"spindlesim run: {name}: {exc.reason}; its files are marked complete = False", err=True)
                if exc.interrupted:
                    _stop(names, name, written, results, book if report else None)
                incomplete.append(name)
            except KeyboardInterrupt:
                book.interrupted(name)
                _stop(names, name, written, results, book if report else None)
            except (ValueError, ArithmeticError, RuntimeError, OSError) as exc:  # LinAlgError is a ValueError
                click.echo(f"spindlesim run: {name} failed: {exc}{unit_hint(loaded)}", err=True)
                book.failed(name, exc)
                failed.append(name)
    if report:
        _studies_written(loaded, out, book)
    if report and not _write_report(book, written):
        failed.append("report")
    print_results(written, summaries_of(results))
    code = outcome_code(failed=bool(failed), incomplete=bool(incomplete))
    if failed:
        click.echo(f"spindlesim run: failed: {', '.join(failed)} (exit code {code})", err=True)
    elif incomplete:
        click.echo(f"spindlesim run: incomplete: {', '.join(incomplete)} (exit code {code})", err=True)
    if code:
        sys.exit(code)


def _stop(names: list, name: str, written: list, results: list, book=None) -> None:
    """Ctrl-C: the analyses after ``name`` are not started; the report says so; what was written is
    listed; exit code 130."""
    from ..sweep.execution import sigint_ignored
    from .common import print_results, summaries_of
    from .exits import outcome_code

    rest = names[names.index(name) + 1:]
    code = outcome_code(interrupted=True)
    click.echo(f"spindlesim run: interrupted during {name}" + (f"; not run: {', '.join(rest)}" if rest else "")
               + f" (exit code {code})", err=True)
    with sigint_ignored():
        if book is not None:
            _write_report(book, written)
        print_results(written, summaries_of(results))
    sys.exit(code)


def _write_report(book, written: list) -> bool:
    """Write report.html and add it to ``written``; a report that cannot be written is one line on
    stderr (the results themselves are on disk) and False."""
    try:
        written.append(book.write())
    except Exception as exc:  # noqa: BLE001 - the report must never hide the results
        click.echo(f"spindlesim run: report.html not written: {type(exc).__name__}: {exc}", err=True)
        return False
    return True


def _studies_written(loaded, out, book) -> None:
    """A deck with a ``calibration:`` or ``optimize:`` section: the study `spindlesim calibrate` or `spindlesim
    optimize` wrote with its default folder (calibration.h5 beside the run's files, ``optimize/`` below them) joins
    the report; `run` runs neither."""
    from pathlib import Path

    from ..sweep.optimize_run import written_study

    for section, folder, stem in (("calibration", Path(out), "calibration"),
                                  ("optimize", Path(out) / "optimize", "optimize")):
        if getattr(loaded.deck, section, None) is None:
            continue
        found = written_study(folder, stem)
        if found is None:
            continue
        paths, reason = found
        book.names.append(stem)
        if reason:
            book.incomplete(stem, paths, reason)
        else:
            book.done(stem, paths)
