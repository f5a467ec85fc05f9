"""What every command shares: deck loading with exit code 2, output directory, progress."""

from __future__ import annotations

import functools
import json
import logging
import sys
from pathlib import Path
from typing import Any, Callable

import click

from .exits import EXIT_DECK_ERROR, exit_code_of

log = logging.getLogger("spindlesim")

#: DECK: any path; what is not a readable YAML file is a located deck error of the loader (exit 2), not click's usage
deck_argument = click.argument("deck", required=False, type=click.Path(path_type=Path))
outdir_option = click.option("-o", "--outdir", type=click.Path(file_okay=False, path_type=Path), default=None,
                             help="Output directory [default: out/<deck stem>].")


def strict_mode() -> bool:
    """``spindlesim --strict``: plausibility warnings are errors (click context, or SPINDLESIM_STRICT=1)."""
    import os

    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.meta.get("spindlesim.strict"):
        return True
    return os.environ.get("SPINDLESIM_STRICT", "") not in ("", "0")


def load_or_default(deck: Path | None, default_name: str):
    """Load DECK, or the embedded default deck; on a bad deck print every issue and exit 2.

    Plausibility warnings are printed (located, on stderr) and the command goes on; with
    ``--strict`` they are errors (exit 2).
    """
    from dataclasses import replace

    from ..deck import DeckError, default_deck, load_deck

    try:
        loaded = load_deck(deck) if deck is not None else default_deck(default_name)
    except DeckError as exc:
        report_deck_error(exc)
    if loaded.warnings and strict_mode():
        report_deck_error(DeckError([replace(w, severity="error") for w in loaded.warnings]),
                          note=" (--strict: plausibility warnings are errors)")
    for w in loaded.warnings:
        click.echo(str(w), err=True)
    return loaded


def unit_hint(loaded) -> str:
    """Appended to a solver failure of a deck with plausibility warnings: they are the likely cause."""
    n = len(loaded.warnings)
    return (f" (the deck has {n} plausibility warning{'s' if n > 1 else ''} above, e.g. a value that looks like "
            "another unit: check them first)") if n else ""


def report_deck_error(exc, note: str = "") -> None:
    """Print every located deck issue and exit with code 2 (with ``--json`` also on stdout as JSON:
    {"errors": [{"file", "line", "column", "key", "message", "severity"}, ...], "exit_code": 2})."""
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.meta.get("spindlesim.report") == "json":
        click.echo(json.dumps({"errors": [{"file": i.file, "line": i.line, "column": i.col, "key": i.path,
                                           "message": i.message, "severity": i.severity} for i in exc.issues],
                               "exit_code": EXIT_DECK_ERROR}))
    for issue in exc.issues:
        click.echo(str(issue), err=True)
    total = getattr(exc, "total", len(exc.issues))
    if total > len(exc.issues):
        click.echo(f"... and {total - len(exc.issues)} more", err=True)
    click.echo(f"spindlesim: {total} error(s) in the deck{note}; nothing was written.", err=True)
    remove_empty_outdirs()
    sys.exit(EXIT_DECK_ERROR)


#: output folders this command made (innermost last): removed again if it ends with nothing written in them
_MADE: list[Path] = []


def remove_empty_outdirs() -> None:
    """The folders this command made that are still empty (a deck error, a failure, a Ctrl-C before any file),
    innermost first: no empty output folder is left behind."""
    for p in reversed(_MADE):
        try:
            p.rmdir()  # only an empty folder goes
        except OSError:
            break
    _MADE.clear()


def resolve_outdir(outdir: Path | None, loaded, sub: str = "") -> Path:
    """The output folder (``-o``, else out/<deck stem>[/sub]; ``loaded``: the deck, or the stem itself), made and
    checked writable before anything is computed: a folder that cannot be written is one line and exit code 2, not
    a failure after the computation."""
    import tempfile

    stem = loaded if isinstance(loaded, str) else loaded.stem
    out = outdir if outdir is not None else Path("out") / stem / sub
    try:
        made = [p for p in (out, *out.parents) if not p.exists()]
        out.mkdir(parents=True, exist_ok=True)
        _MADE.extend(reversed(made))
        with tempfile.TemporaryFile(dir=out):
            pass
    except OSError as exc:
        click.echo(f"spindlesim: cannot write to the output folder {out}: {exc.strerror or exc}; nothing was "
                   "computed (give a writable folder with -o)", err=True)
        sys.exit(EXIT_DECK_ERROR)
    return out


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


