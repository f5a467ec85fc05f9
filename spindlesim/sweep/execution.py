"""Executors: a local process pool, or a Dask distributed cluster through the same Executor interface.

Stopping (Ctrl-C, or any error in the loop that waits for the cases): the executor context
cancels every case not yet started and stops the running ones before the exception goes on:

- process pool: the workers ignore SIGINT (a terminal's Ctrl-C reaches the whole process group;
  the parent decides), pending cases are cancelled and the workers terminated (SIGTERM, then
  SIGKILL after a grace period);
- Dask: every future is cancelled; a LocalCluster is closed, which ends its worker processes.
  On a remote scheduler the cases already running finish on their workers (Dask cannot stop a
  running task); the ones that finish write their own ``case.json``.
"""

from __future__ import annotations

import contextlib
import logging
import os
import signal
import threading
import time
import warnings
from concurrent.futures import Executor, ProcessPoolExecutor
from typing import Iterator

log = logging.getLogger(__name__)

#: seconds a terminated worker gets before it is killed
GRACE_S = 3.0


def _worker_init() -> None:
    """Pool workers leave SIGINT to the parent, which cancels and terminates them."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


@contextlib.contextmanager
def sigint_ignored() -> Iterator[None]:
    """Ignore further Ctrl-C while stopping (main thread only; elsewhere a no-op)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


class Deferred:
    """What :func:`sigint_deferred` saw: ``interrupted`` once a Ctrl-C arrived inside it."""

    interrupted = False


@contextlib.contextmanager
def sigint_deferred() -> Iterator[Deferred]:
    """Hold Ctrl-C back while something short must finish (a summary file of finished work): a Ctrl-C
    inside sets ``interrupted`` and the body goes on; the caller then stops with exit code 130."""
    seen = Deferred()
    if threading.current_thread() is not threading.main_thread():
        yield seen
        return

    def note(signum, frame):
        seen.interrupted = True

    previous = signal.signal(signal.SIGINT, note)
    try:
        yield seen
    finally:
        signal.signal(signal.SIGINT, previous)


def stop_process_pool(ex: ProcessPoolExecutor, grace_s: float = GRACE_S) -> None:
    """Cancel the cases not started and end the worker processes now."""
    # no public handle on the workers before Python 3.14 (terminate_workers)
    procs = list((getattr(ex, "_processes", None) or {}).values())
    manager = getattr(ex, "_executor_manager_thread", None)
    ex.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        if p.is_alive():
            p.terminate()
    deadline = time.monotonic() + grace_s
    for p in procs:
        p.join(max(0.0, deadline - time.monotonic()))
        if p.is_alive():
            log.warning("worker %s did not stop on SIGTERM; killing it", p.pid)
            p.kill()
            p.join(1.0)
    if manager is not None:
        manager.join(grace_s)
    log.info("process pool stopped: %d worker(s) ended", len(procs))


@contextlib.contextmanager
def make_executor(workers: int | None = None, scheduler: str | None = None) -> Iterator[Executor]:
    """``scheduler=None``: ProcessPoolExecutor (all cores by default); ``"local"``: a Dask
    LocalCluster; any other string: the address of a running Dask scheduler."""
    workers = workers or os.cpu_count() or 1
    if scheduler is None:
        ex = ProcessPoolExecutor(max_workers=workers, initializer=_worker_init)
        try:
            yield ex
        except BaseException:
            with sigint_ignored():
                stop_process_pool(ex)
            raise
        ex.shutdown(wait=True)
        return
    try:
        from distributed import Client, LocalCluster
    except ImportError as exc:  # pragma: no cover - depends on the installation
        raise RuntimeError("--scheduler needs Dask: pip install 'spindlesim[dask]'") from exc
    quiet = _quiet_dask()
    if scheduler == "local":
        with warnings.catch_warnings():
            if quiet:  # "Port 8787 is already in use" when another cluster runs: not the user's concern
                warnings.simplefilter("ignore")
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=":0", silence_logs=logging.ERROR)
        client = Client(cluster)
    else:
        cluster = None
        client = Client(scheduler)
    log.info("dask client: %s", client)
    executor = client.get_executor(pure=False)
    try:
        yield executor
    except BaseException:
        with sigint_ignored():
            executor.shutdown(wait=False)  # cancels every future: queued cases never start
            _close_dask(client, cluster)
        raise
    _close_dask(client, cluster)


def _quiet_dask() -> bool:
    """Dask's own log lines (scheduler and worker start-up, connections closed at shutdown) follow the
    command's verbosity: none by default, its INFO lines with -v, DEBUG with -vv.  Importing distributed
    sets its loggers' levels from its configuration, so this runs after the import.  A case that fails
    is reported by the sweep itself, whatever Dask logs."""
    asked = logging.getLogger("spindlesim").getEffectiveLevel()  # -v: INFO, -vv: DEBUG (spindlesim/cli.py)
    level = logging.CRITICAL if asked > logging.INFO else asked
    for name in ("distributed", "tornado", "bokeh"):
        logging.getLogger(name).setLevel(level)
    return level == logging.CRITICAL


def _close_dask(client, cluster) -> None:
    client.close()
    if cluster is not None:
        cluster.close()  # ends the worker processes, running cases included
