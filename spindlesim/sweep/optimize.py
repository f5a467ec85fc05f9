"""Design optimisation over deck values (``spindlesim optimize``, deck section ``optimize:``).

The model is the deck itself, as for ``calibrate``: each design is the deck's text with the variables' values (and
the values tied to them) written at their key paths, validated, and its named results computed by the existing
analyses (``optimize_store.evaluate_design``); every design is recorded as it finishes and never evaluated twice
(``optimize_store.Journal``).  The variables are scaled to the unit cube; each objective is divided by the
magnitude of its value for the deck's own design (evaluated first) and negated when maximised.

Methods, from libraries (docs/decisions.md, "optimize"):

- one objective, continuous variables, smooth results: ``scipy.optimize.minimize`` from the deck's design,
  L-BFGS-B (bounds) without constraints, SLSQP (bounds and inequality constraints) with them; the gradient by
  forward differences of 1e-4 of each range, the design and its n neighbours evaluated as one batch (in parallel);
- one objective where a result is not smooth (``min_limit_depth_mm``: the lobes' minimum jumps between lobes):
  ``scipy.optimize.differential_evolution`` (seeded, the deck's design in the first population, constraints as
  ``NonlinearConstraint``), each generation one batch;
- two or three objectives, or a discrete variable: pymoo's NSGA-II (one objective with a discrete variable: its
  genetic algorithm), the deck's design in the first population, the rest drawn with the seed; a discrete variable
  is a coordinate in [0, 1) cut into as many equal bins as it has values; constraints as pymoo's inequality
  constraints (g <= 0), a failed design violating one of its own.

The Pareto set is every feasible design evaluated that no other feasible design dominates (pymoo's non-dominated
sort), not only the last population.  A failed design counts against the budget and is infeasible.
"""

from __future__ import annotations

import contextlib
import logging
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from .optimize_inputs import Problem
from .optimize_store import Journal, Record, design_key, evaluate_design, model_digest

log = logging.getLogger(__name__)

#: results whose dependence on the variables is not smooth: a global method for one objective
NOT_SMOOTH = ("min_limit_depth_mm",)
#: forward-difference step, a share of each variable's range
FD_STEP = 1e-4
#: a variable this close to a bound (share of its range) or a constraint this close to its bound (relative)
#: limits the design
ACTIVE = 1e-3
#: a constraint is met within this share of its bound (the gradient method meets it to about 1e-10)
SLACK = 1e-9
#: the scaled objective of a failed design for the gradient methods (the scaled objectives are near 1)
FAILED_F = 1e3


class _OverBudget(Exception):
    """The evaluations allowed are spent."""


@dataclass(frozen=True)
class OptimizeResult:
    """What ``spindlesim optimize`` computes (module note): every design in the order the method asked for it,
    the deck's own design, the best (one objective) or the Pareto set (indices into ``records``)."""

    problem: Problem
    records: tuple[Record, ...]
    reference: Record
    best: int | None
    pareto: tuple[int, ...]
    method: str
    message: str
    limits: tuple[str, ...] = ()
    complete: bool = True  # False: interrupted; the designs evaluated so far

    def objectives(self, rec: Record) -> np.ndarray:
        return np.array([rec.results.get(g.name, np.nan) for g in self.problem.objectives], float)

    def feasible(self, rec: Record) -> bool:
        return feasible(self.problem, rec)


def feasible(problem: Problem, rec: Record) -> bool:
    if rec.failed:
        return False
    for c in problem.constraints:
        v = rec.results[c.name]
        if (c.lower is not None and v < c.lower - SLACK * abs(c.lower)) or \
                (c.upper is not None and v > c.upper + SLACK * abs(c.upper)):
            return False
    return True


