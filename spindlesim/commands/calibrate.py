"""``spindlesim calibrate [DECK]``: deck values fitted to measured FRFs (the deck's ``calibration:`` section)."""

import sys

import click

from .common import deck_argument, outdir_option, report_options


@click.command("calibrate")
@deck_argument
@outdir_option
@report_options
def command(deck, outdir):
    """Fit the deck values listed under 'calibration: parameters' (key paths with bounds) to the measured FRFs
    under 'calibration: measurements' by bounded nonlinear least squares on the complex receptance; writes
    calibration.h5 (values, 95 % intervals, correlations, the FRFs before and after), calibrated.yaml (the deck
    with the fitted values in place, comments kept) and calibration_frf.png.  Exit 1 with one line when the fit
    does not converge; Ctrl-C writes the best values evaluated, marked incomplete (exit 130)."""
    from ..output.drawing import figure_process
    from .common import load_or_default, progress_reporter, resolve_outdir, run_command

    with figure_process():
        from ..deck import require_section

        loaded = load_or_default(deck, "tool_library")
        out = resolve_outdir(outdir, loaded)
        update, close = progress_reporter("calibrate")

        def call():
            from ..runs import run_info_for
            from ..sweep.calibrate_run import run_calibration

            require_section(loaded, "calibration", "calibrate",
                            "measurements (measured FRF files and nodes) and parameters (key paths, bounds)")
            return run_calibration(loaded, out, run_info_for(loaded, " ".join(sys.argv)), update)

        run_command("calibrate", loaded, call, close)
