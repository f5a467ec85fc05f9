"""numba's on-disk cache of a compiled function that inlines code from other files.

numba keys a cached function by its own source file only (a documented limitation of its cache):
``explicit_kernel.rk4`` inlines every compiled bearing family (``bearings.compiled`` and the kernels
it dispatches to), so after one of those files changes (an edited kernel in an editable install, a
``git pull``) the loop compiled from the old kernels would still be loaded from ``__pycache__`` and
run.  :func:`track` gives such a function numba's own cache locators (``NUMBA_CACHE_DIR``, next to the
module, the user's cache directory, in numba's order) with a source stamp that also covers the files
it inlines: a change to any of them recompiles it once.

numba's locator classes are not public API; where they are not found, caching stays numba's default
(and a stale loop after an edited kernel stays possible: a debug message says so).
"""

from __future__ import annotations

import functools
import hashlib
import logging
import os

log = logging.getLogger(__name__)

#: (source file, qualified name) of a tracked function -> the files its compiled code inlines
_TRACKED: dict[tuple[str, str], tuple[str, ...]] = {}
_installed = False


@functools.lru_cache(maxsize=None)
def _file_digest(path: str, mtime_ns: int, size: int) -> str:
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def digest(files: tuple[str, ...]) -> str:
    """SHA-256 over the contents of ``files`` (each read once per change of its size or time)."""
    h = hashlib.sha256()
    for path in files:
        st = os.stat(path)
        h.update(_file_digest(path, st.st_mtime_ns, st.st_size).encode())
    return h.hexdigest()


def _tracking(base: type) -> type:
    """``base`` (one of numba's locators) for tracked functions only, its stamp covering their files."""

    class Tracking(base):
        def __init__(self, py_func, py_file):
            super().__init__(py_func, py_file)
            self.dependencies = _TRACKED[(os.path.abspath(py_file), py_func.__qualname__)]

        @classmethod
        def from_function(cls, py_func, py_file):
            if (os.path.abspath(py_file), py_func.__qualname__) not in _TRACKED:
                return None
            return super().from_function(py_func, py_file)

        def get_source_stamp(self):
            return super().get_source_stamp(), digest(self.dependencies)

    Tracking.__name__ = Tracking.__qualname__ = f"Tracking{base.__name__.lstrip('_')}"
    return Tracking


def _install() -> bool:
    global _installed
    if _installed:
        return True
    try:
        from numba.core import caching
    except ImportError:  # pragma: no cover - numba is a dependency
        return False
    impl = getattr(caching, "CacheImpl", None) or getattr(caching, "_CacheImpl", None)
    names = ("UserProvidedCacheLocator", "InTreeCacheLocator", "UserWideCacheLocator")
    bases = [getattr(caching, n, None) or getattr(caching, "_" + n, None) for n in names]
    if impl is None or not isinstance(getattr(impl, "_locator_classes", None), list) or None in bases:
        log.debug("numba's cache locators not found: a kernel inlined into a cached loop is not tracked")
        return False
    impl._locator_classes[:0] = [_tracking(b) for b in bases]
    _installed = True
    return True


def track(source_file: str, qualname: str, files) -> None:
    """Make the cache of the function ``qualname`` of ``source_file`` stale when any of ``files``
    changes.  Call before the function is decorated (the decorator picks its cache locator)."""
    _TRACKED[(os.path.abspath(source_file), qualname)] = tuple(os.path.abspath(f) for f in files)
    _install()
