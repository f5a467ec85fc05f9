"""``report.html``: one self-contained page of a ``spindlesim run`` to hand to a colleague.

In order: the deck's title and the run's status; the provenance (version, deck file and SHA-256,
times, command line, platform, read from the HDF5 files' root attributes); every analysis with
its status and files; the failures (the run goes on after one) with their messages; the warnings
logged during the run and the deck's plausibility warnings; then one section per analysis with
its key results (the summaries the terminal prints, of the results the runs handed back,
:func:`~.summary.summarize_written`; a study another command wrote beside the run, calibration.h5 or
optimize/, from its file: nothing is recomputed here) and its figures with captions; last the deck text
(collapsed on screen, printed in full).

Figures are embedded as PNG data URIs, the style sheet is inline (output/report_style.py) and
there is no script, font or other request: the file opens in a browser offline and prints to PDF
(each analysis starts a page, a figure is never split).  Every text that comes from the deck, the
files or a message is HTML-escaped.

Usage (``spindlesim/commands/run.py``)::

    with RunReport(loaded, run_info, outdir, names) as report:   # collects log warnings meanwhile
        for name in names:
            done = perform_analysis(name, ...)
            report.done(name, done.paths, done)                  # or .incomplete / .failed / .interrupted
    report.write()                                               # outdir/report.html, atomically
"""

from __future__ import annotations

import base64
import datetime
import html
import logging
import re
import struct
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Sequence

from .report_style import CSS

log = logging.getLogger(__name__)

REPORT_NAME = "report.html"
#: distinct warnings kept (a warning repeated at every speed of a sweep is one row with a count)
MAX_WARNINGS = 200

DONE, INCOMPLETE, FAILED, INTERRUPTED, NOT_RUN = "finished", "incomplete", "failed", "interrupted", "not run"

#: what a figure shows, by file stem (a stem ending in a bearing name matches its prefix)
CAPTIONS: dict[str, str] = {
    "static_deflection": "Static deflection of the rotor under the applied loads, with the bearing reactions",
    "optimize_history": "Optimisation: each objective over the evaluations, the best feasible design so far",
    "optimize_parallel": "Optimisation: parallel coordinates of the feasible designs, the best or the Pareto set",
    "optimize_pareto": "Optimisation: the Pareto front with the deck's own design",
    "modal_shapes": "Damped mode shapes at the operating speed",
    "campbell": "Campbell diagram: natural frequencies over speed, 1x line and critical speeds",
    "campbell_frozen": "Campbell diagram with the bearings frozen at their state at rest",
    "frf_magnitude_phase": "Frequency response: magnitude and phase",
    "frf_real_imag": "Frequency response: real and imaginary parts",
    "frf_tool_point": "Tool-point frequency response",
    "unbalance": "Synchronous unbalance response over speed",
    "thermal_pressure_": "Film pressure at thermal equilibrium, bearing",
    "coefficients_": "Stiffness and damping coefficients against the Sommerfeld number, bearing",
    "transient_time": "Time history of the response",
    "transient_orbit": "Orbit",
    "transient_spectrum": "Spectrum of the steady response",
    "transient_run_up": "Run-up",
    "transient_poincare": "Poincare map (once per revolution)",
    "chatter_lobes": "Stability lobes: limit depth of cut over spindle speed",
    "chatter_frf": "Tool-point FRF used for the stability lobes",
    "tools_frf": "Tool library: each tool's tip receptance on the spindle (receptance coupling)",
    "tools_lobes": "Tool library: each tool's stability lobes, minimum and recommended speed",
    "calibration_frf": "Calibration: measured FRFs, the deck's model and the calibrated model",
    "fitmodes_stabilisation": "Modal identification: stabilisation diagram (LSCF poles by model order) and the modes",
    "fitmodes_overlay": "Modal identification: measured and fitted receptance (magnitude, phase, real, imaginary)",
    "impact_records": "Tap test: force and response of every impact, the ones left out and why",
    "impact_frf": "Tap test: H1 receptance and its coherence from the accepted impacts",
    "chatter_stability_map": "Stability map",
    "contact_pressure": "Contact pressure on the raceway",
    "contact_roller": "Roller profile and contact",
    "dtrb_load_distribution": "Roller load distribution",
    "dtrb_stiffness_preload": "Stiffness over preload",
    "dtrb_stiffness_radial": "Stiffness over radial load",
    "campbell_thermal": "Campbell diagram at the spindle's thermal equilibrium of every speed beside the cold "
                        "bearings, with the bearings' radial stiffness",
    "thermal_speeds": "Thermal equilibrium over speed: ring and motor temperatures, operating preload, tool-tip "
                      "axial drift; the runaway speed marked",
    "thermal_warm_up": "Warm-up through the speed steps: temperatures, preload, tool-tip axial drift (ISO 230-3 "
                       "style), natural frequencies and the stable depth of cut at the running speed",
    "chatter_simulation_": "Time-domain simulation of the cut (vibration, spectrum, once-per-tooth Poincare set), "
                           "check",
    "ball_load_distribution": "Ball loads and contact angles around the bearing",
    "ball_contact_ellipses": "Contact ellipses of the balls against the raceway shoulders",
    "ball_stiffness_vs_preload": "Bearing stiffness over preload",
    "ball_stiffness_vs_speed": "Bearing stiffness over speed",
    "ball_contact_angles_vs_speed": "Contact angles over speed (mean over the balls, band: their range)",
    "sweep_scalars": "Key results of the sweep's cases",
    "sweep_": "Every case of the sweep on one figure:",
    "transient_": "Bearing output in time:",
}
#: summary words that deserve a reader's eye
_ALERT = re.compile(r"UNSTABLE|NOT MET|WARNING|INCOMPLETE|CHATTER|EDGE STRESS")


