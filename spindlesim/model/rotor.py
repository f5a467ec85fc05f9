"""Rotor model in SI: shaft elements, disks, bearings, loads (built from a deck by ``model.build``)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .dofs import DofMap


@dataclass(frozen=True)
class ShaftElements:
    """Arrays over elements (SI).  Element i joins ``node_a[i]`` and ``node_b[i]`` (0-based); by default
    node i and node i + 1 (a shaft), a tool and its holder continue from the spindle nose."""

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
    node_a: np.ndarray | None = None  # default arange(count)
    node_b: np.ndarray | None = None  # default node_a + 1

    def __post_init__(self) -> None:
        if self.node_a is None:
            object.__setattr__(self, "node_a", np.arange(len(self.length_m)))
        if self.node_b is None:
            object.__setattr__(self, "node_b", np.asarray(self.node_a) + 1)

    @property
    def count(self) -> int:
        return len(self.length_m)

    @staticmethod
    def join(*parts: "ShaftElements") -> "ShaftElements":
        """One set of every part's elements (material damping from the first part)."""
        cat = {f: np.concatenate([getattr(p, f) for p in parts]) for f in (
            "outer_diameter_m", "inner_diameter_m", "length_m", "density_kg_m3", "youngs_modulus_Pa",
            "shear_modulus_Pa", "poisson", "axial_force_N", "shear_coefficient", "node_a", "node_b")}
        return ShaftElements(**cat, viscous_damping_s=parts[0].viscous_damping_s,
                             hysteretic_loss_factor=parts[0].hysteretic_loss_factor)

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
class Joint:
    """Springs and dampers between two nodes (a tool in its holder): translational on x, y (and z where
    the rotor has it) and rotational on theta_x, theta_y, f_a = -k (q_a - q_b) - c (q_a' - q_b')."""

    node_a: int
    node_b: int
    translational_N_m: float
    rotational_Nm_rad: float
    translational_Ns_m: float = 0.0
    rotational_Nms_rad: float = 0.0


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
    joints: tuple[Joint, ...] = ()
    tool_tip: int | None = None  # 0-based node of the tool tip (deck section ``tool``)

    def __post_init__(self) -> None:
        if self.dofs is None:
            object.__setattr__(self, "dofs", DofMap(len(self.node_z_m)))

    @property
    def n_nodes(self) -> int:
        return len(self.node_z_m)

    @property
    def speed_rad_s(self) -> float:
        return self.speed_rpm * np.pi / 30.0

    @property
    def mass_kg(self) -> float:
        """Mass of every beam element (shaft, holder, tool) and disk."""
        e = self.elements
        beams = float(np.sum(e.density_kg_m3 * e.area_m2 * e.length_m))
        return beams + float(sum(d.mass_kg for d in self.disks))
