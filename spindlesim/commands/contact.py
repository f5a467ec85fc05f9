"""``spindlesim contact [DECK]``: contact pressure of a roller (or ball) on a raceway."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("contact")
@deck_argument
@outdir_option
@report_options
@click.option("--load", "load_N", type=click.FloatRange(min=0.0, min_open=True), default=None,
              help="Roller load [N] (default: deck).")
@click.option("--tilt", "tilt_deg", type=float, default=None, help="Roller tilt [deg] (default: deck).")
@click.option("--nx", type=click.IntRange(min=8), default=None, help="Cells across the contact.")
@click.option("--ny", type=click.IntRange(min=8), default=None, help="Cells along the roller.")
def command(deck, outdir, load_N, tilt_deg, nx, ny):
    """Half-space contact pressure (DC-FFT + conjugate gradients): map, centre-line, half-width."""
    run_and_report("contact", deck, outdir,
                   {"load_N": load_N, "tilt_deg": tilt_deg, "nx": nx, "ny": ny})
