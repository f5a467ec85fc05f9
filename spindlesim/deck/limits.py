"""Limits on what a deck may ask for: the size of the text and of the work it describes.

A deck must fail fast with a located message, never hang a command or exhaust memory.  The
YAML reader enforces the first three limits (``deck/yamlmarks.py``); the schema bounds every list
length, count and grid size where the key is defined (the deck sections); :func:`work_checks`
bounds what only several keys together decide (the size of the rotor, the steps of a transient,
the cells of a contact grid).  docs/deck-format.md, "Limits", lists them all.
"""

from __future__ import annotations

from typing import Any

#: deck text, characters (about 4 MB)
MAX_TEXT_CHARS = 4_000_000
#: nesting of lists and mappings (the deepest deck path is about 6)
MAX_DEPTH = 32
#: values (scalars, lists, mappings) after alias expansion: stops "billion laughs" alias bombs
MAX_VALUES = 250_000
#: issues reported for one deck (the rest are counted)
MAX_ISSUES = 50
#: finite elements of the rotor: shaft + tool holder + tool (dense matrices of ~4 DOF per node)
MAX_ROTOR_ELEMENTS = 500
#: time steps of one transient run (duration / step)
MAX_TRANSIENT_STEPS = 10_000_000
#: output samples of one transient run (duration x sample rate)
MAX_TRANSIENT_SAMPLES = 2_000_000
#: load distributions of the dtrb section x rollers per row x slices (about 25 s at the limit)
MAX_DTRB_WORK = 2_000_000
#: cases of the deck's sweep section
MAX_SWEEP_CASES = 10_000
#: default largest steps of the transient engines [s] (analysis/transient/engine.py)
_RK4_STEP_S = 1e-6
_NEWMARK_STEP_S = 5e-5

Found = list[tuple[tuple[Any, ...], str]]


def _rows(d: Any) -> int:
    n = len(d.shaft.elements) if getattr(d, "shaft", None) is not None else 0
    tool = getattr(d, "tool", None)
    if tool is not None:
        n += len(tool.holder.elements) + len(tool.tool.elements)
    return n


def _transient_rig(sec: Any, bad: Found) -> None:
    it = sec.integrator
    step = it.step_us * 1e-6 if it.step_us is not None else _RK4_STEP_S
    steps = sec.duration_s / step
    if steps > MAX_TRANSIENT_STEPS:
        bad.append((("transient", "duration_s"), f"duration_s / step = {steps:.3g} time steps; the limit is "
                                                 f"{MAX_TRANSIENT_STEPS:g} (shorten the run or give a larger "
                                                 "integrator.step_us)"))
    if it.sample_rate_hz is not None and sec.duration_s * it.sample_rate_hz > MAX_TRANSIENT_SAMPLES:
        bad.append((("transient", "integrator", "sample_rate_hz"),
                    f"duration_s x sample_rate_hz = {sec.duration_s * it.sample_rate_hz:.3g} samples; the limit "
                    f"is {MAX_TRANSIENT_SAMPLES:g}"))


def _rotor_transient(rt: Any, bad: Found) -> None:
    step = rt.time_step_s
    if step is None:
        step = _NEWMARK_STEP_S if rt.method == "newmark" else _RK4_STEP_S
    steps = rt.duration_s / step
    if rt.method in ("newmark", "rk4") and steps > MAX_TRANSIENT_STEPS:
        bad.append((("rotor_transient", "duration_s"),
                    f"duration_s / time step = {steps:.3g} time steps; the limit is {MAX_TRANSIENT_STEPS:g}"))
    fs = rt.sample_rate_hz if rt.sample_rate_hz is not None else (1.0 / step if rt.method == "newmark" else None)
    if fs is not None and rt.duration_s * fs > MAX_TRANSIENT_SAMPLES:
        key = "sample_rate_hz" if rt.sample_rate_hz is not None else "time_step_s"
        bad.append((("rotor_transient", key), f"duration_s x sample rate = {rt.duration_s * fs:.3g} samples; "
                                              f"the limit is {MAX_TRANSIENT_SAMPLES:g}"))


def _dtrb(sec: Any, bad: Found) -> None:
    points = 1 + len(sec.polar_preloads_um) + len(sec.polar_radial_loads_N)
    points += sum(r.count for r in (sec.preload_sweep_um, sec.radial_sweep_N) if r is not None)
    work = points * sec.bearing.rollers_per_row * sec.bearing.slices
    if work > MAX_DTRB_WORK:
        bad.append((("dtrb",), f"{points} load cases (sweep points and polar plots) x {sec.bearing.rollers_per_row} "
                               f"rollers x {sec.bearing.slices} slices = {work:.3g}; the limit is {MAX_DTRB_WORK:g} "
                               "(fewer sweep points or slices)"))


def _sweep(sw: Any, bad: Found) -> None:
    sizes = [len(v) if isinstance(v, list) else v.count for v in sw.parameters.values()]
    cases = max(sizes) if sw.mode == "list" else 1
    if sw.mode != "list":
        for n in sizes:
            cases *= n
    if cases > MAX_SWEEP_CASES:
        bad.append((("sweep", "parameters"), f"{cases:.3g} cases; the limit is {MAX_SWEEP_CASES}"))


def work_checks(d: Any) -> Found:
    """(key path, message) for every limit of :mod:`this module <spindlesim.deck.limits>` a valid deck exceeds."""
    bad: Found = []
    n = _rows(d)
    if n > MAX_ROTOR_ELEMENTS:
        where = ("shaft", "elements") if getattr(d, "shaft", None) is not None else ("tool",)
        bad.append((where, f"the rotor has {n} elements (shaft, holder and tool); the limit is {MAX_ROTOR_ELEMENTS}"))
    if getattr(d, "transient", None) is not None:
        _transient_rig(d.transient, bad)
    if getattr(d, "rotor_transient", None) is not None:
        _rotor_transient(d.rotor_transient, bad)
    if getattr(d, "dtrb", None) is not None:
        _dtrb(d.dtrb, bad)
    if getattr(d, "sweep", None) is not None:
        _sweep(d.sweep, bad)
    return bad
