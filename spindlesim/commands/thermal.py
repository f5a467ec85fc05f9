"""``spindlesim thermal [DECK]``: thermal equilibrium of the fluid-film bearings."""

import click

from .common import deck_argument, outdir_option, run_and_report


@click.command("thermal")
@deck_argument
@outdir_option
@click.option("--speed", "speed_rpm", type=float, default=None, help="Spin speed [rpm] (default: deck).")
def command(deck, outdir, speed_rpm):
    """Thermal equilibrium (seed 003 eqs. 4-14) of every three_lobe/plain bearing: thermal.h5."""
    run_and_report("thermal", deck, outdir, "spindle", {"speed_rpm": speed_rpm})
