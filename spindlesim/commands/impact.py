"""``spindlesim impact [RECORDS...]``: the FRF of a tap test from its impact records (H1 of pyFRF, coherence,
double hits and overloads left out): frf_<direction>.csv, impact.h5, two figures."""

from pathlib import Path

import click

from .common import outdir_option, report_options


@click.command("impact")
@click.argument("records", nargs=-1, type=click.Path(path_type=Path))  # a directory: one located line
@click.option("--direction", type=click.Choice(["x", "y"]), default=None,
              help="Direction of the tap test [default: the records' own (UFF), else x].")
@click.option("--exponential", "decay_1_s", type=click.FloatRange(min=0.0), default=None, metavar="DECAY",
              help="Exponential window e^(-DECAY t) [1/s] on both channels; 0: none [default: only when the response "
                   "still rings at the records' end, then the decay that brings it to 1 % of its peak].")
@outdir_option
@report_options
def command(records, direction, decay_1_s, outdir):
    """The receptance of a tap test from its impact RECORDS (CSV: time_s, force_N and acceleration_m_s2,
    velocity_m_s or displacement_m, one impact per file or an impact column; UFF 58 time records; without RECORDS,
    the packaged simulated tap test of the milling spindle): every impact checked (a double hit or a clipped
    channel leaves it out, said why), H1 and coherence over the others, with a force window and, where needed,
    an exponential window.  Writes frf_<direction>.csv (the chatter readers' layout with a coherence column: chatter
    frf: {file: ...} and spindlesim fitmodes read it), impact.h5, impact_records.png and impact_frf.png."""
    from ..output.drawing import figure_process
    from .common import packaged_inputs, run_measurement

    with figure_process():
        from ..output.measured_summary import impact_summary
        from ..runs.impact import run

        inputs = list(records) or packaged_inputs("impact")
        options = {"direction": direction, "decay_1_s": decay_1_s}
        run_measurement("impact", inputs, outdir, lambda out, info: run(inputs, out, info, options),
                        lambda res, paths: impact_summary(res, paths[0]))
