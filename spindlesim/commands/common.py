"""What every command shares: deck loading with exit code 2, output directory, progress."""

from __future__ import annotations

import logging
import sys
from pathlib import Path
from typing import Callable

import click
import numpy as np

log = logging.getLogger("spindlesim")

deck_argument = click.argument("deck", required=False, type=click.Path(dir_okay=False, path_type=Path))
outdir_option = click.option("-o", "--outdir", type=click.Path(file_okay=False, path_type=Path), default=None,
                             help="Output directory [default: out/<deck stem>].")


def load_or_default(deck: Path | None, default_name: str):
    """Load DECK, or the embedded default deck; on a bad deck print every issue and exit 2."""
    from ..deck import DeckError, default_deck, load_deck

    try:
        return load_deck(deck) if deck is not None else default_deck(default_name)
    except DeckError as exc:
        report_deck_error(exc)


def report_deck_error(exc) -> None:
    """Print every located deck issue and exit with code 2."""
    for issue in exc.issues:
        click.echo(str(issue), err=True)
    click.echo(f"spindlesim: {len(exc.issues)} error(s) in the deck; nothing was written.", err=True)
    sys.exit(2)


def resolve_outdir(outdir: Path | None, loaded) -> Path:
    return outdir if outdir is not None else Path("out") / loaded.stem


def progress_reporter(label: str) -> tuple[Callable[[int, int], None], Callable[[], None]]:
    """A progress callback: a bar on a terminal, periodic log lines otherwise (stderr)."""
    state: dict = {}
    tty = sys.stderr.isatty()

    def update(done: int, total: int) -> None:
        if tty:
            if "bar" not in state:
                state["bar"] = click.progressbar(length=total, label=label, file=sys.stderr)
                state["bar"].__enter__()
            state["bar"].update(done - state.get("done", 0))
        elif done == total or done % max(1, total // 10) == 0:
            click.echo(f"{label}: {done}/{total}", err=True)
        state["done"] = done

    def close() -> None:
        if "bar" in state:
            state["bar"].__exit__(None, None, None)

    return update, close


def run_and_report(name: str, deck: Path | None, outdir: Path | None, default_name: str, options: dict) -> None:
    """Load, run analysis ``name``, print what was written; errors become messages, not tracebacks."""
    from ..runs import run_analysis, run_info_for
    from ..deck import DeckError

    loaded = load_or_default(deck, default_name)
    out = resolve_outdir(outdir, loaded)
    update, close = progress_reporter(name)
    try:
        paths = run_analysis(name, loaded, out, options, progress=update, run=run_info_for(loaded, " ".join(sys.argv)))
    except DeckError as exc:
        close()
        report_deck_error(exc)
    except (ValueError, ArithmeticError, RuntimeError, np.linalg.LinAlgError) as exc:
        close()
        click.echo(f"spindlesim {name}: {exc}", err=True)
        sys.exit(1)
    close()
    for p in paths:
        click.echo(str(p))
