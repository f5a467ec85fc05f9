"""Run a sweep: every case in its own directory, finished cases skipped, failures recorded.

A case is finished when ``cases/<key>/case.json`` says ``"status": "done"`` *and* every HDF5
file it lists is there with ``complete = True``; the key hashes the resolved deck text,
analysis and options, so re-running an interrupted sweep runs only what is missing, and
changing a deck value makes a new case.

Case statuses: ``done``; ``failed`` (the run raised: solver or deck error, or the worker died);
``incomplete`` (the run wrote files marked complete = False, e.g. an integration that stopped);
``interrupted`` (running when the sweep was stopped); ``not run`` (never started; only in the
summary).  Everything but ``done`` is run again on resume.

Ctrl-C (SIGINT, to the parent alone or to the whole process group): no queued case is started,
the running ones are stopped (``execution``), each is recorded as ``interrupted``, and
:func:`run_sweep` raises :class:`SweepInterrupted` carrying the result so far.
"""

from __future__ import annotations

import json
import logging
import os
import time
import traceback
from concurrent.futures import as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from ..output.hdf5 import atomic
from ..runs.status import IncompleteRun, remove_stale_temporaries
from .cases import Case
from .execution import make_executor, sigint_ignored

log = logging.getLogger(__name__)

DONE, FAILED, INCOMPLETE, INTERRUPTED, NOT_RUN = "done", "failed", "incomplete", "interrupted", "not run"


def _write_json_atomic(path: Path, payload: dict) -> None:
    with atomic(path) as tmp:  # published with the umask's mode: the case files are as readable as the rest
        with open(tmp, "w") as fh:
            json.dump(payload, fh, indent=1, default=str)


def _h5_complete(path: Path) -> bool:
    import h5py

    try:
        with h5py.File(path, "r") as f:
            return bool(f.attrs.get("complete", True))
    except OSError:
        return False


def incomplete_files(paths) -> list[Path]:
    """The HDF5 files among ``paths`` that are missing or say complete = False."""
    return [Path(p) for p in paths if Path(p).suffix == ".h5" and not (Path(p).exists() and _h5_complete(Path(p)))]


def _relative(paths, out: Path) -> list[str]:
    rel = []
    for p in paths:
        try:
            rel.append(str(Path(p).relative_to(out)))
        except ValueError:
            rel.append(str(p))
    return rel


def _without_plots(paths: list, options: dict) -> list:
    """Without --case-plots a case keeps no PNG, also from runs that draw regardless of ``plots``."""
    if options.get("plots", True):
        return paths
    keep = []
    for p in map(Path, paths):
        if p.suffix == ".png":
            p.unlink(missing_ok=True)
        else:
            keep.append(p)
    return keep


def case_verdicts(done, deck) -> list[dict[str, str]]:
    """The verdicts of a case's result (``analysis.verdicts``; ``done`` what its run handed back), as JSON: topic,
    text, status."""
    from ..analysis.verdicts import verdicts_of
    from ..deck.describe import operating_range

    return [{"topic": v.topic, "text": v.text, "status": v.status}
            for v in verdicts_of([(done.analysis, done.analysis, done.result)], operating_range(deck))]


def verdict_word(record: dict[str, Any]) -> str:
    """A case's verdicts in a few words: "ok", or the topics that fail ("NOT MET") or warn, with their first words."""
    flagged = [v for v in record.get("verdicts", ()) if v.get("status") in ("bad", "warn")]
    if not flagged:
        return "ok" if record.get("verdicts") else ""
    return "; ".join(f"{v['topic']}: {v['text'].split(':')[0]}" for v in flagged)


def run_case(case: Case, case_dir: str) -> dict[str, Any]:
    """Run one case (in a worker process); returns its record, also written as case.json.

    Never raises for a failing case (the error is recorded); KeyboardInterrupt is recorded and re-raised."""
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    os.environ.setdefault("MPLBACKEND", "Agg")
    from ..deck import DeckError, parse_deck
    from ..runs import perform_analysis, run_info_for
    from .summary import case_results

    out = Path(case_dir)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    record: dict[str, Any] = {"key": case.key, "index": case.index, "parameters": case.parameters,
                              "analysis": case.analysis}
    stop = None
    try:
        (out / "deck.yaml").write_text(case.deck_text)
        loaded = parse_deck(case.deck_text, str(out / "deck.yaml"))
        run = run_info_for(loaded, f"spindlesim sweep case {case.key}")
        done = perform_analysis(case.analysis, loaded, out, case.options, run=run)
        paths = _without_plots(list(done.paths), case.options)
        bad = incomplete_files(paths)
        if bad:  # a run that wrote incomplete files without raising IncompleteRun
            record.update(status=INCOMPLETE, files=_relative(paths, out),
                          error="incomplete output: " + ", ".join(p.name for p in bad))
        else:
            scalars, units = case_results(paths)
            record.update(status=DONE, files=_relative(paths, out), scalars=scalars, units=units,
                          verdicts=case_verdicts(done, loaded.deck))
    except IncompleteRun as exc:
        record.update(status=INTERRUPTED if exc.interrupted else INCOMPLETE, error=exc.reason,
                      files=_relative(exc.paths, out))
    except KeyboardInterrupt as exc:  # only when run in the caller's process: pool workers ignore SIGINT
        record.update(status=INTERRUPTED, error="interrupted by the user")
        stop = exc
    except DeckError as exc:
        record.update(status=FAILED, error="deck error:\n" + str(exc))
    except Exception as exc:  # a failing case must not stop the others
        record.update(status=FAILED, error=f"{type(exc).__name__}: {exc}",
                      traceback=traceback.format_exc(limit=6))
    record["elapsed_s"] = time.perf_counter() - t0
    _write_json_atomic(out / "case.json", record)
    if stop is not None:
        raise stop
    return record


