"""Package exports imported on first use (PEP 562).

A package lists what it exports and the module defining each name; the module is imported when the
name is first read.  Loading a deck reads only the deck sections, so it does not pay for the solvers'
imports (scipy.signal, scipy.interpolate, numba ...)::

    __getattr__, __dir__ = lazy_exports(__name__, {"FluidFilmBearing": "bearing", ...})
"""

from __future__ import annotations

import importlib
import sys
from typing import Callable


def lazy_exports(package: str, exports: dict[str, str]) -> tuple[Callable[[str], object], Callable[[], list[str]]]:
    """(``__getattr__``, ``__dir__``) for ``package`` whose ``exports`` map a name to its submodule."""

    def __getattr__(name: str):
        module = exports.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(f".{module}", package), name)
        setattr(sys.modules[package], name, value)
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(exports))

    return __getattr__, __dir__
