"""The verdicts of a run: one line each on what a spindle engineer decides on, computed from the analyses'
results (nothing is read back from a file, nothing is decided again on the way out):

* API 684 separation margins of the critical speeds (``CampbellStudy``: every 1x/2x/tooth crossing with AF >= 2.5
  and whether it keeps its required margin from the operating speed range);
* stability over the speed range (``CampbellStudy``: the first speed with a negatively damped mode);
* the thermal speed limit against the operating and the maximum continuous speed (``ThermalStudy``);
* the stable depth of cut at the operating speed, and the smallest over the speed range (``ChatterStudy``);
* whether a transient settled to a steady motion (``TransientStudy``).

``status`` is "ok", "warn", "bad" or "info" (a number without a pass mark).  The report opens with them; a sweep
lists each case's.  The registry (``verdicts`` of an analysis's entry) names the function of each analysis that
has verdicts.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Iterable

import numpy as np

OK, WARN, BAD, INFO = "ok", "warn", "bad", "info"

#: (operating speed, maximum continuous speed) [rpm], or None without an operating speed
Operating = tuple[float, float] | None


@dataclass(frozen=True)
class Verdict:
    topic: str
    text: str
    status: str
    analysis: str  # the analysis that says it (the report links to its section)


def campbell_verdicts(study, operating: Operating, analysis: str) -> list[Verdict]:
    """API 684 margins of the critical crossings and the stability threshold of a ``CampbellStudy``'s diagram."""
    res = study.hot
    out = []
    c = res.crossings
    if c is not None:
        crit, meets = np.asarray(c.critical, bool), np.asarray(c.meets_api684, bool)
        margin, need = np.asarray(c.separation_margin), np.asarray(c.required_margin)
        bad = np.flatnonzero(crit & ~meets)
        if len(bad):
            k = bad[np.argmin(margin[bad] - need[bad])]
            out.append(Verdict("API 684 separation margins", f"NOT MET: {len(bad)} critical crossing(s) inside "
                               f"their required margin; worst {c.speed_rpm[k]:.0f} rpm ({c.order[k]:g}x, mode "
                               f"{int(c.mode[k]) + 1}): margin {100 * margin[k]:.1f} % < {100 * need[k]:.1f} %", BAD,
                               analysis))
        elif crit.any():
            out.append(Verdict("API 684 separation margins", f"met: {int(crit.sum())} critical crossing(s), each "
                               "outside its required margin", OK, analysis))
        else:
            out.append(Verdict("API 684 separation margins", "no critical crossing (AF >= 2.5) in the range", OK,
                               analysis))
    sp = np.asarray(res.speed_rpm)
    if res.first_unstable is not None:
        i, k = res.first_unstable
        out.append(Verdict("Stability over speed", f"UNSTABLE from {sp[i]:g} rpm (mode {k + 1})", BAD, analysis))
    elif len(sp):
        out.append(Verdict("Stability over speed", f"every tracked mode stable, {sp[0]:g}-{sp[-1]:g} rpm", OK,
                           analysis))
    return out


def thermal_verdicts(study, operating: Operating, analysis: str) -> list[Verdict]:
    """The thermal speed limit of a ``ThermalStudy`` against the operating range."""
    if study.limit_rpm is not None:
        lo, hi = (float(v) for v in study.limit_rpm)
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
    if study.states:
        top = max(float(s.speed_rpm) for s in study.states)
        return [Verdict("Thermal speed limit", f"no runaway up to {top:,.0f} rpm (the highest speed solved)", OK,
                        analysis)]
    return []


def chatter_verdicts(study, operating: Operating, analysis: str) -> list[Verdict]:
    """The stable depth at the operating speed and the smallest over the speeds of a ``ChatterStudy``."""
    res = study.result
    if res is None:  # interrupted before the lobes
        return []
    out = []
    n, L = np.asarray(res.diagram.speed_rpm, float), np.asarray(res.diagram.limit_depth_m, float)
    if operating is not None and n[0] <= operating[0] <= n[-1] and np.isfinite(L).any():
        ok = np.isfinite(L)
        at = float(np.interp(operating[0], n[ok], L[ok]))
        out.append(Verdict("Stable depth of cut at the operating speed", f"{1e3 * at:.3g} mm at "
                           f"{operating[0]:,.0f} rpm", INFO, analysis))
    if res.minimum is not None:
        s, d = res.minimum
        lim = "" if res.speed_limit_rpm is None else \
            f" (up to the thermal speed limit, {float(res.speed_limit_rpm):,.0f} rpm)"
        out.append(Verdict("Smallest stable depth of cut", f"{1e3 * float(d):.3g} mm at {float(s):,.0f} rpm{lim}", INFO,
                           analysis))
    return out


def transient_verdicts(study, operating: Operating, analysis: str) -> list[Verdict]:
    """Whether a ``TransientStudy``'s run settled to a steady motion."""
    s = study.result.settling
    if s is None:
        return []
    if s.settled:
        return [Verdict("Transient", "settled to a steady motion", OK, analysis)]
    note = str(s.note or "no steady motion").replace("not settled: ", "")
    return [Verdict("Transient", "NOT SETTLED: " + note, WARN, analysis)]


def verdicts_of(results: Iterable[tuple[str, str, Any]], operating: Operating = None) -> list[Verdict]:
    """Every verdict of ``results``: (the name the run is filed under, the analysis that ran, its result; None: a
    run without a result gives none)."""
    from ..registry import analysis

    out: list[Verdict] = []
    for name, ran, result in results:
        fn = analysis(ran).verdicts if ran else ""
        if fn and result is not None:
            out += globals()[fn](result, operating, name)
    return out
