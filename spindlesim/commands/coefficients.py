"""``spindlesim coefficients [DECK]``: fluid-film bearing stiffness and damping."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("coefficients")
@deck_argument
@outdir_option
@report_options
@click.option("--speed", "speed_rpm", type=click.FloatRange(min=0.0), default=None,
              help="Spin speed [rpm], >= 0 (default: deck).")
def command(deck, outdir, speed_rpm):
    """Eight K/C coefficients at the thermal equilibrium of every three_lobe/plain bearing."""
    run_and_report("coefficients", deck, outdir, {"speed_rpm": speed_rpm})
