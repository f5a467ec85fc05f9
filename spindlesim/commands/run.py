import sys

import click

from .common import deck_argument, load_or_default, outdir_option, report_options, resolve_outdir


@click.command("run")
@deck_argument
@outdir_option
@report_options
def command(deck, outdir):
    """The analyses the deck lists under 'analyses', in that order; without that list, every analysis the
    deck has the sections for, in this order:

    \b
      thermal, coefficients          fluid-film bearings (type three_lobe or plain) and operating
      static, modal, campbell, frf   a rotor (shaft or journal) and operating
      unbalance                      a rotor, operating and an unbalance section
      transient                      a rotor, operating and a rotor_transient section; or a transient section
      bearing                        a bearing section
      dtrb                           a dtrb section
      contact                        a contact section
      chatter                        a chatter section

    A sweep section is run by `spindlesim sweep`, not here; a deck with nothing to run is a deck error.
    Without DECK: the embedded deck 'spindle' (`spindlesim decks`).

    Prints the written paths and a short summary of each file's key results.  Exit codes: 0 every
    analysis finished, 1 one failed (the others still run), 2 deck error, 3 one ran but is
    incomplete (its files are marked complete = False), 130 interrupted (Ctrl-C: the analyses
    not yet started are not run)."""
    from ..output.drawing import figure_process

    with figure_process():  # before numpy is imported (spindlesim/output/drawing.py)
        _run(deck, outdir)


def _run(deck, outdir) -> None:
    from ..runs import default_analyses, run_analysis, run_info_for
    from ..runs.status import EXIT_FAILED, EXIT_INCOMPLETE, IncompleteRun
    from ..deck import DeckError
    from .common import print_results, report_deck_error

    loaded = load_or_default(deck, "spindle")
    out = resolve_outdir(outdir, loaded)
    names = loaded.deck.analyses or default_analyses(loaded)
    if not names:
        from ..deck.errors import DeckIssue

        report_deck_error(DeckError([DeckIssue(loaded.source, 1, 1, "analyses", "nothing to run: the deck lists no "
                                               "analyses and has none of the sections an analysis runs on (see "
                                               "`spindlesim run --help`)")]))
    written, failed, incomplete = [], [], []
    for name in names:
        try:
            written += run_analysis(name, loaded, out, {}, run=run_info_for(loaded, " ".join(sys.argv)))
        except DeckError as exc:
            report_deck_error(exc)
        except IncompleteRun as exc:  # written, marked complete = False
            written += exc.paths
            click.echo(f"spindlesim run: {name}: {exc.reason}; its files are marked complete = False", err=True)
            if exc.interrupted:
                _stop(names, name, written)
            incomplete.append(name)
        except KeyboardInterrupt:
            _stop(names, name, written)
        except (ValueError, ArithmeticError, RuntimeError, OSError) as exc:  # LinAlgError is a ValueError
            click.echo(f"spindlesim run: {name} failed: {exc}", err=True)
            failed.append(name)
    print_results(written)
    if failed:
        click.echo(f"spindlesim run: failed: {', '.join(failed)} (exit code {EXIT_FAILED})", err=True)
        sys.exit(EXIT_FAILED)
    if incomplete:
        click.echo(f"spindlesim run: incomplete: {', '.join(incomplete)} (exit code {EXIT_INCOMPLETE})", err=True)
        sys.exit(EXIT_INCOMPLETE)


def _stop(names: list, name: str, written: list) -> None:
    """Ctrl-C: the analyses after ``name`` are not started; what was written is listed; exit code 130."""
    from ..runs.status import EXIT_INTERRUPTED
    from ..sweep.execution import sigint_ignored
    from .common import print_results

    rest = names[names.index(name) + 1:]
    click.echo(f"spindlesim run: interrupted during {name}" + (f"; not run: {', '.join(rest)}" if rest else "")
               + f" (exit code {EXIT_INTERRUPTED})", err=True)
    with sigint_ignored():
        print_results(written)
    sys.exit(EXIT_INTERRUPTED)
