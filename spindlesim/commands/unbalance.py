import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("unbalance")
@deck_argument
@outdir_option
@report_options
def command(deck, outdir):
    """Synchronous unbalance response over the deck's speed range."""
    run_and_report("unbalance", deck, outdir, {})
