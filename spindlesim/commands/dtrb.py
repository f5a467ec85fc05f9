"""``spindlesim dtrb [DECK]``: quasi-static double-row tapered roller bearing (slices, rib contact, 5 DOF)."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("dtrb")
@deck_argument
@outdir_option
@report_options
@click.option("--preload", "preload_um", type=click.FloatRange(min=0.0), default=None,
              help="Axial preload delta0 per row [um] (default: deck).")
@click.option("--speed", "speed_rpm", type=click.FloatRange(min=0.0), default=None,
              help="Inner-ring speed [rpm] (default: deck).")
@click.option("--no-sweeps", is_flag=True, default=False, help="Skip the preload and radial-load sweeps.")
def command(deck, outdir, preload_um, speed_rpm, no_sweeps):
    """Load distribution per row, reactions, 5x5 stiffness; stiffness against preload and radial load."""
    run_and_report("dtrb", deck, outdir,
                   {"preload_um": preload_um, "speed_rpm": speed_rpm, "sweeps": not no_sweeps})
