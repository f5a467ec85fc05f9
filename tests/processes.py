"""Helpers for tests that start real ``spindlesim`` processes and interrupt them."""

from __future__ import annotations

import signal


def as_in_a_terminal() -> None:
    """``preexec_fn`` of a child that a test will Ctrl-C: SIGINT handled as in a terminal.

    A shell running the test suite in the background (``make test &``, some CI runners) starts it
    with SIGINT ignored, and Python leaves an ignored SIGINT ignored in its children: the
    interrupt a test sends would then never arrive."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
