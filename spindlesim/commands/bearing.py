"""``spindlesim bearing [DECK]``: one bearing (set) under a load: stiffness, ball loads, contact angles, life."""

import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("bearing")
@deck_argument
@outdir_option
@report_options
def command(deck, outdir):
    """Angular-contact / deep-groove ball bearing or set (deck section 'bearing', type: ball): 5x5 stiffness,
    ball loads and contact angles, contact pressures, ISO 281 / ISO/TS 16281 life, sweeps over preload, load
    and speed.  A deck with a 'dtrb' section runs the double-row tapered roller bearing instead."""
    run_and_report("bearing", deck, outdir, {})
