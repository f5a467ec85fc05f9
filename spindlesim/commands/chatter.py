"""``spindlesim chatter [DECK]``: stability lobes of turning, boring, grinding or milling."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("chatter")
@deck_argument
@outdir_option
@report_options
@click.option("--simulate", nargs=2, type=click.FloatRange(min=0, min_open=True), multiple=True,
              metavar="SPEED_RPM DEPTH_MM",
              help="Also integrate the cut in time at this speed and axial depth (repeatable): stable or "
                   "chatter, the vibration spectrum and a Poincare section once per tooth period.")
@click.option("--exact", is_flag=True, help="Tool-point FRF at every speed from the full rotor model, not the "
              "reduced one (which is checked against it at the first and last speed).")
@click.option("--map", "stability_map", is_flag=True,
              help="Also the semi-discretization's stability map (spectral radius over speed and depth; about "
                   "three times the evaluations of the lobes alone).")
def command(deck, outdir, simulate, exact, stability_map):
    """Stability lobe diagram (limit depth of cut against spindle speed) from the deck's 'chatter' section: the
    tool-point FRF from the rotor (at the deck speed or at every speed), tap-test modes or measured FRF files;
    Tlusty's oriented FRF (turning, boring, grinding), Altintas-Budak zero order or semi-discretization (milling)."""
    run_and_report("chatter", deck, outdir, {"simulate": simulate, "exact": exact, "map": stability_map})
