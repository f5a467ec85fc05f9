import click
import numpy as np

from .common import deck_argument, outdir_option, run_and_report, report_options


def _speeds(ctx, param, value):
    if value is None:
        return None
    try:
        a, b, n = value.split(":")
        a, b, n = float(a), float(b), int(n)
    except ValueError:
        raise click.BadParameter("expected START:STOP:COUNT in rpm, e.g. 0:12000:50") from None
    if n < 2 or b <= a or a < 0:
        raise click.BadParameter("need 0 <= START < STOP and COUNT >= 2")
    return np.linspace(a, b, n)


@click.command("campbell")
@deck_argument
@outdir_option
@report_options
@click.option("--speeds", callback=_speeds, default=None, metavar="START:STOP:COUNT",
              help="Speed range in rpm (default: deck campbell.speeds_rpm).")
@click.option("--modes", type=click.IntRange(min=1), default=None, help="Modes to track.")
@click.option("--exact", is_flag=True, help="Solve the full state-space model at every speed instead of the "
              "reduced model (the reduced one is checked against it at the first and last speed).")
def command(deck, outdir, speeds, modes, exact):
    """Campbell diagram: tracked modes, log decrement and critical speeds over a speed range."""
    run_and_report("campbell", deck, outdir, {"speeds_rpm": speeds, "modes": modes, "exact": exact})
