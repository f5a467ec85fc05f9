"""Oil viscosity of the fluid-film bearings: the Walther (ASTM D341) relation and ISO VG grades.

The one implementation lives in :mod:`spindlesim.thermal.oil` (the bearings' friction heat of issue
22 uses the same oils, and the thermal package sits below the bearings in the layers); this module
keeps the names the fluid-film code and the decks' documentation use.
"""

from ...thermal.oil import (ISO_VG_40C, ISO_VG_100C_TYPICAL, LIGHT_OIL_SLOPE, OIL_MAX_C, ZERO_C_K,
                            ConstantViscosity, WaltherViscosity)

__all__ = ["ISO_VG_40C", "ISO_VG_100C_TYPICAL", "LIGHT_OIL_SLOPE", "OIL_MAX_C", "ZERO_C_K", "ConstantViscosity",
           "WaltherViscosity"]
