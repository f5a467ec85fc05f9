"""Short result summaries for the terminal, read back from the files a run wrote.

A summary is built from the HDF5 file, not from the solver's objects, so what a user reads on the
terminal (or a script reads with ``--json``) is what the file holds; it never re-reads the deck or
recomputes a verdict (critical speeds, API 684 margins, the stability threshold are the analysis's).
Each analysis names the function that summarises its file in the registry (spindlesim/registry.py);
each returns ``(lines, data)``: a few text lines and the same numbers as a JSON-able dict.  The
rotor's summaries are in rotor_summary.py, the bearings' in bearing_summary.py, a spindle's thermal model's in
thermal_summary.py, the transient's and chatter's here.  A file that several analyses write (thermal.h5: the
fluid-film bearings' or the spindle_thermal section's) is summarised as the analysis whose group it holds
(each writes ``/<its name>``).
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Any, Callable

import numpy as np

from ..registry import file_summaries, file_writers
from .labels import frequency_label, readable_keys
from .numbers import with_resolution

#: analysis (or a command's file stem) -> "module:function" in spindlesim.output: the summary of its file
SUMMARIES: dict[str, str] = file_summaries()
#: file stem -> the analyses that write that file (several: each writes its own group, /<name>)
WRITERS: dict[str, tuple[str, ...]] = file_writers()


def summary_of(name: str) -> Callable | None:
    """The summary function of the analysis ``name`` (or of a command's files ``<name>.h5``), or None."""
    where = SUMMARIES.get(name)
    if where is None:
        return None
    module, function = where.split(":")
    return getattr(importlib.import_module(f"{__package__}.{module}"), function)


def has_summary(path: Path) -> bool:
    """Whether the file ``path`` is one a summary reads (by its name)."""
    return Path(path).suffix == ".h5" and any(n in SUMMARIES for n in WRITERS.get(Path(path).stem, (Path(path).stem,)))


def _writer(f, stem: str) -> str:
    """The analysis that wrote the open file ``f`` named ``<stem>.h5``: the one of its writers whose group it holds."""
    names = WRITERS.get(stem, (stem,))
    return next((n for n in names if n in f), names[0]) if len(names) > 1 else names[0]


def summarize(paths: list[Path]) -> list[tuple[str, list[str], dict[str, Any]]]:
    """(file name, lines, data) for every HDF5 file among ``paths`` that has a summary."""
    import h5py

    out = []
    for p in paths:
        if not has_summary(p):
            continue
        with h5py.File(p, "r") as f:
            fn = summary_of(_writer(f, Path(p).stem))
            if fn is None:
                continue
            lines, data = fn(f)
            if not f.attrs.get("complete", True):
                reason = f.attrs.get("incomplete_reason", "")
                lines.insert(0, f"INCOMPLETE: {reason}" if reason else "INCOMPLETE")
                data["complete"] = False
        out.append((Path(p).name, lines, data))
    return out


def summarize_written(written, reason: str | None = None) -> list[tuple[str, list[str], dict[str, Any]]]:
    """(file name, lines, data) of what a run handed back (``runs.status.Written``): its analysis's summary of its
    result, under the name of the analysis's file; ``reason``: the run stopped early (an INCOMPLETE line first)."""
    from ..registry import analysis

    if written.result is None:  # TRANSITION: a run that hands back its paths only: read the files
        found = summarize(list(written.paths))
        return found
    fn = summary_of(written.analysis)
    if fn is None:
        return []
    lines, data = fn(written.result)
    if reason is not None:
        lines.insert(0, f"INCOMPLETE: {reason}" if reason else "INCOMPLETE")
        data["complete"] = False
    stem = analysis(written.analysis).stem
    name = next((p.name for p in written.paths if p.stem == stem and p.suffix == ".h5"), f"{stem}.h5")
    return [(name, lines, data)]


def scalar(x) -> float:
    return float(np.asarray(x))


def transient(f):
    g = f["transient"]
    t, x = g["time_s"][:], g["displacement_m"][:]
    a = g.attrs
    late = t >= t[-1] / 2
    amp = np.max(np.abs(x[late] - x[late].mean(axis=0)), axis=0) if late.any() else np.full(2, np.nan)
    settled = bool(a["settled"]) if "settled" in a else None
    lines = [f"{t[-1]:.4g} s simulated ({a.get('method', '')}, {int(len(t))} samples); "
             f"vibration amplitude over the last half x {amp[0] * 1e6:.4g} um, y {amp[1] * 1e6:.4g} um"
             + (" (NOT SETTLED: not a steady amplitude)" if settled is False else "")]
    data = {"duration_s": float(t[-1]), "amplitude_m": amp.tolist()}
    bearings = list(g.get("bearings", {}))
    lines += _transient_settling(a, data, bearings)
    if "thermal_equilibrium_rpm" in a:
        rpm = float(scalar(a["thermal_equilibrium_rpm"]))
        lines.append(f"  bearings at the spindle's thermal equilibrium of {rpm:g} rpm (deck spindle_thermal)")
        data["thermal_equilibrium_rpm"] = rpm
    fr = g["spectrum/frequency_hz"][:] if "spectrum" in g else np.zeros(0)
    if len(fr) > 1:
        A = g["spectrum/amplitude_m"][:]
        k = int(np.argmax(np.max(A, axis=1)[1:])) + 1
        df = float(fr[1] - fr[0])
        lines.append(f"  dominant line {with_resolution(fr[k], df / 2, 'Hz')}, {np.max(A[k]) * 1e6:.4g} um"
                     + (" (of a response that has NOT SETTLED)" if settled is False else ""))
        data["dominant_hz"] = float(fr[k])
    elif "spectrum" in g:
        lines.append("  no spectrum: not enough steady data")
    if "poincare" in g and "periodicity" in g["poincare"].attrs:
        lines.append("  " + _poincare_words(g["poincare"].attrs, bearings))
        data["poincare_periodicity"] = str(g["poincare"].attrs["periodicity"])
    for key in ("roller_pass_frequency_hz", "cage_frequency_hz"):
        if key in a:
            data[key] = float(a[key])
    if "roller_pass_frequency_hz" in a:
        lines.append(f"  roller pass {float(a['roller_pass_frequency_hz']):.2f} Hz, cage {float(a['cage_frequency_hz']):.2f} Hz")
    return lines, data


def _transient_settling(a, data: dict, bearings: list[str]) -> list[str]:
    """What the file says of the steady part: settled or not, and the spectrum's resolution."""
    if "settling_note" not in a:
        return []
    note = str(a["settling_note"]).replace("not settled:", "NOT SETTLED:", 1)
    head = f"  steady part from {float(a['settle_s']):.4g} s"
    dur = float(a.get("steady_duration_s", 0.0))
    if dur > 0 and "frequency_resolution_hz" in a:
        head += f" ({dur:.4g} s long, spectrum bin {float(a['frequency_resolution_hz']):.3g} Hz)"
        data["frequency_resolution_hz"] = float(a["frequency_resolution_hz"])
    data["settled"] = bool(a["settled"])
    data["steady_duration_s"] = dur
    unresolved = str(a.get("unresolved_frequencies", ""))
    data["unresolved_frequencies"] = [u for u in unresolved.split(", ") if u]
    out = [f"{head}: {note}"]
    if a.get("resolution_note", ""):
        note = readable_keys(str(a["resolution_note"]), bearings)
        out.append("  " + note.replace("window too short", "WINDOW TOO SHORT", 1))
    return out


def _poincare_words(p, bearings: list[str]) -> str:
    """The primary Poincare set's periodicity, with its tolerance, from its group's attributes."""
    label, n = str(p["periodicity"]), int(p.get("classified_points", 0))
    rel = float(p.get("relative_tolerance", np.nan))
    tol = f"tolerance {float(p['tolerance_m']):.3g} m" + (f" = {100 * rel:.2g} % of the orbit" if np.isfinite(rel)
                                                           else "")
    sampling = str(p.get("sampling", ""))
    if sampling.startswith("once per "):
        sampling = "once per " + frequency_label(sampling[len("once per "):], bearings)
    s = f"Poincare {sampling}: {label}"
    if label.startswith("period-"):
        k = int(p["period"])
        ext = float(p.get("orbit_extent_m", 0.0))
        within = (f"all within {100 * float(p['spread_m']) / ext:.2g} % of the orbit size of their mean"
                  if k == 1 and ext > 0 else f"on {k} places")
        return s + f" ({n} points, {within}; {tol})"
    if n:
        return s + f" ({int(p['distinct_points'])} distinct places among {n} points; {tol})"
    return s


def chatter(f):
    g = f["chatter"]
    a = g.attrs
    lines = [f"{a['process']}; FRF from {a['frf_source']}" + (" recomputed at every speed" if a.get("frf_at_each_speed")
                                                              else "")]
    if "lobes" in a:  # interrupted before the lobes: the tool-point FRF only
        lines.append(f"  lobes: {a['lobes']}; the tool-point FRF is written" + (
            f" (node {int(a['tool_point_node'])})" if "tool_point_node" in a else ""))
        return lines, {}
    lines.append(f"  method: {a.get('method_selection') or str(a['method']).replace('_', ' ')}")
    data: dict[str, Any] = {"method": str(a["method"])}
    if "method" in g:
        used = [str(m) for m in g["method"].asstr()[:]]
        counts = {m: used.count(m) for m in dict.fromkeys(used)}
        if len(counts) > 1:
            lines.append("  limits from " + ", ".join(f"{m.replace('_', ' ')} at {k} speed(s)" for m, k in counts.items()))
    below = ""
    if "thermal_speed_limit_rpm" in a:
        lim = float(a["thermal_speed_limit_rpm"])
        below = f" (up to the thermal speed limit, {lim:,.0f} rpm)"
        data["thermal_speed_limit_rpm"] = lim
    if "minimum_limit_depth_m" in a:
        d, s = float(a["minimum_limit_depth_m"]), float(a["minimum_at_speed_rpm"])
        lines.append(f"  minimum limit depth {d * 1e3:.3g} mm at {s:,.0f} rpm{below}")
        data.update(minimum_limit_depth_m=d, minimum_at_speed_rpm=s)
    if int(a.get("capped_speeds", 0)):
        lines.append(f"  {int(a['capped_speeds'])} speed(s) stable up to the depth cap "
                     f"{float(a['depth_cap_m']) * 1e3:.3g} mm (the largest depth searched; no limit below it): "
                     f"{a.get('capped_speeds_rpm', '')}")
    if "recommended_speed_rpm" in a:
        n, tol = float(a["recommended_speed_rpm"]), float(a["recommended_speed_tolerance_rpm"])
        dep, peak = float(a["recommended_depth_m"]), float(a["pocket_peak_depth_m"])
        lines.append(f"  recommended: {n:,.0f} rpm +- {tol:,.0f} rpm at up to {dep * 1e3:.3g} mm (stability pocket "
                     f"{float(a['pocket_speed_min_rpm']):,.0f}-{float(a['pocket_speed_max_rpm']):,.0f} rpm, where the "
                     f"limit stays at or above {float(a['pocket_level']):.0%} of the pocket's "
                     f"{'>= ' if bool(a['pocket_capped']) else ''}{peak * 1e3:.3g} mm)")
        if int(a.get("pocket_grid_speeds", 3)) < 3:
            lines.append(f"    (no pocket holds 3 or more grid speeds; this one {int(a['pocket_grid_speeds'])}: refine the "
                         "speed grid around it before relying on it)")
        data.update(recommended_speed_rpm=n, recommended_depth_m=dep, recommended_speed_tolerance_rpm=tol)
    elif "recommendation" in a:
        lines.append(f"  recommended: {a['recommendation']}")
    if "stability_map" in a:
        lines.append(f"  stability map: {a['stability_map']}")
    for name in g.get("simulation", {}):
        s = g["simulation"][name].attrs
        state = "stable" if s["stable"] else f"CHATTER at {float(s['chatter_frequency_hz']):.0f} Hz"
        basis = str(s["verdict"]).partition(": ")[2] if "verdict" in s else ""
        lines.append(f"  simulation {float(s['speed_rpm']):g} rpm, {float(s['depth_m']) * 1e3:g} mm: {state}"
                     + (f" ({basis})" if basis else ""))
    return lines, data