def report_options(fn):
    """--quiet / --json on a command: how run_and_report prints the results (stored on the click context)."""

    @click.option("--json", "json_", is_flag=True, help="Print the written paths and the results summary as JSON.")
    @click.option("-q", "--quiet", is_flag=True, help="Print only the written file paths, no results summary.")
    @functools.wraps(fn)
    def wrapper(*args, quiet: bool = False, json_: bool = False, **kwargs):
        click.get_current_context().meta["spindlesim.report"] = "json" if json_ else "quiet" if quiet else "text"
        return fn(*args, **kwargs)

    return wrapper


def summaries_of(items) -> list:
    """[(file name, lines, data)] of runs' results: ``items`` are (``runs.status.Written``, None, or the reason an
    incomplete run's files carry).  A summary that fails is a logged warning: it never hides the results."""
    from ..output.summary import summarize_written

    out = []
    for written, reason in items:
        try:
            out += summarize_written(written, reason)
        except Exception as exc:  # noqa: BLE001 - a summary must never hide the results themselves
            log.warning("results summary of %s unavailable: %s", written.analysis or "the run", exc)
    return out


def print_written(items) -> None:
    """The paths the runs wrote, then the summary of each one's result (``items`` as :func:`summaries_of`'s)."""
    paths = [p for written, _ in items for p in written.paths]
    print_results(paths, summaries_of(items))


def print_results(paths: list[Path], summaries: list | None = None) -> None:
    """The written paths, then a short summary of the key results (or JSON): ``summaries`` [(name, lines, data)]
    built from the results (:func:`summaries_of`); without them, read back from the files (the studies
    ``calibrate`` and ``optimize`` write)."""
    ctx = click.get_current_context(silent=True)
    mode = ctx.meta.get("spindlesim.report", "text") if ctx is not None else "text"
    if mode == "quiet":
        summaries = []
    elif summaries is None:
        from ..output.summary import summarize

        try:
            summaries = summarize(paths)
        except Exception as exc:  # a summary must never hide the results themselves
            log.warning("results summary unavailable: %s", exc)
            summaries = []
    if mode == "json":
        click.echo(json.dumps({"paths": [str(p) for p in paths], "summary": {n: d for n, _, d in summaries}},
                              default=_json_default, allow_nan=True))
        return
    for p in paths:
        click.echo(str(p))
    for name, lines, _ in summaries:
        click.echo(f"\n{name}:")
        for line in lines:
            click.echo(f"  {line}")


def _json_default(v):
    import numpy as np

    if isinstance(v, (np.floating, np.integer, np.bool_)):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    return str(v)


def run_and_report(name: str, deck: Path | None, outdir: Path | None, options: dict) -> None:
    """Load DECK (or the embedded deck the registry names for ``name``), run analysis ``name``, print what
    was written; errors become messages, not tracebacks.

    From the ``spindlesim`` program the figures are drawn in a figure process started here, before
    anything imports numpy (spindlesim/output/drawing.py)."""
    from ..output.drawing import figure_process
    from ..registry import analysis

    with figure_process():
        _run_and_report(name, deck, outdir, analysis(name).deck, options)


def _run_and_report(name: str, deck: Path | None, outdir: Path | None, default_name: str, options: dict) -> None:
    import gc

    from ..runs import perform_analysis, run_info_for

    loaded = load_or_default(deck, default_name)
    gc.freeze()  # the modules imported so far are never garbage: later collections need not walk them
    out = resolve_outdir(outdir, loaded)
    update, close = progress_reporter(name)
    run_command(name, loaded, lambda: perform_analysis(name, loaded, out, options, progress=update,
                                                       run=run_info_for(loaded, " ".join(sys.argv))), close)


