"""Sweep summary: one HDF5 indexing every case (parameters, status, key scalars) and comparison PNGs."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..output.figures import new_figure, save_figure
from ..output.hdf5 import RunInfo, write_h5
from .runner import SweepResult
from .summary import OVERLAYS


def _column(values: list) -> tuple[np.ndarray, str]:
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        return np.asarray(values, float), "deck units"
    return np.array([str(v) for v in values], dtype=object), "1"


def scalar_table(res: SweepResult) -> dict[str, np.ndarray]:
    names = sorted({k for r in res.records for k in (r.get("scalars") or {})})
    return {n: np.array([(r.get("scalars") or {}).get(n, np.nan) for r in res.records], float) for n in names}


def write_summary(res: SweepResult, run: RunInfo, analysis: str) -> Path:
    ds: dict[str, tuple] = {
        "/sweep/case_key": (np.array([c.key for c in res.cases], dtype=object), "1"),
        "/sweep/status": (np.array([r.get("status", "") for r in res.records], dtype=object), "1"),
        "/sweep/error": (np.array([r.get("error", "") for r in res.records], dtype=object), "1"),
        "/sweep/elapsed_s": (np.array([r.get("elapsed_s", np.nan) for r in res.records], float), "s"),
        "/sweep/case_dir": (np.array([f"cases/{c.key}" for c in res.cases], dtype=object), "1"),
    }
    for name in res.cases[0].parameters if res.cases else []:
        ds[f"/sweep/parameters/{name}"] = _column([c.parameters[name] for c in res.cases])
    for name, col in scalar_table(res).items():
        ds[f"/sweep/scalars/{name.replace('@', '.attr.')}"] = (col, "see the case file")
    return write_h5(res.outdir / "sweep.h5", run, ds, {"/sweep": {
        "analysis": analysis, "cases": len(res.cases), "ran": len(res.ran), "skipped": len(res.skipped),
        "failed": sum(r.get("status") != "done" for r in res.records)}})


def short_name(path: str) -> str:
    """Last key of a deck path, keeping list indices with their key (K_N_m.0.0)."""
    parts = path.split(".")
    i = len(parts) - 1
    while i > 0 and parts[i].lstrip("-").isdigit():
        i -= 1
    return ".".join(parts[i:])


def _label(params: dict) -> str:
    return ", ".join(f"{short_name(k)}={v}" for k, v in params.items())


def plot_scalars(res: SweepResult, path: Path, max_panels: int = 6) -> Path | None:
    """Key scalars against the first numeric parameter, one line per combination of the others."""
    if not res.cases:
        return None
    names = list(res.cases[0].parameters)
    xs_name = next((n for n in names if all(isinstance(c.parameters[n], (int, float)) for c in res.cases)), None)
    if xs_name is None:
        return None
    table = scalar_table(res)
    preferred = [k for k in table if not k.endswith(("elapsed_s",)) and np.isfinite(table[k]).any()
                 and np.nanstd(table[k]) > 0]
    preferred = preferred[:max_panels]
    if not preferred:
        return None
    fig = new_figure(9, 2.4 * len(preferred))
    axes = np.atleast_1d(fig.subplots(len(preferred), 1, sharex=True))
    others = [n for n in names if n != xs_name]
    groups: dict[tuple, list[int]] = {}
    for i, c in enumerate(res.cases):
        groups.setdefault(tuple(str(c.parameters[o]) for o in others), []).append(i)
    for ax, key in zip(axes, preferred):
        for g, idx in groups.items():
            x = np.array([res.cases[i].parameters[xs_name] for i in idx], float)
            order = np.argsort(x)
            label = ", ".join(f"{short_name(o)}={v}" for o, v in zip(others, g)) or None
            ax.plot(x[order], table[key][idx][order], "o-", label=label)
        ax.set_ylabel(key.split("/")[-1], fontsize=8)
        ax.grid(True, alpha=0.3)
    if others:
        axes[0].legend(fontsize=7)
    axes[-1].set_xlabel(xs_name)
    fig.suptitle("Sweep: key results against " + xs_name)
    return save_figure(fig, path)


def plot_overlay(res: SweepResult, analysis: str, path: Path) -> Path | None:
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
        if r.get("status") != "done" or not f.exists():
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
    ax.set_title(f"{analysis}: cases side by side")
    return save_figure(fig, path)
