import click

from .common import deck_argument, outdir_option, run_and_report, report_options


@click.command("modal")
@deck_argument
@outdir_option
@report_options
@click.option("--speed", "speed_rpm", type=click.FloatRange(min=0.0), default=None,
              help="Spin speed [rpm], >= 0 (default: deck).")
@click.option("--modes", type=click.IntRange(min=1), default=None, help="Number of modes (default: deck, 8).")
def command(deck, outdir, speed_rpm, modes):
    """Damped modes from the state-space eigenproblem (QR): frequency, damping, whirl, shapes."""
    run_and_report("modal", deck, outdir, {"speed_rpm": speed_rpm, "modes": modes})
