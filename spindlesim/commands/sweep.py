"""``spindlesim sweep DECK``: a parameter study over any deck value, on a process pool or Dask."""

import sys

import click

from .common import deck_argument, load_or_default, report_options, resolve_outdir


@click.command("sweep")
@deck_argument
@click.option("-o", "--outdir", type=click.Path(file_okay=False), default=None,
              help="Sweep directory [default: out/<deck stem>/sweep].")
@click.option("--analysis", default=None, help="Analysis run for every case [default: deck sweep.analysis].")
@click.option("--set", "sets", multiple=True, metavar="PATH=VALUES",
              help="Override a deck value: 'bearings.front.K_N_m.0.0=1e8,2e8' or 'operating.speed_rpm=1000:6000:11'.")
@click.option("--mode", type=click.Choice(["grid", "list"]), default=None,
              help="grid: every combination; list: the i-th values together [default: deck, grid].")
@click.option("--workers", type=click.IntRange(min=1), default=None, help="Parallel workers [default: all cores].")
@click.option("--scheduler", default=None, metavar="ADDRESS|local",
              help="Run on a Dask cluster: a scheduler address, or 'local' for a LocalCluster.")
@click.option("--case-plots/--no-case-plots", default=False,
              help="Draw each case's PNGs into its case folder [default: off: a case folder holds its HDF5 "
                   "files, deck.yaml and case.json; the summary PNGs are always drawn].")
@report_options
def command(deck, outdir, analysis, sets, mode, workers, scheduler, case_plots):
    """Run ANALYSIS for every case of a parameter study; resumable, one HDF5 per case plus sweep.h5.

    Rerunning the same command runs only the cases not done (failed, incomplete, interrupted or
    never started).  Ctrl-C stops the running cases, starts no new one, writes sweep.h5 marked
    incomplete and exits with 130.  Prints the written paths and a table of the key results per
    case.  Exit codes: 0 every case done, 1 a case failed, 2 deck error, 3 a case ran but is
    incomplete (none failed), 130 interrupted."""
    from pathlib import Path

    from ..runs import analyses
    from ..deck import DeckError
    from ..sweep import build_cases
    from ..sweep.study import case_deck_issues, outcome_lines, run_study, study_parameters
    from .exits import EXIT_DECK_ERROR, outcome_code
    from .common import report_deck_error

    from ..decks import DEFAULT_DECKS

    loaded = load_or_default(deck, DEFAULT_DECKS["sweep"])
    sw = loaded.deck.sweep
    try:
        params = study_parameters(sw, sets)
    except ValueError as exc:
        raise click.BadParameter(str(exc), param_hint="--set") from None
    analysis = analysis or (sw.analysis if sw is not None else None)
    if analysis is None or analysis not in analyses():
        raise click.BadParameter(f"give an analysis, one of {', '.join(analyses())}", param_hint="--analysis")
    if not params:
        raise click.UsageError("nothing to sweep: give --set PATH=VALUES or a 'sweep:' section in the deck")
    try:
        cases = build_cases(loaded.text, params, analysis, mode or (sw.mode if sw else "grid"),
                            options={"plots": case_plots})
    except (KeyError, ValueError) as exc:
        click.echo(f"spindlesim sweep: {exc.args[0] if exc.args else exc}", err=True)
        sys.exit(EXIT_DECK_ERROR)
    bad = case_deck_issues(loaded, cases)  # every case's deck is validated before any runs
    if bad:
        report_deck_error(DeckError(bad))
    out = resolve_outdir(Path(outdir) if outdir else None, loaded, "sweep")

    def progress(done, total, eta):
        click.echo(f"sweep: {done}/{total} cases, about {eta:.0f} s left", err=True)

    click.echo(f"sweep: {len(cases)} cases of {analysis} into {out}", err=True)
    res, late = run_study(loaded, cases, analysis, out, workers=workers, scheduler=scheduler, progress=progress,
                          command_line=" ".join(sys.argv), show=_print_results)
    not_done = [r for r in res.records if r.get("status") != "done"]
    for line in outcome_lines(res):
        click.echo(line, err=True)
    code = outcome_code(failed=any(r.get("status") == "failed" for r in not_done), incomplete=bool(not_done),
                        interrupted=res.interrupted or getattr(late, "interrupted", False))
    if res.interrupted:
        click.echo(f"sweep: interrupted; sweep.h5 is marked incomplete. Run the same command again to finish "
                   f"(exit code {code})", err=True)
    elif getattr(late, "interrupted", False):
        click.echo(f"sweep: interrupted after the cases finished; sweep.h5 and its plots are written "
                   f"(exit code {code})", err=True)
    if code:
        sys.exit(code)

def _print_results(paths: list, lines: list[str], data: dict) -> None:
    """The written paths, then the per-case table (or both as JSON with --json; paths only with -q)."""
    import json

    from .common import _json_default

    ctx = click.get_current_context(silent=True)
    mode = ctx.meta.get("spindlesim.report", "text") if ctx is not None else "text"
    if mode == "json":
        click.echo(json.dumps({"paths": [str(p) for p in paths], "summary": {"sweep.h5": data}},
                              default=_json_default, allow_nan=True))
        return
    for p in paths:
        click.echo(str(p))
    if mode != "quiet" and lines:
        click.echo("\nsweep.h5:")
        for line in lines:
            click.echo(f"  {line}")
