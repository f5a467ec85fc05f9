"""A library call without stray output: what it prints, its progress bars and its warnings go to the log.

sdypy-EMA draws tqdm progress bars on stderr and prints notes; pyFRF prints when asked to be verbose; both
warn through :mod:`warnings`.  Library code of spindlesim logs and never prints, so every call into them
runs inside :func:`quiet`: standard output and error are caught for its duration (the call runs in the
main thread of a command; nothing else writes meanwhile) and replayed as debug lines of this logger
(``spindlesim -vv`` shows them), and warnings are recorded and logged the same way.
"""

from __future__ import annotations

import contextlib
import io
import logging
import warnings
from typing import Iterator

log = logging.getLogger(__name__)


@contextlib.contextmanager
def quiet(library: str) -> Iterator[None]:
    """Run the body with ``library``'s prints, progress bars and warnings caught and logged (debug)."""
    out, err = io.StringIO(), io.StringIO()
    try:
        with warnings.catch_warnings(record=True) as caught, contextlib.redirect_stdout(out), \
                contextlib.redirect_stderr(err):
            warnings.simplefilter("always")
            yield
    finally:
        for stream, text in (("printed", out.getvalue()), ("wrote on stderr", err.getvalue())):
            lines = [s for s in text.replace("\r", "\n").splitlines() if s.strip()]
            if lines:
                log.debug("%s %s %d line(s), last: %s", library, stream, len(lines), lines[-1].strip())
        for w in locals().get("caught") or ():
            log.debug("%s warned: %s", library, w.message)
