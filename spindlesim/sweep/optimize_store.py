"""The evaluations of an optimisation: one design analysed (``evaluate_design``, in a worker process or here), its
record, and the journal that keeps every record as it finishes (``evaluations.jsonl`` in the output folder).

A design is the deck's text with the variables' values written at their key paths (``deck.paths.replace_in_text``,
17 digits: the value evaluated exactly), validated as any deck, and its named results computed by the existing
analyses (``named_results``).  A design that fails (the deck refuses it, a bearing that does not converge, a
thermal runaway) is a record with its reason and no results: infeasible, never the end of the study.

The journal is keyed by the deck without its ``optimize:`` section (a changed budget or objective keeps the
designs evaluated; a changed model value starts afresh) and by the design's values: rerunning the same command
reads it back and evaluates only designs not in it, so an interrupted study resumes where it stopped and ends as
an uninterrupted one would (the methods are deterministic given their seed and the values they are given).
"""

from __future__ import annotations

import hashlib
import json
import logging
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

log = logging.getLogger(__name__)

JOURNAL = "evaluations.jsonl"


@dataclass(frozen=True)
class Record:
    """One design: its variables' values (numbers, or the chosen word), the named results (empty when it
    failed), why it failed ("" : it did not), the seconds it took."""

    values: tuple
    results: dict = field(default_factory=dict)
    error: str = ""
    elapsed_s: float = 0.0

    @property
    def failed(self) -> bool:
        return bool(self.error)


def design_key(values) -> str:
    return json.dumps([v if isinstance(v, str) else float(v) for v in values])


def evaluate_design(text: str, source: str, names: tuple[str, ...]) -> tuple[dict, str, float]:
    """(named results, error, seconds) of one design's deck text; never raises but for Ctrl-C."""
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    from ..deck import DeckError, parse_deck
    from .named_results import evaluate_names

    t0 = time.perf_counter()
    results: dict = {}
    error = ""
    try:
        results = evaluate_names(parse_deck(text, source), names)
        bad = [n for n, v in results.items() if not math.isfinite(v)]
        if bad:
            error, results = f"{bad[0]} is not finite ({results[bad[0]]})", {}
    except DeckError as exc:
        error = f"deck error: {exc.issues[0].message}"
    except Exception as exc:  # noqa: BLE001 - a failing design is recorded, never the end of the study
        error = f"{type(exc).__name__}: {exc}".splitlines()[0]
    return results, error, time.perf_counter() - t0


def model_digest(text: str) -> str:
    """SHA-256 of the deck's data without its ``optimize:`` section."""
    from ..deck.yamlmarks import DeckLoader

    data = yaml.load(text, Loader=DeckLoader)
    if isinstance(data, dict):
        data.pop("optimize", None)
    return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()


class Journal:
    """``evaluations.jsonl``: one line a finished design, appended and flushed as it finishes."""

    def __init__(self, outdir: Path, digest: str):
        self.path = Path(outdir) / JOURNAL
        self.digest = digest
        self.cache: dict[str, Record] = {}
        if self.path.exists():
            for line in self.path.read_text().splitlines():
                try:
                    row = json.loads(line)
                except ValueError:  # a line cut short by a kill: that design is evaluated again
                    continue
                if row.get("model") == digest:
                    rec = Record(tuple(row["values"]), row.get("results") or {}, row.get("error", ""),
                                 float(row.get("elapsed_s", 0.0)))
                    self.cache[design_key(rec.values)] = rec
            log.info("optimize: %d design(s) evaluated before read from %s", len(self.cache), self.path)

    def get(self, values, names) -> Record | None:
        rec = self.cache.get(design_key(values))
        if rec is None or (not rec.failed and any(n not in rec.results for n in names)):
            return None
        return rec

    def add(self, rec: Record) -> None:
        self.cache[design_key(rec.values)] = rec
        row = {"model": self.digest, "values": list(rec.values), "results": rec.results, "error": rec.error,
               "elapsed_s": rec.elapsed_s}
        with open(self.path, "a") as fh:
            fh.write(json.dumps(row) + "\n")
            fh.flush()
