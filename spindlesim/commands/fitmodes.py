"""``spindlesim fitmodes [FILE]``: the modes of a measured FRF file (LSCF/LSFD of sdypy-EMA with a stabilisation
diagram) in the chatter section's modal form: fitmodes.h5, modes.yaml, two figures."""

from pathlib import Path

import click

from .common import outdir_option, report_options


def _band(ctx, param, value):
    if value is None:
        return None
    try:
        lo, hi = (float(v) for v in value.split(":"))
    except ValueError:
        raise click.BadParameter(f"{value!r}: give LO:HI in Hz, e.g. 400:3000") from None
    if not 0 <= lo < hi:
        raise click.BadParameter(f"{value!r}: needs 0 <= LO < HI")
    return lo, hi


@click.command("fitmodes")
@click.argument("file", required=False, type=click.Path(path_type=Path))  # a directory: one located line
@click.option("--direction", type=click.Choice(["x", "y"]), default=None,
              help="The direction of a single-direction CSV file (default x), or the one term fitted of a file with "
                   "both [default: every direct term].")
@click.option("--band", "band_hz", callback=_band, metavar="LO:HI",
              help="Frequency band fitted [Hz] [default: where the coherence is 0.9 or more, else the whole file].")
@click.option("--max-order", type=click.IntRange(6, 200), default=40, show_default=True,
              help="The LSCF model orders are 2, 4, ..., 2 x MAX_ORDER.")
@outdir_option
@report_options
def command(file, direction, band_hz, max_order, outdir):
    """Identify the modes of a measured tool-point FRF FILE (any file the chatter section's readers take: CSV, UFF
    58; without FILE, the packaged simulated tap test of the milling spindle) and write fitmodes.h5, modes.yaml (a
    list that pastes under `chatter: frf: modes:`), fitmodes_stabilisation.png and fitmodes_overlay.png.  Poles
    stable through the model orders in frequency, damping and residue are the modes; computational ones
    (negative damping, a residue of the wrong sign, a tiny peak) are left out and listed."""
    from ..output.drawing import figure_process
    from .common import packaged_inputs, run_measurement

    with figure_process():
        from ..output.measured_summary import fitmodes_summary
        from ..runs.fitmodes import run

        inputs = [file] if file is not None else packaged_inputs("fitmodes")
        options = {"direction": direction, "band_hz": band_hz, "max_order": max_order}
        run_measurement("fitmodes", inputs, outdir, lambda out, info: run(inputs[0], out, info, options),
                        lambda ident, paths: fitmodes_summary(ident, paths[1]))