def run_command(name: str, loaded, call: Callable[[], Any], close: Callable[[], None]) -> None:
    """``call()`` (a run that writes files and returns a ``runs.status.Written``, or the paths of a study's files),
    then the paths and the summary; how it ended
    becomes an exit code and one line (a deck error, an incomplete or interrupted run, a solver failure)."""
    from ..deck import DeckError
    from ..runs.status import IncompleteRun, Written

    try:
        done = call()
    except DeckError as exc:
        close()
        report_deck_error(exc)
    # --- run status (spindlesim/runs/status.py): incomplete runs and Ctrl-C have their own exit codes ---
    except IncompleteRun as exc:  # the files are written, marked complete = False
        close()
        if exc.result is not None:
            print_written([(exc.written, exc.noted)])
        else:
            print_results(exc.paths)
        code = exit_code_of(exc)
        click.echo(f"spindlesim {name}: {exc.reason}; the files are marked complete = False "
                   f"(exit code {code})", err=True)
        sys.exit(code)
    except KeyboardInterrupt as exc:  # before or after the part of the run that saves what it computed
        close()
        code = exit_code_of(exc)
        click.echo(f"spindlesim {name}: interrupted (exit code {code})", err=True)
        remove_empty_outdirs()
        sys.exit(code)
    # --- end run status ---
    except (ValueError, ArithmeticError, RuntimeError) as exc:  # numpy's LinAlgError is a ValueError
        close()
        located = _located_input_error(name, loaded, exc)
        if located is not None:
            report_deck_error(located)
        fail(f"spindlesim {name}: {exc}{unit_hint(loaded)}", exit_code_of(exc))
    except OSError as exc:  # a file that cannot be written (disk full, a directory in the way, permissions)
        close()
        fail(f"spindlesim {name}: cannot write the results: {exc}", exit_code_of(exc))
    close()
    if isinstance(done, Written):
        print_written([(done, None)])
    else:
        print_results(done)


def _located_input_error(name: str, loaded, exc: BaseException):
    """An input error met while solving that names the deck key holding what to correct (``deck_key``: a rotor not
    held names its bearings): a DeckError located at that key's line, else None."""
    if exit_code_of(exc) != EXIT_DECK_ERROR or not hasattr(loaded, "issue"):
        return None
    seen: BaseException | None = exc
    while seen is not None and getattr(seen, "deck_key", None) is None:
        seen = seen.__cause__
    if seen is None:
        return None
    from ..deck import DeckError

    return DeckError([loaded.issue(tuple(seen.deck_key), f"{name}: {exc}{unit_hint(loaded)}")])


def fail(message: str, code: int) -> None:
    """A run that wrote nothing: the message on stderr (and with ``--json`` as {"error", "exit_code"} on
    stdout), then exit ``code``."""
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.meta.get("spindlesim.report") == "json":
        click.echo(json.dumps({"error": message, "exit_code": code}))
    click.echo(message, err=True)
    remove_empty_outdirs()
    sys.exit(code)


# ----------------------------------------------------------------------------------------------
# commands on measurement files (fitmodes, impact): a FILE instead of a deck


def packaged_inputs(name: str) -> list[Path]:
    """The packaged measurement files command ``name`` runs without FILE (its registry entry's ``input``, a
    glob under spindlesim/decks/)."""
    from importlib import resources

    from ..registry import command_entry

    folder = Path(str(resources.files("spindlesim.decks")))
    return sorted(folder.glob(command_entry(name).input))


def run_measurement(name: str, inputs: list[Path], outdir: Path | None, call: Callable, summarize: Callable) -> None:
    """``call(out, run_info) -> (result, paths)`` on the measurement files ``inputs``, then the paths and
    ``summarize(result, paths) -> (lines, data)``.  A file that cannot be used or measurements that cannot be
    analysed: one line (``path:line: message``), exit 2, nothing written; no result: one line, exit 1."""
    from ..chatter.readers import FrfFileError

    out = None
    try:
        for p in inputs:
            if not p.is_file():
                raise FrfFileError(p, None, "no such file" if not p.exists() else
                                   "a directory, not a file" if p.is_dir() else "not a regular file")
        out = resolve_outdir(outdir, inputs[0].stem)
        from ..runs.common import measurement_run_info

        result, paths = call(out, measurement_run_info(inputs, " ".join(sys.argv)))
    except KeyboardInterrupt as exc:
        code = exit_code_of(exc)
        click.echo(f"spindlesim {name}: interrupted (exit code {code})", err=True)
        remove_empty_outdirs()
        sys.exit(code)
    except FrfFileError as exc:
        fail(f"{exc}; nothing was written", exit_code_of(exc))
    except (ValueError, ArithmeticError, RuntimeError, OSError) as exc:
        where = str(inputs[0]) if len(inputs) == 1 else f"{len(inputs)} files"
        fail(f"spindlesim {name}: {where}: {exc}; nothing was written", exit_code_of(exc))
    lines, data = summarize(result, paths)
    print_results(paths, [(name, lines, data)])
