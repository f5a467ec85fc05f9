"""``spindlesim tools [DECK]``: the deck's tool library coupled onto its spindle (receptance coupling)."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("tools")
@deck_argument
@outdir_option
@report_options
@click.option("--speed", "speed_rpm", type=click.FloatRange(min=0.0), default=None,
              help="Spin speed [rpm], >= 0 (default: the deck's operating speed).")
@click.option("--no-lobes", is_flag=True, help="The tip receptances only, not each tool's lobes (a deck with a "
              "chatter section computes them by default).")
def command(deck, outdir, speed_rpm, no_lobes):
    """Each tool of the deck's 'tools' list on the spindle: its tip receptance from the spindle's receptances at the
    nose (computed once per speed and static state, rotations included) and the tool's own (Timoshenko beam with
    its gyroscopic terms, its joints), coupled by RCSA; with a 'chatter' section each tool's lobes, minimum and
    recommended speed.  The bearings sit at the spindle's thermal equilibrium when the deck has a
    spindle_thermal section."""
    run_and_report("tools", deck, outdir, {"speed_rpm": speed_rpm, "lobes": not no_lobes})
