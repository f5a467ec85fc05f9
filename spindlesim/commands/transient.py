"""``spindlesim transient [DECK]``: rotor in a roller bearing, time integration (issue 4)."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("transient")
@deck_argument
@outdir_option
@report_options
@click.option("--rollers", type=click.IntRange(min=3, max=100), default=None, help="Number of rollers (default: deck).")
@click.option("--duration", "duration_s", type=click.FloatRange(min=0.0, min_open=True), default=None,
              help="Simulated time [s] (default: deck).")
@click.option("--model", type=click.Choice(["flexible_race", "rigid_race"]), default=None,
              help="Segmented flexible outer race (seed 000) or the rigid-race 2-DOF model.")
def command(deck, outdir, rollers, duration_s, model):
    """Shaft-centre history, orbit, spectrum, Poincare map, roller loads, race deflection.

    With a rotor deck whose bearings include a nonlinear one (type: dtrb), the FE rotor is
    integrated instead (seed 001): response at the DTRB node, spectrum against the linearised
    natural frequencies, Poincare map once per revolution."""
    run_and_report("transient", deck, outdir, "transient",
                   {"rollers": rollers, "duration_s": duration_s, "model": model})
