"""Command-line interface: a click group whose subcommands are imported only when invoked.

``spindlesim --help`` and ``--version`` never import numpy, scipy, h5py or
matplotlib. Each subcommand lives in ``spindlesim/commands/<name>.py`` as a
click command named ``command``; the registry (spindlesim/registry.py) lists them.
"""

from __future__ import annotations

import importlib
import logging
import os

import click

from . import __version__
from .commands.exits import EXIT_INTERRUPTED
from .registry import commands

#: command -> its line of ``spindlesim --help``; the command is ``spindlesim/commands/<name>.py``
COMMANDS: dict[str, str] = commands()


class LazyGroup(click.Group):
    def list_commands(self, ctx):
        return list(COMMANDS)

    def get_command(self, ctx, name):
        if name not in COMMANDS:
            return None
        module = importlib.import_module(f"spindlesim.commands.{name}")
        cmd = module.command
        if not any(p.name == "strict_here" for p in cmd.params):  # `--strict` after the command too
            cmd.params.append(click.Option(["--strict", "strict_here"], is_flag=True, expose_value=False,
                                           callback=_strict, help="Treat deck plausibility warnings (likely unit "
                                                                  "mistakes) as errors (exit 2)."))
        return cmd

    def invoke(self, ctx):
        """Run the subcommand; a Ctrl-C anywhere in it (its imports and deck loading included, before the
        command's own handler is in place) is exit code 130 with one line, never click's "Aborted!"."""
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt:
            _interrupted()

    def format_commands(self, ctx, formatter):
        rows = list(COMMANDS.items())
        with formatter.section("Commands"):
            formatter.write_dl(rows)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="spindlesim")
@click.option("-v", "--verbose", count=True, help="More log output on stderr (-v info, -vv debug).")
@click.option("--strict", is_flag=True, help="Treat deck plausibility warnings (likely unit mistakes) as errors (exit 2).")
@click.pass_context
def main(ctx: click.Context, verbose: int, strict: bool) -> None:
    """spindlesim: static and dynamic analysis of machine-tool spindles from YAML decks.

    Every subcommand takes an optional DECK (without one, an embedded default
    deck is used) and -o OUTDIR (default out/<deck stem>); fitmodes and impact
    take measurement files instead (without one, a packaged simulated tap test).
    """
    ctx.meta["spindlesim.strict"] = strict  # read by commands.common.load_or_default
    _configure_logging(verbose)
    os.environ.setdefault("MPLBACKEND", "Agg")
    _one_blas_thread()


def _one_blas_thread() -> None:
    """Rotor matrices are small (~100-500 DOF): threaded BLAS only adds overhead (docs/decisions.md), and a
    process forked while BLAS threads exist (a computation set aside, a figure process) can stall in them.  Read
    when numpy is first imported: :func:`console` sets it before click resolves the subcommand (which imports
    the command's module, and numpy with it, before the group's own callback runs)."""
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(var, "1")


def _show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """Python warnings (numpy's "invalid value encountered ...") as one "warning:" line naming where they arose."""
    where = "/".join(str(filename).replace("\\", "/").split("/")[-2:])
    logging.getLogger("spindlesim").warning("%s (%s in %s:%d)", message, category.__name__, where, lineno)


def _strict(ctx: click.Context, _param, value: bool) -> None:
    if value:
        ctx.meta["spindlesim.strict"] = True  # meta is shared by the group's and the command's contexts


class _Formatter(logging.Formatter):
    """``warning: message`` for the user; the logger's name only in debug output (-vv)."""

    def format(self, record: logging.LogRecord) -> str:
        text = super().format(record)
        if record.levelno <= logging.DEBUG:
            return f"debug {record.name}: {text}"
        return f"{record.levelname.lower()}: {text}"


def _configure_logging(verbose: int) -> None:
    """Warnings by default; -v adds spindlesim's info lines, -vv its debug lines.  Other libraries
    (matplotlib, h5py, numba, Dask) stay at warnings: their chatter is not the user's business."""
    root = logging.getLogger()
    if not root.handlers:  # as logging.basicConfig: a host that configured logging (a test runner) keeps its own
        handler = logging.StreamHandler()
        handler.setFormatter(_Formatter("%(message)s"))
        root.addHandler(handler)
        root.setLevel(logging.WARNING)
    logging.getLogger("spindlesim").setLevel(logging.WARNING - 10 * min(verbose, 2))
    import warnings

    warnings.showwarning = _show_warning  # a numpy or scipy warning is one located line, not two raw ones
    if verbose:  # the sweep's Dask cluster follows -v (sweep/execution.py reads this)
        logging.getLogger("distributed").setLevel(logging.INFO if verbose == 1 else logging.DEBUG)


def _interrupted() -> None:
    click.echo(f"spindlesim: interrupted (exit code {EXIT_INTERRUPTED})", err=True)
    raise SystemExit(EXIT_INTERRUPTED)


def console() -> None:
    """The ``spindlesim`` program: :func:`main` with figures drawn in a figure process
    (spindlesim/output/drawing.py) and no final garbage collection.

    At exit the interpreter's last collection walks every object of numpy, scipy, matplotlib and
    pydantic (about 0.15 s) to free memory the operating system takes back anyway; the objects are
    frozen instead.  Files are closed by then (every writer closes its own, and the figure process
    has been waited for)."""
    import gc

    _one_blas_thread()
    try:
        from .output import drawing

        drawing.allow()
        main(prog_name="spindlesim")
    except KeyboardInterrupt:  # before the group runs (imports at start-up)
        _interrupted()
    finally:
        gc.freeze()
