"""Sweep summary: one HDF5 indexing every case (parameters, status, key scalars) and comparison PNGs."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from ..output.figures import new_figure, save_figure
from ..output.hdf5 import Data, RunInfo, write_h5
from .runner import verdict_word, DONE, FAILED, INCOMPLETE, INTERRUPTED, NOT_RUN, SweepResult
from .summary import OVERLAYS, is_bookkeeping, key_order, unit_from_name

#: SI unit -> (from magnitude, divide by, unit shown): the first row whose magnitude the largest value reaches
_DISPLAY = {"m": ((1.0, 1.0, "m"), (1e-3, 1e-3, "mm"), (1e-6, 1e-6, "um"), (0.0, 1e-9, "nm")),
            "Pa": ((1e9, 1e9, "GPa"), (1e6, 1e6, "MPa"), (0.0, 1.0, "Pa")),
            "N/m": ((1e6, 1e6, "N/um"), (0.0, 1.0, "N/m")), "N s/m": ((1e3, 1e3, "N s/mm"), (0.0, 1.0, "N s/m")),
            "m/N": ((1e-6, 1e-6, "um/N"), (0.0, 1e-9, "nm/N")), "m^2": ((1.0, 1.0, "m^2"), (0.0, 1e-6, "mm^2"))}


def _column(values: list, unit: str):
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        return np.asarray(values, float), unit or "deck units"
    # a matrix or a word: the values as the deck writes them, in the unit its key names
    return Data(np.array([str(v) for v in values], dtype=object), unit or "1", None,
                "the values as written in the deck (text)")


def scalar_table(res: SweepResult) -> dict[str, np.ndarray]:
    """Every scalar of every finished case, NaN where a case is not done or lacks it."""
    names: list[str] = []
    for r in res.records:
        names += [k for k in (r.get("scalars") or {}) if k not in names]
    done = [r if r.get("status") == DONE else {} for r in res.records]
    return {n: np.array([(r.get("scalars") or {}).get(n, np.nan) for r in done], float) for n in sorted(names)}


def scalar_units(res: SweepResult) -> dict[str, str]:
    """The unit of each scalar as its source file states it (first case that has one)."""
    units: dict[str, str] = {}
    for r in res.records:
        for k, u in (r.get("units") or {}).items():
            if u and not units.get(k):
                units[k] = u
    return units


def _status_counts(res: SweepResult) -> dict[str, int]:
    return {"done": res.count(DONE), "failed": res.count(FAILED), "incomplete": res.count(INCOMPLETE),
            "interrupted": res.count(INTERRUPTED), "not_run": res.count(NOT_RUN)}


def write_summary(res: SweepResult, run: RunInfo, analysis: str) -> Path:
    """sweep.h5; ``complete`` is False unless every case is done (the reason says what is missing)."""
    units = scalar_units(res)
    ds: dict[str, tuple] = {
        "/sweep/case_key": (np.array([c.key for c in res.cases], dtype=object), "1"),
        "/sweep/status": (np.array([r.get("status", "") for r in res.records], dtype=object), "1"),
        "/sweep/error": (np.array([r.get("error", "") for r in res.records], dtype=object), "1"),
        "/sweep/elapsed_s": (np.array([r.get("elapsed_s", np.nan) for r in res.records], float), "s"),
        "/sweep/case_dir": (np.array([f"cases/{c.key}" for c in res.cases], dtype=object), "1"),
    }
    for name in res.cases[0].parameters if res.cases else []:
        ds[f"/sweep/parameters/{name}"] = _column([c.parameters[name] for c in res.cases], unit_from_name(name))
    for name, col in scalar_table(res).items():
        ds[f"/sweep/scalars/{name.replace('@', '.attr.')}"] = (col, units.get(name) or "see the case file")
    counts = _status_counts(res)
    if not res.complete:
        missing = ", ".join(f"{n} {k.replace('_', ' ')}" for k, n in counts.items() if k != "done" and n)
        why = "interrupted by the user; " if res.interrupted else ""
        run = dataclasses.replace(run, complete=False, incomplete_reason=f"{why}{missing} of {len(res.cases)} cases "
                                  "(rerun the same command to run what is missing)")
    return write_h5(res.outdir / "sweep.h5", run, ds, {"/sweep": {
        "analysis": analysis, "cases": len(res.cases), "ran": len(res.ran), "skipped": len(res.skipped),
        "interrupted_sweep": res.interrupted, **counts}})


def short_name(path: str) -> str:
    """Last key of a deck path, keeping list indices with their key (K_N_m.0.0)."""
    parts = path.split(".")
    i = len(parts) - 1
    while i > 0 and parts[i].lstrip("-").isdigit():
        i -= 1
    return ".".join(parts[i:])


def _label(params: dict) -> str:
    return ", ".join(f"{short_name(k)}={v}" for k, v in params.items())


def display_scale(values: np.ndarray, unit: str) -> tuple[float, str]:
    """(divide by, unit shown) so that the numbers read in a familiar unit (um, GPa, N/um)."""
    big = float(np.nanmax(np.abs(values))) if np.isfinite(values).any() else 0.0
    for threshold, factor, shown in _DISPLAY.get(unit, ()):
        if big >= threshold:
            return factor, shown
    return 1.0, unit


def _scalar_label(name: str, unit: str) -> str:
    leaf = name.split("/")[-1].replace("@", " ")
    suffix = next((s for s in ("_m_N", "_N_m", "_Ns_m", "_hz", "_rpm", "_Pa", "_N", "_m", "_C")
                   if leaf.split("[")[0].endswith(s)), "")
    if suffix:
        base, _, idx = leaf.partition("[")
        leaf = base[: -len(suffix)] + (f"[{idx}" if idx else "")
    group = name.split("/")[-2] if name.count("/") >= 2 else ""
    text = (f"{group} " if group else "") + leaf.replace("_", " ")
    return f"{text} [{'-' if unit in ('1', '') else unit}]"


def plotted_scalars(res: SweepResult, max_panels: int = 6) -> list[str]:
    """The key results of the analysis (summary.KEY_SCALARS) present in some finished case, then other
    scalars that vary between cases (not bookkeeping such as iteration counts)."""
    table = scalar_table(res)
    finite = [k for k in table if np.isfinite(table[k]).any()]
    keys = key_order(finite)
    rest = [k for k in finite if k not in keys and not is_bookkeeping(k) and np.nanstd(table[k]) > 0]
    return (keys + rest)[:max_panels]


#: a scalar that varies between the cases by at most this share of its size is drawn flat (a 0.003 %
#: spread over the whole panel height reads as a trend that is not there)
FLAT_SHARE = 1e-4


def flat_limits(values: np.ndarray) -> tuple[float, float] | None:
    """Axis limits +- 1 % of the size about the mean for values within :data:`FLAT_SHARE` of each other,
    else None (autoscale)."""
    v = np.asarray(values, float)
    v = v[np.isfinite(v)]
    size = float(np.max(np.abs(v))) if v.size else 0.0
    if size == 0.0 or float(np.ptp(v)) > FLAT_SHARE * size:
        return None
    mid = float(np.mean(v))
    return mid - 0.01 * size, mid + 0.01 * size


def plot_scalars(res: SweepResult, path: Path, max_panels: int = 6, title: str = "") -> Path | None:
    """Key results against the first numeric parameter, one line per combination of the others."""
    fig = scalars_figure(res, max_panels, title)
    return None if fig is None else save_figure(fig, path)


def scalars_figure(res: SweepResult, max_panels: int = 6, title: str = ""):
    """The figure of :func:`plot_scalars` (None when there is nothing to plot)."""
    if not res.cases:
        return None
    names = list(res.cases[0].parameters)
    xs_name = next((n for n in names if all(isinstance(c.parameters[n], (int, float)) for c in res.cases)), None)
    if xs_name is None:
        return None
    table, units = scalar_table(res), scalar_units(res)
    shown = plotted_scalars(res, max_panels)
    if not shown:
        return None
    fig = new_figure(8, 1.0 + 2.1 * len(shown))
    axes = np.atleast_1d(fig.subplots(len(shown), 1, sharex=True))
    others = [n for n in names if n != xs_name]
    groups: dict[tuple, list[int]] = {}
    for i, c in enumerate(res.cases):
        groups.setdefault(tuple(str(c.parameters[o]) for o in others), []).append(i)
    for ax, key in zip(axes, shown):
        scale, unit = display_scale(table[key], units.get(key, ""))
        for g, idx in groups.items():
            x = np.array([res.cases[i].parameters[xs_name] for i in idx], float)
            order = np.argsort(x)
            label = ", ".join(f"{short_name(o)}={v}" for o, v in zip(others, g)) or None
            ax.plot(x[order], table[key][idx][order] / scale, "o-", label=label)
            flagged = [i for i in idx if verdict_word(res.records[i]) not in ("", "ok")]
            if flagged:  # a case whose verdict fails or warns: a red ring around its point
                fx = np.array([res.cases[i].parameters[xs_name] for i in flagged], float)
                ax.plot(fx, table[key][flagged] / scale, "o", ms=11, mfc="none", mec="tab:red", mew=1.4,
                        label="verdict: " + ", ".join(sorted({verdict_word(res.records[i]) for i in flagged}))
                        if ax is axes[0] and g == next(iter(groups)) else None)
        missing = sum(r.get("status") == DONE and not np.isfinite(v) for r, v in zip(res.records, table[key]))
        if missing:  # e.g. no converged contact pressure at a sharp roller edge
            ax.text(0.01, 0.95, f"no value in {missing} finished case(s)", transform=ax.transAxes, fontsize=7,
                    va="top", color="0.35")
        flat = flat_limits(table[key] / scale)
        if flat is not None:
            v = table[key][np.isfinite(table[key])]
            ax.set_ylim(*flat)
            ax.text(0.99, 0.95, f"constant to {100 * np.ptp(v) / np.max(np.abs(v)):.2g} % (drawn flat)",
                    transform=ax.transAxes, fontsize=7, va="top", ha="right", color="0.35", gid="flat")
        ax.set_ylabel(_scalar_label(key, unit), fontsize=8)
        ax.ticklabel_format(axis="y", useOffset=False)
        ax.grid(True, alpha=0.3)
    if others or any(verdict_word(r) not in ("", "ok") for r in res.records):
        axes[0].legend(fontsize=7)
    x_unit = unit_from_name(xs_name)
    axes[-1].set_xlabel(short_name(xs_name) + (f" [{x_unit}]" if x_unit else "") + f"   ({xs_name})")
    not_done = sum(r.get("status") != DONE for r in res.records)
    head = f"{title}\n" if title else ""
    note = f" ({not_done} of {len(res.cases)} cases not done: missing points)" if not_done else ""
    fig.suptitle(f"{head}Key results against {short_name(xs_name)}{note}", fontsize=10)
    return fig


def plot_overlay(res: SweepResult, analysis: str, path: Path, title: str = "") -> Path | None:
    """Curves of every finished case side by side (e.g. spectra of 5/8/12 rollers)."""
    if analysis not in OVERLAYS:
        return None
    import h5py

    fname, xp, yp, xl, yl = OVERLAYS[analysis]
    fig = new_figure(9, 5)
    ax = fig.subplots()
    drawn = 0
    for c, r in zip(res.cases, res.records):
        f = res.outdir / "cases" / c.key / fname
        if r.get("status") != DONE or not f.exists():
            continue
        with h5py.File(f, "r") as h:
            x, y = h[xp][()], np.abs(h[yp][()])
        y = y if y.ndim == 1 else np.hypot(y[:, 0], y[:, 1]) if y.shape[1] == 2 else y[:, 0]
        ax.semilogy(x, np.maximum(y, 1e-30), lw=1, label=_label(c.parameters))
        drawn += 1
    if not drawn:
        return None
    ax.set_xlabel(xl)
    ax.set_ylabel(yl)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title((f"{title}\n" if title else "") + f"{analysis}: cases side by side", fontsize=10)
    return save_figure(fig, path)


def _cell(v: float, scale: float) -> str:
    return f"{v / scale:.4g}" if np.isfinite(v) else "-"


def summary_table(res: SweepResult, max_scalars: int = 3) -> tuple[list[str], dict]:
    """A compact text table, one row per case: index, parameters, status and the key results
    (summary.KEY_SCALARS, in a readable unit); and the same numbers (SI) as a JSON-able dict."""
    if not res.cases:
        return [], {"cases": []}
    table, units = scalar_table(res), scalar_units(res)
    shown = plotted_scalars(res, max_scalars)
    params = list(res.cases[0].parameters)
    head = ["case"] + [short_name(p) + (f" [{unit_from_name(p)}]" if unit_from_name(p) else "") for p in params]
    head.append("status")
    verdicts = [verdict_word(r) for r in res.records]
    scales = {}
    for k in shown:
        scales[k] = display_scale(table[k], units.get(k, ""))
        head.append(_scalar_label(k, scales[k][1]))
    rows, data = [], []
    for i, (c, r) in enumerate(zip(res.cases, res.records)):
        row = [str(c.index)] + [f"{c.parameters[p]:g}" if isinstance(c.parameters[p], float) else
                                str(c.parameters[p]) for p in params] + [str(r.get("status", ""))]
        row += [_cell(table[k][i], scales[k][0]) for k in shown]
        rows.append(row)
        data.append({"case": c.index, "key": c.key, "parameters": c.parameters, "status": r.get("status", ""),
                     "scalars": {k: (float(table[k][i]) if np.isfinite(table[k][i]) else None) for k in shown},
                     "verdicts": r.get("verdicts", [])})
    widths = [max(len(h), *(len(r[j]) for r in rows)) for j, h in enumerate(head)]
    lines = ["  ".join(h.rjust(w) for h, w in zip(head, widths)) + ("  verdict" if any(verdicts) else "")]
    lines += ["  ".join(v.rjust(w) for v, w in zip(r, widths)) + (f"  {vd}" if any(verdicts) else "")
              for r, vd in zip(rows, verdicts)]
    return lines, {"cases": data, "units": {k: units.get(k, "") for k in shown}}
