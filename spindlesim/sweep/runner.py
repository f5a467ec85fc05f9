"""Run a sweep: every case in its own directory, finished cases skipped, failures recorded.

A case is finished when ``cases/<key>/case.json`` says ``"status": "done"``; the key
hashes the resolved deck text, analysis and options, so re-running an interrupted
sweep runs only what is missing, and changing a deck value makes a new case.
"""

from __future__ import annotations

import json
import logging
import os
import tempfile
import time
import traceback
from concurrent.futures import as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from .cases import Case
from .execution import make_executor

log = logging.getLogger(__name__)


def _write_json_atomic(path: Path, payload: dict) -> None:
    fd, tmp = tempfile.mkstemp(prefix=path.name + ".", suffix=".tmp", dir=path.parent)
    with os.fdopen(fd, "w") as fh:
        json.dump(payload, fh, indent=1, default=str)
    os.replace(tmp, path)


def run_case(case: Case, case_dir: str) -> dict[str, Any]:
    """Run one case (in a worker process); never raises: errors are returned and recorded."""
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    os.environ.setdefault("MPLBACKEND", "Agg")
    from ..runs import run_analysis, run_info_for
    from ..deck import DeckError, parse_deck
    from .summary import case_scalars

    out = Path(case_dir)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    record: dict[str, Any] = {"key": case.key, "index": case.index, "parameters": case.parameters,
                              "analysis": case.analysis}
    try:
        (out / "deck.yaml").write_text(case.deck_text)
        loaded = parse_deck(case.deck_text, str(out / "deck.yaml"))
        run = run_info_for(loaded, f"spindlesim sweep case {case.key}")
        paths = run_analysis(case.analysis, loaded, out, case.options, run=run)
        record.update(status="done", files=[str(p) for p in paths], scalars=case_scalars(paths))
    except DeckError as exc:
        record.update(status="failed", error="deck error:\n" + str(exc))
    except Exception as exc:  # a failing case must not stop the others
        record.update(status="failed", error=f"{type(exc).__name__}: {exc}",
                      traceback=traceback.format_exc(limit=6))
    record["elapsed_s"] = time.perf_counter() - t0
    _write_json_atomic(out / "case.json", record)
    return record


def load_record(case_dir: Path) -> dict[str, Any] | None:
    try:
        return json.loads((case_dir / "case.json").read_text())
    except (OSError, ValueError):
        return None


@dataclass(frozen=True)
class SweepResult:
    cases: tuple[Case, ...]
    records: tuple[dict[str, Any], ...]
    ran: tuple[str, ...]  # keys run in this invocation
    skipped: tuple[str, ...]  # keys already finished before
    outdir: Path


def run_sweep(cases: list[Case], outdir: str | Path, workers: int | None = None, scheduler: str | None = None,
              progress: Callable[[int, int, float], None] | None = None) -> SweepResult:
    """Run every unfinished case on the chosen executor; returns the records of all cases."""
    outdir = Path(outdir)
    (outdir / "cases").mkdir(parents=True, exist_ok=True)
    records: dict[str, dict] = {}
    todo: list[Case] = []
    for c in cases:
        rec = load_record(outdir / "cases" / c.key)
        if rec is not None and rec.get("status") == "done":
            records[c.key] = rec
        else:
            todo.append(c)
    skipped = tuple(records)
    log.info("sweep: %d cases, %d finished before, %d to run", len(cases), len(skipped), len(todo))
    t0 = time.perf_counter()
    done = 0
    if todo:
        with make_executor(workers, scheduler) as ex:
            futures = {ex.submit(run_case, c, str(outdir / "cases" / c.key)): c for c in todo}
            for fut in as_completed(futures):
                c = futures[fut]
                try:
                    rec = fut.result()
                except Exception as exc:  # worker died (e.g. killed): record and go on
                    rec = {"key": c.key, "index": c.index, "parameters": c.parameters, "status": "failed",
                           "error": f"worker failed: {type(exc).__name__}: {exc}"}
                records[c.key] = rec
                done += 1
                if progress is not None:
                    elapsed = time.perf_counter() - t0
                    progress(done, len(todo), elapsed / done * (len(todo) - done))
    ordered = tuple(records[c.key] for c in cases)
    return SweepResult(tuple(cases), ordered, tuple(c.key for c in todo), skipped, outdir)
