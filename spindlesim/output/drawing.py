"""Where figures are drawn: in this process, or in a figure process started before the imports.

A run writes a PNG with ``draw(path, figure, *args, **kwargs)``: ``figure(*args, **kwargs)`` builds a
matplotlib figure (a module-level function of a plotting module) and :func:`save_figure` writes it
atomically to ``path``.  ``draw`` returns ``path``.

In a library call (and in the test suite's in-process command runs) that happens at once, here.

The ``spindlesim`` program starts a *figure process* (:func:`figure_process`) before it imports
numpy: a forked child that imports matplotlib (a quarter of a second, as long as the deck, the
physics and the HDF5 file of an everyday command together) while this process reads the deck and
computes, and then draws the figures it is sent, while this process writes its files.  ``draw``
then only sends (figure, arguments) and returns; :func:`wait` returns once every figure sent is
on disk and raises the first failure as it would have been raised here.  The plotting modules
used through ``draw`` import matplotlib inside their functions, so this process never pays for it.

The single-bearing (``bearing``) run builds its figures itself and saves them with
:func:`~.figures.save_figure`.  The transient sends its result without the rotor's DOFs
(``transient_plots.for_figures``) and draws its time series decimated to the pixel columns.

Rules of the figure process (docs/decisions.md, "Process start-up"):
* it is a child made by ``fork`` before numpy, BLAS threads or any other thread exists; where
  there is no ``fork`` (Windows) or ``SPINDLESIM_FIGURE_PROCESS=0``, figures are drawn here;
* it ignores SIGINT: Ctrl-C reaches this process, which cancels the figures not yet started; the
  one being drawn is finished (a file is replaced whole, never half-written) before it exits;
* it exits on its own when this process dies (a watchdog thread polls the parent's pid), so a
  killed run leaves no process behind.
"""

from __future__ import annotations

import logging
import os
import threading
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Callable, Iterator

from ..analysis.aside import exit_with_parent

log = logging.getLogger(__name__)

ENV = "SPINDLESIM_FIGURE_PROCESS"  # "0": draw in the main process even from the command line

_allowed = False  # set by allow(): only the spindlesim program makes figure processes
_executor = None  # concurrent.futures.ProcessPoolExecutor while a figure process runs
_pending: list = []  # futures of figures sent and not yet waited for


def draw(path: str | Path, figure: Callable[..., Any], *args: Any, **kwargs: Any) -> Path:
    """Write ``figure(*args, **kwargs)`` as the PNG ``path``; returns ``path``.

    With a figure process the file exists once :func:`wait` has returned."""
    path = Path(path)
    if _executor is None:
        return _draw(path, figure, args, kwargs)
    _pending.append(_executor.submit(_draw, path, figure, args, kwargs))
    return path


def wait() -> None:
    """Block until every figure sent is written; raise the first failure (the others are still waited for)."""
    first = None
    while _pending:
        fut = _pending.pop(0)
        exc = fut.exception()
        if exc is not None and first is None:
            first = exc
    if first is not None:
        raise first


def abandon() -> None:
    """A run failed or was interrupted: cancel the figures not yet started (the one being drawn finishes)."""
    while _pending:
        _pending.pop().cancel()


def allow() -> None:
    """Let :func:`figure_process` make figure processes (called by the ``spindlesim`` program only:
    a library caller, a test runner or a sweep worker draws in its own process)."""
    global _allowed
    _allowed = True


def available() -> bool:
    """True where a figure process can be made: allowed, ``fork`` exists, SPINDLESIM_FIGURE_PROCESS is not 0."""
    return _allowed and hasattr(os, "fork") and os.environ.get(ENV, "1") != "0"


@contextmanager
def figure_process(enabled: bool = True) -> Iterator[bool]:
    """Run the body with figures drawn in a forked figure process; yields whether one runs.

    Call it before numpy is imported: the child is made at once and starts importing matplotlib."""
    global _executor
    if not enabled or _executor is not None or not available():
        yield False
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    import signal

    # Ctrl-C held back while the child is made: it starts with SIGINT blocked and ignores it before
    # unblocking (a Ctrl-C in between would otherwise kill it in its start-up); here a Ctrl-C that
    # came meanwhile is delivered when the block is lifted, right after the fork
    masked = hasattr(signal, "pthread_sigmask")
    if masked:
        signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        executor = ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("fork"),
                                       initializer=_start_child, initargs=(os.getpid(),))
        executor.submit(int)  # makes the child now (fork), before this process starts any thread
    except (OSError, ImportError) as exc:  # no process to spare, no POSIX semaphores (/dev/shm): draw here
        log.info("no figure process (%s); figures are drawn in the main process", exc)
        if masked:
            signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
        yield False
        return
    if masked:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    _executor = executor
    try:
        yield True
    except BaseException:
        abandon()
        raise
    finally:
        _executor = None
        try:
            wait()  # figures sent by a body that returned normally; nothing left after abandon()
        finally:
            executor.shutdown(wait=True, cancel_futures=True)


def _draw(path: Path, figure: Callable[..., Any], args: tuple, kwargs: dict) -> Path:
    from .figures import save_figure

    return save_figure(figure(*args, **kwargs), path)


def _start_child(parent: int) -> None:
    """In the figure process: ignore Ctrl-C, exit with the parent, import matplotlib."""
    import gc
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})  # blocked by the parent around the fork
    threading.Thread(target=exit_with_parent, args=(parent,), daemon=True, name="figure-process-watchdog").start()
    from . import figures

    figures.new_figure()  # the canvas and the font cache: the first figure costs no more than the others
    gc.freeze()  # the imported modules are never garbage: the collector need not walk them again

