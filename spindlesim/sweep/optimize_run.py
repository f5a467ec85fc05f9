"""``spindlesim optimize``: the study (``optimize.optimize``) written: optimize.h5 (every design: variables, named
results, feasibility, reason of a failure, seconds; the Pareto set), optimized.yaml (the best design, or for a
Pareto front the design of the first objective's best and one deck per Pareto point under pareto/), the figures
(objective history, Pareto front with the deck's design, parallel coordinates) and the summary lines.  A Ctrl-C
writes the designs evaluated so far, marked incomplete; the same command resumes."""

from __future__ import annotations

import dataclasses
import datetime
from pathlib import Path
from typing import Any

import numpy as np


def _numeric(values) -> np.ndarray:
    return np.array([float(v) if not isinstance(v, str) else np.nan for v in values], float)


def write_optimize(path: Path, run: Any, res) -> Path:
    from ..output.hdf5 import Data, labels, write_h5

    p = res.problem
    g = "/optimize"
    recs = res.records
    n = len(recs)
    data: dict = {**labels(g, "variable", [v.path for v in p.variables], "deck key path"),
                  **labels(g, "result", list(p.names), "named result (docs/deck-format.md, optimize)")}
    X = np.array([_numeric(r.values) for r in recs], float).reshape(n, len(p.variables))
    choice = np.array([[v.choices.index(x) if v.discrete else -1 for v, x in zip(p.variables, r.values)]
                       for r in recs], np.int32).reshape(n, len(p.variables))
    Y = np.array([[r.results.get(name, np.nan) for name in p.names] for r in recs], float).reshape(n, len(p.names))
    data[f"{g}/values"] = Data(X, "", ("evaluation", "variable"), "each design's variables, in their deck keys' "
                               "units (NaN: a word chosen, see choice)", fill_nan=True)
    data[f"{g}/choice"] = Data(choice, "1", ("evaluation", "variable"),
                               "index of a discrete variable's value in its list (-1: continuous)")
    data[f"{g}/results"] = Data(Y, "", ("evaluation", "result"), "named results (NaN: the design failed)",
                                fill_nan=True, component_units=np.array([_unit(nm) for nm in p.names], dtype=object))
    data[f"{g}/values_text"] = Data(np.array([[_show(x) for x in r.values] for r in recs], dtype=object).reshape(
        n, len(p.variables)), "1", ("evaluation", "variable"), "each design's variables as written in its deck")
    data[f"{g}/feasible"] = Data(np.array([res.feasible(r) for r in recs], np.int8), "1", ("evaluation",))
    data[f"{g}/elapsed_s"] = Data(np.array([r.elapsed_s for r in recs], float), "s", ("evaluation",))
    data[f"{g}/error"] = Data(np.array([r.error or "" for r in recs], dtype=object), "1", ("evaluation",),
                              "why a design failed (empty: it did not)")
    data[f"{g}/pareto"] = Data(np.array(res.pareto, np.int64), "1", ("pareto",),
                               "evaluations of the Pareto set (one objective: the best)")
    attrs = {g: {"method": res.method, "message": res.message, "budget": p.budget, "seed": p.seed,
                 "evaluations": n, "objectives": "; ".join(o.label for o in p.objectives),
                 "constraints": "; ".join(c.label for c in p.constraints) or "none",
                 "best": -1 if res.best is None else int(res.best),
                 "limits": "; ".join(res.limits) or "none"}}
    if not res.complete:
        run = dataclasses.replace(run, complete=False, incomplete_reason=res.message)
    return write_h5(path, run, data, attrs)


def _unit(name: str) -> str:
    from .named_results import NAMED_RESULTS

    return NAMED_RESULTS[name].unit


def design_deck(loaded: Any, res, rec, what: str) -> str:
    """The deck with ``rec``'s values in place (6 digits) and a comment naming the study and the design."""
    from .optimize import Evaluator

    ev = Evaluator(loaded, res.problem, None)
    day = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [f"# {what}: spindlesim optimize on {day} from {loaded.source}"]
    for v, x, x0 in zip(res.problem.variables, rec.values, res.reference.values):
        lines.append(f"#   {v.path} = {_show(x)}, was {_show(x0)}")
    for name in res.problem.names:
        lines.append(f"#   {name} = {rec.results.get(name, float('nan')):.6g} {_unit(name)}, was "
                     f"{res.reference.results.get(name, float('nan')):.6g}")
    if not res.complete:
        lines.append("# INCOMPLETE: interrupted; the best design evaluated so far")
    return "\n".join(lines) + "\n" + ev.text(rec.values, 6)


def _show(x) -> str:
    return x if isinstance(x, str) else f"{float(x):.6g}"


def run_optimize(loaded: Any, outdir: Path, run_info: Any, workers: int | None = 1, scheduler: str | None = None,
                 progress=None) -> tuple[Any, list[Path]]:
    from ..output.drawing import draw, wait
    from ..output.hdf5 import write_text_atomic
    from .optimize_plots import history_figure, parallel_figure, pareto_figure
    from ..runs.status import IncompleteRun
    from .optimize import optimize

    interrupted = None
    try:
        res = optimize(loaded, outdir, workers, scheduler, progress)
    except KeyboardInterrupt as exc:
        res = getattr(exc, "partial", None)
        if res is None or not res.records:
            raise
        interrupted = exc
    paths = [write_optimize(outdir / "optimize.h5", run_info, res)]
    if res.pareto:
        best = res.best if res.best is not None else _first_objective_best(res)
        paths.append(write_text_atomic(outdir / "optimized.yaml", design_deck(loaded, res, res.records[best],
                                                                              "Best design")))
        if len(res.problem.objectives) > 1:
            (outdir / "pareto").mkdir(exist_ok=True)
            for k, i in enumerate(res.pareto):
                paths.append(write_text_atomic(outdir / "pareto" / f"point_{k + 1:03d}.yaml",
                                               design_deck(loaded, res, res.records[i], f"Pareto point {k + 1}")))
    title = loaded.deck.title
    paths.append(draw(outdir / "optimize_history.png", history_figure, res, title))
    paths.append(draw(outdir / "optimize_parallel.png", parallel_figure, res, title))
    if len(res.problem.objectives) > 1:
        paths.append(draw(outdir / "optimize_pareto.png", pareto_figure, res, title))
    if interrupted is not None:
        wait()
        raise IncompleteRun("optimize interrupted: the designs evaluated so far are written; the same command "
                            "resumes", paths, interrupted=True)
    return res, paths


def _first_objective_best(res) -> int:
    g = res.problem.objectives[0]
    return max(res.pareto, key=lambda i: g.sense * res.records[i].results[g.name])


def written_study(folder: Path, stem: str = "optimize") -> tuple[list[Path], str] | None:
    """(``<stem>.h5`` and its figures ``<stem>_*.png``, why it is incomplete or "") of a study written into
    ``folder``; None: none."""
    import h5py

    h5 = Path(folder) / f"{stem}.h5"
    if not h5.exists():
        return None
    with h5py.File(h5, "r") as f:
        reason = "" if bool(f.attrs.get("complete", True)) else str(f.attrs.get("incomplete_reason", "incomplete"))
    return [h5, *sorted(Path(folder).glob(f"{stem}_*.png"))], reason
