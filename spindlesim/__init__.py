"""spindlesim: static and dynamic analysis of machine-tool spindles and their bearings.

The package is layered (see docs/decisions.md): ``deck`` reads YAML into a frozen
SI ``Deck``; ``model`` builds the rotor; ``fe`` assembles matrices; ``bearings``
holds bearing models; ``analysis`` solves; ``output`` writes HDF5 and PNG.
"""

__version__ = "0.1.0"


def _caches() -> None:
    import os

    from ._cachedirs import ensure

    ensure(os.path.dirname(__file__))


_caches()  # before numba or matplotlib is imported: writable caches on a read-only installation
del _caches
