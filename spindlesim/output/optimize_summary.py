"""Terminal summary of optimize.h5: the method and how it ended, the evaluations (failed, infeasible), the best
design against the deck's own (evaluation 0) variable by variable and what limits it, or the Pareto set's range."""

from __future__ import annotations

import numpy as np


def optimize(f):
    g = f["optimize"]
    a = g.attrs
    names = [str(n) for n in g["variable"][:].astype(str)]
    results = [str(n) for n in g["result"][:].astype(str)]
    units = [str(u) for u in g["results"].attrs.get("component_units", [""] * len(results))]
    text = g["values_text"][:].astype(str)
    Y = g["results"][:]
    feasible = g["feasible"][:].astype(bool)
    errors = g["error"][:].astype(str)
    pareto = [int(i) for i in g["pareto"][:]]
    n = len(feasible)
    failed = int(sum(bool(e) for e in errors))
    lines = [f"{a['method']}: {a['message']}",
             f"evaluations: {n} of {int(a['budget'])} ({failed} failed, {int(n - feasible.sum()) - failed} "
             "infeasible)"]
    first = next((k for k, e in enumerate(errors) if e), None)
    if first is not None:
        lines.append(f"  first failure, evaluation {first}: {errors[first]}")
    data: dict = {"evaluations": n, "failed": failed, "pareto": pareto}
    if not pareto:
        lines.append("no feasible design found" + ("" if failed == n else "; the constraints over the designs evaluated:"))
        lines.extend(_constraints_reached(str(a.get("constraints", "")), results, units, Y, errors))
        return lines, data
    best = int(a["best"])
    if best >= 0:
        lines.append("best design (evaluation %d) against the deck's:" % best)
        for k, name in enumerate(names):
            lines.append(f"  {name}: {text[0, k]} -> {text[best, k]}")
        for k, name in enumerate(results):
            lines.append(f"  {name}: {Y[0, k]:.6g} -> {Y[best, k]:.6g} {units[k]}")
        lines.append(f"limited by: {a['limits'] if a['limits'] != 'none' else 'nothing (an interior optimum)'}")
        data["best"] = {"variables": {nm: text[best, k] for k, nm in enumerate(names)},
                        "results": {nm: float(Y[best, k]) for k, nm in enumerate(results)}}
    else:
        objectives = [o.split(" ", 1)[1] for o in str(a["objectives"]).split("; ")]
        lines.append(f"Pareto set: {len(pareto)} designs (pareto/point_*.yaml)")
        senses = [o.split(" ", 1)[0] for o in str(a["objectives"]).split("; ")]
        for o, sense in zip(objectives, senses):
            k = results.index(o)
            v = Y[pareto, k]
            lines.append(f"  {o}: {np.min(v):.6g} .. {np.max(v):.6g} {units[k]} (the deck's design: {Y[0, k]:.6g})")
            end = pareto[int(np.argmax(v) if sense == "maximize" else np.argmin(v))]
            lines.append(f"    its best end (evaluation {end}): "
                         + ", ".join(f"{nm} = {text[end, j]}" for j, nm in enumerate(names)))
    return lines, data


def _constraints_reached(constraints: str, results: list[str], units: list[str], Y: np.ndarray, errors) -> list[str]:
    """Each constraint as optimize.h5 states it ("name <= b", "a <= name", "a <= name <= b") with the range its
    result took over the designs that did not fail, and how many met it: what to relax when none is feasible."""
    ok = np.array([not e for e in errors], bool)
    out = []
    for c in filter(None, (t.strip() for t in constraints.split(";"))):
        tokens = c.split()
        names = [t for t in tokens if t in results]
        if len(names) != 1 or not ok.any():
            continue
        j = tokens.index(names[0])
        try:
            lo = float(tokens[j - 2]) if j >= 2 and tokens[j - 1] == "<=" else -np.inf
            hi = float(tokens[j + 2]) if j + 2 < len(tokens) and tokens[j + 1] == "<=" else np.inf
            if j + 2 < len(tokens) and tokens[j + 1] == ">=":
                lo = float(tokens[j + 2])
        except ValueError:
            continue
        k = results.index(names[0])
        v = Y[ok, k]
        met = int(np.sum((v >= lo) & (v <= hi)))
        out.append(f"  {c}: {np.nanmin(v):.6g} .. {np.nanmax(v):.6g} {units[k]}".rstrip() + f"; met by {met} of {len(v)}")
    return out
