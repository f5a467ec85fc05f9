"""Executors: a local process pool, or a Dask distributed cluster through the same Executor interface."""

from __future__ import annotations

import contextlib
import logging
import os
from concurrent.futures import Executor, ProcessPoolExecutor
from typing import Iterator

log = logging.getLogger(__name__)


@contextlib.contextmanager
def make_executor(workers: int | None = None, scheduler: str | None = None) -> Iterator[Executor]:
    """``scheduler=None``: ProcessPoolExecutor (all cores by default); ``"local"``: a Dask
    LocalCluster; any other string: the address of a running Dask scheduler."""
    workers = workers or os.cpu_count() or 1
    if scheduler is None:
        with ProcessPoolExecutor(max_workers=workers) as ex:
            yield ex
        return
    try:
        from distributed import Client, LocalCluster
    except ImportError as exc:  # pragma: no cover - depends on the installation
        raise RuntimeError("--scheduler needs Dask: pip install 'spindlesim[dask]'") from exc
    if scheduler == "local":
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=None, silence_logs=logging.ERROR)
        client = Client(cluster)
    else:
        cluster = None
        client = Client(scheduler)
    log.info("dask client: %s", client)
    try:
        yield client.get_executor(pure=False)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
