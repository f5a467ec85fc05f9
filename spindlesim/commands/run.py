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
    from ..deck import DeckError
    from .common import report_deck_error

    loaded = load_or_default(deck, "spindle")
    out = resolve_outdir(outdir, loaded)
    names = loaded.deck.analyses or default_analyses(loaded)
    failed = []
    for name in names:
        try:
            for p in run_analysis(name, loaded, out, {}, run=run_info_for(loaded, " ".join(sys.argv))):
                click.echo(str(p))
        except DeckError as exc:
            report_deck_error(exc)
        except (ValueError, ArithmeticError, RuntimeError, np.linalg.LinAlgError) as exc:
            click.echo(f"spindlesim run: {name} failed: {exc}", err=True)
            failed.append(name)
    if failed:
        sys.exit(1)
