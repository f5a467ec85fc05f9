import click

from .common import deck_argument, outdir_option, run_and_report


@click.command("unbalance")
@deck_argument
@outdir_option
def command(deck, outdir):
    """Synchronous unbalance response over the deck's speed range."""
    run_and_report("unbalance", deck, outdir, "spindle", {})
