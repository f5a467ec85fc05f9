"""Writable cache directories for numba and matplotlib where the defaults are not (a read-only install).

numba caches compiled kernels next to their modules (``__pycache__``), else under the user's cache
directory, and raises at import ("cannot cache function ...: no locator available") when neither
can be written: a read-only installation with a read-only or missing home directory.  matplotlib
then warns that its configuration directory is not writable and rebuilds its font cache in a new
temporary directory at every run.  :func:`ensure` (called when the package is imported, before
numba or matplotlib) points them, only in that case and only if the user has not, at the first
writable of spindlesim's cache directory (``$SPINDLESIM_CACHE`` or ``~/.cache/spindlesim``) and the
temporary directory, which persist across runs.  It imports neither library.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


def writable(path: Path) -> bool:
    """True if ``path`` exists or can be made, and a file can be created in it."""
    try:
        path.mkdir(parents=True, exist_ok=True)
        tempfile.TemporaryFile(dir=path).close()
        return True
    except OSError:
        return False


def _user_cache() -> Path:
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")


def _fallback(name: str) -> Path | None:
    """``name`` under spindlesim's cache directory, else under the temporary directory; None if neither."""
    try:
        own = Path(os.environ["SPINDLESIM_CACHE"]) if os.environ.get("SPINDLESIM_CACHE") else \
            _user_cache() / "spindlesim"
    except RuntimeError:  # no home directory
        own = None
    uid = os.getuid() if hasattr(os, "getuid") else 0
    for path in ([own / name] if own is not None else []) + [Path(tempfile.gettempdir()) / f"spindlesim-{uid}" / name]:
        if writable(path):
            return path
    return None


def ensure(package_dir: str) -> None:
    """Set NUMBA_CACHE_DIR and MPLCONFIGDIR where numba's and matplotlib's defaults cannot be written."""
    if not os.environ.get("NUMBA_CACHE_DIR") and not writable(Path(package_dir) / "__pycache__"):
        try:
            numba_default = writable(_user_cache() / "numba")
        except RuntimeError:
            numba_default = False
        path = None if numba_default else _fallback("numba")
        if path is not None:
            os.environ["NUMBA_CACHE_DIR"] = str(path)
    if not os.environ.get("MPLCONFIGDIR"):
        try:
            config = Path(os.environ.get("XDG_CONFIG_HOME") or Path.home() / ".config") / "matplotlib"
            ok = writable(config)
        except RuntimeError:
            ok = False
        path = None if ok else _fallback("matplotlib")
        if path is not None:
            os.environ["MPLCONFIGDIR"] = str(path)