class Evaluator:
    """Designs from unit-cube points, evaluated in batches (cached, journalled, within the budget)."""

    def __init__(self, loaded: Any, problem: Problem, journal: Journal, executor=None,
                 progress: Callable[[int, int], None] | None = None):
        self.loaded, self.problem, self.journal, self.executor = loaded, problem, journal, executor
        self.progress = progress
        self.records: list[Record] = []  # in the order asked, each design once
        self._seen: dict[str, int] = {}

    def design(self, u) -> tuple:
        out = []
        for v, x in zip(self.problem.variables, np.clip(np.asarray(u, float), 0.0, 1.0)):
            if v.discrete:
                out.append(v.choices[min(int(x * len(v.choices)), len(v.choices) - 1)])
            else:
                out.append(float(v.lower + x * (v.upper - v.lower)))
        return tuple(out)

    def unit(self, values) -> np.ndarray:
        u = []
        for v, x in zip(self.problem.variables, values):
            if v.discrete:
                k = v.choices.index(x) if x in v.choices else 0
                u.append((k + 0.5) / len(v.choices))
            else:
                u.append(min(max((float(x) - v.lower) / (v.upper - v.lower), 0.0), 1.0))
        return np.array(u)

    def text(self, values, digits: int = 17) -> str:
        from ..deck.paths import replace_in_text

        changes: dict = {}
        for v, x in zip(self.problem.variables, values):
            changes.update(v.deck_values(x))
        return replace_in_text(self.loaded.text, changes, digits)

    def batch(self, designs: list[tuple]) -> list[Record]:
        """The records of ``designs`` (values), each evaluated at most once in the study."""
        names = self.problem.names
        todo = []
        for d in designs:
            key = design_key(d)
            if key in self._seen or key in {design_key(t) for t in todo}:
                continue
            if len(self._seen) + len(todo) >= self.problem.budget:
                break
            todo.append(d)
        fresh = [d for d in todo if self.journal.get(d, names) is None]
        try:
            if fresh:
                self._run(fresh, names)
        finally:  # a Ctrl-C in the batch: the designs that finished are recorded all the same
            for d in todo:
                rec = self.journal.get(d, names)
                if rec is not None:
                    self._seen[design_key(d)] = len(self.records)
                    self.records.append(rec)
        if self.progress is not None and todo:
            self.progress(len(self.records), self.problem.budget)
        missing = [d for d in designs if design_key(d) not in self._seen]
        if missing:
            raise _OverBudget
        return [self.records[self._seen[design_key(d)]] for d in designs]

    def _run(self, designs: list[tuple], names) -> None:
        src = self.loaded.source
        if self.executor is None:
            for d in designs:
                self.journal.add(Record(d, *evaluate_design(self.text(d), src, names)))
            return
        from concurrent.futures import as_completed

        futures = {self.executor.submit(evaluate_design, self.text(d), src, names): d for d in designs}
        for fut in as_completed(futures):
            try:
                out = fut.result()
            except Exception as exc:  # noqa: BLE001 - a worker that died: the design is infeasible
                out = ({}, f"worker failed: {type(exc).__name__}: {exc}", 0.0)
            self.journal.add(Record(futures[fut], *out))


# ---- scalar views for the methods ------------------------------------------------------------------------

class _Scaled:
    """Scaled objectives f (minimised) and constraints g (>= 0 feasible) of a record."""

    def __init__(self, problem: Problem, reference: Record):
        self.problem = problem
        self.scale = []
        for g in problem.objectives:
            v = reference.results.get(g.name)
            self.scale.append(abs(v) if v is not None and v != 0 else 1.0)

    def f(self, rec: Record) -> np.ndarray:
        if rec.failed:
            return np.full(len(self.scale), FAILED_F)
        return np.array([-g.sense * rec.results[g.name] / s for g, s in zip(self.problem.objectives, self.scale)])

    def g(self, rec: Record) -> np.ndarray:
        """One entry per side of each constraint (lower, upper), scaled by the bound; -1 for a failed design."""
        out = []
        for c in self.problem.constraints:
            for bound, sign in ((c.lower, 1.0), (c.upper, -1.0)):
                if bound is None:
                    continue
                if rec.failed:
                    out.append(-1.0)
                else:
                    out.append(sign * (rec.results[c.name] - bound) / (abs(bound) or 1.0))
        return np.array(out)


