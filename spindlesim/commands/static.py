import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("static")
@deck_argument
@outdir_option
@report_options
@click.option("--speed", "speed_rpm", type=click.FloatRange(min=0.0), default=None,
              help="Spin speed [rpm], >= 0 (default: deck).")
def command(deck, outdir, speed_rpm):
    """Static deflection K^-1 Q, slopes, bearing reactions and static stiffness."""
    run_and_report("static", deck, outdir, {"speed_rpm": speed_rpm})
