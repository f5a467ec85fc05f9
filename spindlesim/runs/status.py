"""How a run ended.

A run that wrote its files but did not finish (the integration stopped early, or the user
pressed Ctrl-C) raises :class:`IncompleteRun` *after* writing them: the files carry
``complete = False`` and the reason, the exception carries the paths.  The commands turn it
into an exit code (3, or 130 when interrupted) with the one map of spindlesim/commands/exits.py.

Also here: removal of the temporary files (``<name>.<random>.tmp``, ``.tmp.png``) that an
atomic writer killed mid-write leaves next to its output.
"""

from __future__ import annotations

import logging
import os
import re
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable

log = logging.getLogger(__name__)

#: what the transient engine writes as the reason of a run stopped by KeyboardInterrupt
_INTERRUPT_REASON = re.compile(r"^\s*interrupted by the user", re.IGNORECASE)


@dataclass(frozen=True)
class Written:
    """What a run hands back: its analysis's frozen result (what the terminal summary, the report's section, the
    verdicts and a sweep's case read) and the files it wrote from it.  ``analysis``: the registered analysis that
    ran (``perform_analysis`` fills it in: the ``thermal`` command runs ``spindle_thermal`` on a spindle deck)."""

    result: Any
    paths: tuple[Path, ...]
    analysis: str = ""
    #: files of another analysis's kind the run wrote too, each summarised as that analysis summarises its own:
    #: (file name, analysis, its result); e.g. a transient's contact pressure of a DTRB's most loaded roller
    also: tuple[tuple[str, str, Any], ...] = ()


class IncompleteRun(Exception):
    """A run that wrote (some of) its files but did not finish; raised after writing them.  ``result``: what was
    computed before it stopped (the analysis's result, partial), or None; ``noted``: the reason its files carry
    (``incomplete_reason``; default ``reason``), which its summary repeats."""

    def __init__(self, reason: str, paths: Iterable[Path] = (), interrupted: bool = False, result: Any = None,
                 noted: str | None = None, also: tuple = ()):
        super().__init__(reason)
        self.reason = reason
        self.noted = reason if noted is None else noted
        self.paths = [Path(p) for p in paths]
        self.interrupted = interrupted
        self.result = result
        self.also = tuple(also)  # files of another analysis's kind written too (as ``Written.also``)
        self.analysis = ""

    @property
    def written(self) -> Written:
        return Written(self.result, tuple(self.paths), self.analysis, self.also)


def is_interrupt(result) -> bool:
    """Whether an incomplete result was stopped by the user (Ctrl-C) rather than by the solver.

    Uses the result's ``interrupted`` flag when it has one, else the engine's reason text."""
    flag = getattr(result, "interrupted", None)
    if flag is not None:
        return bool(flag)
    return bool(_INTERRUPT_REASON.match(getattr(result, "reason", "") or ""))


#: ``<name>.<8 characters of tempfile.mkstemp>.tmp`` or ``.tmp.png``
_STALE = re.compile(r"^.+\.[A-Za-z0-9_]{8}\.tmp(\.png)?$")


def remove_stale_temporaries(outdir: str | Path, older_than_s: float = 10.0) -> list[Path]:
    """Delete the atomic writers' temporary files in ``outdir`` (not below it) last modified more
    than ``older_than_s`` before now: leftovers of a run killed while writing.  A file a live
    writer is filling is younger than that and is kept.  Returns what was removed."""
    folder = Path(outdir)
    if not folder.is_dir():
        return []
    limit = time.time() - older_than_s
    removed = []
    for p in folder.iterdir():
        if not _STALE.match(p.name):
            continue
        try:
            if p.is_file() and p.stat().st_mtime < limit:
                p.unlink()
                removed.append(p)
        except OSError as exc:  # gone already, or not ours to delete
            log.debug("could not remove %s: %s", p, exc)
    if removed:
        log.info("removed %d stale temporary file(s) in %s: %s", len(removed), folder,
                 ", ".join(p.name for p in removed))
    return removed


def file_mode() -> int:
    """The mode a new file gets under the current umask (0o644 under umask 022); tempfile.mkstemp
    creates 0o600, which an atomic writer then renames into place."""
    try:  # Linux: read the umask without changing it (os.umask is process-wide, not thread-safe)
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("Umask:"):
                return 0o666 & ~int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return 0o666 & ~mask
