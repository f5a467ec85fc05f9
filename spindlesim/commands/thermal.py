"""``spindlesim thermal [DECK]``: thermal equilibrium of the fluid-film bearings, or of the spindle's thermal model
(the ``spindle_thermal`` analysis) on a deck with a ``spindle_thermal:`` section (runs.analysis_for)."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("thermal")
@deck_argument
@outdir_option
@report_options
@click.option("--speed", "speed_rpm", type=click.FloatRange(min=0.0), default=None,
              help="Spin speed [rpm], >= 0 (default: deck).")
def command(deck, outdir, speed_rpm):
    """Thermal equilibrium of every three_lobe/plain bearing (heat generated in the film = heat carried by the
    oil + heat through the housing; the effective viscosity at the mean film temperature), or, on a deck with a
    spindle_thermal section, of the spindle's thermal model at its speeds (heat, temperatures, preload, tool-tip
    drift, the thermal speed limit; the warm-up): thermal.h5."""
    run_and_report("thermal", deck, outdir, {"speed_rpm": speed_rpm})
