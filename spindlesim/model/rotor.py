"""Rotor model in SI: shaft elements, disks, bearings, loads (built from a deck by ``model.build``)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .dofs import DofMap


@dataclass(frozen=True)
class ShaftElements:
    """Arrays over elements (SI). Element i joins node i and node i+1 (0-based)."""

    outer_diameter_m: np.ndarray
    inner_diameter_m: np.ndarray
    length_m: np.ndarray
    density_kg_m3: np.ndarray
    youngs_modulus_Pa: np.ndarray
    shear_modulus_Pa: np.ndarray
    poisson: np.ndarray
    axial_force_N: np.ndarray  # positive = tension
    shear_coefficient: np.ndarray
    viscous_damping_s: float = 0.0  # eta_v, seed 003 eq. 17
    hysteretic_loss_factor: float = 0.0  # eta_h

    @property
    def count(self) -> int:
        return len(self.length_m)

    @classmethod
    def empty(cls) -> "ShaftElements":
        """No shaft (a rigid journal)."""
        z = np.zeros(0)
        return cls(z, z, z, z, z, z, z, z, z)

    @property
    def area_m2(self) -> np.ndarray:
        return np.pi / 4 * (self.outer_diameter_m**2 - self.inner_diameter_m**2)

    @property
    def second_moment_m4(self) -> np.ndarray:
        return np.pi / 64 * (self.outer_diameter_m**4 - self.inner_diameter_m**4)


@dataclass(frozen=True)
class Disk:
    node: int  # 0-based
    mass_kg: float
    polar_inertia_kg_m2: float
    diametral_inertia_kg_m2: float
    name: str = ""


@dataclass(frozen=True)
class NodalLoad:
    node: int
    force_N: tuple[float, float, float, float]  # fx, fy, mx, my
    axial_N: float = 0.0  # fz, used when the model has the axial DOF


@dataclass(frozen=True)
class Rotor:
    node_z_m: np.ndarray
    elements: ShaftElements
    disks: tuple[Disk, ...] = ()
    bearings: tuple = ()  # objects following the bearing contract (spindlesim/bearings/base.py)
    loads: tuple[NodalLoad, ...] = ()
    speed_rpm: float = 0.0  # the deck's operating speed
    gravity_m_s2: float = 0.0  # 0 = gravity off; otherwise along -y
    dofs: DofMap = field(default=None)  # type: ignore[assignment]
    ground_damping_Ns_m: float = 0.0  # viscous damping of the x, y translations to ground (rigid journal)

    def __post_init__(self) -> None:
        if self.dofs is None:
            object.__setattr__(self, "dofs", DofMap(len(self.node_z_m)))

    @property
    def n_nodes(self) -> int:
        return len(self.node_z_m)

    @property
    def speed_rad_s(self) -> float:
        return self.speed_rpm * np.pi / 30.0