def _gradient_method(ev: Evaluator, sc: _Scaled, u0: np.ndarray) -> str:
    from scipy.optimize import minimize

    n = len(u0)

    def points(u):
        u = np.clip(np.asarray(u, float), 0.0, 1.0)
        steps = [FD_STEP if u[i] + FD_STEP <= 1.0 else -FD_STEP for i in range(n)]
        us = [u] + [u + s * np.eye(n)[i] for i, s in enumerate(steps)]
        recs = ev.batch([ev.design(x) for x in us])
        return recs, np.array(steps)

    def fun(u):
        recs, h = points(u)
        f0 = sc.f(recs[0])[0]
        grad = np.array([(sc.f(r)[0] - f0) / h[i] for i, r in enumerate(recs[1:])])
        return f0, np.where(np.isfinite(grad), grad, 0.0)

    bounds = [(0.0, 1.0)] * n
    if not ev.problem.constraints:
        res = minimize(fun, u0, jac=True, method="L-BFGS-B", bounds=bounds,
                       options={"maxfun": ev.problem.budget, "ftol": 1e-13, "gtol": 1e-9})
        return f"L-BFGS-B: {res.message}"

    def con(u):
        return sc.g(points(u)[0][0])

    def con_jac(u):
        recs, h = points(u)
        g0 = sc.g(recs[0])
        return np.array([(sc.g(r) - g0) / h[i] for i, r in enumerate(recs[1:])]).T

    res = minimize(fun, u0, jac=True, method="SLSQP", bounds=bounds,
                   constraints=[{"type": "ineq", "fun": con, "jac": con_jac}],
                   options={"maxiter": ev.problem.budget, "ftol": 1e-12})
    return f"SLSQP: {res.message}"


