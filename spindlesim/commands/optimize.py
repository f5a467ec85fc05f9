"""``spindlesim optimize [DECK]``: design optimisation over deck values (the deck's ``optimize:`` section)."""

import sys

import click

from .common import deck_argument, outdir_option, report_options


@click.command("optimize")
@deck_argument
@outdir_option
@click.option("--workers", type=click.IntRange(min=1), default=1, show_default=True,
              help="Designs evaluated in parallel (local processes).")
@click.option("--scheduler", default=None, metavar="ADDRESS|local",
              help="Evaluate on a Dask cluster: a scheduler address, or 'local' for a LocalCluster.")
@report_options
def command(deck, outdir, workers, scheduler):
    """Choose the deck values listed under 'optimize: variables' (key paths with bounds, or values to choose
    from) for the objectives under 'optimize: objectives' (one: an optimum by scipy.optimize; two or three, or a
    discrete choice: a Pareto front by NSGA-II) within the constraints, each a named result of the existing
    analyses at the operating speed.  Writes optimize.h5 (every design), optimized.yaml (the best design; a
    front: pareto/point_*.yaml too) and the figures; prints the best design against the deck's and what limits
    it.  Every design is kept in evaluations.jsonl as it finishes: Ctrl-C writes what was evaluated (exit 130)
    and the same command resumes, ending as an uninterrupted run would."""
    from ..output.drawing import figure_process
    from .common import load_or_default, progress_reporter, resolve_outdir, run_command

    with figure_process():
        from ..deck import require_section

        loaded = load_or_default(deck, "bearing_span")
        require = lambda: require_section(loaded, "optimize", "optimize",  # noqa: E731
                                          "variables (key paths, bounds), objectives, constraints, budget")
        update, close = progress_reporter("optimize")

        def call():
            from ..runs import run_info_for
            from ..sweep.optimize_inputs import check_problem
            from ..sweep.optimize_run import run_optimize

            require()
            check_problem(loaded)  # every bad input before the output folder is made: nothing written
            out = resolve_outdir(outdir, loaded, "optimize")
            return run_optimize(loaded, out, run_info_for(loaded, " ".join(sys.argv)), workers, scheduler,
                                update)[1]

        run_command("optimize", loaded, call, close)
