"""Command-line interface: a click group whose subcommands are imported only when invoked.

``spindlesim --help`` and ``--version`` never import numpy, scipy, h5py or
matplotlib. Each subcommand lives in ``spindlesim/commands/<name>.py`` as a
click command named ``command``; add it to ``COMMANDS`` below.
"""

from __future__ import annotations

import importlib
import logging
import os

import click

from . import __version__

COMMANDS: dict[str, tuple[str, str]] = {
    "static": ("static", "Static deflection K^-1 Q, bearing reactions, static stiffness."),
    "modal": ("modal", "Damped modes (state-space QR): frequencies, damping, whirl, shapes."),
    "campbell": ("campbell", "Campbell diagram with tracked modes and critical speeds."),
    "frf": ("frf", "Complex frequency response (receptance) between two DOFs."),
    "unbalance": ("unbalance", "Synchronous unbalance response over speed."),
    "thermal": ("thermal", "Thermal equilibrium of fluid-film bearings (seed 003 eqs. 4-14)."),
    "coefficients": ("coefficients", "Fluid-film bearing stiffness and damping at thermal equilibrium."),
    "transient": ("transient", "Time simulation: rotor in a roller bearing (seed 000) or a rotor on a DTRB (seed 001)."),
    "dtrb": ("dtrb", "Double-row tapered roller bearing: load distribution, 5x5 stiffness, preload/load sweeps."),
    "contact": ("contact", "Roller/ball contact pressure on a raceway (half-space, DC-FFT + CGM)."),
    "run": ("run", "Every analysis the deck lists."),
    "sweep": ("sweep", "Parameter study over any deck value (process pool or Dask), resumable."),
}


class LazyGroup(click.Group):
    def list_commands(self, ctx):
        return list(COMMANDS)

    def get_command(self, ctx, name):
        if name not in COMMANDS:
            return None
        module = importlib.import_module(f"spindlesim.commands.{COMMANDS[name][0]}")
        return module.command

    def format_commands(self, ctx, formatter):
        rows = [(name, help_) for name, (_, help_) in COMMANDS.items()]
        with formatter.section("Commands"):
            formatter.write_dl(rows)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="spindlesim")
@click.option("-v", "--verbose", count=True, help="More log output on stderr (-v info, -vv debug).")
def main(verbose: int) -> None:
    """spindlesim: static and dynamic analysis of machine-tool spindles from YAML decks.

    Every subcommand takes an optional DECK (without one, an embedded default
    deck is used) and -o OUTDIR (default out/<deck stem>).
    """
    level = logging.WARNING - 10 * min(verbose, 2)
    logging.basicConfig(level=level, format="%(levelname)s %(name)s: %(message)s")
    os.environ.setdefault("MPLBACKEND", "Agg")
    # Rotor matrices are small (~100-500 DOF): threaded BLAS only adds overhead (docs/decisions.md).
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(var, "1")
