"""Short result summaries for the terminal and the report, of the results the analyses return.

A run hands back its analysis's frozen result (``runs.status.Written``); :func:`summarize_written` calls the
summary the registry names for that analysis (spindlesim/registry.py) on the result itself, so what a user reads
is what the analysis computed, every number and verdict computed once, in the analysis (the summary formats, it
never re-reads the deck or decides again).  Each summary returns ``(lines, data)``: a few text lines and the same
numbers as a JSON-able dict.  The rotor's summaries are in rotor_summary.py, the bearings' in bearing_summary.py, a
spindle's thermal model's in thermal_summary.py, the tool library's in tools_summary.py, the transient's and
chatter's here.  The studies of ``calibrate`` and ``optimize`` are summarised from their files
(:func:`summarize`): ``run``'s report shows them when an earlier command wrote them beside the run.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Any, Callable

import numpy as np

from ..registry import file_summaries, study_files
from .labels import frequency_label, readable_keys
from .numbers import with_resolution

#: analysis (or a study command's file stem) -> "module:function" in spindlesim.output: the summary of its result
#: (of a study's file)
SUMMARIES: dict[str, str] = file_summaries()
#: the stems of the files the study commands write (calibration, optimize): summarised from the file
STUDY_FILES: tuple[str, ...] = study_files()


def summary_of(name: str) -> Callable | None:
    """The summary function of the analysis ``name`` (or of a command's files ``<name>.h5``), or None."""
    where = SUMMARIES.get(name)
    if where is None:
        return None
    module, function = where.split(":")
    return getattr(importlib.import_module(f"{__package__}.{module}"), function)


def has_summary(path: Path) -> bool:
    """Whether the file ``path`` is a study command's file that :func:`summarize` reads (by its name)."""
    return Path(path).suffix == ".h5" and Path(path).stem in STUDY_FILES


def summarize(paths: list[Path]) -> list[tuple[str, list[str], dict[str, Any]]]:
    """(file name, lines, data) of every study command's HDF5 file among ``paths`` (calibration.h5, optimize.h5:
    ``run``'s report shows the ones an earlier command wrote beside the run; there is no result in memory)."""
    import h5py

    out = []
    for p in paths:
        if not has_summary(p):
            continue
        with h5py.File(p, "r") as f:
            fn = summary_of(Path(p).stem)
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

    if written.result is None:  # an incomplete run that stopped before it had a result
        return []
    out = []
    stem = analysis(written.analysis).stem
    name = next((p.name for p in written.paths if p.stem == stem and p.suffix == ".h5"), f"{stem}.h5")
    for file, kind, result in ((name, written.analysis, written.result), *written.also):
        fn = summary_of(kind)
        if fn is None:
            continue
        lines, data = fn(result)
        if reason is not None and kind == written.analysis:
            lines.insert(0, f"INCOMPLETE: {reason}" if reason else "INCOMPLETE")
            data["complete"] = False
        out.append((file, lines, data))
    return out


def transient(study):
    """The run in time (``analysis.transient.result.TransientStudy``): its length, the vibration amplitude over the
    last half, whether it settled, the dominant spectral line, the Poincare set's periodicity."""
    res = study.result
    t, x = res.time_s, res.displacement_m
    late = t >= t[-1] / 2
    amp = np.max(np.abs(x[late] - x[late].mean(axis=0)), axis=0) if late.any() else np.full(2, np.nan)
    settled = bool(res.settling.settled) if res.settling is not None else None
    lines = [f"{t[-1]:.4g} s simulated ({res.method}, {int(len(t))} samples); "
             f"vibration amplitude over the last half x {amp[0] * 1e6:.4g} um, y {amp[1] * 1e6:.4g} um"
             + (" (NOT SETTLED: not a steady amplitude)" if settled is False else "")]
    data = {"duration_s": float(t[-1]), "amplitude_m": amp.tolist()}
    bearings = sorted(res.bearing_names)
    lines += _transient_settling(res, data, bearings)
    if study.thermal_equilibrium_rpm is not None:
        rpm = float(study.thermal_equilibrium_rpm)
        lines.append(f"  bearings at the spindle's thermal equilibrium of {rpm:g} rpm (deck spindle_thermal)")
        data["thermal_equilibrium_rpm"] = rpm
    fr = np.asarray(res.spectrum.frequency_hz)
    if len(fr) > 1:
        A = np.asarray(res.spectrum.amplitude)
        k = int(np.argmax(np.max(A, axis=1)[1:])) + 1
        df = float(fr[1] - fr[0])
        lines.append(f"  dominant line {with_resolution(fr[k], df / 2, 'Hz')}, {np.max(A[k]) * 1e6:.4g} um"
                     + (" (of a response that has NOT SETTLED)" if settled is False else ""))
        data["dominant_hz"] = float(fr[k])
    else:
        lines.append("  no spectrum: not enough steady data")
    if res.poincare and res.poincare[0].periodicity is not None:
        lines.append("  " + _poincare_words(res.poincare[0], bearings))
        data["poincare_periodicity"] = res.poincare[0].periodicity.label
    rp = [k for k in res.frequencies_hz if k.endswith(".roller_pass")]
    if rp:  # the rolling bearing's numbers (DESIGN.md section 5)
        roller_pass = float(res.frequencies_hz[rp[0]])
        cage = res.frequencies_hz.get(rp[0].replace("roller_pass", "cage"))
        data["roller_pass_frequency_hz"] = roller_pass
        if cage is not None:
            data["cage_frequency_hz"] = float(cage)
        lines.append(f"  roller pass {roller_pass:.2f} Hz, cage {float(cage):.2f} Hz")
    return lines, data


def _finite(v) -> bool:
    return v is not None and bool(np.isfinite(v))


def _transient_settling(res, data: dict, bearings: list[str]) -> list[str]:
    """What the run says of its steady part: settled or not, and the spectrum's resolution."""
    s = res.settling
    if s is None:
        return []
    note = str(s.note).replace("not settled:", "NOT SETTLED:", 1)
    head = f"  steady part from {float(res.settle_s):.4g} s"
    dur = float(s.duration_s) if _finite(s.duration_s) else 0.0
    if dur > 0 and _finite(s.resolution_hz):
        head += f" ({dur:.4g} s long, spectrum bin {float(s.resolution_hz):.3g} Hz)"
        data["frequency_resolution_hz"] = float(s.resolution_hz)
    data["settled"] = bool(s.settled)
    data["steady_duration_s"] = dur
    data["unresolved_frequencies"] = [k for k, _ in s.unresolved if k]
    out = [f"{head}: {note}"]
    if s.resolution_note:
        text = readable_keys(str(s.resolution_note), bearings)
        out.append("  " + text.replace("window too short", "WINDOW TOO SHORT", 1))
    return out


def _poincare_words(p, bearings: list[str]) -> str:
    """The primary Poincare set's periodicity (``PoincareSet``), with its tolerance."""
    q = p.periodicity
    label, n = str(q.label), int(q.points) if _finite(q.points) else 0
    rel = float(q.relative_tolerance) if _finite(q.relative_tolerance) else np.nan
    tol = f"tolerance {float(q.tolerance_m):.3g} m" + (f" = {100 * rel:.2g} % of the orbit" if np.isfinite(rel)
                                                        else "")
    s = f"Poincare once per {frequency_label(p.name, bearings)}: {label}"
    if label.startswith("period-"):
        k = int(q.period)
        ext = float(q.extent_m) if _finite(q.extent_m) else 0.0
        within = (f"all within {100 * float(q.spread_m) / ext:.2g} % of the orbit size of their mean"
                  if k == 1 and ext > 0 else f"on {k} places")
        return s + f" ({n} points, {within}; {tol})"
    if n:
        return s + f" ({int(q.distinct)} distinct places among {n} points; {tol})"
    return s


def chatter(study):
    """The lobes of a ``ChatterStudy`` (analysis.chatter_study): the method, the minimum limit depth, the speeds
    stable up to the depth cap, the recommended speed, the time-domain checks."""
    from ..analysis.chatter_study import NO_LOBES
    from ..chatter.results import speed_runs
    from .chatter_writer import MAP_NOT_ASKED

    info, res = study.info, study.result
    process = res.diagram.process if res is not None else study.spec.process.describe()
    lines = [f"{process}; FRF from {info['frf_source']}" + (" recomputed at every speed" if info.get("frf_at_each_speed")
                                                            else "")]
    if res is None:  # interrupted before the lobes: the tool-point FRF only
        lines.append(f"  lobes: {NO_LOBES}; the tool-point FRF is written" + (
            f" (node {int(info['node'])})" if "node" in info else ""))
        return lines, {}
    dg = res.diagram
    lines.append(f"  method: {dg.selection or str(dg.method).replace('_', ' ')}")
    data: dict[str, Any] = {"method": str(dg.method)}
    used = [str(m) for m in dg.method_per_speed]
    counts = {m: used.count(m) for m in dict.fromkeys(used)}
    if len(counts) > 1:
        lines.append("  limits from " + ", ".join(f"{m.replace('_', ' ')} at {k} speed(s)" for m, k in counts.items()))
    below = ""
    if res.speed_limit_rpm is not None:
        lim = float(res.speed_limit_rpm)
        below = f" (up to the thermal speed limit, {lim:,.0f} rpm)"
        data["thermal_speed_limit_rpm"] = lim
    if res.minimum is not None:
        s, d = (float(v) for v in res.minimum)
        lines.append(f"  minimum limit depth {d * 1e3:.3g} mm at {s:,.0f} rpm{below}")
        data.update(minimum_limit_depth_m=d, minimum_at_speed_rpm=s)
    capped = np.asarray(dg.capped, bool)
    if capped.any():
        lines.append(f"  {int(capped.sum())} speed(s) stable up to the depth cap {float(dg.depth_cap_m) * 1e3:.3g} mm "
                     f"(the largest depth searched; no limit below it): "
                     f"{speed_runs(np.asarray(dg.speed_rpm)[capped])}")
    r = res.recommendation if res.pockets else None
    if r is not None:
        n, tol, dep, peak = float(r.speed_rpm), float(r.tolerance_rpm), float(r.depth_m), float(r.peak_depth_m)
        lines.append(f"  recommended: {n:,.0f} rpm +- {tol:,.0f} rpm at up to {dep * 1e3:.3g} mm (stability pocket "
                     f"{float(r.speed_min_rpm):,.0f}-{float(r.speed_max_rpm):,.0f} rpm, where the "
                     f"limit stays at or above {float(r.level):.0%} of the pocket's "
                     f"{'>= ' if bool(r.capped) else ''}{peak * 1e3:.3g} mm)")
        if int(r.grid_speeds) < 3:
            lines.append(f"    (no pocket holds 3 or more grid speeds; this one {int(r.grid_speeds)}: refine the "
                         "speed grid around it before relying on it)")
        data.update(recommended_speed_rpm=n, recommended_depth_m=dep, recommended_speed_tolerance_rpm=tol)
    else:
        lines.append(f"  recommended: {res.recommendation_text}")
    if dg.method == "semi_discretization":
        lines.append(f"  stability map: {'written' if dg.stability_map is not None else MAP_NOT_ASKED}")
    for sim in res.simulations:
        state = "stable" if sim.stable else f"CHATTER at {float(sim.chatter_frequency_hz):.0f} Hz"
        basis = str(sim.verdict).partition(": ")[2]
        lines.append(f"  simulation {float(sim.speed_rpm):g} rpm, {float(sim.depth_m) * 1e3:g} mm: {state}"
                     + (f" ({basis})" if basis else ""))
    return lines, data
