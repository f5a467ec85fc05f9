"""``spindlesim transient [DECK]``: the rotor in time with its bearings' full nonlinear reactions."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("transient")
@deck_argument
@outdir_option
@report_options
@click.option("--rollers", type=click.IntRange(min=3, max=100), default=None,
              help="Number of rollers of the rig, or of every type: roller bearing of a rotor deck (default: deck).")
@click.option("--duration", "duration_s", type=click.FloatRange(min=0.0, min_open=True), default=None,
              help="Simulated time [s] (default: deck).")
@click.option("--model", type=click.Choice(["flexible_race", "rigid_race"]), default=None,
              help="Roller bearing model (rig or type: roller bearings): seed 000's segmented flexible outer "
                   "race, or the rigid-race 2-DOF model.")
def command(deck, outdir, rollers, duration_s, model):
    """Response history, orbit, spectrum, Poincare maps and bearing outputs in time.

    Without DECK, or with a deck that has the rig section transient: and no shaft: or journal:, a
    rigid journal in a roller bearing (seed 000) is integrated and its centre recorded.  With a rotor deck
    (shaft: or journal:, settings in rotor_transient:), the rotor with every bearing of the deck;
    the response (x, y) is recorded at rotor_transient.record_node, by default at the node of the
    first entry under bearings: (whatever its type).  The spectrum of the steady part (after
    rotor_transient.settle_fraction of the run) is drawn against the linearised natural
    frequencies; Poincare maps once per revolution and once per characteristic period of each
    bearing.  The summary and the figures say when the response has not settled or the steady
    part is too short to resolve the frequencies they name."""
    run_and_report("transient", deck, outdir,
                   {"rollers": rollers, "duration_s": duration_s, "model": model})
