"""The verdicts of a run, read from its files: one line each on what a spindle engineer decides on.

* API 684 separation margins of the critical speeds (campbell.h5: every 1x/2x/tooth crossing with AF >= 2.5 and
  whether it keeps its required margin from the operating speed range);
* stability over the speed range (campbell.h5: the first speed with a negatively damped mode);
* the thermal speed limit against the operating and the maximum continuous speed (thermal.h5);
* the stable depth of cut at the operating speed, and the smallest over the speed range (chatter.h5);
* whether a transient settled to a steady motion (transient.h5).

Nothing is recomputed: each verdict is the analysis's, as its file holds it.  ``status`` is "ok", "warn", "bad"
or "info" (a number without a pass mark).  The report opens with them; a sweep lists each case's.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Iterable

import numpy as np

OK, WARN, BAD, INFO = "ok", "warn", "bad", "info"


@dataclass(frozen=True)
class Verdict:
    topic: str
    text: str
    status: str
    analysis: str  # the analysis whose file says it (the report links to its section)


def _campbell(g, analysis: str) -> list[Verdict]:
    out = []
    if "crossings" in g:
        c = g["crossings"]
        crit = c["critical"][:].astype(bool)
        meets = c["meets_api684"][:].astype(bool)
        sp, order, mode = c["speed_rpm"][:], c["order"][:], c["mode"][:]
        margin, need = c["separation_margin"][:], c["required_separation_margin"][:]
        bad = np.flatnonzero(crit & ~meets)
        if len(bad):
            k = bad[np.argmin(margin[bad] - need[bad])]
            out.append(Verdict("API 684 separation margins", f"NOT MET: {len(bad)} critical crossing(s) inside "
                               f"their required margin; worst {sp[k]:.0f} rpm ({order[k]:g}x, mode {int(mode[k])}): "
                               f"margin {100 * margin[k]:.1f} % < {100 * need[k]:.1f} %", BAD, analysis))
        elif crit.any():
            out.append(Verdict("API 684 separation margins", f"met: {int(crit.sum())} critical crossing(s), each "
                               "outside its required margin", OK, analysis))
        else:
            out.append(Verdict("API 684 separation margins", "no critical crossing (AF >= 2.5) in the range", OK,
                               analysis))
    sp = g["speed_rpm"][:]
    if "first_unstable" in g.attrs:
        i, k = (int(v) for v in g.attrs["first_unstable"])
        out.append(Verdict("Stability over speed", f"UNSTABLE from {sp[i]:g} rpm (mode {k + 1})", BAD, analysis))
    elif g.attrs.get("stable", False):
        out.append(Verdict("Stability over speed", f"every tracked mode stable, {sp[0]:g}-{sp[-1]:g} rpm", OK,
                           analysis))
    return out


def _thermal(g, operating: tuple[float, float] | None, analysis: str) -> list[Verdict]:
    a = g.attrs
    if "speed_limit_rpm" in a:
        lo, hi = (float(v) for v in a["speed_limit_rpm"])
        text = f"stable up to {lo:,.0f} rpm, runs away from {hi:,.0f} rpm"
        if operating is None:
            return [Verdict("Thermal speed limit", text, INFO, analysis)]
        op, top = operating
        if op > lo:
            return [Verdict("Thermal speed limit", f"NOT MET: the operating speed {op:,.0f} rpm is above it; {text}",
                            BAD, analysis)]
        if top > lo:
            return [Verdict("Thermal speed limit", f"the maximum continuous speed {top:,.0f} rpm is above it; {text}",
                            WARN, analysis)]
        return [Verdict("Thermal speed limit", f"{text}; the operating range ends at {top:,.0f} rpm", OK, analysis)]
    if "speed_rpm" in g:
        top = float(np.max(g["speed_rpm"][:]))
        return [Verdict("Thermal speed limit", f"no runaway up to {top:,.0f} rpm (the highest speed solved)", OK,
                        analysis)]
    return []


def _chatter(g, operating: tuple[float, float] | None, analysis: str) -> list[Verdict]:
    a = g.attrs
    out = []
    if "limit_depth_m" not in g:  # interrupted before the lobes
        return out
    n, L = g["speed_rpm"][:], g["limit_depth_m"][:]
    if operating is not None and n[0] <= operating[0] <= n[-1] and np.isfinite(L).any():
        ok = np.isfinite(L)
        at = float(np.interp(operating[0], n[ok], L[ok]))
        out.append(Verdict("Stable depth of cut at the operating speed", f"{1e3 * at:.3g} mm at "
                           f"{operating[0]:,.0f} rpm", INFO, analysis))
    if "minimum_limit_depth_m" in a:
        lim = f" (up to the thermal speed limit, {float(a['thermal_speed_limit_rpm']):,.0f} rpm)" \
            if "thermal_speed_limit_rpm" in a else ""
        out.append(Verdict("Smallest stable depth of cut", f"{1e3 * float(a['minimum_limit_depth_m']):.3g} mm at "
                           f"{float(a['minimum_at_speed_rpm']):,.0f} rpm{lim}", INFO, analysis))
    return out


def _transient(g, analysis: str) -> list[Verdict]:
    a = g.attrs
    if "settled" not in a:
        return []
    if bool(a["settled"]):
        return [Verdict("Transient", "settled to a steady motion", OK, analysis)]
    return [Verdict("Transient", "NOT SETTLED: " + str(a.get("settling_note", "no steady motion")).replace(
        "not settled: ", ""), WARN, analysis)]


def verdicts(paths: Iterable[Path], analysis_of: dict[str, str] | None = None,
             operating: tuple[float, float] | None = None) -> list[Verdict]:
    """Every verdict the files among ``paths`` hold (module note); ``analysis_of`` maps a file stem to the
    analysis that wrote it (default: the stem), ``operating`` is (operating, maximum continuous) speed [rpm]."""
    import h5py

    out: list[Verdict] = []
    for p in paths:
        p = Path(p)
        if p.suffix != ".h5":
            continue
        name = (analysis_of or {}).get(p.stem, p.stem)
        try:
            with h5py.File(p, "r") as f:
                if "campbell" in f:
                    out += _campbell(f["campbell"], name)
                if "spindle_thermal" in f:
                    out += _thermal(f["spindle_thermal"], operating, name)
                if "chatter" in f:
                    out += _chatter(f["chatter"], operating, name)
                if "transient" in f:
                    out += _transient(f["transient"], name)
        except (OSError, KeyError, ValueError):  # a file without what a verdict needs gives none
            continue
    return out


def operating_range(deck) -> tuple[float, float] | None:
    """(operating speed, maximum continuous speed) [rpm] of a deck, None without an operating speed."""
    op = getattr(deck, "operating", None)
    if op is None or not op.speed_rpm:
        return None
    top = op.max_continuous_rpm if op.max_continuous_rpm is not None else op.speed_rpm
    return float(op.speed_rpm), float(max(top, op.speed_rpm))
