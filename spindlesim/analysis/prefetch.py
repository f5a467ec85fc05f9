"""Modes of a Campbell diagram's static states while the next states are still being found.

The static states of a Campbell diagram are found one after the other, each started from its
neighbour's (bearings re-solved at every speed: ball sets, fluid films); the modes of a state need
only that state and the reduced basis.  :class:`ModalPrefetch` guesses the basis the reduced model
starts from (its first cut-off, built at the first state, as :func:`.reduced.checked_basis` builds
it) and solves each state's modes on a second thread as soon as the state is known.  Once every
state is known, the guess must still pass the check against the full model at the first and the
last speed (:func:`.reduced.checked_basis` given the guess); when it does not, the prefetched modes
are dropped and the diagram is solved as without prefetching.  Either way the results are those of
the serial path: the same basis, the same eigenproblem at every speed.

After the last state the calling thread takes speeds from the back while the worker goes on from
the front.
"""

from __future__ import annotations

import threading
from typing import Any, Callable


class ModalPrefetch:
    """``solve(state, rpm)`` for each state ``add``-ed, on a worker thread, in order."""

    def __init__(self, solve: Callable[[Any, float], Any]):
        self._solve = solve
        self._items: list[tuple[Any, float]] = []
        self._results: dict[int, Any] = {}
        self._error: Exception | None = None
        self._front = 0
        self._back: int | None = None  # set by finish(): the calling thread works down from here
        self._stop = False
        self._cond = threading.Condition()
        self._thread = threading.Thread(target=self._work, name="campbell-modal-prefetch", daemon=True)
        self._thread.start()

    def add(self, state: Any, rpm: float) -> None:
        with self._cond:
            self._items.append((state, rpm))
            self._cond.notify()

    def finish(self) -> list | None:
        """Every state's result, in order (the last ones solved here); None when a solve failed (the
        serial path then solves again and reports the first failing speed, as it would have)."""
        with self._cond:
            self._back = len(self._items)
            self._cond.notify_all()
        while self._error is None:
            with self._cond:
                if self._back <= self._front:
                    break
                self._back -= 1
                k = self._back
            if not self._run(k):
                break
        self._thread.join()
        if self._error is not None:
            return None
        return [self._results[k] for k in range(len(self._items))]

    def cancel(self) -> None:
        """Drop whatever is left (the guessed basis failed its check, or the states failed)."""
        with self._cond:
            self._stop = True
            self._cond.notify_all()
        self._thread.join()

    def _work(self) -> None:
        while True:
            with self._cond:
                while not self._stop and self._front >= len(self._items) and self._back is None:
                    self._cond.wait()
                end = len(self._items) if self._back is None else self._back
                if self._stop or self._error is not None or self._front >= end:
                    return
                k = self._front
                self._front += 1
            if not self._run(k):
                return

    def _run(self, k: int) -> bool:
        state, rpm = self._items[k]
        try:
            self._results[k] = self._solve(state, rpm)
        except Exception as exc:  # finish() then hands over to the serial path
            with self._cond:
                if self._error is None:
                    self._error = exc
                self._cond.notify_all()
            return False
        return True