def _global_method(ev: Evaluator, sc: _Scaled, u0: np.ndarray) -> str:
    from scipy.optimize import NonlinearConstraint, differential_evolution

    n = len(u0)

    def fun(U):  # vectorized: U [n, S]
        return np.array([sc.f(r)[0] for r in ev.batch([ev.design(u) for u in np.atleast_2d(U.T)])])

    kw: dict = {}
    if ev.problem.constraints:
        def con(U):
            return np.array([sc.g(r) for r in ev.batch([ev.design(u) for u in np.atleast_2d(U.T)])]).T

        kw["constraints"] = NonlinearConstraint(con, 0.0, np.inf)
    popsize = max(4, min(15, ev.problem.budget // (10 * n)))
    res = differential_evolution(fun, [(0.0, 1.0)] * n, seed=ev.problem.seed, vectorized=True, updating="deferred",
                                 popsize=popsize, maxiter=ev.problem.budget, polish=False, x0=u0, tol=1e-8, **kw)
    return f"differential evolution: {res.message}"


def _evolutionary_method(ev: Evaluator, sc: _Scaled, u0: np.ndarray) -> str:
    from pymoo.core.problem import Problem as PymooProblem
    from pymoo.optimize import minimize

    p = ev.problem
    n, n_obj = len(u0), len(p.objectives)
    n_con = 1 + sum((c.lower is not None) + (c.upper is not None) for c in p.constraints)

    class _P(PymooProblem):
        def __init__(self):
            super().__init__(n_var=n, n_obj=n_obj, n_ieq_constr=n_con, xl=0.0, xu=1.0)

        def _evaluate(self, X, out, *args, **kwargs):
            recs = ev.batch([ev.design(u) for u in X])
            out["F"] = np.array([sc.f(r) for r in recs])
            # pymoo: g <= 0 feasible; the first column says the design failed
            out["G"] = np.array([np.concatenate([[1.0 if r.failed else -1.0], -sc.g(r)]) for r in recs])

    pop = int(max(8, min(40, p.budget // 8)))
    rng = np.random.default_rng(p.seed)
    start = np.vstack([u0, rng.random((pop - 1, n))])
    if n_obj > 1:
        from pymoo.algorithms.moo.nsga2 import NSGA2

        algorithm, name = NSGA2(pop_size=pop, sampling=start, eliminate_duplicates=True), "NSGA-II"
    else:
        from pymoo.algorithms.soo.nonconvex.ga import GA

        algorithm, name = GA(pop_size=pop, sampling=start, eliminate_duplicates=True), "genetic algorithm"
    minimize(_P(), algorithm, ("n_eval", p.budget), seed=p.seed, verbose=False)
    return f"{name} (pymoo), population {pop}"


def method_of(problem: Problem) -> str:
    if len(problem.objectives) > 1 or problem.discrete:
        return "evolutionary"
    if any(n in NOT_SMOOTH for n in problem.names):
        return "global"
    return "gradient"


def pareto_set(problem: Problem, records) -> tuple[int, ...]:
    """Indices of the feasible records no other feasible record dominates (objectives as minimised)."""
    idx = [i for i, r in enumerate(records) if feasible(problem, r)]
    if not idx:
        return ()
    F = np.array([[-g.sense * records[i].results[g.name] for g in problem.objectives] for i in idx])
    if len(problem.objectives) == 1:
        return (idx[int(np.argmin(F[:, 0]))],)
    from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

    front = NonDominatedSorting().do(F, only_non_dominated_front=True)
    return tuple(sorted(idx[int(k)] for k in front))


def limits_of(ev: Evaluator, rec: Record) -> tuple[str, ...]:
    """What holds a design where it is: a continuous variable at a bound, a constraint at its bound."""
    out = []
    for v, x in zip(ev.problem.variables, rec.values):
        if v.discrete:
            continue
        share = (float(x) - v.lower) / (v.upper - v.lower)
        if share <= ACTIVE or share >= 1.0 - ACTIVE:
            out.append(f"{v.path} at its {'lower' if share <= ACTIVE else 'upper'} bound "
                       f"({v.lower if share <= ACTIVE else v.upper:g})")
    for c in ev.problem.constraints:
        val = rec.results.get(c.name)
        for bound, side in ((c.lower, "min"), (c.upper, "max")):
            if bound is not None and val is not None and abs(val - bound) <= ACTIVE * max(abs(bound), 1e-300):
                out.append(f"constraint {c.name} {side} {bound:g} active ({val:.6g})")
    return tuple(out)


def optimize(loaded: Any, outdir, workers: int | None = 1, scheduler: str | None = None,
             progress: Callable[[int, int], None] | None = None) -> OptimizeResult:
    """The deck's ``optimize:`` study (module note), its designs journalled in ``outdir``.

    DeckError: a located problem of the section.  KeyboardInterrupt: the designs evaluated so far are in the
    exception's ``partial`` attribute (an OptimizeResult with ``complete = False``); rerunning resumes."""
    from pathlib import Path

    from .execution import make_executor
    from .optimize_inputs import check_problem

    problem = check_problem(loaded)
    Path(outdir).mkdir(parents=True, exist_ok=True)
    journal = Journal(Path(outdir), model_digest(loaded.text))
    method = method_of(problem)
    with contextlib.ExitStack() as stack:
        executor = None
        if workers is None or workers > 1 or scheduler is not None:
            executor = stack.enter_context(make_executor(workers, scheduler))
        ev = Evaluator(loaded, problem, journal, executor, progress)
        initial = tuple(v.initial for v in problem.variables)
        run = {"gradient": _gradient_method, "global": _global_method, "evolutionary": _evolutionary_method}[method]
        try:
            reference = ev.batch([initial])[0]
            message = run(ev, _Scaled(problem, reference), ev.unit(reference.values))
        except _OverBudget:
            message = f"the budget of {problem.budget} evaluations is spent"
        except KeyboardInterrupt as exc:
            reference = ev.records[0] if ev.records else Record(initial, error="not evaluated: interrupted")
            exc.partial = _result(ev, reference, method, "interrupted by the user: the designs evaluated so far",
                                  complete=False)  # type: ignore[attr-defined]
            raise
    log.info("optimize: %s after %d evaluations", message, len(ev.records))
    return _result(ev, reference, method, message)


def _result(ev: Evaluator, reference: Record, method: str, message: str, complete: bool = True) -> OptimizeResult:
    recs = tuple(ev.records)
    front = pareto_set(ev.problem, recs)
    best = front[0] if len(ev.problem.objectives) == 1 and front else None
    limits = limits_of(ev, recs[best]) if best is not None else ()
    return OptimizeResult(ev.problem, recs, reference, best, front, method, message, limits, complete)
