"""A computation set aside: run in a forked process while this one goes on, its result waited for when needed.

An analysis sometimes needs a second, independent result only at its end: ``chatter`` the lobes of the deck
speed's FRF drawn for comparison and the spindle's thermal speed limit, both independent of the lobes at every
speed; the warm-up's stable depth is one independent lobe solve per instant (:func:`map_aside`).  Computed one after the other they leave a core idle while this process builds the per-speed models
(work that holds the interpreter lock).  :class:`Aside` computes ``fn(*args)`` in a child process forked at
once (it inherits ``fn`` and ``args``: nothing is pickled but the result) and :meth:`Aside.result` waits for it.

The numbers are those of the call made here: the same function on the same arguments, in one process.  The
child runs everything on its one thread (as the semi-discretization's worker processes do) and ignores Ctrl-C:
this process decides, and :meth:`Aside.cancel` stops the child.  Where no process can be forked (no ``fork``,
inside a worker process, SPINDLESIM_SD_PROCESSES=0, which also keeps the semi-discretization in this process)
or the child dies, ``fn(*args)`` is computed here when its result is asked for.
"""

from __future__ import annotations

import itertools
import logging
import multiprocessing
import os
import signal
import sys
import threading
import time
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from typing import Any, Callable

log = logging.getLogger(__name__)

_TASKS: dict[int, tuple[Callable[..., Any], tuple]] = {}  # what a child is forked to compute, by key
_KEYS = itertools.count()


def _child_start() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # this process decides (cancel)
    threading.Thread(target=exit_with_parent, args=(os.getppid(),), daemon=True, name="aside-watchdog").start()
    sd = sys.modules.get("spindlesim.chatter.semi_discretization")
    if sd is not None:  # the thread pools copied from this process have no threads in the child
        sd._SERIAL = True


def exit_with_parent(parent: int, period_s: float = 0.5) -> None:
    """A child's watchdog (run on a daemon thread): exit when the process ``parent`` is gone (killed: a child
    that waits for work from it would wait for ever)."""
    while os.getppid() == parent:
        time.sleep(period_s)
    os._exit(1)


class _Failed:
    """The child's call raised: computed again here, so that the exception is the call's own (an exception
    need not survive pickling)."""


def _run(key: int) -> Any:
    fn, args = _TASKS[key]
    try:
        return fn(*args)
    except Exception:  # noqa: BLE001 - raised again, whole, by the call made in the parent
        return _Failed()


def available() -> bool:
    """Whether a computation can be set aside in a forked process here."""
    return (hasattr(os, "fork") and os.environ.get("SPINDLESIM_SD_PROCESSES", "1") != "0"
            and multiprocessing.parent_process() is None and (os.cpu_count() or 1) > 1)


class Aside:
    """``fn(*args)``, computed in a forked child process from now on (module note); :meth:`result` returns it."""

    def __init__(self, fn: Callable[..., Any], *args: Any):
        self._fn, self._args = fn, args
        self._pool: ProcessPoolExecutor | None = None
        self._future = None
        if not available():
            return
        key = next(_KEYS)
        _TASKS[key] = (fn, args)
        try:  # the child is forked in submit: it has the task in its memory
            self._pool = ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("fork"),
                                             initializer=_child_start)
            self._future = self._pool.submit(_run, key)
        except (OSError, ValueError) as exc:  # no process to spare: computed here when asked for
            log.info("computed in this process, not aside: %s", exc)
            self._stop()
        finally:
            _TASKS.pop(key, None)

    def result(self) -> Any:
        """The result (the child's exception raised here, as the call would raise it)."""
        if self._future is None:
            return self._fn(*self._args)
        try:
            got = self._future.result()
        except BrokenProcessPool as exc:  # the child died (killed, out of memory): computed here
            log.warning("a computation set aside stopped (%s); computed again in this process", exc)
            got = _Failed()
        finally:
            self._stop()
        self._future = None
        return self._fn(*self._args) if isinstance(got, _Failed) else got

    def cancel(self) -> None:
        """Stop the child (the user pressed Ctrl-C, or the result is not needed)."""
        if self._pool is not None:
            for p in list(getattr(self._pool, "_processes", {}).values()):
                p.kill()
        self._stop()

    def _stop(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=False, cancel_futures=True)
            self._pool = None


def _each(fn: Callable[[Any], Any], items: list) -> list:
    return [fn(x) for x in items]


def map_aside(fn: Callable[[Any], Any], items) -> list:
    """``[fn(x) for x in items]`` with the items shared between this process and forked children (one per
    further core, an :class:`Aside` each, the last shares; this process takes the first): every item computed
    whole in one process, so the list is the serial one.  ``fn`` should not raise (a child's exception makes
    its share computed again here)."""
    items = list(items)
    n = min(len(items), os.cpu_count() or 1, 8) if available() else 1
    if n < 2:
        return _each(fn, items)
    cut = [round(k * len(items) / n) for k in range(n + 1)]
    others = [Aside(_each, fn, items[cut[k]:cut[k + 1]]) for k in range(1, n)]
    try:
        out = _each(fn, items[:cut[1]])
        for o in others:
            out += o.result()
    except BaseException:
        for o in others:
            o.cancel()
        raise
    return out


class Known:
    """A result known already, with :class:`Aside`'s interface."""

    def __init__(self, value: Any):
        self._value = value

    def result(self) -> Any:
        return self._value

    def cancel(self) -> None:
        pass


class Then:
    """The result of ``pending`` (an :class:`Aside` or :class:`Known`) passed through ``fn``, same interface."""

    def __init__(self, pending: Any, fn: Callable[[Any], Any]):
        self._pending, self._fn = pending, fn

    def result(self) -> Any:
        return self._fn(self._pending.result())

    def cancel(self) -> None:
        self._pending.cancel()