@dataclass
class Outcome:
    """How one analysis of the run ended and what it wrote."""

    name: str
    status: str = NOT_RUN
    paths: list[Path] = field(default_factory=list)
    message: str = ""
    #: what the run handed back (``runs.status.Written``: its result), None for a study read from its file
    written: Any = None
    #: an incomplete run's reason as its files carry it
    noted: str | None = None


@dataclass
class LoggedWarning:
    source: str  # "deck" or the logger's name
    analysis: str  # the analysis running when it was logged ("" before the first)
    level: str
    message: str
    count: int = 1


class _Collector(logging.Handler):
    """Warnings (and worse) logged by spindlesim while the run goes on."""

    def __init__(self, report: "RunReport"):
        super().__init__(logging.WARNING)
        self.report = report

    def emit(self, record: logging.LogRecord) -> None:
        try:
            message = record.getMessage()
        except Exception:  # noqa: BLE001 - a bad format string is still a warning worth showing
            message = str(record.msg)
        self.report.add_warning(record.name, record.levelname, message)


class RunReport:
    """What a ``spindlesim run`` did, collected as it goes; :meth:`write` makes ``report.html``.

    As a context manager it listens to the ``spindlesim`` loggers for warnings; each is attributed
    to the analysis running at the time (the first of ``names`` not yet given an outcome)."""

    def __init__(self, loaded: Any, run: Any, outdir: str | Path, names: Sequence[str]):
        self.loaded, self.run, self.outdir = loaded, run, Path(outdir)
        self.names = list(names)
        self.outcomes: list[Outcome] = []
        self.warnings: dict[tuple[str, str, str, str], LoggedWarning] = {}
        self._handler = _Collector(self)
        for w in getattr(loaded, "warnings", ()):
            self.add_warning("deck", "WARNING", str(w), analysis="")

    def __enter__(self) -> "RunReport":
        logging.getLogger("spindlesim").addHandler(self._handler)
        return self

    def __exit__(self, *exc: Any) -> None:
        logging.getLogger("spindlesim").removeHandler(self._handler)

    # --- outcomes, in the order of ``names`` ---
    def done(self, name: str, paths: Iterable[Path], written: Any = None) -> None:
        self.outcomes.append(Outcome(name, DONE, [Path(p) for p in paths], written=written))

    def incomplete(self, name: str, paths: Iterable[Path], reason: str, written: Any = None,
                   noted: str | None = None) -> None:
        self.outcomes.append(Outcome(name, INCOMPLETE, [Path(p) for p in paths], reason, written, noted))

    def failed(self, name: str, error: BaseException | str) -> None:
        message = error if isinstance(error, str) else f"{type(error).__name__}: {error}"
        self.outcomes.append(Outcome(name, FAILED, [], message))

    def interrupted(self, name: str) -> None:
        self.outcomes.append(Outcome(name, INTERRUPTED, [], "interrupted by the user (Ctrl-C)"))

    def add_warning(self, source: str, level: str, message: str, analysis: str | None = None) -> None:
        if analysis is None:
            k = len(self.outcomes)
            analysis = self.names[k] if k < len(self.names) else ""
        key = (source, analysis, level, message)
        if key in self.warnings:
            self.warnings[key].count += 1
        elif len(self.warnings) < MAX_WARNINGS:
            self.warnings[key] = LoggedWarning(source, analysis, level, message)

    def all_outcomes(self) -> list[Outcome]:
        """The outcomes given, then the analyses never started (after Ctrl-C or a deck error)."""
        return self.outcomes + [Outcome(n) for n in self.names[len(self.outcomes):]]

    def write(self) -> Path:
        """Write ``report.html`` into the output folder (temporary file, then rename); returns its path."""
        page = render(self)
        path = self.outdir / REPORT_NAME
        from .hdf5 import write_text_atomic

        write_text_atomic(path, page)
        log.info("wrote %s (%d kB)", path, len(page.encode()) // 1024)
        return path


# ----------------------------------------------------------------------------------------------
# reading the files


def _text(v: Any) -> str:
    return v.decode("utf-8", "replace") if isinstance(v, bytes) else str(v)


def file_provenance(paths: Iterable[Path]) -> dict[str, Any]:
    """Root attributes of the HDF5 files: those of the first, the range of their times, and the files
    whose run is incomplete (with the reason)."""
    import h5py

    first: dict[str, str] = {}
    times: list[str] = []
    incomplete: list[tuple[str, str]] = []
    for p in paths:
        if Path(p).suffix != ".h5":
            continue
        try:
            with h5py.File(p, "r") as f:
                attrs = {k: _text(f.attrs[k]) for k in f.attrs if k != "deck_text"}
                complete = bool(f.attrs.get("complete", True))
        except OSError as exc:
            log.warning("report: cannot read %s: %s", p, exc)
            continue
        first = first or attrs
        if "created_utc" in attrs:
            times.append(attrs["created_utc"])
        if not complete:
            incomplete.append((Path(p).name, attrs.get("incomplete_reason", "")))
    return {"attrs": first, "times": sorted(times), "incomplete": incomplete}


def _summaries(path: Path) -> tuple[list[str] | None, str]:
    """The summary lines of one HDF5 file (None when it has no summary) or why there are none."""
    from .summary import has_summary, summarize

    if not has_summary(path):
        return None, ""
    try:
        found = summarize([path])
    except Exception as exc:  # noqa: BLE001 - a summary must never hide the rest of the report
        log.warning("report: no summary of %s: %s", path.name, exc)
        return None, f"summary unavailable: {exc}"
    return (found[0][1] if found else None), ""


def _result_summary(o: Outcome) -> dict[str, tuple[list[str] | None, str]]:
    """file name -> (summary lines, why none) of the result the analysis's run handed back."""
    if o.written is None or o.written.result is None:
        return {}
    from .summary import summarize_written

    try:
        found = summarize_written(o.written, o.noted if o.status == INCOMPLETE else None)
    except Exception as exc:  # noqa: BLE001 - a summary must never hide the rest of the report
        log.warning("report: no summary of %s: %s", o.name, exc)
        stem = next((p.name for p in o.paths if p.suffix == ".h5"), "")
        return {stem: (None, f"summary unavailable: {exc}")}
    return {name: (lines, "") for name, lines, _ in found}


def png_data_uri(path: Path) -> tuple[str, int, int]:
    """The PNG as a ``data:`` URI with its pixel width and height (0, 0 if the header is not a PNG's)."""
    data = path.read_bytes()
    w = h = 0
    if data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR":
        w, h = struct.unpack(">II", data[16:24])
    return "data:image/png;base64," + base64.b64encode(data).decode("ascii"), w, h


def caption(path: Path) -> str:
    stem = path.stem
    if stem in CAPTIONS:
        return CAPTIONS[stem]
    for key, text in CAPTIONS.items():
        if key.endswith("_") and stem.startswith(key):
            return f"{text} {stem[len(key):]}"
    return stem.replace("_", " ").capitalize()


# ----------------------------------------------------------------------------------------------
# the page

e = html.escape


def _now() -> str:
    return datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")


def _anchor(k: int, name: str) -> str:
    return f"a{k}-" + re.sub(r"[^A-Za-z0-9_-]", "_", name)


def _status_line(outcomes: list[Outcome]) -> tuple[bool, str]:
    counts: dict[str, list[str]] = {}
    for o in outcomes:
        counts.setdefault(o.status, []).append(o.name)
    if set(counts) <= {DONE}:
        return True, f"complete: {len(outcomes)} {'analysis' if len(outcomes) == 1 else 'analyses'} finished"
    parts = [f"{len(v)} {s} ({', '.join(v)})" for s, v in counts.items() if s != DONE]
    done = len(counts.get(DONE, []))
    return False, f"incomplete: {done} of {len(outcomes)} finished; " + "; ".join(parts)


def _row(key: str, value: str, cls: str = "") -> str:
    return f"<tr><th scope=\"row\">{e(key)}</th><td" + (f" class=\"{cls}\"" if cls else "") + f">{e(value)}</td></tr>"


def _provenance(report: RunReport, outcomes: list[Outcome], ok: bool, status: str) -> str:
    from .hdf5 import provenance

    fp = file_provenance(p for o in outcomes for p in o.paths)
    a, times, now = fp["attrs"], fp["times"], provenance()
    written = (times[0] if times[0] == times[-1] else f"{times[0]} to {times[-1]}") if times else "no file written"
    rows = [
        _row("Status", status, "ok" if ok else "bad"),
        _row("spindlesim version", a.get("spindlesim_version", now["spindlesim_version"])),
        _row("Deck file", report.run.deck_source),
        _row("Deck SHA-256", a.get("deck_sha256", report.run.deck_sha256), "mono"),
        _row("Results written (UTC)", written),
        _row("Report written (UTC)", _now()),
        _row("Command line", a.get("command_line", report.run.command_line), "mono"),
        _row("Output folder", str(report.outdir)),
    ]
    rows += [_row(f"Incomplete file {name}", reason or "no reason given", "bad") for name, reason in fp["incomplete"]]
    libs = ", ".join(f"{k.removesuffix('_version')} {a.get(k, now.get(k, '?'))}"
                     for k in ("python_version", "numpy_version", "scipy_version", "h5py_version", "numba_version"))
    rows += [_row("Platform", a.get("platform", now["platform"])), _row("Libraries", libs)]
    return "<section id=\"provenance\"><h2>Provenance</h2><table class=\"kv\">" + "".join(rows) + "</table></section>"


def _verdicts(report: RunReport, outcomes: list[Outcome]):
    """The verdicts of the results the runs handed back (analysis.verdicts), filed under each outcome's name."""
    from ..analysis.verdicts import verdicts_of
    from ..deck.describe import operating_range

    return verdicts_of([(o.name, o.written.analysis, o.written.result) for o in outcomes if o.written is not None],
                       operating_range(report.loaded.deck))


def _verdict_table(found, outcomes: list[Outcome]) -> str:
    """The verdicts at the top of the page, each linking to the section of the analysis that says it."""
    if not found:
        return ""
    anchors = {o.name: _anchor(k, o.name) for k, o in enumerate(outcomes)}
    rows = []
    for v in found:
        topic = f"<a href=\"#{anchors[v.analysis]}\">{e(v.topic)}</a>" if v.analysis in anchors else e(v.topic)
        rows.append(f"<tr><td>{topic}</td><td class=\"st {_VERDICT_CLS[v.status]}\">{e(v.text)}</td></tr>")
    return ("<section id=\"verdicts\"><h2>Verdicts</h2><table class=\"grid verdicts\"><thead><tr><th>what</th>"
            "<th>verdict</th></tr></thead><tbody>" + "".join(rows) + "</tbody></table></section>")


_VERDICT_CLS = {"ok": "ok", "warn": "warn", "bad": "bad", "info": "info"}


def _overview(outcomes: list[Outcome]) -> str:
    rows = []
    for k, o in enumerate(outcomes):
        files = ", ".join(p.name for p in o.paths) or "none"
        target = _anchor(k, o.name) if o.status in (DONE, INCOMPLETE) else "failures" if o.message else ""
        name = f"<a href=\"#{target}\">{e(o.name)}</a>" if target else e(o.name)
        rows.append(f"<tr><td>{name}</td><td class=\"st {_cls(o.status)}\">{e(o.status)}</td>"
                    f"<td class=\"files\">{e(files)}</td></tr>")
    return ("<section id=\"analyses\"><h2>Analyses</h2><table class=\"grid\"><thead><tr><th>analysis</th>"
            "<th>status</th><th>files</th></tr></thead><tbody>" + "".join(rows) + "</tbody></table></section>")


def _cls(status: str) -> str:
    return {DONE: "ok", INCOMPLETE: "warn"}.get(status, "bad")


def _warning_row(w: LoggedWarning) -> str:
    level = f"<strong class=\"bad\">{e(w.level)}</strong> " if w.level not in ("WARNING", "") else ""
    count = f" <span class=\"count\">({w.count} times)</span>" if w.count > 1 else ""
    return f"<tr><td>{e(w.analysis or '-')}</td><td>{e(w.source)}</td><td>{level}{e(w.message)}{count}</td></tr>"


def _problems(outcomes: list[Outcome], warnings: list[LoggedWarning]) -> str:
    failed = [o for o in outcomes if o.status in (FAILED, INTERRUPTED, INCOMPLETE)]
    out = []
    if failed:
        items = "".join(f"<li><strong>{e(o.name)}</strong> {e(o.status)}: <span class=\"mono\">{e(o.message)}</span></li>"
                        for o in failed)
        out.append("<section id=\"failures\"><h2>Failures</h2><p>The run went on after each failure; a failed "
                   f"analysis wrote no file.</p><ul class=\"failures\">{items}</ul></section>")
    if warnings:
        rows = "".join(_warning_row(w) for w in warnings)
        more = "" if len(warnings) < MAX_WARNINGS else f"<p>Only the first {MAX_WARNINGS} distinct warnings are listed.</p>"
        out.append("<section id=\"warnings\"><h2>Warnings</h2><table class=\"grid\"><thead><tr><th>during</th>"
                   f"<th>from</th><th>message</th></tr></thead><tbody>{rows}</tbody></table>{more}</section>")
    return "".join(out)


def _summary_block(lines: list[str]) -> str:
    body = "\n".join(f"<span class=\"alert\">{e(s)}</span>" if _ALERT.search(s) else e(s) for s in lines)
    return f"<pre class=\"summary\">{body}</pre>"


def _analysis(k: int, o: Outcome, figure_no: list[int]) -> str:
    parts = [f"<section class=\"analysis\" id=\"{_anchor(k, o.name)}\"><h2>{e(o.name)} "
             f"<span class=\"st {_cls(o.status)}\">{e(o.status)}</span></h2>"]
    if o.message:
        parts.append(f"<p class=\"note {_cls(o.status)}\">{e(o.message)}</p>")
    from_result = _result_summary(o)
    for p in o.paths:
        if p.suffix == ".h5":
            lines, why = from_result[p.name] if p.name in from_result else _summaries(p)
            parts.append(f"<h3>Key results <span class=\"file\">{e(p.name)}</span></h3>")
            parts.append(_summary_block(lines) if lines else f"<p>{e(why or 'no summary for this file')}</p>")
    for p in o.paths:
        if p.suffix == ".png":
            figure_no[0] += 1
            text = f"Figure {figure_no[0]}. {caption(p)} ({p.name})"
            try:
                uri, w, h = png_data_uri(p)
            except OSError as exc:
                log.warning("report: cannot read figure %s: %s", p, exc)
                parts.append(f"<p class=\"note bad\">{e(text)}: not readable ({e(str(exc))})</p>")
                continue
            size = f" width=\"{w}\" height=\"{h}\"" if w and h else ""
            parts.append(f"<figure><img src=\"{uri}\" alt=\"{e(caption(p))}\"{size}>"
                         f"<figcaption>{e(text)}</figcaption></figure>")
    others = [p.name for p in o.paths if p.suffix not in (".h5", ".png")]
    if others:
        parts.append(f"<p>Other files: {e(', '.join(others))}</p>")
    parts.append("</section>")
    return "".join(parts)


def _deck(report: RunReport) -> str:
    text = report.run.deck_text
    n = len(text.splitlines())
    return (f"<section id=\"deck\"><h2>Deck</h2><details><summary>Deck text: {e(report.run.deck_source)}, {n} lines "
            f"(SHA-256 {e(report.run.deck_sha256[:12])}...)</summary><pre class=\"deck\">{e(text)}</pre></details>"
            "</section>")


def _header(title: str, ok: bool, status: str, problems: bool, n_warnings: int, found=()) -> str:
    from .. import __version__

    if n_warnings:
        status += f"; {n_warnings} warning{'s' if n_warnings != 1 else ''}"
    failing = [v.topic for v in found if v.status == "bad"]
    if failing:  # the run finished, the spindle does not pass: the banner says so first
        status = f"NOT MET: {', '.join(failing)}. " + status
        ok = False
    links = [("verdicts", "Verdicts")] * bool(found) + [("provenance", "Provenance"), ("analyses", "Analyses")] \
        + [("failures", "Failures")] * problems \
        + [("warnings", "Warnings")] * bool(n_warnings) + [("deck", "Deck")]
    nav = " ".join(f"<a href=\"#{a}\">{t}</a>" for a, t in links)
    return (f"<header><p class=\"kicker\">spindlesim {e(__version__)} run report</p><h1>{e(title)}</h1>"
            f"<p class=\"banner {'ok' if ok else 'bad'}\">{e(status)}</p><nav>{nav}</nav></header>")


def render(report: RunReport) -> str:
    """The whole page as one string."""
    outcomes = report.all_outcomes()
    ok, status = _status_line(outcomes)
    title = str(getattr(report.loaded.deck, "title", "") or "untitled")
    warnings = list(report.warnings.values())
    problems = any(o.status in (FAILED, INTERRUPTED, INCOMPLETE) for o in outcomes)
    figure_no = [0]
    found = _verdicts(report, outcomes)
    body = [_header(title, ok, status, problems, len(warnings), found), "<main>", _verdict_table(found, outcomes),
            _provenance(report, outcomes, ok, status), _overview(outcomes), _problems(outcomes, warnings)]
    body += [_analysis(k, o, figure_no) for k, o in enumerate(outcomes) if o.status in (DONE, INCOMPLETE)]
    body += [_deck(report), "</main><footer>Written by spindlesim from the files of this run; the figures are "
             "embedded: the page needs no network and no other file.</footer>"]
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            f"<title>{e(title)}: spindlesim report</title><link rel=\"icon\" href=\"data:,\">"
            f"<style>{CSS}</style></head>\n<body>\n" + "\n".join(body) + "\n</body></html>\n")
