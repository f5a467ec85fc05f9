"""Fluid properties vs temperature: air, water, water-ethylene glycol (SI, temperatures in degC).

Tables at 1 atm (air, water) and 3 bar (glycol mixtures), evaluated with CoolProp 8.0 and written
here as numbers (the library does not depend on CoolProp):

- water: IAPWS-95 (Wagner and Pruss 2002, J. Phys. Chem. Ref. Data 31, 387), viscosity IAPWS 2008
  (Huber et al. 2009), conductivity IAPWS 2011 (Huber et al. 2012); 0.01-90 degC.
- air: Lemmon et al. 2000 (J. Phys. Chem. Ref. Data 29, 331) and Lemmon and Jacobsen 2004 (Int. J.
  Thermophys. 25, 21) transport; -20-200 degC.
- monoethylene glycol in water, 30 % and 50 % by mass: Melinder, Properties of Secondary Working
  Fluids for Indirect Systems (IIR 2010), as CoolProp's incompressible ``MEG`` fits; 0-80 degC.

Between table points the viscosity is interpolated linearly in ln(mu) against 1/T (Andrade's form,
exact for an Arrhenius law), the other properties linearly in T; outside a table's range a
ValueError is raised (no extrapolation).  Interpolation error against the formulations: below 0.5 % (water viscosity near 5 degC), below
0.15 % for everything else (checked in the tests).
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass

import numpy as np

#: kelvin at 0 degC
KELVIN = 273.15


@dataclass(frozen=True)
class FluidProperties:
    """Density [kg/m^3], dynamic viscosity [Pa s], conductivity [W/(m K)], c_p [J/(kg K)]."""

    density_kg_m3: float
    viscosity_Pa_s: float
    conductivity_W_mK: float
    specific_heat_J_kgK: float

    @property
    def kinematic_viscosity_m2_s(self) -> float:
        return self.viscosity_Pa_s / self.density_kg_m3

    @property
    def prandtl(self) -> float:
        return self.viscosity_Pa_s * self.specific_heat_J_kgK / self.conductivity_W_mK

    @property
    def diffusivity_m2_s(self) -> float:
        return self.conductivity_W_mK / (self.density_kg_m3 * self.specific_heat_J_kgK)


# columns: t [degC], rho, mu, k, cp
_WATER = np.array([
    [0.01, 999.844, 1.79113e-3, 0.555675, 4219.41],
    [10.0, 999.702, 1.30590e-3, 0.578777, 4195.16],
    [20.0, 998.207, 1.00160e-3, 0.598012, 4184.05],
    [30.0, 995.649, 7.97222e-4, 0.614392, 4179.82],
    [40.0, 992.216, 6.52729e-4, 0.628486, 4179.41],
    [50.0, 988.035, 5.46516e-4, 0.640621, 4181.34],
    [60.0, 983.196, 4.66035e-4, 0.651000, 4184.95],
    [70.0, 977.765, 4.03548e-4, 0.659758, 4190.07],
    [80.0, 971.790, 3.54051e-4, 0.666994, 4196.75],
    [90.0, 965.310, 3.14175e-4, 0.672789, 4205.21],
])

_AIR = np.array([
    [-20.0, 1.39565, 1.62012e-5, 0.0228117, 1005.54],
    [0.0, 1.29307, 1.72184e-5, 0.0243605, 1005.68],
    [20.0, 1.20458, 1.82057e-5, 0.0258738, 1006.14],
    [40.0, 1.12745, 1.91652e-5, 0.0273543, 1006.92],
    [60.0, 1.05963, 2.00991e-5, 0.0288041, 1008.02],
    [80.0, 0.999515, 2.10089e-5, 0.0302253, 1009.46],
    [100.0, 0.945869, 2.18965e-5, 0.0316199, 1011.23],
    [120.0, 0.897696, 2.27631e-5, 0.0329895, 1013.34],
    [140.0, 0.854199, 2.36103e-5, 0.0343358, 1015.79],
    [160.0, 0.814726, 2.44391e-5, 0.0356603, 1018.55],
    [180.0, 0.778745, 2.52507e-5, 0.0369641, 1021.62],
    [200.0, 0.745810, 2.60461e-5, 0.0382486, 1024.97],
])

_MEG30 = np.array([
    [0.0, 1044.97, 4.29759e-3, 0.445923, 3658.09],
    [10.0, 1041.81, 2.98300e-3, 0.455508, 3688.51],
    [20.0, 1038.05, 2.16645e-3, 0.464897, 3718.25],
    [30.0, 1033.70, 1.63889e-3, 0.474076, 3747.23],
    [40.0, 1028.80, 1.28555e-3, 0.483027, 3775.35],
    [50.0, 1023.38, 1.04090e-3, 0.491735, 3802.55],
    [60.0, 1017.46, 8.66045e-4, 0.500183, 3828.72],
    [70.0, 1011.08, 7.37094e-4, 0.508356, 3853.79],
    [80.0, 1004.26, 6.38840e-4, 0.516237, 3877.67],
])

_MEG50 = np.array([
    [0.0, 1074.62, 7.92977e-3, 0.376816, 3202.88],
    [10.0, 1070.02, 5.25651e-3, 0.382963, 3258.41],
    [20.0, 1064.93, 3.69321e-3, 0.389148, 3312.04],
    [30.0, 1059.39, 2.72865e-3, 0.395348, 3363.55],
    [40.0, 1053.44, 2.10328e-3, 0.401538, 3412.72],
    [50.0, 1047.13, 1.67810e-3, 0.407692, 3459.32],
    [60.0, 1040.49, 1.37492e-3, 0.413786, 3503.15],
    [70.0, 1033.57, 1.14774e-3, 0.419797, 3543.97],
    [80.0, 1026.41, 9.68457e-4, 0.425698, 3581.58],
])

TABLES = {"air": _AIR, "water": _WATER, "water_glycol_30": _MEG30, "water_glycol_50": _MEG50}
#: coolant names accepted by :func:`fluid`
FLUIDS = tuple(TABLES)


class PropertyRangeError(ValueError):
    """A fluid's temperature left its property table (a coolant boiling, air beyond 200 C): in a spindle's
    thermal loop, the sign that the spindle has run away."""


class _Table:
    """Columns of a property table as Python lists (a scalar lookup is a bisect, ~1 us)."""

    def __init__(self, table: np.ndarray, name: str):
        self.name = name
        self.t = [float(x) for x in table[:, 0]]
        self.cols = [[float(x) for x in table[:, j]] for j in (1, 3, 4)]
        self.inv = [1.0 / (x + KELVIN) for x in self.t]
        self.lnmu = [math.log(x) for x in table[:, 2]]

    def __call__(self, t_C: float) -> FluidProperties:
        t = float(t_C)
        ts = self.t
        if not ts[0] - 1e-9 <= t <= ts[-1] + 1e-9:
            raise PropertyRangeError(f"{self.name} properties are tabulated for {ts[0]:g}..{ts[-1]:g} degC, "
                                     f"not {t:g} degC")
        i = min(max(bisect.bisect_right(ts, t) - 1, 0), len(ts) - 2)
        w = (t - ts[i]) / (ts[i + 1] - ts[i])
        rho, k, cp = ((1.0 - w) * c[i] + w * c[i + 1] for c in self.cols)
        v = (1.0 / (t + KELVIN) - self.inv[i]) / (self.inv[i + 1] - self.inv[i])
        mu = math.exp((1.0 - v) * self.lnmu[i] + v * self.lnmu[i + 1])
        return FluidProperties(rho, mu, k, cp)


_LOOKUP = {name: _Table(table, name) for name, table in TABLES.items()}


#: the air temperatures [C] the spindle's network evaluates its film properties within (clipped to them)
AIR_FILM_RANGE_C = (-20.0, 200.0)


def clip_air_C(t_C: float) -> float:
    """``t_C`` clipped to :data:`AIR_FILM_RANGE_C`: where the spindle network's air films take their properties."""
    return min(max(t_C, AIR_FILM_RANGE_C[0]), AIR_FILM_RANGE_C[1])


def air(t_C: float) -> FluidProperties:
    """Dry air at 1 atm, -20..200 degC."""
    return _LOOKUP["air"](t_C)


def water(t_C: float) -> FluidProperties:
    """Liquid water at 1 atm, 0.01..90 degC."""
    return _LOOKUP["water"](t_C)


def fluid(name: str, t_C: float) -> FluidProperties:
    """Properties of ``name`` (one of :data:`FLUIDS`) at ``t_C``."""
    try:
        table = _LOOKUP[name]
    except KeyError:
        raise ValueError(f"unknown fluid {name!r}; known: {', '.join(FLUIDS)}") from None
    return table(t_C)