def load_record(case_dir: Path) -> dict[str, Any] | None:
    try:
        return json.loads((case_dir / "case.json").read_text())
    except (OSError, ValueError):
        return None


def is_finished(record: dict[str, Any] | None, case_dir: Path) -> bool:
    """``done``, and every HDF5 file of the record present and complete (a record written by an
    older version that marked interrupted runs as done fails this and is run again)."""
    if not record or record.get("status") != DONE:
        return False
    files = [case_dir / (Path(f).name if Path(f).is_absolute() else f) for f in record.get("files") or []]
    return not incomplete_files(files) and all(f.exists() for f in files)


@dataclass(frozen=True)
class SweepResult:
    cases: tuple[Case, ...]
    records: tuple[dict[str, Any], ...]
    ran: tuple[str, ...]  # keys run to an end (any status) in this invocation
    skipped: tuple[str, ...]  # keys already finished before
    outdir: Path
    interrupted: bool = False

    def count(self, status: str) -> int:
        return sum(r.get("status") == status for r in self.records)

    @property
    def complete(self) -> bool:
        return not self.interrupted and all(r.get("status") == DONE for r in self.records)


class SweepInterrupted(IncompleteRun):
    """Ctrl-C during a sweep: the cases are stopped and recorded; ``result`` holds every record."""

    def __init__(self, result: SweepResult):
        n_int, n_not = result.count(INTERRUPTED), result.count(NOT_RUN)
        super().__init__(f"sweep interrupted: {n_int} case(s) stopped while running, {n_not} not started",
                         interrupted=True)
        self.result = result


def _stopped_record(c: Case, case_dir: Path, started_after: float) -> dict[str, Any]:
    """The record of a case unfinished when the sweep stopped (its worker has ended by now)."""
    rec = load_record(case_dir)
    if is_finished(rec, case_dir):  # finished just before the stop
        return rec
    base = {"key": c.key, "index": c.index, "parameters": c.parameters, "analysis": c.analysis}
    deck = case_dir / "deck.yaml"
    if deck.exists() and deck.stat().st_mtime >= started_after - 1.0:
        rec = {**base, "status": INTERRUPTED, "error": "stopped by the user while running; rerun the sweep to redo it"}
        _write_json_atomic(case_dir / "case.json", rec)
        return rec
    return {**base, "status": NOT_RUN, "error": "not started: the sweep was interrupted"}


def _outcome(fut, c: Case) -> dict[str, Any]:
    try:
        return fut.result()
    except Exception as exc:  # worker died (e.g. killed): record and go on
        return {"key": c.key, "index": c.index, "parameters": c.parameters, "analysis": c.analysis,
                "status": FAILED, "error": f"worker failed: {type(exc).__name__}: {exc}"}


def run_sweep(cases: list[Case], outdir: str | Path, workers: int | None = None, scheduler: str | None = None,
              progress: Callable[[int, int, float], None] | None = None) -> SweepResult:
    """Run every unfinished case on the chosen executor; returns the records of all cases.

    Raises :class:`SweepInterrupted` (with the result) on Ctrl-C, after stopping the workers."""
    outdir = Path(outdir)
    (outdir / "cases").mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(outdir)
    records: dict[str, dict] = {}
    todo: list[Case] = []
    for c in cases:
        rec = load_record(outdir / "cases" / c.key)
        if is_finished(rec, outdir / "cases" / c.key):
            records[c.key] = rec
        else:
            todo.append(c)
    skipped = tuple(records)
    log.info("sweep: %d cases, %d finished before, %d to run", len(cases), len(skipped), len(todo))
    t0, started = time.perf_counter(), time.time()
    ran: list[str] = []
    interrupted = False
    try:
        if todo:
            with make_executor(workers, scheduler) as ex:
                futures = {ex.submit(run_case, c, str(outdir / "cases" / c.key)): c for c in todo}
                for fut in as_completed(futures):
                    c = futures[fut]
                    records[c.key] = _outcome(fut, c)
                    ran.append(c.key)
                    if progress is not None:
                        elapsed = time.perf_counter() - t0
                        progress(len(ran), len(todo), elapsed / len(ran) * (len(todo) - len(ran)))
    except KeyboardInterrupt:
        interrupted = True
        with sigint_ignored():
            for c in todo:
                if c.key not in records:
                    records[c.key] = _stopped_record(c, outdir / "cases" / c.key, started)
        log.warning("sweep interrupted after %.1f s: %d case(s) finished in this run", time.perf_counter() - t0,
                    len(ran))
    res = SweepResult(tuple(cases), tuple(records[c.key] for c in cases), tuple(ran), skipped, outdir, interrupted)
    if interrupted:
        raise SweepInterrupted(res)
    return res
