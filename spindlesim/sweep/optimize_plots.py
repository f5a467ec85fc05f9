"""Figures of ``spindlesim optimize``: each objective over the evaluations (feasible, infeasible, failed, the best
so far), the Pareto front with the deck's own design and the constraints' boundary where a constraint is an
objective too, and parallel coordinates of every feasible design (variables and named results, each scaled to
its range; the Pareto set in colour)."""

from __future__ import annotations

import numpy as np

from ..output.figures import new_figure


def _unit(name: str) -> str:
    from .named_results import NAMED_RESULTS

    return NAMED_RESULTS[name].unit


def history_figure(res, title: str = ""):
    p = res.problem
    fig = new_figure(9.0, 2.0 + 2.4 * len(p.objectives))
    axes = np.atleast_1d(fig.subplots(len(p.objectives), 1, sharex=True))
    k = np.arange(len(res.records))
    ok = np.array([res.feasible(r) for r in res.records], bool)
    failed = np.array([r.failed for r in res.records], bool)
    for ax, g in zip(axes, p.objectives):
        y = np.array([r.results.get(g.name, np.nan) for r in res.records], float)
        ax.plot(k[ok], y[ok], "o", ms=3.5, color="C0", label="feasible")
        ax.plot(k[~ok & ~failed], y[~ok & ~failed], "x", ms=4, color="C3", label="infeasible")
        if failed.any():
            lo = np.nanmin(y) if np.isfinite(y).any() else 0.0
            ax.plot(k[failed], np.full(failed.sum(), lo), "v", ms=4, color="0.4", label="failed")
        if ok.any():
            best = np.where(ok, g.sense * np.nan_to_num(y, nan=-np.inf * g.sense), -np.inf)
            run = np.maximum.accumulate(best) * g.sense
            run[~np.isfinite(run)] = np.nan
            ax.plot(k, run, "-", color="C1", lw=1.3, label="best feasible so far")
        ax.axhline(res.reference.results.get(g.name, np.nan), color="0.3", ls="--", lw=0.9, label="deck's design")
        ax.set_ylabel(f"{g.name}\n[{_unit(g.name)}]", fontsize="small")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize="x-small", loc="best")
    axes[-1].set_xlabel("evaluation")
    none = "" if ok.any() else "; NO FEASIBLE DESIGN (the summary gives each constraint's range)"
    fig.suptitle(f"{title}\n{res.method}: {res.message}{none}", fontsize="small")
    return fig


def pareto_figure(res, title: str = ""):
    p = res.problem
    names = [g.name for g in p.objectives]
    pairs = [(0, 1)] if len(names) == 2 else [(0, 1), (0, 2), (1, 2)]
    fig = new_figure(6.0 * len(pairs), 5.0)
    axes = np.atleast_1d(fig.subplots(1, len(pairs)))
    Y = np.array([[r.results.get(n, np.nan) for n in names] for r in res.records], float)
    ok = np.array([res.feasible(r) for r in res.records], bool)
    front = list(res.pareto)
    ref = [res.reference.results.get(n, np.nan) for n in names]
    for ax, (i, j) in zip(axes, pairs):
        ax.plot(Y[~ok, i], Y[~ok, j], "x", ms=4, color="0.6", label="infeasible or failed")
        ax.plot(Y[ok, i], Y[ok, j], "o", ms=3, color="C0", alpha=0.5, label="feasible")
        order = sorted(front, key=lambda k: Y[k, i])
        ax.plot(Y[order, i], Y[order, j], "o-", ms=5, color="C3", lw=1.2, label="Pareto set")
        ax.plot(ref[i], ref[j], "*", ms=14, color="k", label="deck's design")
        for c in p.constraints:  # a constraint on a plotted objective: its boundary
            for bound in (c.lower, c.upper):
                if bound is None:
                    continue
                if c.name == names[i]:
                    ax.axvline(bound, color="C2", ls=":", lw=1.2, label=f"constraint {c.name}")
                if c.name == names[j]:
                    ax.axhline(bound, color="C2", ls=":", lw=1.2, label=f"constraint {c.name}")
        ax.set_xlabel(f"{names[i]} [{_unit(names[i])}]")
        ax.set_ylabel(f"{names[j]} [{_unit(names[j])}]")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize="x-small", loc="best")
    cons = "; ".join(c.label for c in p.constraints)
    fig.suptitle(f"{title}\nPareto front ({len(front)} designs)" + (f"; subject to {cons}" if cons else ""),
                 fontsize="small")
    return fig


def parallel_figure(res, title: str = ""):
    p = res.problem
    cols = [v.path for v in p.variables] + list(p.names)
    recs = [r for r in res.records if res.feasible(r)]
    fig = new_figure(max(7.0, 1.6 * len(cols)), 5.0)
    ax = fig.subplots()

    def row(r):
        vals = [(v.choices.index(x) if v.discrete else float(x)) for v, x in zip(p.variables, r.values)]
        return vals + [r.results.get(n, np.nan) for n in p.names]

    if recs:
        Z = np.array([row(r) for r in recs], float)
        lo, hi = np.nanmin(Z, axis=0), np.nanmax(Z, axis=0)
        span = np.where(hi > lo, hi - lo, 1.0)
        S = (Z - lo) / span
        x = np.arange(len(cols))
        front = {id(res.records[i]) for i in res.pareto}
        for r, s in zip(recs, S):
            on = id(r) in front
            ax.plot(x, s, "-", color="C3" if on else "0.7", lw=1.4 if on else 0.6, alpha=0.9 if on else 0.5,
                    zorder=3 if on else 1)
        if not res.reference.failed:
            ax.plot(x, (np.array(row(res.reference), float) - lo) / span, "--", color="k", lw=1.5, zorder=4,
                    label="deck's design")
        for k in range(len(cols)):
            var = p.variables[k] if k < len(p.variables) else None
            low, high = ((var.choices[int(lo[k])], var.choices[int(hi[k])]) if var is not None and var.discrete
                         else (lo[k], hi[k]))
            ax.annotate(_label(low), (k, 0), textcoords="offset points", xytext=(2, -12), fontsize="x-small")
            ax.annotate(_label(high), (k, 1), textcoords="offset points", xytext=(2, 4), fontsize="x-small")
        ax.set_xticks(x)
        ax.set_xticklabels(cols, rotation=20, ha="right", fontsize="x-small")
        ax.legend(fontsize="x-small", loc="upper right")
    ax.set_ylabel("share of each column's range (feasible designs)")
    ax.set_ylim(-0.1, 1.1)
    ax.grid(True, axis="x", alpha=0.4)
    fig.suptitle(f"{title}\nfeasible designs; " + ("the Pareto set" if len(p.objectives) > 1 else "the best")
                 + " in red", fontsize="small")
    return fig


def _label(v) -> str:
    return v if isinstance(v, str) else f"{float(v):.4g}"
