"""Frozen result records of the fluid-film bearing analysis (SI units).

Clearance bases (see docs/theory.md):

- ``eccentricity_ratio`` = e / Cb (assembled clearance), as seed 003 Table 1;
- ``sommerfeld`` = mu N D L / (psi^2 W) with psi = 2 Cp / D (seed 003 eq. 3, machined
  clearance Cp; equal to Cb for a plain bearing); ``sommerfeld_b`` is the same group on Cb
  (Raimondi & Boyd's S = mu N L D (R/C)^2 / W for a plain bearing);
- ``k`` = K Cp / W and ``c`` = B Cp omega / W (seed 003 eqs. 15-16, on Cp), in the x, y
  frame; ``k_load``/``c_load`` are on Cb in the load frame (x along the load, y 90 deg
  ahead in the direction of rotation), the usual frame of Lund's tables and of Ocvirk;
- ``reynolds_number`` = rho omega R Cb / mu (on Cb).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np


@dataclass(frozen=True)
class FilmResult:
    """Isoviscous operating point of a bearing at a given speed, load and viscosity."""

    viscosity_Pa_s: float
    speed_rad_s: float
    load_N: np.ndarray  # (2,) force the shaft puts on the bearing, x, y
    position_m: np.ndarray  # (2,) journal centre relative to the bearing centre, x, y
    eccentricity_ratio: float  # e / Cb
    attitude_angle_deg: float  # from the load line to the eccentricity, + in rotation sense
    sommerfeld: float  # on Cp (seed 003 eq. 3)
    sommerfeld_b: float  # on Cb
    min_film_m: float
    friction_torque_Nm: float  # on the journal
    power_loss_W: float
    friction_coefficient: float  # T / (R W)
    inlet_flow_m3_s: float  # into the leading edges of the lands
    side_flow_m3_s: float  # leakage through both bearing edges
    reynolds_number: float  # rho omega R Cb / mu
    K_N_m: np.ndarray  # (2, 2) x, y
    C_Ns_m: np.ndarray  # (2, 2) x, y
    k: np.ndarray  # K Cp / W, x, y
    c: np.ndarray  # B Cp omega / W, x, y
    k_load: np.ndarray  # K Cb / W, load frame
    c_load: np.ndarray  # B Cb omega / W, load frame
    pressure_Pa: np.ndarray  # on the grid unknowns
    node_theta_rad: np.ndarray  # angle of each unknown in the x, y frame
    node_z_m: np.ndarray  # axial position of each unknown (0 = mid-plane, half width)
    full_film: np.ndarray | None = None  # full-film set on the solver grid (warm starts)
    #: the dimensionless film solution at this position (independent of viscosity, speed and load):
    #: the first Newton step of a neighbouring operating point starts from it without a new solve
    solution: Any = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class ThermalResult:
    """Thermal equilibrium (seed 003 eqs. 4-14) and the operating point at it."""

    temperature_mean_C: float
    temperature_out_C: float
    temperature_in_C: float
    ambient_C: float
    heat_generated_W: float  # H = T_f omega (eq. 6)
    heat_to_oil_W: float  # H1 (eq. 7)
    heat_to_housing_W: float  # H2 (eq. 9)
    oil_flow_m3_s: float  # q of eq. 7
    housing_conductance_W_K: float  # a_hat * A
    isoviscous: bool
    #: film solutions the search took (each a Reynolds solution in the joint steps from a neighbour, each a
    #: journal equilibrium at a trial temperature in the nested search)
    iterations: int
    film: FilmResult
    #: dg/dtheta at the equilibrium, g(theta) = balance temperature - trial temperature (negative; NaN when
    #: not measured): the first step of the next search from a neighbouring state
    balance_slope: float = field(default=float("nan"), compare=False)

    #: the scalar quantities of the result and its film, as thermal.h5 names them
    SCALARS: ClassVar[tuple[str, ...]] = ("temperature_mean_C", "temperature_out_C", "temperature_in_C", "ambient_C", "viscosity_Pa_s",
               "sommerfeld", "sommerfeld_b", "eccentricity_ratio", "attitude_angle_deg", "min_film_m",
               "friction_torque_Nm", "power_loss_W", "friction_coefficient", "oil_flow_m3_s", "inlet_flow_m3_s",
               "side_flow_m3_s", "reynolds_number", "heat_generated_W", "heat_to_oil_W", "heat_to_housing_W")

    def quantity(self, name: str) -> float:
        """The scalar ``name`` (of :data:`SCALARS`), of the result or of its film."""
        return float(getattr(self, name) if hasattr(self, name) else getattr(self.film, name))

    def not_computed(self) -> tuple[str, ...]:
        """The scalars an isoviscous film without the oil's density and specific heat does not have (no heat
        balance: its temperatures, heat flows, Reynolds number are not finite); () for a thermal equilibrium."""
        if not self.isoviscous:
            return ()
        return tuple(k for k in self.SCALARS if not np.isfinite(self.quantity(k)))


@dataclass(frozen=True)
class FilmBearings:
    """What the ``thermal`` and ``coefficients`` analyses of a deck's fluid-film bearings compute: each bearing
    (by name, in the deck's order) at its thermal equilibrium at one speed."""

    speed_rad_s: float
    names: tuple[str, ...]
    results: tuple[ThermalResult, ...]

    @property
    def speed_rpm(self) -> float:
        return self.speed_rad_s * 30.0 / math.pi

    def by_name(self) -> list[tuple[str, ThermalResult]]:
        """(name, result) in the order of the names (how an HDF5 file lists its groups)."""
        return sorted(zip(self.names, self.results), key=lambda item: item[0])
