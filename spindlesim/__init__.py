"""spindlesim: static and dynamic analysis of machine-tool spindles and their bearings.

The package is layered (see docs/decisions.md): ``deck`` reads YAML into a frozen
SI ``Deck``; ``model`` builds the rotor; ``fe`` assembles matrices; ``bearings``
holds bearing models; ``analysis`` solves; ``output`` writes HDF5 and PNG.
"""

__version__ = "0.1.0"
