import sys

import click

from .common import deck_argument, load_or_default, outdir_option, resolve_outdir


@click.command("run")
@deck_argument
@outdir_option
def command(deck, outdir):
    """Every analysis the deck lists (key 'analyses'), or static, modal, campbell, frf (and unbalance)."""
    import numpy as np

    from ..runs import default_analyses, run_analysis, run_info_for
    from ..runs.status import EXIT_FAILED, EXIT_INCOMPLETE, IncompleteRun
    from ..deck import DeckError
    from .common import report_deck_error

    loaded = load_or_default(deck, "spindle")
    out = resolve_outdir(outdir, loaded)
    names = loaded.deck.analyses or default_analyses(loaded)
    failed, incomplete = [], []
    for name in names:
        try:
            for p in run_analysis(name, loaded, out, {}, run=run_info_for(loaded, " ".join(sys.argv))):
                click.echo(str(p))
        except DeckError as exc:
            report_deck_error(exc)
        except IncompleteRun as exc:  # written, marked complete = False
            for p in exc.paths:
                click.echo(str(p))
            click.echo(f"spindlesim run: {name}: {exc.reason}", err=True)
            if exc.interrupted:
                _stop(names, name)
            incomplete.append(name)
        except KeyboardInterrupt:
            _stop(names, name)
        except (ValueError, ArithmeticError, RuntimeError, np.linalg.LinAlgError) as exc:
            click.echo(f"spindlesim run: {name} failed: {exc}", err=True)
            failed.append(name)
    if failed:
        sys.exit(EXIT_FAILED)
    if incomplete:
        sys.exit(EXIT_INCOMPLETE)


def _stop(names: list, name: str) -> None:
    """Ctrl-C: the analyses after ``name`` are not started; exit code 130."""
    from ..runs.status import EXIT_INTERRUPTED

    rest = names[names.index(name) + 1:]
    click.echo(f"spindlesim run: interrupted during {name}" + (f"; not run: {', '.join(rest)}" if rest else ""),
               err=True)
    sys.exit(EXIT_INTERRUPTED)
