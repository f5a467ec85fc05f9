"""Oil viscosity: Walther / ASTM D341 relation and ISO VG grades (fluid-film bearings, bearing friction).

Walther equation (ASTM D341; seed 003 eq. 13, REFERENCES.md)::

    log10 log10(nu + 0.8) = -m log10(T) + k        nu in cSt (mm^2/s), T in K

and the dynamic viscosity ``mu = rho * nu * 1e-6`` (seed 003 eq. 14; the paper prints
``exp{exp{...}}`` but the constants are decadic, as in eq. 13 and ASTM D341).  The oil
density is taken constant, as in seed 003 Table 1.

ISO VG grades (ISO 3448) fix only the mid-point kinematic viscosity at 40 degC.  The
slope needs a second point: for VG 10 and above we use the typical 100 degC viscosities
of VI ~ 95-100 mineral oils tabulated by lubesolut.com ("Viscosity industrial reference
table", ISO VG 10: 2.5 cSt ... VG 1500: 74 cSt at 100 degC).  For the light spindle oils
VG 2 to VG 7 no 100 degC value is tabulated; we take the Walther slope of VG 10,
m = 3.935, which gives 0.94, 1.21, 1.53, 1.97 cSt at 100 degC for VG 2, 3, 5, 7
(a typical spindle oil VG 3 has ~1.2 cSt at 100 degC).  These are generic oils: give the
Walther constants (``walther_m``, ``walther_k``) of the real oil whenever they are known.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

ZERO_C_K = 273.15
_SHIFT = 0.8  # cSt, seed 003 eq. 13

#: ISO 3448 mid-point kinematic viscosity at 40 degC (cSt)
ISO_VG_40C: dict[int, float] = {
    2: 2.2, 3: 3.2, 5: 4.6, 7: 6.8, 10: 10.0, 15: 15.0, 22: 22.0, 32: 32.0, 46: 46.0,
    68: 68.0, 100: 100.0, 150: 150.0, 220: 220.0, 320: 320.0, 460: 460.0, 680: 680.0,
    1000: 1000.0, 1500: 1500.0,
}
#: typical kinematic viscosity at 100 degC (cSt) of VI ~ 95-100 mineral oils (lubesolut.com)
ISO_VG_100C_TYPICAL: dict[int, float] = {
    10: 2.5, 15: 3.5, 22: 4.5, 32: 5.5, 46: 6.5, 68: 8.5, 100: 11.4, 150: 14.5,
    220: 19.0, 320: 24.5, 460: 32.0, 680: 42.0, 1000: 55.0, 1500: 74.0,
}
#: Walther slope used for VG 2-7 (that of VG 10 from the two points above)
LIGHT_OIL_SLOPE = 3.935
#: mean film temperature above which a mineral oil is past its usable range (its oxidation life
#: halves every ~10 C; 120 C is the usual upper limit of circulating-oil systems)
OIL_MAX_C = 120.0


def _ll(nu_cst: float) -> float:
    return math.log10(math.log10(nu_cst + _SHIFT))


@dataclass(frozen=True)
class WaltherViscosity:
    """Walther (ASTM D341) oil: constants ``m``, ``k`` and constant density."""

    m: float
    k: float
    density_kg_m3: float

    @classmethod
    def from_two_points(cls, nu1_cst: float, t1_C: float, nu2_cst: float, t2_C: float,
                        density_kg_m3: float) -> "WaltherViscosity":
        """Fit m and k through two (kinematic viscosity, temperature) points."""
        if nu1_cst <= 0.2 or nu2_cst <= 0.2 or t1_C == t2_C:
            raise ValueError("need two distinct temperatures and viscosities > 0.2 cSt")
        x1, x2 = math.log10(t1_C + ZERO_C_K), math.log10(t2_C + ZERO_C_K)
        y1, y2 = _ll(nu1_cst), _ll(nu2_cst)
        m = -(y2 - y1) / (x2 - x1)
        return cls(m=m, k=y1 + m * x1, density_kg_m3=density_kg_m3)

    @classmethod
    def from_grade(cls, grade: str, density_kg_m3: float) -> "WaltherViscosity":
        """ISO VG grade, e.g. ``"ISO VG 3"`` or ``"VG32"`` (see module docstring)."""
        mt = re.fullmatch(r"\s*(?:ISO\s*)?(?:VG\s*)?(\d+)\s*", grade, flags=re.I)
        if not mt or int(mt.group(1)) not in ISO_VG_40C:
            raise ValueError(
                f"unknown oil grade {grade!r}; known: "
                + ", ".join(f"ISO VG {g}" for g in ISO_VG_40C))
        g = int(mt.group(1))
        nu40 = ISO_VG_40C[g]
        if g in ISO_VG_100C_TYPICAL:
            return cls.from_two_points(nu40, 40.0, ISO_VG_100C_TYPICAL[g], 100.0,
                                       density_kg_m3)
        x40 = math.log10(40.0 + ZERO_C_K)
        m = LIGHT_OIL_SLOPE
        return cls(m=m, k=_ll(nu40) + m * x40, density_kg_m3=density_kg_m3)

    def kinematic_cst(self, temperature_C: float) -> float:
        """Kinematic viscosity in cSt at ``temperature_C``."""
        T = temperature_C + ZERO_C_K
        if T <= 0:
            raise ValueError("temperature below absolute zero")
        return 10.0 ** (10.0 ** (self.k - self.m * math.log10(T))) - _SHIFT

    def __call__(self, temperature_C: float) -> float:
        """Dynamic viscosity in Pa s (seed 003 eq. 14)."""
        return self.density_kg_m3 * self.kinematic_cst(temperature_C) * 1e-6


@dataclass(frozen=True)
class ConstantViscosity:
    """Isoviscous oil (no temperature dependence)."""

    viscosity_Pa_s: float
    density_kg_m3: float = 850.0

    def __post_init__(self) -> None:
        if self.viscosity_Pa_s <= 0:
            raise ValueError("viscosity must be positive")

    def __call__(self, temperature_C: float) -> float:
        return self.viscosity_Pa_s
